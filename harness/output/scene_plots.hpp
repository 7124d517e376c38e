// Charts of `masonry-joint scene`, drawn by gnuplot from the files the
// command wrote (the script stays next to the pictures, as for validate):
// base shear against top displacement, the energy history, and the wall at
// each snapshot (outlines displaced, joint points coloured by damage).
#pragma once

#include <string>
#include <vector>

namespace mortar::harness {

// Writes <dir>/scene.gp for `snapshot_labels.size()` snapshots; returns its name.
std::string write_scene_plot_script(const std::string& dir, const std::vector<std::string>& snapshot_labels,
                                    double magnification);

}  // namespace mortar::harness
