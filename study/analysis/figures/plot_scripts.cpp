#include "study/analysis/figures/plot_scripts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace robozoo {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "NaN";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string terminal(const std::string& png_path, const PlotStyle& style) {
  return "set terminal pngcairo enhanced size " + std::to_string(style.width) + "," + std::to_string(style.height) +
         " font " + gnuplot_quote(style.font) + "\nset output " + gnuplot_quote(png_path) + "\n";
}

// Breaks `text` at spaces into lines of at most about `width` characters.
std::string wrap(const std::string& text, size_t width) {
  std::string out, line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (char c : text) {
    if (c == ' ') {
      flush_word();
    } else {
      word += c;
    }
  }
  flush_word();
  return out + line;
}

}  // namespace

std::string gnuplot_number(double v) { return num(v); }

std::string gnuplot_png_terminal(const std::string& png_path, const PlotStyle& style) {
  return terminal(png_path, style);
}

std::string gnuplot_quote(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    if (c == '\n') {
      q += "\\n";
      continue;
    }
    q += c;
  }
  return q + "\"";
}

std::string gnuplot_text(const std::string& s) {
  std::string marked;
  for (char c : s) {
    if (c == '_' || c == '@' || c == '&' || c == '~' || c == '{' || c == '}') marked += '\\';
    marked += c;
  }
  return gnuplot_quote(marked);
}

std::string fitness_curve_script(const std::vector<CurvePoint>& curve, const std::string& png_path,
                                 const std::string& title, const PlotStyle& style, double alpha) {
  if (curve.empty()) throw std::invalid_argument("fitness_curve_script: no generation to plot");
  // The marks sit a little below the lowest error band.
  double low = INFINITY, high = -INFINITY;
  bool any_mark = false;
  for (const auto& p : curve) {
    for (const SampleStats* x : {&p.control, &p.experimental})
      if (x->n > 0) {
        low = std::min(low, x->mean - x->se);
        high = std::max(high, x->mean + x->se);
      }
    any_mark |= p.student.p < alpha;
  }
  const double mark_y = std::isfinite(low) ? low - 0.04 * std::max(high - low, 1e-9) : 0.0;
  std::ostringstream s;
  s << terminal(png_path, style);
  s << "$curve << EOD\n# generation control_mean control_se experimental_mean experimental_se student_p\n";
  for (const auto& p : curve)
    s << p.generation << ' ' << num(p.control.mean) << ' ' << num(p.control.se) << ' ' << num(p.experimental.mean)
      << ' ' << num(p.experimental.se) << ' ' << num(p.student.p) << '\n';
  s << "EOD\n";
  s << "set title " << gnuplot_text(title) << "\n"
    << "set xlabel \"generation\"\nset ylabel \"best-so-far fitness (r + d)\"\n"
    << "set key top left\nset grid\nset style fill transparent solid 0.15 noborder\n"
    << "plot $curve using 1:($2-$3):($2+$3) with filledcurves lc rgb \"#1f4fd6\" notitle, \\\n"
    << "     $curve using 1:($4-$5):($4+$5) with filledcurves lc rgb \"#d62728\" notitle, \\\n"
    << "     $curve using 1:2 with lines lw 2 lc rgb \"#1f4fd6\" title "
    << gnuplot_text("control: " + style.control_label + " CPPNs") << ", \\\n"
    << "     $curve using 1:($2-$3) with lines dt 3 lc rgb \"#1f4fd6\" notitle, \\\n"
    << "     $curve using 1:($2+$3) with lines dt 3 lc rgb \"#1f4fd6\" notitle, \\\n"
    << "     $curve using 1:4 with lines lw 2 lc rgb \"#d62728\" title "
    << gnuplot_text("experimental: " + style.experimental_label + " CPPNs") << ", \\\n"
    << "     $curve using 1:($4-$5) with lines dt 3 lc rgb \"#d62728\" notitle, \\\n"
    << "     $curve using 1:($4+$5) with lines dt 3 lc rgb \"#d62728\" notitle";
  if (any_mark)
    s << ", \\\n     $curve using 1:($6 < " << num(alpha) << " ? " << num(mark_y)
      << " : NaN) with points pt 7 ps 0.6 lc rgb \"black\" title "
      << gnuplot_text("p < " + num(alpha) + " (Student's t per generation, uncorrected)");
  s << "\n";
  s << "unset output\n";
  return s.str();
}

