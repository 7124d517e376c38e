#include "output/scene_plots.hpp"

#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"

namespace mortar::harness {

namespace {

std::string number(double x) {  // 3 significant digits: 208, 0.241
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// The scene's base shear, and the measured curve (experiment.csv) when
// the scene file names one.
void base_shear_chart(std::ostream& g, const std::string& experiment) {
  g << "set title \"Base shear against top displacement\"\n"
    << (experiment.empty() ? "set key off\n" : "set key bottom right box opaque\n")
    << "set xlabel \"top displacement [mm]\"\nset ylabel \"base shear [kN]\"\n"
    << "plot \"history.csv\" using (column(\"top_ux\")):(column(\"stage\") >= 3 ? column(\"base_shear\")/1000 : 1/0)"
       " with lines lw 2 lc rgb \"#0072B2\" title \"this scene\"";
  if (!experiment.empty())
    g << ", \\\n     \"experiment.csv\" using (column(\"top_displacement_mm\")):(column(\"base_shear_kN\")) with "
         "linespoints lw 1 pt 6 lc rgb \"#000000\" title " << quoted(experiment);
  g << "\n";
}

// Above: the parts the external work went into, stacked (each band from the
// sum of those below it), the external work over them. Below: the balance
// error, external work minus the parts, on its own scale.
void energy_chart(std::ostream& g) {
  const char* parts[][3] = {{"elastic_energy", "joint elastic", "#0072B2"},
                            {"plastic_dissipation", "dissipated: plastic (SDV 16)", "#D55E00"},
                            {"damage_dissipation", "dissipated: damage (SDV 17)", "#009E73"},
                            {"unilateral_energy", "dissipated: unilateral (SDV 18)", "#8C564B"},
                            {"kinetic_energy", "kinetic", "#CC79A7"},
                            {"damping_work", "damping", "#E69F00"}};
  g << "set multiplot\nset origin 0,0.3\nset size 1,0.7\nset bmargin 1\nset format x \"\"\nset xlabel \"\"\n"
    << "set title \"Energy books: where the external work went\"\nset key top left box opaque invert\n"
    << "set offsets 0, 0, graph 0.5, 0\n"
    << "set ylabel \"energy [N mm]\"\nplot ";
  std::string below = "0";
  for (const auto& p : parts) {
    const std::string above = below + " + column(\"" + p[0] + "\")";
    g << "\"history.csv\" using (column(\"time\")):(" << below << "):(" << above
      << ") with filledcurves fs solid 0.75 noborder lc rgb " << quoted(p[2]) << " title " << quoted(p[1])
      << ", \\\n     ";
    below = above;
  }
  g << "\"history.csv\" using (column(\"time\")):(column(\"external_work\")) with lines lw 4 lc rgb \"#000000\""
       " title \"external work\", \\\n     "
    << "\"history.csv\" using (column(\"time\")):(column(\"energy_accounted\")) with lines lw 2 dt 2 lc rgb "
       "\"#56B4E9\" title \"sum of the parts (the top of the stack)\"\n"
    << "set origin 0,0\nset size 1,0.3\nset tmargin 0\nset bmargin\nset format x\nset title \"\"\n"
    << "set offsets 0, 0, 0, 0\nset key top left noinvert\nset xlabel \"time [s]\"\nset ylabel \"error [N mm]\"\n"
    << "plot \"history.csv\" using (column(\"time\")):(column(\"balance_error\")) with lines lw 2 lc rgb \"#000000\""
       " title \"balance error = external work - sum of the parts\"\n"
    << "unset multiplot\nset origin 0,0\nset size 1,1\nset tmargin\nset key noinvert\n";
}

// The colour legend: the quantity and its unit.
std::string joint_colour_legend(JointColour colour) {
  switch (colour) {
    case JointColour::opening: return "joint opening [mm] (closed: grey)";
    case JointColour::damage: return "damage max(d_n, d_s) [-]";
    case JointColour::dissipation: break;
  }
  return "dissipated energy per unit area, SDV 16 + 17 + 18 [N/mm]";
}

void wall_picture(std::ostream& g, int k, const std::string& label, const Magnification& mag, JointColour colour) {
  const std::string stem = "snapshot_" + std::to_string(k);
  const std::string factor = "displacements x " + number(mag.factor), largest = number(mag.largest_relative) + " mm";
  const std::string scale = mag.automatic ? factor + ": the largest joint opening or slip (" + largest +
                                                ") drawn as 5 % of the wall's height"
                                          : factor + " (the scene file's; the largest joint opening or slip " +
                                                largest + ")";
  std::string value, range = "[0:*]", scale_cb = "";
  switch (colour) {
    case JointColour::dissipation:  // decades apart: a cracked joint (GIC) and a crushed toe (Gfc)
      value = "(column(\"dissipation_N_per_mm\") > 1e-3 ? column(\"dissipation_N_per_mm\") : 1e-3)";
      range = "[1e-3:*]", scale_cb = "set logscale cb\n";
      break;
    case JointColour::opening: value = "column(\"opening_mm\")"; break;
    case JointColour::damage:
      value = "(column(\"d_n\") > column(\"d_s\") ? column(\"d_n\") : column(\"d_s\"))";
      range = "[0:1]";
      break;
  }
  const std::string at = label == "peak" || label == "end" ? "the " + label : label;
  g << "set title " << quoted("The wall at " + at) << ".\"\\n\"." << quoted(scale)
    << "\nset key off\nset size ratio -1\nset xlabel \"x [mm]\"\nset ylabel \"y [mm]\"\n"
    << scale_cb << "set cbrange " << range << "\nset cblabel "
    << quoted(joint_colour_legend(colour) + (scale_cb.empty() ? "" : " (log)"))
    << "\nset palette defined (0 \"#d0d0d0\", 0.5 \"#E69F00\", 1 \"#D55E00\")\n"
    << "plot " << quoted(stem + "_blocks.csv") << " using 1:2 with lines lw 1 lc rgb \"#404040\", \\\n     "
    << quoted(stem + "_joints.csv") << " using 1:2:(" << value << ") with points pt 7 ps 0.6 palette\n"
    << "set size noratio\nset cbrange [*:*]\nunset logscale cb\n";
}

}  // namespace

std::string write_scene_plot_script(const std::string& dir, const std::vector<std::string>& labels,
                                    const std::vector<Magnification>& magnifications, JointColour colour,
                                    const std::string& experiment_label) {
  const std::string name = "scene.gp";
  std::ofstream g(dir + "/" + name);
  if (!g) throw InputError(cannot_write(dir + "/" + name));
  g << "# Written by masonry-joint scene; rerun with: gnuplot " << name << "\nset datafile separator \",\"\n"
    << "set grid lc rgb \"#c8c8c8\"\n";
  for (const char* ext : {"png", "svg"}) {
    const std::string term = std::string(ext) == "png" ? "pngcairo" : "svg";
    const std::string size = " size 1000,700 enhanced font \"DejaVu Sans,12\" background \"white\"\n";
    g << "set terminal " << term << size << "set output \"base_shear." << ext << "\"\n";
    base_shear_chart(g, experiment_label);
    g << "set output \"energy." << ext << "\"\n";
    energy_chart(g);
    for (size_t k = 0; k < labels.size(); ++k) {
      g << "set output \"wall_" << k << "." << ext << "\"\n";
      wall_picture(g, static_cast<int>(k), labels[k], magnifications.at(k), colour);
    }
    g << "set output\n";
  }
  if (!g) throw InputError(dir + "/" + name + ": write failed");
  return name;
}

}  // namespace mortar::harness
