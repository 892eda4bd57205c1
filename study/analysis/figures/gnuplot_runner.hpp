#pragma once
// Running gnuplot (Debian's gnuplot-nox) on a script file: the experiment's
// plots come from a real plotting tool.
#include <string>

namespace robozoo {

/// True when `gnuplot` (a command name looked up in PATH, or a path) runs and
/// has the pngcairo terminal.
bool gnuplot_available(const std::string& gnuplot = "gnuplot");

/// Runs `gnuplot script_path` in the folder `cwd` (empty: the current one; a
/// relative script path is read from there); throws std::runtime_error with
/// gnuplot's own messages when it cannot be started or exits with an error.
void run_gnuplot(const std::string& script_path, const std::string& gnuplot = "gnuplot", const std::string& cwd = "");

}  // namespace robozoo
