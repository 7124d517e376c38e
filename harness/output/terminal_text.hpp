// Terminal output within a width: markdown (the bench summary, the
// calibration report) with its prose wrapped at spaces and its tables
// too wide for the width redrawn with their cells wrapped; the files keep
// the full form (--wide prints that form).
#pragma once

#include <cstddef>
#include <string>

namespace mortar::harness {

constexpr size_t kTerminalColumns = 100;

// Columns a line takes: UTF-8 code points.
size_t display_width(const std::string& line);

// Every line of `text` within `width` columns, words longer than that
// excepted (a path is put on its own line, not cut).
std::string fit_to_width(const std::string& text, size_t width = kTerminalColumns);

// `text` as it is when `wide`, else fit_to_width(text).
std::string terminal_text(const std::string& text, bool wide);

}  // namespace mortar::harness
