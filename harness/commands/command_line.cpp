#include "commands/command_line.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#ifndef MJ_VERSION
#define MJ_VERSION "unknown"
#endif
#ifndef MJ_GIT_DESCRIBE
#define MJ_GIT_DESCRIBE ""
#endif

namespace mortar::harness {

namespace {
// Levenshtein distance, small strings.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

std::string unknown_subcommand(int argc, char** argv, const std::vector<std::string>& names) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string given = argv[1];
  if (std::find(names.begin(), names.end(), given) != names.end()) return "";
  std::string nearest;
  size_t best = 3;  // at most two edits
  for (const std::string& n : names) {
    const size_t d = edit_distance(given, n);
    if (d < best) best = d, nearest = n;
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return "unknown subcommand '" + given + "'" + (nearest.empty() ? "" : " (did you mean " + nearest + "?)") +
         "; the subcommands are: " + list + " (masonry-joint --help)";
}

std::string default_data_dir(const std::string& built_from) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "masonry-joint" / "calibration_data";
    if (fs::is_directory(installed, ec)) return installed.string();
  }
  return built_from;
}

std::string version_text() {
  const std::string git = MJ_GIT_DESCRIBE;
  return std::string("masonry-joint ") + MJ_VERSION + (git.empty() ? "" : " (git " + git + ")");
}

}  // namespace mortar::harness
