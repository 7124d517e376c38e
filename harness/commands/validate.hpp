// `masonry-joint validate`: runs every case of calibration_data/, checks it,
// compares it with its regression baseline and any experimental curve,
// prints the table, writes the CSVs and the charts.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace mortar::harness {

struct ValidateOptions {
  std::string data_dir;                // calibration_data/
  std::string out_dir = "validation";  // CSVs, charts, the table as text
  std::vector<std::string> series;     // only these series (folder names); all when empty
  double traction_tolerance = 1e-9;    // MPa, of the mixed control
  bool quiet = false;
  bool wide = false;  // the table as validation.txt has it, not fitted to 100 columns
  bool plots = true;
  bool write_references = false;  // store fresh curves as baselines (only where every check passes)
};

// Returns the exit status: 0 when every check passed, 1 otherwise.
// InputError for unreadable data.
int run_validation(const ValidateOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mortar::harness
