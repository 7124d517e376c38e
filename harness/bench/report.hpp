// The bench's files: bench.csv and reference.csv (one row per run and per
// reference), stability.md (the stability map as a list), summary.md (the
// command's summary). Formats in harness/README.md.
#pragma once

#include <string>

#include "bench/bench.hpp"

namespace mortar::harness {

void write_rows_csv(const std::string& file, const BenchResult& r);
void write_references_csv(const std::string& file, const BenchResult& r);
void write_text(const std::string& file, const std::string& text);

// How far the references moved when tightened, over every path and size.
struct ReferenceSpread {
  double traction = 0, energy = 0;
};
ReferenceSpread reference_spread(const BenchResult& r);

std::string stability_list(const BenchResult& r);
// The summary the command prints and writes: totals, the reference's spread,
// each scheme's cost to reach kTargetError on vdp_sn0.5, and the tables.
std::string bench_summary(const BenchResult& r);

}  // namespace mortar::harness
