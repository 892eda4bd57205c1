#include "study/analysis/figures/gnuplot_runner.hpp"

#include <stdexcept>

#include "util/run_program.hpp"

namespace robozoo {

bool gnuplot_available(const std::string& gnuplot) {
  const ProgramResult f = run_program({gnuplot, "-e", "set terminal pngcairo; print 'ok'"});
  return f.status == 0 && f.output.find("ok") != std::string::npos;
}

void run_gnuplot(const std::string& script_path, const std::string& gnuplot, const std::string& cwd) {
  const ProgramResult f = run_program({gnuplot, script_path}, cwd);
  if (f.status == 126) throw std::runtime_error("cannot enter " + cwd + " to run " + gnuplot);
  if (f.status == 127) throw std::runtime_error("cannot run " + gnuplot + " (install gnuplot-nox)");
  if (f.status != 0)
    throw std::runtime_error(gnuplot + " failed on " + script_path + " (exit status " + std::to_string(f.status) +
                             "): " + f.output);
}

}  // namespace robozoo
