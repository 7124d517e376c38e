// The calibration's charts (report.hpp, write_calibration_plots): a gnuplot
// script over the fit_<curve>.csv files, 2 x 3 panels: shear, dilatancy and
// tension above (and compression, when given: 2 x 4), each quantity's own
// residuals below. The slip axes are
// logarithmic: on a linear axis the peaks sat in the first 5-7 % of it.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

#include "calibration/report.hpp"
#include "input/input_error.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"

namespace mortar::harness {

namespace {

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

// The legend of a curve: its sigma_n (tension: "tension") and its misfit.
std::string legend(const TestCurve& c, const FitResult* fit) {
  std::string s = c.shear() ? fmt("σn = %g MPa", c.sigma_n) : std::string(c.compression() ? "compression" : "tension");
  if (fit)
    for (const CurveMisfit& m : fit->misfit)
      if (m.curve == c.name) s += m.failed ? " (run failed)" : fmt(" (RMS %.3f)", m.rms_scaled);
  return s;
}

// The title: misfit, verdict, and the one set's values, two lines of them.
std::string title(const CalibrationReport& r) {
  std::string t = "Calibration, one set";
  if (r.one_set) t += fmt(": RMS misfit %.4f of each curve's scale", r.one_set->rms);
  if (r.verdict) t += r.verdict->accepted() ? ", accepted" : ", REJECTED (params.rejected.toml)";
  for (int i = 0; i < kParameterCount; ++i)
    t += std::string(i % 7 ? ", " : "\n") + kParameterInfo[size_t(i)].name + " " +
         fmt("%.4g", r.final.entries[size_t(i)].value);
  // gnuplot's escape for the line breaks (quoted() leaves them as they are).
  std::string q = quoted(t);
  for (size_t at = q.find('\n'); at != std::string::npos; at = q.find('\n', at)) q.replace(at, 1, "\\n");
  return q;
}

struct Panel {
  const char *title, *xlabel, *ylabel, *data, *fit;
  bool log_x;
  bool (*wanted)(const TestCurve&);
};

}  // namespace

std::string write_calibration_plots(const std::string& out_dir, const std::vector<TestCurve>& curves,
                                    const CalibrationReport& r) {
  static const char* colour[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};
  const std::string name = "calibration.gp";
  std::ofstream g(out_dir + "/" + name);
  if (!g) throw InputError(cannot_write(out_dir + "/" + name));
  g << "# Written by masonry-joint calibrate; rerun with: gnuplot " << name << "\nset datafile separator \",\"\n";
  auto shear = [](const TestCurve& c) { return c.shear(); };
  auto uplift = [](const TestCurve& c) { return c.has_uplift(); };
  auto tension = [](const TestCurve& c) { return !c.shear() && !c.compression(); };
  auto compression = [](const TestCurve& c) { return c.compression(); };
  bool crushed = false;  // a compression curve: a fourth column
  for (const TestCurve& c : curves) crushed = crushed || c.compression();
  std::vector<Panel> panels = {
      {"Shear: data (points), fit (lines)", "slip [mm] (log)", "{/Symbol t} [MPa]", "2", "3", true, shear},
      {"Dilatancy", "slip [mm] (log)", "uplift [mm]", "5", "6", true, uplift},
      {"Tension", "opening [mm]", "{/Symbol s} [MPa]", "2", "3", false, tension},
      {"Shear residuals (fit - data)", "slip [mm] (log)", "{/Symbol t} [MPa]", "4", "", true, shear},
      {"Uplift residuals (fit - data)", "slip [mm] (log)", "uplift [mm]", "7", "", true, uplift},
      {"Tension residuals (fit - data)", "opening [mm]", "{/Symbol s} [MPa]", "4", "", false, tension}};
  if (crushed) {
    panels.insert(panels.begin() + 3, {"Compression (with the cap)", "closure [mm]", "{/Symbol s} [MPa]", "2", "3", false,
                                       compression});
    panels.push_back({"Compression residuals (fit - data)", "closure [mm]", "{/Symbol s} [MPa]", "4", "", false, compression});
  }
  for (const char* ext : {"png", "svg"}) {
    g << "\nset terminal " << (ext[0] == 'p' ? "pngcairo" : "svg")
      << " size " << (crushed ? 2000 : 1500) << ",950 enhanced font \"DejaVu Sans,10\" background \"white\"\nset output \"calibration." << ext
      << "\"\nset grid lc rgb \"#c8c8c8\"\nset key top right font \",9\"\nset multiplot layout 2," << (crushed ? 4 : 3) << " title "
      << title(r) << " noenhanced\n";
    for (const Panel& p : panels) {
      g << "set title " << quoted(p.title) << "\nset xlabel " << quoted(p.xlabel) << "\nset ylabel " << quoted(p.ylabel)
        << "\n" << (p.log_x ? "set logscale x\n" : "unset logscale x\n") << "plot ";
      std::string sep;
      for (size_t i = 0; i < curves.size(); ++i) {
        if (!p.wanted(curves[i])) continue;
        const std::string file = quoted("fit_" + curves[i].name + ".csv"), col = quoted(colour[i % 6]);
        // A log axis cannot show slip 0: those rows are left out.
        const std::string x = p.log_x ? "($1 > 0 ? $1 : NaN)" : "1";
        g << sep << file << " using " << x << ":" << p.data << " with points pt 6 lc rgb " << col << " title "
          << quoted(legend(curves[i], r.one_set)) << " noenhanced";
        if (*p.fit) g << ", " << file << " using " << x << ":" << p.fit << " with lines lw 2 lc rgb " << col << " notitle";
        sep = ", \\\n     ";
      }
      if (sep.empty()) g << "NaN title \"(no such curve)\"";
      g << "\n";
    }
    g << "unset multiplot\nset output\n";
  }
  if (!g) throw InputError(out_dir + "/" + name + ": write failed");
  return name;
}

}  // namespace mortar::harness
