// `masonry-joint inp --params FILE --two-blocks explicit|standard`: the
// first job to run, complete: two pairs of blocks joined by the law, one
// pressed and sheared (SHEAR), one pulled apart (TENSION). Each lower block
// is elastic and stiff (its compliance 0.4 % of the joint's in M15's kn),
// fixed at its base; each upper block is a rigid body loaded at its
// reference node. Step 1 presses the SHEAR pair; step 2 slides it and
// opens the TENSION pair. Abaqus/Explicit: general contact with
// VUINTERACTION; Abaqus/Standard: contact pairs with UINTER and increments
// of the loading programs' sizes. The same loading as harness programs:
// examples/two_blocks/ (their curves, and what a first run should show).
#pragma once

#include <iosfwd>
#include <vector>

namespace mortar::harness {

// The loading, also in examples/two_blocks/{shear,tension}.toml (the test
// reads both and compares).
struct TwoBlockLoading {
  double side = 100.0;        // the joint is side × side [mm²]
  double height = 50.0;       // of each block [mm]
  double pressure = 0.5;      // on the SHEAR pair in step 1 [MPa]
  double slip = 0.2;          // of the SHEAR pair's upper block in step 2 [mm]
  double opening = 0.05;      // of the TENSION pair's upper block in step 2 [mm]
  long increments[2] = {10, 400};          // Abaqus/Standard: fixed increments of steps 1 and 2
  double explicit_time[2] = {0.01, 0.04};  // Abaqus/Explicit: durations of steps 1 and 2 [s]
};

enum class DeckSolver { explicit_general_contact, standard_contact_pair };

// `props`: props(1..) as for `inp` (output/inp_deck.hpp).
void write_two_block_deck(std::ostream& out, const std::vector<double>& props, DeckSolver solver,
                          const TwoBlockLoading& loading = TwoBlockLoading{});

}  // namespace mortar::harness
