#include "study/analysis/sensitivity/sensitivity_plot.hpp"

#include <cmath>
#include <sstream>

namespace robozoo {

namespace {

/// A datablock row: y, gap, low, high (an interval that is not finite collapses onto the gap).
std::string row(double y, const MeanGap& g) {
  const bool bars = std::isfinite(g.low) && std::isfinite(g.high);
  return gnuplot_number(y) + " " + gnuplot_number(g.gap) + " " + gnuplot_number(bars ? g.low : g.gap) + " " +
         gnuplot_number(bars ? g.high : g.gap) + "\n";
}

}  // namespace

std::string sensitivity_plot_script(const SensitivityAnalysis& a, const std::string& png_path, const std::string& title,
                                    const PlotStyle& style) {
  const SensitivityParams& p = a.params;
  const size_t n = a.factors.size();
  const int level = static_cast<int>(std::lround(100 * p.level));
  std::ostringstream s;
  s << gnuplot_png_terminal(png_path, style);
  s << "set title " << gnuplot_text(title) << "\n";
  // The first factor on top: factor i at y = n - i, its reference a quarter below.
  s << "$factor << EOD\n";
  for (size_t i = 0; i < n; ++i) s << row(static_cast<double>(n - i), a.factors[i].gap);
  s << "EOD\n$reference << EOD\n";
  for (size_t i = 0; i < n; ++i) s << row(static_cast<double>(n - i) - 0.25, a.factors[i].reference_gap);
  s << "EOD\n";
  s << "set ytics (";
  for (size_t i = 0; i < n; ++i) s << (i ? ", " : "") << gnuplot_text(a.factors[i].name) << " " << n - i;
  s << ")\n";
  s << "set yrange [0.4:" << n << ".5]\n";
  s << "set xlabel "
    << gnuplot_text("gap in best-so-far fitness after " + std::to_string(p.generation) +
                    " generations: " + p.control_arm + " mean minus " + p.experimental_arm + " mean, with its " +
                    std::to_string(level) + " % interval")
    << "\n";
  s << "set grid xtics\n";
  s << "set key outside top center horizontal\n";
  s << "set arrow from 0, graph 0 to 0, graph 1 nohead dashtype 2 linecolor rgb \"gray30\"\n";
  s << "plot $factor using 2:1:3:4 with xerrorbars pointtype 7 pointsize 1.4 linewidth 2 linecolor rgb \"#c0392b\" "
       "title \"the factor changed\", \\\n"
       "     $reference using 2:1:3:4 with xerrorbars pointtype 6 pointsize 1.4 linewidth 2 linecolor rgb "
       "\"#2c3e50\" title \"the reference, the same seeds\"\n";
  return s.str();
}

}  // namespace robozoo
