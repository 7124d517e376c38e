#include "bench/plots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"
#include "validation/checks.hpp"

namespace mortar::harness {

namespace {

// Okabe-Ito colours (plots.cpp uses the same palette): one per scheme.
// Modified Euler: one shade of its colour per increment size, dark = fine.
const char* shade(size_t h_index) {
  static const char* c[] = {"#7F2704", "#D55E00", "#F28E2B", "#FDBF6F", "#FEE6CE"};
  return c[std::min<size_t>(h_index, 4)];
}

const char* scheme_colour(const std::string& scheme) {
  if (scheme == "forward-euler") return "#0072B2";
  if (scheme == "modified-euler") return "#D55E00";
  return "#009E73";
}
const char* scheme_title(const std::string& scheme) {
  if (scheme == "forward-euler") return "forward Euler";
  if (scheme == "modified-euler") return "modified Euler";
  return "implicit return mapping";
}
// One point type per increment size, the same in every series.
int point_type(size_t h_index) {
  static const int pt[] = {7, 5, 9, 13, 11, 15};
  return pt[h_index % 6];
}
// Outcome colours of the map.
const char* outcome_colour(Outcome o) {
  switch (o) {
    case Outcome::accurate: return "#009E73";
    case Outcome::inaccurate: return "#F0E442";
    case Outcome::drifted: return "#E69F00";
    case Outcome::failed: return "#CC79A7";
    case Outcome::non_finite: return "#000000";
  }
  return "#FFFFFF";
}

// Text for gnuplot's enhanced mode: path ids keep their underscores.
std::string plain(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~') out += "\\";
    out += c;
  }
  return out;
}

std::string e_format(double x, int digits = 0) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*e", digits, x);
  return b;
}

size_t h_index(const BenchResult& r, double h) {
  return std::find(r.increment_sizes.begin(), r.increment_sizes.end(), h) - r.increment_sizes.begin();
}

// A line of the work-precision chart: (cost, error, point type) rows.
struct Line {
  std::string title, colour;
  std::vector<std::array<double, 3>> points;
};

double cost_of(const BenchRow& row, bool whole_path) {
  return whole_path ? row.path_microseconds() : row.timing.median_ns;
}

// Timed (completed) rows only; errors below 1e-16 are drawn at 1e-16 (the
// log axis has no zero).
void add_point(Line& line, const BenchResult& r, const BenchRow& row, bool whole_path) {
  if (row.timing.repeats == 0 || !std::isfinite(row.error_traction)) return;
  line.points.push_back({cost_of(row, whole_path), std::max(row.error_traction, 1e-16),
                         double(point_type(h_index(r, row.h)))});
}

// The error axis: the decades the plotted errors and the target lines span.
std::string error_yrange(const BenchResult& r, const std::vector<std::string>& paths) {
  double lo = kAccurateError, hi = kTargetError;
  for (const BenchRow& row : r.rows)
    if (row.timing.repeats > 0 && std::isfinite(row.error_traction) &&
        std::find(paths.begin(), paths.end(), row.path) != paths.end()) {
      lo = std::min(lo, std::max(row.error_traction, 1e-16));
      hi = std::max(hi, row.error_traction);
    }
  return "set yrange [" + e_format(std::pow(10.0, std::floor(std::log10(lo)))) + ":" +
         e_format(std::pow(10.0, std::ceil(std::log10(hi)))) + "]\n";
}

std::string stol_range(const BenchResult& r) {
  double lo = 1, hi = 0;
  for (const BenchScheme& s : r.schemes)
    if (s.controls.scheme == Scheme::modified_euler) {
      lo = std::min(lo, s.controls.stol);
      hi = std::max(hi, s.controls.stol);
    }
  return "STOL " + e_format(hi) + "..." + e_format(lo);
}

