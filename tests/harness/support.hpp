// Helpers shared by the harness tests: input files, temporary folders, runs
// recorded per point.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "input/parameter_file.hpp"
#include "input/protocol.hpp"
#include "solvers/explicit_run.hpp"

namespace mortar::harness::testing {

inline std::string data_file(const std::string& name) { return std::string(MJ_TEST_DATA_DIR) + "/" + name; }

// The folders fresh_directory made, removed when the test process ends.
struct TemporaryFolders {
  std::vector<std::filesystem::path> made;
  ~TemporaryFolders() {
    std::error_code ignored;
    for (const auto& dir : made) std::filesystem::remove_all(dir, ignored);
  }
};
inline TemporaryFolders& temporary_folders() {
  static TemporaryFolders folders;
  return folders;
}

// A fresh, empty folder under the system's temporary directory, of this
// process alone (test runs of several builds may share the machine).
inline std::filesystem::path fresh_directory(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("mj_harness_test_" + name + "_" + std::to_string(::getpid()));
  temporary_folders().made.push_back(dir);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

// The samples of every point, indexed [point][increment].
inline std::vector<std::vector<Sample>> run_all_points(const Parameters& p, const Protocol& protocol,
                                                       const RunSettings& settings) {
  std::vector<std::vector<Sample>> curves(static_cast<size_t>(settings.points));
  run_protocol(p, protocol, settings, [&](int point, const Sample& s) { curves[point].push_back(s); });
  return curves;
}

inline std::vector<Sample> run_one_point(const Parameters& p, const Protocol& protocol, RunSettings settings) {
  settings.points = 1;
  return run_all_points(p, protocol, settings).front();
}

}  // namespace mortar::harness::testing
