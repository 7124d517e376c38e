// Where the commands write: checked before anything runs, so that bad input
// is named (exit 2) before minutes of work, and a file that cannot be
// opened says why.
#pragma once

#include <string>

namespace mortar::harness {

// The folder `dir` given as `option` (e.g. "--out"): created if missing;
// an InputError (naming the option, the path and the reason) when it is a
// file, cannot be created or does not take a new file.
void prepare_output_folder(const std::string& dir, const std::string& option);

// A file `path` given as `option` that the command will write: its folder
// must exist and take a new file, and the path must not be a folder.
void check_output_file(const std::string& path, const std::string& option);

// "<path>: cannot be written: <reason>", the reason from errno or from
// what the path's folder is (missing, a file).
std::string cannot_write(const std::string& path);

}  // namespace mortar::harness
