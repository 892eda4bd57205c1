#pragma once
// Where the running program lives, so that one robozoo program finds another
// in the same bin folder (robozoo-experiment runs robozoo-evolve, robozoo-stats
// runs robozoo-render).
#include <string>

namespace robozoo {

/// The folder of the running executable (from /proc/self/exe); throws
/// std::runtime_error when it cannot be read.
std::string program_dir();

/// True when `path` is an executable regular file.
bool is_executable(const std::string& path);

/// `name` as execv needs it: unchanged when it holds a '/', else the first
/// executable `dir/name` over the folders of `search_path` (a PATH value);
/// "" when there is none.
std::string find_program(const std::string& name, const std::string& search_path);

}  // namespace robozoo
