#include "input/scene_file.hpp"

#include <cmath>
#include <sstream>

#include "input/toml_input.hpp"
#include "output/csv.hpp"

namespace mortar::harness {

namespace {

std::string format(double x) {
  std::ostringstream s;
  s.precision(12);
  s << x;
  return s.str();
}

// Reads the keys of one table with messages that name the table, the key,
// the value and the rule.
class TableReader {
 public:
  TableReader(const std::string& file, const toml::value& root, const std::string& name, bool required)
      : file_(file), name_(name) {
    if (root.contains(name)) {
      table_ = &root.at(name);
      if (!table_->is_table())
        throw InputError(position_of(file, *table_) + ": '" + name + "' must be a table ([" + name + "])");
    } else if (required) {
      throw InputError(file + ": missing table [" + name + "]");
    }
  }
  bool has(const char* key) const { return table_ && table_->contains(key); }
  const toml::value& at(const char* key) const {
    if (!has(key)) throw InputError(file_ + ": missing key '" + key + "' in [" + name_ + "]");
    return table_->at(key);
  }
  std::string what(const char* key) const { return "[" + name_ + "] " + key; }
  void keys(std::initializer_list<const char*> allowed) const {
    if (table_) reject_unknown_keys(file_, *table_, allowed, "[" + name_ + "]");
  }
  // A number; `rule` is checked by `ok` and stated in the message.
  template <class Ok>
  double number(const char* key, double fallback, bool required, Ok ok, const char* rule) const {
    if (!has(key)) {
      if (required) at(key);
      return fallback;
    }
    const double x = read_number(file_, at(key), what(key));
    if (!ok(x))
      throw InputError(position_of(file_, at(key)) + ": " + what(key) + " = " + format(x) +
                       " violates the rule: " + rule);
    return x;
  }
  double positive(const char* key) const {
    return number(key, 0, true, [](double x) { return x > 0; }, "> 0");
  }
  double non_negative(const char* key, double fallback) const {
    return number(key, fallback, false, [](double x) { return x >= 0; }, ">= 0");
  }
  long integer(const char* key, long fallback, long min, long max) const {
    return has(key) ? read_integer(file_, at(key), what(key), min, max) : fallback;
  }
  // A bound on a count: whole, written as an integer or as 2e7.
  long count(const char* key, long fallback) const {
    return static_cast<long>(number(key, static_cast<double>(fallback), false,
                                    [](double x) { return x >= 1 && x <= 1e9 && x == std::floor(x); },
                                    "a whole number in [1, 1e9]"));
  }
  bool boolean(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_boolean())
      throw InputError(position_of(file_, at(key)) + ": " + what(key) + " must be true or false");
    return at(key).as_boolean();
  }
  // One of `names`; returns its index.
  int choice(const char* key, std::initializer_list<const char*> names, int fallback) const {
    if (!has(key)) return fallback;
    const std::string v = read_string(file_, at(key), what(key));
    int i = 0;
    std::string list;
    for (const char* n : names) {
      if (v == n) return i;
      list += (i++ ? ", " : "") + std::string("\"") + n + "\"";
    }
    throw InputError(position_of(file_, at(key)) + ": " + what(key) + " = \"" + v + "\" violates the rule: one of " +
                     list);
  }
  std::vector<double> numbers(const char* key) const {
    std::vector<double> out;
    if (!has(key)) return out;
    const toml::value& v = at(key);
    if (!v.is_array()) throw InputError(position_of(file_, v) + ": " + what(key) + " must be an array of numbers");
    for (const auto& x : v.as_array()) out.push_back(read_number(file_, x, what(key) + " entry"));
    return out;
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_, name_;
  const toml::value* table_ = nullptr;
};

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

void read_wall(const TableReader& t, WallGeometry& w) {
  t.keys({"unit_length", "unit_height", "unit_depth", "joint_thickness", "density", "courses", "units_per_course",
          "bond", "tie_bottom_course", "tie_top_course"});
  w.unit_length = t.positive("unit_length");
  w.unit_height = t.positive("unit_height");
  w.unit_depth = t.positive("unit_depth");
  w.joint = t.non_negative("joint_thickness", 0);
  // kg/m³ in the file (as tables give it), t/mm³ inside.
  w.density = 1e-12 * t.number("density", 0, true, [](double x) { return x >= 0; }, ">= 0 kg/m^3");
  w.courses = static_cast<int>(t.integer("courses", 0, 1, 10000));
  if (!t.has("courses")) t.at("courses");
  w.units_per_course = t.number("units_per_course", 0, true,
                                [](double x) { return x >= 0.5 && x <= 10000 && std::fabs(2 * x - std::round(2 * x)) < 1e-12; },
                                "a whole or half number of units in [0.5, 10000]");
  w.bond = t.choice("bond", {"running", "stack"}, 0) == 0 ? Bond::running : Bond::stack;
  w.tie_bottom_course = t.boolean("tie_bottom_course", false);
  w.tie_top_course = t.boolean("tie_top_course", false);
  if (w.tie_bottom_course && w.tie_top_course && w.courses < 2)
    throw InputError(t.file() + ": [wall] courses = 1 with both tie_bottom_course and tie_top_course: the one course "
                     "cannot be clamped in the base and the beam at once");
}

void read_beam(const TableReader& t, WallGeometry& w) {
  t.keys({"mass", "height", "rotation", "vertical"});
  w.beam_mass = 1e-3 * t.non_negative("mass", 0);  // kg in the file, t inside
  w.beam_height = t.non_negative("height", 0);
  w.beam_rotation = t.choice("rotation", {"fixed", "free"}, 0) == 0 ? BeamRotation::fixed : BeamRotation::free;
  w.beam_held = t.choice("vertical", {"free", "held"}, 0) == 1;
  if (w.beam_mass <= 0 && !w.tie_top_course)
    throw InputError(t.file() + ": [top_beam] mass = 0 violates the rule: > 0 unless [wall] tie_top_course = true "
                     "(an explicit solver needs a mass on every free degree of freedom)");
}

void read_contact(const TableReader& t, WallGeometry& w) {
  t.keys({"points_per_face", "rule"});
  w.points_per_face = static_cast<int>(t.integer("points_per_face", 2, 1, 1000));
  w.rule = t.choice("rule", {"trapezoid", "midpoint"}, 0) == 0 ? PointRule::trapezoid : PointRule::midpoint;
}

// The corners of a history: finite, bounded, each differing from the one before.
std::vector<double> read_corners(const TableReader& t, const char* key, double bound, const char* unit) {
  std::vector<double> out = t.numbers(key);
  if (out.empty()) t.at(key);
  double prev = 0;
  for (double d : out) {
    if (d == prev)
      throw InputError(position_of(t.file(), t.at(key)) + ": [loading] " + key + " repeats " + format(d) + " " + unit +
                       ": violates the rule: every corner differs from the one before (the first from 0)");
    if (!(std::fabs(d) <= bound))
      throw InputError(position_of(t.file(), t.at(key)) + ": [loading] " + key + " corner " + format(d) + " " + unit +
                       " violates the rule: |corner| <= " + format(bound) + " " + unit);
    prev = d;
  }
  return out;
}

void read_loading(const TableReader& t, LoadingSpec& l) {
  t.keys({"gravity", "self_weight_time", "precompression", "precompression_time", "hold_time", "control",
          "displacement", "velocity", "force", "force_rate", "action_height"});
  l.gravity = t.non_negative("gravity", 9810.0);
  l.self_weight_time = t.positive("self_weight_time");
  l.precompression = t.non_negative("precompression", 0);
  l.precompression_time = t.positive("precompression_time");
  l.hold_time = t.non_negative("hold_time", 0);
  l.force_control = t.choice("control", {"displacement", "force"}, 0) == 1;
  // The other control's keys are an error in the file that sets `control`
  // (a file that `extends` another overrides its history).
  const std::string control_file = t.has("control") ? file_of(t.at("control"), t.file()) : t.file();
  const char* const displacement_keys[2] = {"displacement", "velocity"}, *const force_keys[2] = {"force", "force_rate"};
  for (const char* other : l.force_control ? displacement_keys : force_keys)
    if (t.has(other) && file_of(t.at(other), t.file()) == control_file)
      throw InputError(position_of(t.file(), t.at(other)) + ": [loading] " + other + " violates the rule: not with control = \"" +
                       (l.force_control ? "force" : "displacement") + "\"");
  if (l.force_control) {
    l.force = read_corners(t, "force", 1e9, "N");
    l.force_rate = t.positive("force_rate");
  } else {
    l.displacement = read_corners(t, "displacement", 1e4, "mm");
    l.velocity = t.positive("velocity");
  }
  if (t.has("action_height")) l.action_height = t.non_negative("action_height", 0);
}

void read_solver(const TableReader& t, SolverSpec& s) {
  t.keys({"safety_factor", "mass_scaling", "mass_damping", "max_increments"});
  s.safety_factor = t.number("safety_factor", 0.8, false, [](double x) { return x > 0 && x <= 1; }, "0 < x <= 1");
  s.mass_scaling = t.number("mass_scaling", 1.0, false, [](double x) { return x >= 1; }, ">= 1");
  s.mass_damping = t.non_negative("mass_damping", 0);
  s.max_increments = t.count("max_increments", s.max_increments);
}

std::string resolve(const std::string& scene, const std::string& file) {
  return file.empty() || file[0] == '/' ? file : folder_of(scene) + file;
}

// A path read from `v`, relative to the file that holds it.
std::string path_value(const std::string& scene, const toml::value& v, const std::string& what) {
  return resolve(file_of(v, scene), read_string(scene, v, what));
}

// [output] experiment: read and checked here, before anything is written.
void read_experiment(const TableReader& t, SceneOutputSpec& o) {
  if (!t.has("experiment")) return;
  const std::string& path = t.file();
  o.experiment = path_value(path, t.at("experiment"), "[output] experiment");
  try {
    const CsvTable curve = read_csv(o.experiment);
    const int u = curve.require("top_displacement_mm"), v = curve.require("base_shear_kN");
    for (const auto& row : curve.rows)
      o.experiment_curve.push_back({row[static_cast<size_t>(u)], row[static_cast<size_t>(v)]});
  } catch (const InputError& e) {
    throw InputError(position_of(path, t.at("experiment")) + ": [output] experiment: " + e.what());
  }
  if (o.experiment_curve.empty())
    throw InputError(o.experiment + ": [output] experiment has no rows: violates the rule: at least one point");
  o.experiment_label = t.has("experiment_label") ? read_string(path, t.at("experiment_label"), "[output] experiment_label")
                                                 : "experiment";
}

void read_output(const TableReader& t, SceneOutputSpec& o) {
  t.keys({"every", "snapshots", "magnification", "max_rows", "joint_colour", "experiment", "experiment_label"});
  o.every = static_cast<int>(t.integer("every", 0, 0, 1000000000));
  o.snapshot_times = t.numbers("snapshots");
  o.magnification = t.non_negative("magnification", 0);
  o.max_rows = t.count("max_rows", o.max_rows);
  o.joint_colour = static_cast<JointColour>(t.choice("joint_colour", {"dissipation", "opening", "damage"}, 0));
  read_experiment(t, o);
}

// The scene file's tables, on top of those of the file it `extends`: a
// key of a table replaces the base's key, the other keys stay the base's.
toml::value scene_root(const std::string& path, int depth) {
  toml::value root = parse_toml_file(path);
  if (!root.contains("extends")) return root;
  if (depth >= 8)
    throw InputError(position_of(path, root.at("extends")) + ": extends violates the rule: at most 8 files in a chain");
  toml::value merged;
  try {
    merged = scene_root(path_value(path, root.at("extends"), "extends"), depth + 1);
  } catch (const InputError& e) {
    throw InputError(position_of(path, root.at("extends")) + ": extends: " + e.what());
  }
  for (const auto& [key, v] : root.as_table()) {
    if (key == "extends") continue;
    if (v.is_table() && merged.contains(key) && merged.at(key).is_table())
      for (const auto& [k, x] : v.as_table()) merged.at(key).as_table()[k] = x;
    else
      merged.as_table()[key] = v;
  }
  merged.as_table().erase("extends");
  return merged;
}

// [interfaces]: a parameter file per role; a unit_crack file splits every
// unit into two halves.
void read_interfaces(const std::string& path, const toml::value& root, SceneSpec& s) {
  s.interface.fill(s.joint);
  if (!root.contains("interfaces")) return;
  const toml::value& t = root.at("interfaces");
  if (!t.is_table()) throw InputError(position_of(path, t) + ": 'interfaces' must be a table ([interfaces])");
  reject_unknown_keys(path, t, {"bed", "head", "unit_crack"}, "[interfaces]");
  const char* keys[kInterfaceRoles] = {"bed", "head", "unit_crack"};
  for (int r = 0; r < kInterfaceRoles; ++r) {
    if (!t.contains(keys[r])) continue;
    s.interface[r] = read_parameter_file(path_value(path, t.at(keys[r]), std::string("[interfaces] ") + keys[r]));
  }
  s.wall.split_units = t.contains("unit_crack");
}

void read_units(const TableReader& t, UnitElasticity& u) {
  t.keys({"young_modulus", "poisson"});
  u.young = t.number("young_modulus", 0, false, [](double x) { return x == 0 || (x >= 1 && x <= 1e6); },
                     "0 (rigid units) or 1 <= E <= 1e6 MPa");
  u.poisson = t.number("poisson", 0, false, [](double x) { return x >= 0 && x < 0.5; }, "0 <= nu < 0.5");
}

// Each role's law with the units in series, checked against the law's rules.
void lump_units(SceneSpec& s) {
  for (int r = 0; r < kInterfaceRoles; ++r) {
    const auto role = static_cast<InterfaceRole>(r);
    const Parameters p = in_series_with_units(s.interface[r].values, s.units, lumped_unit_length(s.wall, role));
    ValidationError e = validate(p);
    if (e.ok()) e = validate(s.interface[r].cap, p);
    if (!e.ok())
      throw InputError(s.file + ": the " + role_name(role) + "s' law " + s.interface[r].file + " with [units] in series (kn = " +
                       format(p.kn) + ", ks = " + format(p.ks) + " N/mm^3): " + e.message());
    s.interface_law[r] = p;
  }
}

}  // namespace

Parameters in_series_with_units(const Parameters& p, const UnitElasticity& u, double l) {
  if (u.young <= 0) return p;
  const double g = u.young / (2 * (1 + u.poisson));
  Parameters out = p;
  out.kn = 1 / (1 / p.kn + l / u.young);
  out.ks = 1 / (1 / p.ks + l / g);
  return out;
}

double action_arm(const SceneSpec& s, const WallModel& m) {
  const double h = s.loading.action_height;
  return std::isnan(h) ? 0.0 : h - m.bodies[static_cast<size_t>(m.beam())].cy;
}

std::vector<double> SceneSpec::stage_ends() const {
  const LoadingSpec& l = loading;
  std::vector<double> ends;
  double t = l.self_weight_time;
  ends.push_back(t);
  ends.push_back(t += l.precompression_time);
  ends.push_back(t += l.hold_time);
  double prev = 0;
  for (double d : l.corners()) {
    ends.push_back(t += std::fabs(d - prev) / l.rate());
    prev = d;
  }
  return ends;
}

SceneSpec read_scene_file(const std::string& path) {
  const toml::value root = scene_root(path, 0);
  reject_unknown_keys(path, root, {"extends", "joint", "scheme", "stol", "wall", "interfaces", "units", "top_beam", "contact", "loading", "solver",
                       "output"},
                      "the scene file");
  SceneSpec s;
  s.file = path;
  if (!root.contains("joint")) throw InputError(path + ": missing key 'joint' (the joint law's parameter file)");
  s.joint = read_parameter_file(path_value(path, root.at("joint"), "joint"));
  if (root.contains("scheme")) {
    const std::string v = read_string(path, root.at("scheme"), "scheme");
    if (v == "modified-euler") s.scheme = Scheme::modified_euler;
    else if (v == "forward-euler") s.scheme = Scheme::forward_euler;
    else if (v == "implicit") s.scheme = Scheme::implicit;
    else
      throw InputError(position_of(path, root.at("scheme")) + ": scheme = \"" + v +
                       "\" violates the rule: one of \"modified-euler\", \"forward-euler\", \"implicit\"");
  }
  if (root.contains("stol")) {
    s.stol = read_number(path, root.at("stol"), "stol");
    if (!(s.stol == 0 || (s.stol > 0 && s.stol < 1)))
      throw InputError(position_of(path, root.at("stol")) + ": stol = " + format(s.stol) +
                       " violates the rule: 0 < stol < 1, or 0 for the routine's default");
  }
  read_wall(TableReader(path, root, "wall", true), s.wall);
  read_interfaces(path, root, s);
  read_units(TableReader(path, root, "units", false), s.units);
  read_beam(TableReader(path, root, "top_beam", false), s.wall);
  read_contact(TableReader(path, root, "contact", false), s.wall);
  read_loading(TableReader(path, root, "loading", true), s.loading);
  read_solver(TableReader(path, root, "solver", false), s.solver);
  read_output(TableReader(path, root, "output", false), s.output);
  lump_units(s);
  return s;
}

}  // namespace mortar::harness
