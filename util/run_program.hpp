#pragma once
// Running another program to completion and capturing what it prints (gnuplot
// for the plots, robozoo-render for the zoo sheets).
#include <string>
#include <vector>

namespace robozoo {

struct ProgramResult {
  int status = -1;     ///< exit status, 128 + signal, 127 when it could not be started
  std::string output;  ///< stdout and stderr together
};

/// Runs argv (argv[0] looked up in PATH when it holds no '/') with stdin from
/// /dev/null, in the folder `cwd` (empty: the current one), waits for it and
/// returns its status and output.
ProgramResult run_program(const std::vector<std::string>& argv, const std::string& cwd = "");

}  // namespace robozoo
