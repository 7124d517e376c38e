// Charts of `masonry-joint bench`, drawn by gnuplot (output/plots.hpp runs it):
// scripts with their data inline, so each can be restyled and rerun alone.
//   work_precision.gp      -> work_precision.{png,svg}: error against cost on
//                             the van der Pluijm -0.5 MPa path (cost per
//                             point-update, and per point for the whole path)
//   work_precision_all.gp  -> work_precision_all.{png,svg}: the same, one
//                             panel per path
//   stability_map.gp       -> stability_map.{png,svg}: the outcome grid
#pragma once

#include <string>
#include <vector>

#include "bench/bench.hpp"

namespace mortar::harness {

// Writes the scripts into out_dir; returns their file names.
std::vector<std::string> write_bench_plot_scripts(const std::string& out_dir, const BenchResult& r);

}  // namespace mortar::harness