// forward Euler and the implicit scheme: one line across the increment
// sizes; modified Euler: one line per increment size, across STOL.
std::vector<Line> lines_of(const BenchResult& r, const std::string& path, bool whole_path) {
  std::vector<Line> lines;
  for (const char* scheme : {"forward-euler", "modified-euler", "implicit"}) {
    const bool per_h = std::string(scheme) == "modified-euler";
    for (double h : per_h ? r.increment_sizes : std::vector<double>{0.0}) {
      Line line;
      line.colour = per_h ? shade(h_index(r, h)) : scheme_colour(scheme);
      line.title = std::string(scheme_title(scheme)) + (per_h ? ", h = " + e_format(h) + " mm, " + stol_range(r)
                                                              : ", h = " + e_format(r.increment_sizes.front()) +
                                                                    "..." + e_format(r.increment_sizes.back()) + " mm");
      for (const BenchRow& row : r.rows)
        if (row.path == path && row.scheme.name == scheme && (!per_h || row.h == h))
          add_point(line, r, row, whole_path);
      if (!line.points.empty()) lines.push_back(line);
    }
  }
  return lines;
}

// `key`: gnuplot's key settings for this panel, "" for none.
void write_panel(std::ostream& g, const BenchResult& r, const std::string& path, const std::string& title,
                 bool whole_path, const std::string& key_settings, int& block) {
  const bool key = !key_settings.empty();
  g << (key ? "set key " + key_settings : std::string("unset key")) << "\n";
  const std::vector<Line> lines = lines_of(r, path, whole_path);
  std::vector<std::string> items;
  for (const Line& line : lines) {
    const std::string name = "$wp" + std::to_string(block++);
    g << name << " << EOD\n";
    for (const auto& p : line.points) g << p[0] << " " << p[1] << " " << int(p[2]) << "\n";
    g << "EOD\n";
    items.push_back(name + " using 1:2:3 with linespoints lw 1.5 ps 1.1 pt variable lc rgb " + quoted(line.colour) +
                    (key ? " title " + quoted(line.title) : " notitle"));
  }
  items.push_back(e_format(kTargetError) + " with lines dt 2 lw 1 lc rgb \"#555555\"" +
                  (key ? " title \"error " + e_format(kTargetError) + "\"" : " notitle"));
  items.push_back(e_format(kAccurateError) + " with lines dt 3 lw 1 lc rgb \"#555555\"" +
                  (key ? " title \"accurate below " + e_format(kAccurateError) + "\"" : " notitle"));
  if (key)
    for (size_t i = 0; i < r.increment_sizes.size(); ++i)
      items.push_back("keyentry with points pt " + std::to_string(point_type(i)) + " lc rgb \"#333333\" title \"h = " +
                      e_format(r.increment_sizes[i]) + " mm\"");
  g << "set title " << quoted(title) << "\n"
    << "set xlabel " << quoted(whole_path ? "cost per point for the whole path [{/Symbol m}s]"
                                         : "cost per point-update [ns]")
    << "\nset ylabel \"relative traction error\"\n"
    << "plot " << (items.empty() ? "NaN notitle" : "");
  for (size_t i = 0; i < items.size(); ++i) g << (i ? ", \\\n     " : "") << items[i];
  g << "\n";
}

const std::string kTerminals[2][2] = {
    {"pngcairo size %W%,%H% enhanced font \"DejaVu Sans,11\" background \"white\"", "png"},
    {"svg size %W%,%H% enhanced font \"DejaVu Sans,11\" background \"white\"", "svg"}};

std::string terminal(int i, int width, int height) {
  std::string t = kTerminals[i][0];
  t.replace(t.find("%W%"), 3, std::to_string(width));
  t.replace(t.find("%H%"), 3, std::to_string(height));
  return t;
}

std::ofstream open_script(const std::string& out_dir, const std::string& name) {
  std::ofstream g(out_dir + "/" + name);
  if (!g) throw InputError(cannot_write(out_dir + "/" + name));
  g << "# Written by masonry-joint bench; rerun with: gnuplot " << name << "\n";
  return g;
}

const std::string kFocus = "vdp_sn0.5";

