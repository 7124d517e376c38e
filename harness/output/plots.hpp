// Charts of a validated series, drawn by gnuplot from the CSVs that validate
// writes: a script per series (kept next to the pictures, so a person can
// restyle and rerun it) producing <series>.png and <series>.svg.
#pragma once

#include <string>
#include <vector>

#include "validation/calibration_data.hpp"

namespace mortar::harness {

struct PlotCase {
  std::string label;
  std::string csv;                // run CSV, relative to the output folder
  std::string experimental_csv;   // absolute path, "" when absent
  IndependentValues independent;  // drawn as markers where given
};

// Writes <out_dir>/<series.id>.gp; returns its file name.
std::string write_plot_script(const std::string& out_dir, const SeriesSpec& series,
                              const std::vector<PlotCase>& cases);

// True when a gnuplot executable is on the PATH.
// s as a gnuplot string literal: in double quotes, with " and \\ escaped.
std::string quoted(const std::string& s);

bool gnuplot_available();

// Runs gnuplot on the script inside out_dir; returns false (and the error
// text in `message`) when gnuplot fails.
bool run_gnuplot(const std::string& out_dir, const std::string& script, std::string& message);

}  // namespace mortar::harness
