// What main() checks before CLI11 parses: a mistyped subcommand, and where
// the calibration data are when --data is not given (next to an installed
// executable, else the source folder it was built from); the version.
#pragma once

#include <string>
#include <vector>

namespace mortar::harness {

// "" when argv[1] is an option or one of `names`; otherwise the message
// "unknown subcommand 'valdate' (did you mean validate?); the subcommands
// are: ..." (the suggestion only when one name is within two edits).
std::string unknown_subcommand(int argc, char** argv, const std::vector<std::string>& names);

// The default of --data: <prefix>/share/masonry-joint/calibration_data when
// the executable runs from <prefix>/bin (cmake --install), else `built_from`
// (the source folder of the build).
std::string default_data_dir(const std::string& built_from);

// "masonry-joint 0.1.0 (git 07a71b7)" from the project version and, when the
// configure step found one, `git describe`.
std::string version_text();

}  // namespace mortar::harness
