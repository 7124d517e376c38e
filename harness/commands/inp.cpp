#include "commands/inp.hpp"

#include "commands/run.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "mortar/state_layout.hpp"
#include "output/inp_deck.hpp"

namespace mortar::harness {

int inp_command(const InpArgs& a, std::ostream& out) {
  if (const std::string problem = abaqus_name_problem(a.name); !problem.empty())
    throw InputError("--name '" + a.name + "' " + problem + ": " + kAbaqusNameRule);
  check_stol(a.stol);
  const ParameterSet params = read_parameter_file(a.params);
  Controls c;
  if (!a.scheme.empty()) c.scheme = scheme_names().at(a.scheme);
  c.stol = a.stol;
  const auto props = to_props(params.values, c);
  // Controls only when asked for: absent props, and zero ones, mean the
  // routine's defaults.
  const bool controls = !a.scheme.empty() || a.stol != 0;
  InpOptions o;
  o.name = a.name;
  // Abaqus/Explicit loads the single-precision routine unless the job says
  // double=both; it keeps its state as float pairs only with DEPVAR >= 34
  // (docs/model.md 3), and either routine records the integration flags in
  // SDV 35 with DEPVAR >= 35 (docs/model.md 9).
  o.depvar = kFlaggedStateCount;
  o.props.assign(props.begin(), props.begin() + kParameterCount + (controls ? 2 : 0));
  if (controls && a.scheme.empty()) o.props[kParameterCount] = 0.0;
  write_surface_interaction(out, o);
  return 0;
}

}  // namespace mortar::harness