std::string write_focus_chart(const std::string& out_dir, const BenchResult& r) {
  const std::string name = "work_precision.gp";
  std::ofstream g = open_script(out_dir, name);
  const auto it = std::find(r.paths.begin(), r.paths.end(), kFocus);
  const std::string path = it == r.paths.end() ? r.paths.front() : *it;
  const std::string title = r.path_titles[(it == r.paths.end() ? r.paths.begin() : it) - r.paths.begin()];
  for (int t = 0; t < 2; ++t) {
    int block = 0;
    g << "\nset terminal " << terminal(t, 1700, 800) << "\nset output \"work_precision." << kTerminals[t][1]
      << "\"\nset logscale xy\nset format y \"10^{%L}\"\nset format x \"10^{%L}\"\nset grid lc rgb \"#c8c8c8\"\n"
      << error_yrange(r, {path})
      << "set multiplot layout 1,2 title " << quoted("Work-precision: " + title + " (path " + plain(path) + ")")
      << " font \",13\" margins 0.06,0.70,0.1,0.88 spacing 0.07\n";
    write_panel(g, r, path, "error against cost per point-update", false, "", block);
    // The key beside the panels, where it covers no point.
    write_panel(g, r, path, "error against cost for the whole path", true,
                "at screen 0.715,0.88 left top Left reverse font \",9\" box", block);
    g << "unset multiplot\nset output\n";
  }
  if (!g) throw InputError(out_dir + "/" + name + ": write failed");
  return name;
}

std::string write_all_paths_chart(const std::string& out_dir, const BenchResult& r) {
  const std::string name = "work_precision_all.gp";
  std::ofstream g = open_script(out_dir, name);
  // One cell more than the paths: the key goes into the first free one.
  const int columns = 3, rows = static_cast<int>((r.paths.size() + columns) / columns);
  const int free_row = static_cast<int>(r.paths.size()) / columns, free_column = static_cast<int>(r.paths.size()) % columns;
  std::ostringstream key;
  key << "at screen " << (free_column + 0.12) / columns << "," << 0.95 * (rows - free_row) / rows - 0.02
      << " left top font \",10\" box opaque";
  for (int t = 0; t < 2; ++t) {
    int block = 0;
    g << "\nset terminal " << terminal(t, 1800, 480 * rows) << "\nset output \"work_precision_all."
      << kTerminals[t][1] << "\"\nset logscale xy\nset format y \"10^{%L}\"\nset format x \"10^{%L}\"\nset grid lc rgb \"#c8c8c8\"\n"
      << error_yrange(r, r.paths) << "set multiplot layout " << rows << "," << columns
      << " title \"Work-precision on every bench path: traction error against cost per point-update\" font "
         "\",13\"\n";
    for (size_t p = 0; p < r.paths.size(); ++p)
      write_panel(g, r, r.paths[p], plain(r.paths[p]), false, p == 0 ? key.str() : "", block);
    g << "unset multiplot\nset output\n";
  }
  if (!g) throw InputError(out_dir + "/" + name + ": write failed");
  return name;
}

