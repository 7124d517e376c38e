#include "input/scene_file.hpp"

#include <cmath>
#include <sstream>

#include "input/toml_input.hpp"

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
  t.keys({"mass", "height", "rotation"});
  w.beam_mass = 1e-3 * t.non_negative("mass", 0);  // kg in the file, t inside
  w.beam_height = t.non_negative("height", 0);
  w.beam_rotation = t.choice("rotation", {"fixed", "free"}, 0) == 0 ? BeamRotation::fixed : BeamRotation::free;
  if (w.beam_mass <= 0 && !w.tie_top_course)
    throw InputError(t.file() + ": [top_beam] mass = 0 violates the rule: > 0 unless [wall] tie_top_course = true "
                     "(an explicit solver needs a mass on every free degree of freedom)");
}

void read_contact(const TableReader& t, WallGeometry& w) {
  t.keys({"points_per_face", "rule"});
  w.points_per_face = static_cast<int>(t.integer("points_per_face", 2, 1, 1000));
  w.rule = t.choice("rule", {"trapezoid", "midpoint"}, 0) == 0 ? PointRule::trapezoid : PointRule::midpoint;
}

void read_loading(const TableReader& t, LoadingSpec& l) {
  t.keys({"gravity", "self_weight_time", "precompression", "precompression_time", "hold_time", "displacement",
          "velocity"});
  l.gravity = t.non_negative("gravity", 9810.0);
  l.self_weight_time = t.positive("self_weight_time");
  l.precompression = t.non_negative("precompression", 0);
  l.precompression_time = t.positive("precompression_time");
  l.hold_time = t.non_negative("hold_time", 0);
  l.displacement = t.numbers("displacement");
  if (l.displacement.empty()) t.at("displacement");
  double prev = 0;
  for (double d : l.displacement) {
    if (d == prev)
      throw InputError(position_of(t.file(), t.at("displacement")) + ": [loading] displacement repeats " + format(d) +
                       " mm: violates the rule: every corner differs from the one before (the first from 0)");
    prev = d;
  }
  l.velocity = t.positive("velocity");
}

void read_solver(const TableReader& t, SolverSpec& s) {
  t.keys({"safety_factor", "mass_scaling", "mass_damping", "max_increments"});
  s.safety_factor = t.number("safety_factor", 0.8, false, [](double x) { return x > 0 && x <= 1; }, "0 < x <= 1");
  s.mass_scaling = t.number("mass_scaling", 1.0, false, [](double x) { return x >= 1; }, ">= 1");
  s.mass_damping = t.non_negative("mass_damping", 0);
  s.max_increments = t.count("max_increments", s.max_increments);
}

void read_output(const TableReader& t, SceneOutputSpec& o) {
  t.keys({"every", "snapshots", "magnification", "max_rows"});
  o.every = static_cast<int>(t.integer("every", 0, 0, 1000000000));
  o.snapshot_times = t.numbers("snapshots");
  o.magnification = t.non_negative("magnification", 0);
  o.max_rows = t.count("max_rows", o.max_rows);
}

}  // namespace

std::vector<double> SceneSpec::stage_ends() const {
  const LoadingSpec& l = loading;
  std::vector<double> ends;
  double t = l.self_weight_time;
  ends.push_back(t);
  ends.push_back(t += l.precompression_time);
  ends.push_back(t += l.hold_time);
  double prev = 0;
  for (double d : l.displacement) {
    ends.push_back(t += std::fabs(d - prev) / l.velocity);
    prev = d;
  }
  return ends;
}

SceneSpec read_scene_file(const std::string& path) {
  const toml::value root = parse_toml_file(path);
  reject_unknown_keys(path, root, {"joint", "scheme", "stol", "wall", "top_beam", "contact", "loading", "solver", "output"},
                      "the scene file");
  SceneSpec s;
  s.file = path;
  if (!root.contains("joint")) throw InputError(path + ": missing key 'joint' (the joint law's parameter file)");
  std::string joint = read_string(path, root.at("joint"), "joint");
  if (joint.empty() || joint[0] != '/') joint = folder_of(path) + joint;
  s.joint = read_parameter_file(joint);
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
  read_beam(TableReader(path, root, "top_beam", false), s.wall);
  read_contact(TableReader(path, root, "contact", false), s.wall);
  read_loading(TableReader(path, root, "loading", true), s.loading);
  read_solver(TableReader(path, root, "solver", false), s.solver);
  read_output(TableReader(path, root, "output", false), s.output);
  return s;
}

}  // namespace mortar::harness
