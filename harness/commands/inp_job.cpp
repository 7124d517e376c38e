// `masonry-joint inp --scene FILE` and `inp --params FILE --two-blocks
// SOLVER`: complete Abaqus jobs (output/wall_deck.hpp,
// output/two_block_deck.hpp) on standard output. The options that only the
// parameter block takes are refused with the rule, as are missing ones.
#include "commands/inp.hpp"

#include <ostream>

#include "commands/run.hpp"
#include "input/input_error.hpp"
#include "input/parameter_file.hpp"
#include "input/scene_file.hpp"
#include "output/inp_deck.hpp"
#include "output/two_block_deck.hpp"
#include "output/wall_deck.hpp"
#include "solvers/block_solver.hpp"
#include "solvers/scene_plan.hpp"

namespace mortar::harness {

namespace {

int scene_job(const InpArgs& a, std::ostream& out) {
  if (!a.params.empty())
    throw InputError("--scene " + a.scene + " with --params " + a.params +
                     ": give one of them (the scene names its own joint parameter file)");
  if (!a.scheme.empty() || a.stol != 0 || !a.two_blocks.empty())
    throw InputError("--scene " + a.scene +
                     ": --scheme, --stol and --two-blocks do not apply (the scene file sets scheme and stol)");
  const SceneSpec spec = read_scene_file(a.scene);
  // The scene solver's own increment: the deck's fixed Abaqus increment.
  ScenePlan plan(spec, BlockSolverOptions{});
  write_wall_deck(out, spec, plan.model(), plan.solver().time_increment());
  return 0;
}

int two_block_job(const InpArgs& a, std::ostream& out) {
  check_stol(a.stol);
  if (a.params.empty())
    throw InputError("--two-blocks " + a.two_blocks + ": --params FILE is needed (the joint's parameter file)");
  const ParameterSet params = read_parameter_file(a.params);
  const bool standard = a.two_blocks == "standard";
  const bool controls = !a.scheme.empty() || a.stol != 0;
  const Scheme scheme = a.scheme.empty() ? Scheme::modified_euler : scheme_names().at(a.scheme);
  write_two_block_deck(out, deck_props(params.values, controls, !a.scheme.empty(), scheme, a.stol, params.cap),
                       standard ? DeckSolver::standard_contact_pair : DeckSolver::explicit_general_contact);
  return 0;
}

}  // namespace

bool inp_writes_job(const InpArgs& a) { return !a.scene.empty() || !a.two_blocks.empty(); }

int inp_job_command(const InpArgs& a, std::ostream& out) {
  return a.scene.empty() ? two_block_job(a, out) : scene_job(a, out);
}

}  // namespace mortar::harness
