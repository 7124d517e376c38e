// `masonry-joint inp --scene FILE`: a scene's wall (input/scene_file.hpp,
// scenes/wall.hpp) as a complete Abaqus/Explicit job. Each body of the
// scene (the base, every unit, the top beam, tied courses included in
// theirs) is a rigid body of C3D8R elements extruded over the unit depth,
// with its reference node at the scene's centroid; the joints are general
// contact with one user interaction per role (bed, head, base, top joints);
// the supports, self-weight, precompression and the beam's displacement
// history are boundary conditions, loads and SMOOTH STEP amplitudes through
// the stage ends of the scene; mass-proportional damping as dashpots to
// ground. Geometry and loading only as far as the scene defines them
// (docs/abaqus.md, "Decks").
#pragma once

#include <iosfwd>

#include "input/scene_file.hpp"
#include "scenes/wall.hpp"

namespace mortar::harness {

// `time_increment`: the fixed increment of *DYNAMIC, EXPLICIT, DIRECT USER
// CONTROL (rigid bodies give Abaqus no element-based stable increment; the
// scene solver's own increment is passed here).
void write_wall_deck(std::ostream& out, const SceneSpec& scene, const WallModel& model, double time_increment);

}  // namespace mortar::harness
