#pragma once
// A program's errors as its exit status: what a command's body throws becomes
// one line on stderr, "PROGRAM: what", and the status robozoo's programs share:
// 2 for bad input or options (std::invalid_argument), 1 for any other failure.
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

namespace robozoo {

/// Runs `body` (which returns the exit status) and reports what it throws.
template <class Body>
int exit_status_of(const std::string& program, Body&& body) {
  try {
    return body();
  } catch (const std::invalid_argument& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace robozoo