std::string comparison_panels_script(const std::vector<Comparison>& comparisons, const std::string& png_path,
                                     const std::string& title, int columns, const PlotStyle& style,
                                     double share_scale) {
  if (comparisons.empty()) throw std::invalid_argument("comparison_panels_script: no statistic to plot");
  if (columns < 1) throw std::invalid_argument("comparison_panels_script: columns must be >= 1");
  const int n = static_cast<int>(comparisons.size());
  const int rows = (n + columns - 1) / columns;
  std::ostringstream s;
  s << terminal(png_path, style);
  for (int i = 0; i < n; ++i) {
    const Comparison& c = comparisons[static_cast<size_t>(i)];
    const double k = c.unit == "share" ? share_scale : 1.0;
    // An empty sample is drawn as a zero bar (gnuplot refuses a panel with no valid point).
    auto mean = [k](const SampleStats& x) { return x.n ? x.mean * k : 0.0; };
    s << "$p" << i << " << EOD\n"
      << "0 " << num(mean(c.control)) << ' ' << num(c.control.se * k) << "\n"
      << "1 " << num(mean(c.experimental)) << ' ' << num(c.experimental.se * k) << "\nEOD\n";
  }
  s << "set multiplot layout " << rows << "," << columns << " title " << gnuplot_text(title) << "\n"
    << "set style fill solid 1.0 border rgb \"black\"\nset boxwidth 0.6\nset xrange [-0.6:1.6]\n"
    << "set xtics (" << gnuplot_text(style.control_label) << " 0, " << gnuplot_text(style.experimental_label)
    << " 1) scale 0\nset grid ytics\nset key off\n"
    << "set offsets 0, 0, graph 0.1, 0\n";
  for (int i = 0; i < n; ++i) {
    const Comparison& c = comparisons[static_cast<size_t>(i)];
    std::string t = c.label;
    const std::string unit = c.unit == "share" && share_scale == 100.0 ? "%" : c.unit;
    if (!unit.empty() && unit != "count") t += " (" + unit + ")";
    // About 7 pixels per character of the panel titles' font.
    t = wrap(t, static_cast<size_t>(std::max(20, style.width / columns / 8)));
    t += "\nn = " + std::to_string(c.control.n) + " / " + std::to_string(c.experimental.n);
    if (!std::isnan(c.student.p))
      t += c.student.p < 1e-4 ? ", p < 0.0001" : ", p = " + num(std::round(c.student.p * 1e4) / 1e4);
    if (c.samples == Samples::PooledEvents) t += " (pooled, descriptive)";
    if (!c.stars.empty()) t += "  " + c.stars;
    const bool nonneg = (c.control.n == 0 || c.control.mean - c.control.se >= 0) &&
                        (c.experimental.n == 0 || c.experimental.mean - c.experimental.se >= 0);
    s << "set title " << gnuplot_text(t) << " font \",10\"\n"
      << (nonneg ? "set yrange [0:*]\n" : "set autoscale y\n") << "plot $p" << i
      << " every ::0::0 using 1:2 with boxes lc rgb \"#ffffff\", \\\n"
      << "     $p" << i << " every ::1::1 using 1:2 with boxes lc rgb \"#d62728\", \\\n"
      << "     $p" << i << " using 1:2:3 with yerrorbars lc rgb \"black\" pt 7 ps 0.5\n";
  }
  s << "unset multiplot\nunset output\n";
  return s.str();
}

std::string outcome_shares_script(const std::vector<std::array<double, 6>>& shares, const std::string& png_path,
                                  const std::string& title, const PlotStyle& style) {
  if (shares.empty()) throw std::invalid_argument("outcome_shares_script: no generation to plot");
  static const char* names[6] = {"not simulated",      "completed",         "stopped early",
                                 "acceleration fault", "rolling (contact)", "rolling (spin)"};
  static const char* colours[6] = {"#bbbbbb", "#2ca02c", "#1f77b4", "#d62728", "#ff7f0e", "#9467bd"};
  std::ostringstream s;
  s << terminal(png_path, style);
  s << "$shares << EOD\n# generation, then cumulative per cent of the outcomes in generation_t's order\n";
  for (size_t g = 0; g < shares.size(); ++g) {
    s << g;
    double sum = 0;
    for (double x : shares[g]) {
      sum += 100.0 * x;
      s << ' ' << num(sum);
    }
    s << '\n';
  }
  s << "EOD\n";
  s << "set title " << gnuplot_text(title) << "\n"
    << "set xlabel \"generation\"\nset ylabel \"share of the population (%)\"\nset yrange [0:100]\n"
    << (shares.size() > 1 ? "set xrange [0:" + std::to_string(shares.size() - 1) + "]\n" : "")
    << "set key outside right\nset style fill solid 0.8 noborder\nplot ";
  for (int k = 5; k >= 0; --k) {
    s << "$shares using 1:" << (k + 2) << " with filledcurves x1 lc rgb \"" << colours[k] << "\" title "
      << gnuplot_text(names[k]) << (k > 0 ? ", \\\n     " : "\n");
  }
  s << "unset output\n";
  return s.str();
}

}  // namespace robozoo
