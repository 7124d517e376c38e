#include "output/output_paths.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "input/input_error.hpp"

namespace mortar::harness {

namespace fs = std::filesystem;

namespace {

// Why a file cannot be created in `folder`, or "" when a probe file can.
std::string probe_folder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) return "the folder " + folder.string() + " does not exist";
  if (!fs::is_directory(folder, ec)) return folder.string() + " is a file, not a folder";
  const fs::path probe = folder / ".masonry-joint-write-probe";
  errno = 0;
  {
    std::ofstream f(probe);
    if (!f) return "the folder " + folder.string() + " does not take a new file (" + std::strerror(errno) + ")";
  }
  fs::remove(probe, ec);
  return "";
}

fs::path folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

}  // namespace

void prepare_output_folder(const std::string& dir, const std::string& option) {
  if (dir.empty()) throw InputError(option + " '': an output folder is needed");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(option + " " + dir + ": is a file; an output folder is needed");
  fs::create_directories(dir, ec);
  if (ec) throw InputError(option + " " + dir + ": the folder cannot be created (" + ec.message() + ")");
  if (const std::string why = probe_folder(dir); !why.empty()) throw InputError(option + " " + dir + ": " + why);
}

void check_output_file(const std::string& path, const std::string& option) {
  std::error_code ec;
  if (path.empty()) throw InputError(option + " '': an output file is needed");
  if (fs::is_directory(path, ec)) throw InputError(option + " " + path + ": is a folder; an output file is needed");
  if (const std::string why = probe_folder(folder_of(path)); !why.empty())
    throw InputError(option + " " + path + ": cannot be written: " + why);
}

std::string cannot_write(const std::string& path) {
  const int err = errno;
  std::error_code ec;
  if (fs::is_directory(path, ec)) return path + ": cannot be written: it is a folder";
  const std::string why = probe_folder(folder_of(path));
  return path + ": cannot be written: " + (why.empty() ? std::string(std::strerror(err)) : why);
}

}  // namespace mortar::harness
