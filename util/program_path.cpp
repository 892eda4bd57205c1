#include "util/program_path.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>

namespace robozoo {

std::string program_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot read /proc/self/exe: " + ec.message());
  return exe.parent_path().string();
}

bool is_executable(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

std::string find_program(const std::string& name, const std::string& search_path) {
  if (name.empty()) return "";
  if (name.find('/') != std::string::npos) return name;
  size_t from = 0;
  for (;;) {
    const size_t colon = search_path.find(':', from);
    std::string dir = search_path.substr(from, colon == std::string::npos ? std::string::npos : colon - from);
    if (dir.empty()) dir = ".";  // an empty PATH entry means the current folder
    const std::string candidate = dir + "/" + name;
    if (is_executable(candidate)) return candidate;
    if (colon == std::string::npos) return "";
    from = colon + 1;
  }
}

}  // namespace robozoo
