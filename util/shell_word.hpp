#pragma once
// A word for a shell command line that a report prints for people to run again.
#include <string>

namespace robozoo {

/// `w` as one POSIX shell word: as it is when it holds only characters no shell
/// treats specially (letters, digits and /._-+,=:@%), else in single quotes, each
/// single quote written as '\''.
std::string shell_word(const std::string& w);

}  // namespace robozoo
