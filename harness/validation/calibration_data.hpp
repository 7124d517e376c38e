// The calibration_data/ folder: one sub-folder per test series, each with a
// series.toml that lists its cases (parameter file, loading program, label,
// and optional numbers of an independent implementation to print beside the
// project's), reference/<case>.csv (the project's own regression baselines)
// and optionally experimental/<case>.csv (digitised test curves). The format
// is documented in calibration_data/README.md.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

enum class SeriesKind { monotonic_shear, cyclic_shear, tension };
const char* series_kind_name(SeriesKind k);

// Values an independent implementation reported for a case (docs/model.md 8),
// printed as comparison rows, never checked.
struct IndependentValues {
  double peak = 0;       // [MPa], 0 when not given
  double peak_slip = 0;  // [mm]
  double uplift_min = 0, uplift_max = 0;  // normal uplift range [mm]
  std::vector<std::pair<double, double>> tau_at;  // (slip [mm], tau [MPa])
};

struct CaseSpec {
  std::string name;   // also the file stem of its reference and experimental curves
  std::string label;  // legend text
  std::string params_file, protocol_file;  // absolute or relative to the working directory
  std::string reference_file, experimental_file;  // conventional locations (may not exist)
  IndependentValues independent;
};

struct SeriesSpec {
  std::string id;   // folder name
  std::string dir;  // folder path
  std::string title;
  SeriesKind kind = SeriesKind::monotonic_shear;
  Scheme scheme = Scheme::modified_euler;
  double stol = 0;
  std::vector<CaseSpec> cases;
};

// Every series of `data_dir` (sub-folders holding a series.toml, in name
// order), or only those named in `only` (InputError for an unknown name).
std::vector<SeriesSpec> read_calibration_data(const std::string& data_dir, const std::vector<std::string>& only);

}  // namespace mortar::harness
