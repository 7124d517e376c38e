// Charts of `masonry-joint scene`, drawn by gnuplot from the files the
// command wrote (the script stays next to the pictures, as for validate):
// base shear against top displacement, the energy books (the parts the
// external work went into, stacked, and the balance error), and the wall at
// each snapshot (outlines displaced, joint points coloured by the scene's
// `joint_colour`).
#pragma once

#include <string>
#include <vector>

#include "input/scene_file.hpp"
#include "output/scene_csv.hpp"

namespace mortar::harness {

// Writes <dir>/scene.gp for the snapshots (a label and a magnification
// each), the measured curve <dir>/experiment.csv drawn beside the base shear
// when `experiment_label` is not empty; returns its name.
std::string write_scene_plot_script(const std::string& dir, const std::vector<std::string>& snapshot_labels,
                                    const std::vector<Magnification>& magnifications, JointColour colour,
                                    const std::string& experiment_label = "");

}  // namespace mortar::harness
