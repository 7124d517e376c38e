#include "input/protocol.hpp"

#include <cmath>
#include <sstream>

#include "input/toml_input.hpp"

namespace mortar::harness {

long Protocol::total_increments() const {
  long n = 0;
  for (const ProgramStep& s : steps) n += s.increments;
  return n;
}

namespace {

// What one component of one [[step]] says.
struct ComponentEntry {
  enum Kind { absent, displacement, traction, cycles } kind = absent;
  double value = 0;                // displacement or traction target
  std::vector<double> amplitudes;  // cycles
  long repeat = 1;
  double about = 0;
  int line = 0;
};

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

ComponentEntry read_component(const std::string& file, const toml::value& v, const std::string& where) {
  ComponentEntry e;
  e.line = line_of(v);
  if (!v.is_table())
    throw InputError(position_of(file, v) + ": " + where +
                     " must be an inline table such as {displacement = 0.1}, {traction = -0.5} or "
                     "{cycles = [0.5, 1.0], repeat = 2}");
  reject_unknown_keys(file, v, {"displacement", "traction", "cycles", "repeat", "about"}, where);
  const auto& t = v.as_table();
  const int given = int(t.count("displacement")) + int(t.count("traction")) + int(t.count("cycles"));
  if (given != 1)
    throw InputError(position_of(file, v) + ": " + where +
                     " needs exactly one of 'displacement' [mm], 'traction' [MPa] or 'cycles' [mm]");
  if ((t.count("repeat") || t.count("about")) && !t.count("cycles"))
    throw InputError(position_of(file, v) + ": " + where + ": 'repeat' and 'about' belong to 'cycles'");
  if (t.count("displacement")) {
    e.kind = ComponentEntry::displacement;
    e.value = read_number(file, t.at("displacement"), where + " displacement");
    if (!(std::abs(e.value) <= kMaxDisplacementTarget))
      throw InputError(position_of(file, t.at("displacement")) + ": " + where + " displacement = " + fmt(e.value) +
                       " mm violates the rule: |displacement| <= " + fmt(kMaxDisplacementTarget) + " mm");
  } else if (t.count("traction")) {
    e.kind = ComponentEntry::traction;
    e.value = read_number(file, t.at("traction"), where + " traction");
    // Beyond any joint's strength by far: a typo or a unit mistake, which
    // the solver would otherwise chase into a failure (exit 1).
    if (!(std::abs(e.value) <= kMaxTractionTarget))
      throw InputError(position_of(file, t.at("traction")) + ": " + where + " traction = " + fmt(e.value) +
                       " MPa violates the rule: |traction| <= " + fmt(kMaxTractionTarget) + " MPa");
  } else {
    e.kind = ComponentEntry::cycles;
    const toml::value& a = t.at("cycles");
    if (!a.is_array() || a.as_array().empty())
      throw InputError(position_of(file, a) + ": " + where +
                       " cycles must be a non-empty array of amplitudes [mm], e.g. [0.5, 1.0]");
    for (const toml::value& x : a.as_array()) {
      const double amp = read_number(file, x, where + " cycle amplitude");
      if (!(amp > 0 && amp <= kMaxDisplacementTarget))
        throw InputError(position_of(file, x) + ": " + where + " cycle amplitude " + fmt(amp) +
                         " must be > 0 and <= " + fmt(kMaxDisplacementTarget) +
                         " mm (cycles go to about + a, then about - a)");
      e.amplitudes.push_back(amp);
    }
    if (t.count("repeat")) e.repeat = read_integer(file, t.at("repeat"), where + " repeat", 1, 100000);
    if (t.count("about")) e.about = read_number(file, t.at("about"), where + " about");
  }
  return e;
}

class ProtocolReader {
 public:
  ProtocolReader(const std::string& file, Protocol& out) : file_(file), out_(out) {}

  void read(const toml::value& root) {
    reject_unknown_keys(file_, root, {"title", "directions", "step"}, "the protocol file");
    if (root.contains("title")) out_.title = read_string(file_, root.at("title"), "title");
    if (root.contains("directions"))
      out_.directions = static_cast<int>(read_integer(file_, root.at("directions"), "directions", 2, 3));
    if (!root.contains("step") || !root.at("step").is_array() || root.at("step").as_array().empty())
      throw InputError(file_ + ": a protocol needs at least one [[step]] table");
    int index = 0;
    for (const toml::value& step : root.at("step").as_array()) read_step(step, ++index);
    if (out_.total_increments() > kMaxIncrementsTotal)
      throw InputError(file_ + ": " + std::to_string(out_.total_increments()) +
                       " increments in total; the harness accepts at most " + std::to_string(kMaxIncrementsTotal));
  }

