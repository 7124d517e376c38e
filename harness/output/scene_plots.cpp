#include "output/scene_plots.hpp"

#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"
#include "output/plots.hpp"

namespace mortar::harness {

namespace {

void base_shear_chart(std::ostream& g) {
  g << "set title \"Base shear against top displacement\"\nset key off\n"
    << "set xlabel \"top displacement [mm]\"\nset ylabel \"base shear [kN]\"\n"
    << "plot \"history.csv\" using (column(\"top_ux\")):(column(\"stage\") >= 3 ? column(\"base_shear\")/1000 : 1/0)"
       " with lines lw 2 lc rgb \"#0072B2\"\n";
}

void energy_chart(std::ostream& g) {
  g << "set title \"Energy history\"\nset key top left box opaque\n"
    << "set xlabel \"time [s]\"\nset ylabel \"energy [N mm]\"\nplot ";
  const char* cols[][3] = {{"external_work", "external work", "#000000"},
                           {"elastic_energy", "joint elastic", "#0072B2"},
                           {"dissipation", "dissipated (spd + sfd)", "#7F7F7F"},
                           {"plastic_dissipation", "  of which plastic (SDV 16)", "#D55E00"},
                           {"damage_dissipation", "  damage (SDV 17)", "#009E73"},
                           {"unilateral_energy", "  closure jumps (SDV 18)", "#8C564B"},
                           {"kinetic_energy", "kinetic", "#CC79A7"},
                           {"damping_work", "damping", "#E69F00"},
                           {"balance_error", "balance error", "#56B4E9"}};
  // The dissipation with its split: SDV 16 and 18 can be large and nearly
  // cancel where damaged joints close (docs/model.md 6, closure jump).
  for (size_t i = 0; i < sizeof cols / sizeof cols[0]; ++i)
    g << (i ? ", \\\n     " : "") << "\"history.csv\" using (column(\"time\")):(column(\"" << cols[i][0]
      << "\")) with lines lw 2 lc rgb " << quoted(cols[i][2]) << " title " << quoted(cols[i][1]);
  g << "\n";
}

void wall_picture(std::ostream& g, int k, const std::string& label, double magnification) {
  const std::string stem = "snapshot_" + std::to_string(k);
  std::ostringstream factor;  // 50, not std::to_string's 50.000000
  factor << magnification;
  g << "set title " << quoted("The wall at " + label + " (displacements x " + factor.str() +
                              "; joints coloured by damage)")
    << "\nset key off\nset size ratio -1\nset xlabel \"x [mm]\"\nset ylabel \"y [mm]\"\n"
    << "set cbrange [0:1]\nset cblabel \"damage\"\nset palette defined (0 \"#d0d0d0\", 0.5 \"#E69F00\", 1 \"#D55E00\")\n"
    << "plot " << quoted(stem + "_blocks.csv") << " using 1:2 with lines lw 1 lc rgb \"#404040\", \\\n     "
    << quoted(stem + "_joints.csv") << " using 1:2:4 with points pt 7 ps 0.6 palette\nset size noratio\n";
}

}  // namespace

std::string write_scene_plot_script(const std::string& dir, const std::vector<std::string>& labels,
                                    double magnification) {
  const std::string name = "scene.gp";
  std::ofstream g(dir + "/" + name);
  if (!g) throw InputError(cannot_write(dir + "/" + name));
  g << "# Written by masonry-joint scene; rerun with: gnuplot " << name << "\nset datafile separator \",\"\n"
    << "set grid lc rgb \"#c8c8c8\"\n";
  for (const char* ext : {"png", "svg"}) {
    const std::string term = std::string(ext) == "png" ? "pngcairo" : "svg";
    const std::string size = " size 1000,700 enhanced font \"DejaVu Sans,12\" background \"white\"\n";
    g << "set terminal " << term << size << "set output \"base_shear." << ext << "\"\n";
    base_shear_chart(g);
    g << "set output \"energy." << ext << "\"\n";
    energy_chart(g);
    for (size_t k = 0; k < labels.size(); ++k) {
      g << "set output \"wall_" << k << "." << ext << "\"\n";
      wall_picture(g, static_cast<int>(k), labels[k], magnification);
    }
    g << "set output\n";
  }
  if (!g) throw InputError(dir + "/" + name + ": write failed");
  return name;
}

}  // namespace mortar::harness
