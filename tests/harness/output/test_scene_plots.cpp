// The gnuplot script of `scene` (output/scene_plots.hpp): the colour legend
// names the quantity and unit of each joint_colour, the title states the
// magnification, and every column the script reads is one the CSVs write.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

#include "input/scene_file.hpp"
#include "output/scene_csv.hpp"
#include "output/scene_plots.hpp"
#include "support.hpp"

using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string script_for(JointColour colour, const Magnification& mag) {
  const std::filesystem::path dir = fresh_directory("scene_plots");
  write_scene_plot_script(dir.string(), {"peak"}, {mag}, colour);
  return read_text(dir / "scene.gp");
}

// The first line of the CSV at `path`, split at the commas.
std::set<std::string> header(const std::filesystem::path& path) {
  std::istringstream line(read_text(path).substr(0, read_text(path).find('\n')));
  std::set<std::string> names;
  for (std::string cell; std::getline(line, cell, ',');) names.insert(cell);
  return names;
}

}  // namespace

TEST_CASE("scene plots: the colour legend names the quantity and its unit", "[scene_plots]") {
  const Magnification mag;
  const std::string dissipation = script_for(JointColour::dissipation, mag);
  CHECK_THAT(dissipation, Catch::Contains("set cblabel \"dissipated energy per unit area, SDV 16 + 17 + 18 [N/mm] (log)") &&
                              Catch::Contains("set logscale cb") &&
                              Catch::Contains("column(\"dissipation_N_per_mm\")"));
  const std::string damage = script_for(JointColour::damage, mag);
  CHECK_THAT(damage, Catch::Contains("set cblabel \"damage max(d_n, d_s) [-]\"") &&
                         Catch::Contains("column(\"d_n\") > column(\"d_s\")"));
  const std::string opening = script_for(JointColour::opening, mag);
  CHECK_THAT(opening, Catch::Contains("set cblabel \"joint opening [mm]") && Catch::Contains("column(\"opening_mm\")"));
}

TEST_CASE("scene plots: the title states the magnification and the largest joint motion", "[scene_plots]") {
  Magnification mag;
  mag.factor = 207.04, mag.largest_relative = 0.2712;
  CHECK_THAT(script_for(JointColour::dissipation, mag),
             Catch::Contains("displacements x 207: the largest joint opening or slip (0.271 mm)"));
  mag.factor = 50, mag.automatic = false;
  CHECK_THAT(script_for(JointColour::dissipation, mag),
             Catch::Contains("displacements x 50 (the scene file's; the largest joint opening or slip 0.271 mm)"));
}

TEST_CASE("scene plots: every column the script reads is written, and the stack holds the six parts",
          "[scene_plots]") {
  // Arrange: the CSVs' headers as the scene command writes them.
  const SceneSpec spec = read_scene_file(data_file("wall_small.toml"));
  const WallModel model = build_wall(spec.wall);
  const std::filesystem::path dir = fresh_directory("scene_plots_columns");
  { HistoryCsv history((dir / "history.csv").string()); }
  WallSnapshot snap;
  snap.q.assign(3 * model.bodies.size(), 0.0);
  for (auto* v : {&snap.opening, &snap.slip, &snap.damage_n, &snap.damage_s, &snap.dissipation, &snap.kappa_c})
    v->assign(model.points.size(), 0.0);
  write_snapshot_csv(dir.string(), 0, model, snap, 1.0);
  std::set<std::string> written = header(dir / "history.csv");
  for (const std::string& name : header(dir / "snapshot_0_joints.csv")) written.insert(name);
  // Act
  std::string script;
  for (JointColour c : {JointColour::dissipation, JointColour::opening, JointColour::damage})
    script += script_for(c, Magnification{});
  // Assert
  const std::regex column("column\\(\"([A-Za-z0-9_]+)\"\\)");
  int read = 0;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), column); it != std::sregex_iterator(); ++it, ++read)
    CHECK(written.count((*it)[1].str()) == 1);
  CHECK(read > 10);
  // The stack's top band reaches the sum of the six parts the balance counts
  // (the dissipation by its three parts), and the sum is drawn against it.
  CHECK_THAT(script, Catch::Contains("0 + column(\"elastic_energy\") + column(\"plastic_dissipation\") + "
                                     "column(\"damage_dissipation\") + column(\"unilateral_energy\") + "
                                     "column(\"kinetic_energy\") + column(\"damping_work\")") &&
                         Catch::Contains("column(\"energy_accounted\")") &&
                         Catch::Contains("column(\"balance_error\")"));
}

TEST_CASE("scene plots: a measured curve named by the scene is drawn beside the base shear, with its label",
          "[scene_plots]") {
  const std::filesystem::path dir = fresh_directory("scene_plots_experiment");
  write_scene_plot_script(dir.string(), {"peak"}, {Magnification{}}, JointColour::dissipation, "wall X, test");
  const std::string with = read_text(dir / "scene.gp");
  CHECK_THAT(with, Catch::Contains("\"experiment.csv\" using (column(\"top_displacement_mm\")):(column(\"base_shear_kN\"))") &&
                       Catch::Contains("title \"wall X, test\""));
  CHECK_THAT(script_for(JointColour::dissipation, Magnification{}), !Catch::Contains("experiment.csv"));
}