// The map: one column per (path, h), paths in groups, one row per scheme.
std::string write_stability_map(const std::string& out_dir, const BenchResult& r) {
  const std::string name = "stability_map.gp";
  std::ofstream g = open_script(out_dir, name);
  const size_t nh = r.increment_sizes.size();
  auto column_of = [&](size_t p, size_t j) { return double(p * (nh + 1) + j); };
  auto row_of = [&](const BenchScheme& s) {
    for (size_t i = 0; i < r.schemes.size(); ++i)
      if (r.schemes[i].label() == s.label()) return double(r.schemes.size() - 1 - i);
    return 0.0;
  };
  g << "$cells << EOD\n";
  for (const BenchRow& row : r.rows) {
    const size_t p = std::find(r.paths.begin(), r.paths.end(), row.path) - r.paths.begin();
    const std::string text = std::isfinite(row.error_traction) ? e_format(row.error_traction) : "-";
    g << column_of(p, h_index(r, row.h)) << " " << row_of(row.scheme) << " 0x"
      << std::string(outcome_colour(row.outcome) + 1) << " " << quoted(text) << "\n";
  }
  g << "EOD\n";
  // Drifted and failed cells also carry a marker of their own shape.
  for (const auto& [block, outcome] : {std::pair<const char*, Outcome>{"$drifted", Outcome::drifted},
                                       {"$failed", Outcome::failed}}) {
    g << block << " << EOD\n";
    for (const BenchRow& row : r.rows)
      if (row.outcome == outcome)
        g << column_of(std::find(r.paths.begin(), r.paths.end(), row.path) - r.paths.begin(), h_index(r, row.h)) << " "
          << row_of(row.scheme) << "\n";
    g << "0 -100\nEOD\n";  // (off the map: an empty block would stop gnuplot)
  }
  const double width = double(r.paths.size() * (nh + 1)) - 1;
  std::ostringstream xtics, ytics;
  for (size_t p = 0; p < r.paths.size(); ++p)
    for (size_t j = 0; j < nh; ++j)
      xtics << (xtics.tellp() > 0 ? ", " : "") << quoted(e_format(r.increment_sizes[j])) << " " << column_of(p, j);
  for (const BenchScheme& s : r.schemes) ytics << (ytics.tellp() > 0 ? ", " : "") << quoted(s.label()) << " " << row_of(s);
  const int px_width = std::max(900, static_cast<int>(38 * (width + 1)) + 260);
  for (int t = 0; t < 2; ++t) {
    g << "\nset terminal " << terminal(t, px_width, 760) << "\nset output \"stability_map." << kTerminals[t][1]
      << "\"\nunset key\nset title \"Stability map: outcome of each scheme x increment size x path "
         "(cell text: relative traction error)\" font \",13\" offset 0,1.5\n"
      << "set xrange [-0.6:" << width + 0.6 << "]\nset yrange [-0.6:" << r.schemes.size() - 0.4 << "]\n"
      << "set xtics (" << xtics.str() << ") rotate by 90 right font \",8\" scale 0\n"
      << "set ytics (" << ytics.str() << ") font \",9\" scale 0\n"
      << "set xlabel \"increment size h [mm], grouped by path\"\nset tmargin 7\nset bmargin 6\n"
      << "unset label\n";
    for (size_t p = 0; p < r.paths.size(); ++p)
      g << "set label " << p + 1 << " " << quoted(plain(r.paths[p])) << " at " << column_of(p, 0) + 0.5 * (nh - 1) << ","
        << r.schemes.size() - 0.2 << " center font \",9\"\n";
    g << "set key outside bottom center horizontal font \",10\"\n"
      << "plot $cells using 1:2:(0.48):(0.48):3 with boxxy fs solid 1.0 border lc rgb \"#ffffff\" lc rgb variable "
         "notitle, \\\n     $cells using 1:2:4 with labels font \",6.5\" notitle, \\\n"
         "     $drifted using ($1-0.3):($2+0.27) with points pt 2 ps 0.8 lw 1.5 lc rgb \"#000000\" notitle, \\\n"
         "     $failed using ($1-0.3):($2+0.27) with points pt 6 ps 0.8 lw 1.5 lc rgb \"#000000\" notitle";
    for (Outcome o : {Outcome::accurate, Outcome::inaccurate, Outcome::drifted, Outcome::failed,
                      Outcome::non_finite})
      g << ", \\\n     keyentry with boxes fs solid 1.0 lc rgb " << quoted(outcome_colour(o)) << " title "
        << quoted(std::string(outcome_name(o)) +
                  (o == Outcome::drifted ? " (marked x)" : o == Outcome::failed ? " (marked o)" : ""));
    g << "\nset output\n";
  }
  if (!g) throw InputError(out_dir + "/" + name + ": write failed");
  return name;
}

}  // namespace

std::vector<std::string> write_bench_plot_scripts(const std::string& out_dir, const BenchResult& r) {
  if (r.paths.empty()) return {};
  return {write_focus_chart(out_dir, r), write_all_paths_chart(out_dir, r), write_stability_map(out_dir, r)};
}

}  // namespace mortar::harness
