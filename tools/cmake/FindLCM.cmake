# FindLCM: LCM (Lightweight Communications and Marshalling) from Debian's
# liblcm-dev / liblcm-bin / liblcm-java. Debian ships no CMake config for LCM,
# only a pkg-config file (which in turn needs glib-2.0's development files).
#
# Provides:
#   LCM::lcm            imported library target (C and C++ API)
#   LCM_GEN_EXECUTABLE  path of lcm-gen
#   LCM_JAR             path of lcm.jar (may be empty: Java types are optional)
#   LCM_FOUND, LCM_VERSION
find_package(PkgConfig REQUIRED)
pkg_check_modules(PC_LCM QUIET IMPORTED_TARGET lcm)

find_program(LCM_GEN_EXECUTABLE lcm-gen)
find_file(LCM_JAR lcm.jar PATHS /usr/share/java /usr/local/share/java
          PATH_SUFFIXES lcm NO_DEFAULT_PATH)
set(LCM_VERSION "${PC_LCM_VERSION}")

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LCM
  REQUIRED_VARS LCM_GEN_EXECUTABLE PC_LCM_FOUND
  VERSION_VAR LCM_VERSION
  FAIL_MESSAGE "LCM not found: run tools/setup.sh (needs liblcm-dev, liblcm-bin and libglib2.0-dev)")

if(LCM_FOUND AND NOT TARGET LCM::lcm)
  add_library(LCM::lcm INTERFACE IMPORTED)
  target_link_libraries(LCM::lcm INTERFACE PkgConfig::PC_LCM)
endif()
