#include "commands/inp.hpp"

#include "commands/run.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "output/inp_deck.hpp"

namespace mortar::harness {

int inp_command(const InpArgs& a, std::ostream& out) {
  if (const std::string problem = abaqus_name_problem(a.name); !problem.empty())
    throw InputError("--name '" + a.name + "' " + problem + ": " + kAbaqusNameRule);
  if (inp_writes_job(a)) return inp_job_command(a, out);
  if (a.params.empty()) throw InputError("inp: --params FILE is needed (or --scene FILE)");
  check_stol(a.stol);
  const ParameterSet params = read_parameter_file(a.params);
  const Scheme scheme = a.scheme.empty() ? Scheme::modified_euler : scheme_names().at(a.scheme);
  // Controls only when asked for.
  const bool controls = !a.scheme.empty() || a.stol != 0;
  InpOptions o;
  o.name = a.name;
  o.props = deck_props(params.values, controls, !a.scheme.empty(), scheme, a.stol, params.cap);
  o.depvar = deck_depvar(o.props, false);
  write_surface_interaction(out, o);
  return 0;
}

}  // namespace mortar::harness
