#pragma once
// robozoo's software version: the git commit the build was made from, taken at
// build time (tools/cmake/version_stamp.cmake), with "-dirty" when tracked
// files differed from it. Written into every run_t and checkpoint, compared by
// --resume and robozoo-replay check, printed by every program's --version.
#include <string>

namespace robozoo {

const char* software_version_string();  ///< e.g. "3594238abcde" or "3594238abcde-dirty"
const char* project_version_string();   ///< the CMake project version, e.g. "0.1.0"

/// The line every program's --version prints: "robozoo 0.1.0, git 3594238abcde".
std::string version_line();

}  // namespace robozoo