 private:
  void read_step(const toml::value& step, int index) {
    std::string where = "step " + std::to_string(index);
    if (!step.is_table()) throw InputError(position_of(file_, step) + ": " + where + " must be a table");
    reject_unknown_keys(file_, step, {"name", "increments", "n", "s1", "s2", "max_increment", "increments_per_quarter"},
                        where);
    const auto& t = step.as_table();
    std::string name = t.count("name") ? read_string(file_, t.at("name"), where + " name") : where;
    if (t.count("name")) where += " ('" + name + "')";

    ComponentEntry entry[3];
    int cycling = -1;
    for (int j = 0; j < 3; ++j) {
      if (!t.count(kComponentNames[j])) continue;
      const toml::value& v = t.at(kComponentNames[j]);
      if (j == 2 && out_.directions == 2)
        throw InputError(position_of(file_, v) + ": " + where +
                         " sets s2, but the protocol has directions = 2 (one slip component)");
      entry[j] = read_component(file_, v, where + " component " + kComponentNames[j]);
      if (entry[j].kind == ComponentEntry::cycles) {
        if (cycling >= 0)
          throw InputError(position_of(file_, v) + ": " + where + " cycles more than one component");
        cycling = j;
      }
    }
    // The components this step controls, with the unspecified ones holding
    // what they did at the end of the previous step (bonded at zero separation
    // before the first step).
    std::array<ComponentProgram, 3> resolved = previous();
    for (int j = 0; j < 3; ++j) {
      if (entry[j].kind == ComponentEntry::displacement) resolved[j] = {Control::displacement, entry[j].value};
      if (entry[j].kind == ComponentEntry::traction) resolved[j] = {Control::traction, entry[j].value};
    }
    const int line = line_of(step);
    if (cycling < 0) {
      if (t.count("max_increment") || t.count("increments_per_quarter"))
        throw InputError(position_of(file_, step) + ": " + where +
                         ": 'max_increment' and 'increments_per_quarter' belong to cycle steps; "
                         "a plain step sets 'increments'");
      if (!t.count("increments"))
        throw InputError(position_of(file_, step) + ": " + where + " needs 'increments' (a whole number >= 1)");
      const long n = read_integer(file_, t.at("increments"), where + " increments", 1, kMaxIncrementsPerStep);
      out_.steps.push_back(ProgramStep{name, line, n, resolved});
      return;
    }
    expand_cycles(step, where, name, line, resolved, cycling, entry[cycling]);
  }

  // Fully reversed displacement cycles of component j about `about`: for each
  // amplitude a, `repeat` times to about + a and to about - a; finally back to
  // about. One program step per leg; the other components do in the first leg
  // what the step says and hold it afterwards.
  void expand_cycles(const toml::value& step, const std::string& where, const std::string& name, int line,
                     std::array<ComponentProgram, 3> resolved, int j, const ComponentEntry& e) {
    const auto& t = step.as_table();
    if (t.count("increments"))
      throw InputError(position_of(file_, step) + ": " + where +
                       " is a cycle step: set 'max_increment' [mm] or 'increments_per_quarter', not 'increments'");
    const int sizing = int(t.count("max_increment")) + int(t.count("increments_per_quarter"));
    if (sizing != 1)
      throw InputError(position_of(file_, step) + ": " + where +
                       " is a cycle step: give exactly one of 'max_increment' [mm] or 'increments_per_quarter'");
    double max_increment = 0;
    long per_quarter = 0;
    if (t.count("max_increment")) {
      max_increment = read_number(file_, t.at("max_increment"), where + " max_increment");
      if (!(max_increment > 0))
        throw InputError(position_of(file_, t.at("max_increment")) + ": " + where + " max_increment = " +
                         fmt(max_increment) + " must be > 0 [mm]");
    } else {
      per_quarter = read_integer(file_, t.at("increments_per_quarter"), where + " increments_per_quarter", 1,
                                 kMaxIncrementsPerStep);
    }
    const ComponentProgram before = previous()[j];
    if (before.kind != Control::displacement)
      throw InputError(file_position(file_, e.line) + ": " + where + " cycles " + kComponentNames[j] +
                       ", which is traction-controlled before this step; cycles start from a known "
                       "displacement, so control it by displacement in the step before");
    struct Leg {
      double target, amplitude;
      std::string label;
    };
    std::vector<Leg> legs;
    for (size_t k = 0; k < e.amplitudes.size(); ++k) {
      const double a = e.amplitudes[k];
      for (long r = 1; r <= e.repeat; ++r) {
        const std::string tag = name + ": amplitude " + fmt(a) + " mm, cycle " + std::to_string(r) + "/" +
                                std::to_string(e.repeat);
        legs.push_back({e.about + a, a, tag + ", to +" + fmt(a)});
        legs.push_back({e.about - a, a, tag + ", to -" + fmt(a)});
      }
    }
    legs.push_back({e.about, e.amplitudes.back(), name + ": back to " + fmt(e.about)});
    double from = before.target;
    bool first = true;
    for (const Leg& leg : legs) {
      const double length = std::abs(leg.target - from);
      const double n = max_increment > 0 ? std::ceil(length / max_increment - 1e-9)
                                         : std::round(double(per_quarter) * length / leg.amplitude);
      if (n > double(kMaxIncrementsPerStep))
        throw InputError(position_of(file_, step) + ": " + where + " needs " + fmt(n) +
                         " increments for one leg; at most " + std::to_string(kMaxIncrementsPerStep));
      resolved[j] = {Control::displacement, leg.target};
      ProgramStep s{leg.label, line, std::max(1L, static_cast<long>(n)), resolved};
      if (!first) {
        // Held: traction targets stay, displacements stay where they ended.
        for (int i = 0; i < 3; ++i)
          if (i != j) s.component[i] = out_.steps.back().component[i];
      }
      out_.steps.push_back(s);
      first = false;
      from = leg.target;
    }
  }

  std::array<ComponentProgram, 3> previous() const {
    if (out_.steps.empty()) return {};  // bonded: every component at zero separation
    return out_.steps.back().component;
  }

  const std::string& file_;
  Protocol& out_;
};

}  // namespace

Protocol read_protocol_file(const std::string& path) {
  const toml::value root = parse_toml_file(path);
  Protocol p;
  p.file = path;
  ProtocolReader(path, p).read(root);
  return p;
}

}  // namespace mortar::harness
