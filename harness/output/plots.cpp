#include "output/plots.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"

namespace mortar::harness {

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

namespace {

// Line colours that stay apart for colour-blind readers (Okabe-Ito).
const char* colour(size_t i) {
  static const char* c[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};
  return c[i % 6];
}

// One panel: x and y columns of every case, plus experimental points and
// independent markers when asked.
struct Panel {
  std::string title, xlabel, ylabel;
  std::string x, y;          // gnuplot expressions of the run CSV columns
  std::string exp_x, exp_y;  // same, for experimental CSVs ("" to skip)
  bool independent_tau = false;
  std::string key = "top right";  // where the legend sits clear of the curves
};

void write_panel(std::ostream& g, const Panel& p, const std::vector<PlotCase>& cases) {
  g << "set title " << quoted(p.title) << "\nset key " << p.key << " box opaque\n"
    << "set xlabel " << quoted(p.xlabel) << "\nset ylabel " << quoted(p.ylabel) << "\n";
  std::vector<std::string> items;
  for (size_t i = 0; i < cases.size(); ++i) {
    const PlotCase& c = cases[i];
    items.push_back(quoted(c.csv) + " using " + p.x + ":" + p.y + " with lines lw 2 lc rgb " + quoted(colour(i)) +
                    " title " + quoted(c.label));
    if (!p.exp_x.empty() && !c.experimental_csv.empty())
      items.push_back(quoted(c.experimental_csv) + " using " + p.exp_x + ":" + p.exp_y +
                      " with points pt 6 ps 0.8 lc rgb " + quoted(colour(i)) + " title " +
                      quoted(c.label + ", experiment"));
    const IndependentValues& v = c.independent;
    if (p.independent_tau && (v.peak > 0 || !v.tau_at.empty()))
      items.push_back("$independent" + std::to_string(i) + " using 1:2 with points pt 2 ps 1.4 lw 2 lc rgb " +
                      quoted(colour(i)) + (i == 0 ? " title \"independent implementation\"" : " notitle"));
  }
  g << "plot ";
  for (size_t i = 0; i < items.size(); ++i) g << (i ? ", \\\n     " : "") << items[i];
  g << "\n";
}

void write_data_blocks(std::ostream& g, const std::vector<PlotCase>& cases) {
  for (size_t i = 0; i < cases.size(); ++i) {
    const IndependentValues& v = cases[i].independent;
    if (v.peak <= 0 && v.tau_at.empty()) continue;
    g << "$independent" << i << " << EOD\n";
    // Comma-separated like the CSVs: the script sets the separator once.
    if (v.peak > 0) g << v.peak_slip << "," << v.peak << "\n";
    for (const auto& [s, t] : v.tau_at) g << s << "," << t << "\n";
    g << "EOD\n";
  }
}

std::vector<Panel> panels_of(const SeriesSpec& s) {
  switch (s.kind) {
    case SeriesKind::monotonic_shear:
      return {{"Shear stress against slip at constant normal stress", "slip {/Symbol d}_{s} [mm]",
               "shear stress {/Symbol t} [MPa]", "(column(\"delta_s1\"))", "(column(\"tau_1\"))",
               "(column(\"slip_mm\"))", "(column(\"tau_MPa\"))", true},
              {"Dilatancy: normal opening against slip", "slip {/Symbol d}_{s} [mm]",
               "normal opening {/Symbol d}_{n} [{/Symbol m}m]", "(column(\"delta_s1\"))",
               "(1000*column(\"delta_n\"))", "", "", false, "bottom right"}};
    case SeriesKind::cyclic_shear:
      // The loops overlap, so the second panel unrolls them along the slip
      // travelled (gnuplot accumulates |d(delta_s1)| row by row, from zero
      // at each file's first row).
      return {{"Cyclic shear at constant normal stress: the loops", "slip {/Symbol d}_{s} [mm]",
               "shear stress {/Symbol t} [MPa]", "(column(\"delta_s1\"))", "(column(\"tau_1\"))",
               "(column(\"slip_mm\"))", "(column(\"tau_MPa\"))", false, "below"},
              {"The same loops unrolled along the slip travelled", "accumulated slip travel {/Symbol S}|{/Symbol D}{/Symbol d}_{s}| [mm]",
               "shear stress {/Symbol t} [MPa]",
               "(travel = (column(0) == 0 ? 0 : travel + abs(column(\"delta_s1\") - last_slip)), "
               "last_slip = column(\"delta_s1\"), travel)",
               "(column(\"tau_1\"))", "", "", false, "below"}};
    case SeriesKind::tension:
      return {{"Uniaxial tension: traction against opening", "opening {/Symbol d}_{n} [mm]",
               "normal traction {/Symbol s}_{n} [MPa]", "(column(\"delta_n\"))", "(column(\"sigma_n\"))",
               "(column(\"opening_mm\"))", "(column(\"sigma_MPa\"))", false},
              {"Normal damage against opening", "opening {/Symbol d}_{n} [mm]", "damage d_{n} [-]",
               "(column(\"delta_n\"))", "(column(\"SDV10_d_n\"))", "", "", false}};
  }
  return {};
}

}  // namespace

std::string write_plot_script(const std::string& out_dir, const SeriesSpec& series,
                              const std::vector<PlotCase>& cases) {
  const std::string name = series.id + ".gp";
  std::ofstream g(out_dir + "/" + name);
  if (!g) throw InputError(cannot_write(out_dir + "/" + name));
  g << "# " << series.title << "\n# Written by masonry-joint validate; rerun with: gnuplot " << name << "\n"
    << "set datafile separator \",\"\n"
    << "travel = 0; last_slip = 0  # running sums of the unrolled cyclic panel\n";
  write_data_blocks(g, cases);
  const std::vector<Panel> panels = panels_of(series);
  const struct {
    const char* terminal;
    const char* extension;
  } outputs[] = {{"pngcairo size 1100,1000 enhanced font \"DejaVu Sans,12\" background \"white\"", "png"},
                 {"svg size 1100,1000 enhanced font \"DejaVu Sans,12\" background \"white\"", "svg"}};
  for (const auto& o : outputs) {
    g << "\nset terminal " << o.terminal << "\nset output " << quoted(series.id + "." + o.extension) << "\n"
      << "set grid lc rgb \"#c8c8c8\"\nset border lw 1.2\nset offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n"
      << "set multiplot layout " << panels.size() << ",1 title " << quoted(series.title) << " font \",14\"\n";
    for (const Panel& p : panels) write_panel(g, p, cases);
    g << "unset multiplot\nset output\n";
  }
  if (!g) throw InputError(out_dir + "/" + name + ": write failed");
  return name;
}

bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

bool run_gnuplot(const std::string& out_dir, const std::string& script, std::string& message) {
  std::string dir_quoted = "'";
  for (char c : out_dir) dir_quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  dir_quoted += "'";
  const std::string log = script + ".log";
  const std::string cmd = "cd " + dir_quoted + " && gnuplot '" + script + "' > '" + log + "' 2>&1";
  if (std::system(cmd.c_str()) == 0) {
    std::remove((out_dir + "/" + log).c_str());
    return true;
  }
  std::ifstream in(out_dir + "/" + log);
  std::ostringstream text;
  text << in.rdbuf();
  message = text.str();
  return false;
}

}  // namespace mortar::harness
