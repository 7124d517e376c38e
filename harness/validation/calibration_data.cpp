#include "validation/calibration_data.hpp"

#include <algorithm>
#include <filesystem>

#include "input/toml_input.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

const char* series_kind_name(SeriesKind k) {
  switch (k) {
    case SeriesKind::monotonic_shear: return "monotonic_shear";
    case SeriesKind::cyclic_shear: return "cyclic_shear";
    case SeriesKind::tension: return "tension";
  }
  return "unknown";
}

namespace {

IndependentValues read_independent(const std::string& file, const toml::value& v) {
  reject_unknown_keys(file, v, {"peak", "peak_slip", "uplift_range", "tau_at"}, "an [case.independent] table");
  IndependentValues iv;
  const auto& t = v.as_table();
  if (t.count("peak")) iv.peak = read_number(file, t.at("peak"), "independent peak");
  if (t.count("peak_slip")) iv.peak_slip = read_number(file, t.at("peak_slip"), "independent peak_slip");
  if (t.count("uplift_range")) {
    const toml::value& r = t.at("uplift_range");
    if (!r.is_array() || r.as_array().size() != 2)
      throw InputError(position_of(file, r) + ": uplift_range must be [min, max] in mm");
    iv.uplift_min = read_number(file, r.as_array()[0], "uplift_range min");
    iv.uplift_max = read_number(file, r.as_array()[1], "uplift_range max");
  }
  if (t.count("tau_at")) {
    const toml::value& a = t.at("tau_at");
    if (!a.is_array()) throw InputError(position_of(file, a) + ": tau_at must be an array of [slip, tau] pairs");
    for (const toml::value& pair : a.as_array()) {
      if (!pair.is_array() || pair.as_array().size() != 2)
        throw InputError(position_of(file, pair) + ": each tau_at entry is [slip in mm, tau in MPa]");
      iv.tau_at.emplace_back(read_number(file, pair.as_array()[0], "tau_at slip"),
                             read_number(file, pair.as_array()[1], "tau_at tau"));
    }
  }
  return iv;
}

CaseSpec read_case(const std::string& file, const fs::path& dir, const toml::value& v, int index) {
  const std::string where = "case " + std::to_string(index);
  if (!v.is_table()) throw InputError(position_of(file, v) + ": " + where + " must be a table");
  reject_unknown_keys(file, v, {"name", "label", "params", "protocol", "independent"}, where);
  const auto& t = v.as_table();
  for (const char* key : {"name", "params", "protocol"})
    if (!t.count(key)) throw InputError(position_of(file, v) + ": " + where + " needs '" + key + "'");
  CaseSpec c;
  c.name = read_string(file, t.at("name"), where + " name");
  if (c.name.empty() || c.name.find_first_of("/\\ \"'") != std::string::npos)
    throw InputError(position_of(file, t.at("name")) + ": case name '" + c.name +
                     "' must be non-empty, without spaces, quotes or slashes (it names files)");
  c.label = t.count("label") ? read_string(file, t.at("label"), where + " label") : c.name;
  c.params_file = (dir / read_string(file, t.at("params"), where + " params")).string();
  c.protocol_file = (dir / read_string(file, t.at("protocol"), where + " protocol")).string();
  c.reference_file = (dir / "reference" / (c.name + ".csv")).string();
  c.experimental_file = (dir / "experimental" / (c.name + ".csv")).string();
  if (t.count("independent")) c.independent = read_independent(file, t.at("independent"));
  return c;
}

SeriesSpec read_series(const fs::path& dir) {
  const std::string file = (dir / "series.toml").string();
  const toml::value root = parse_toml_file(file);
  reject_unknown_keys(file, root, {"title", "kind", "scheme", "stol", "case"}, "a series file");
  SeriesSpec s;
  s.id = dir.filename().string();
  s.dir = dir.string();
  s.title = root.contains("title") ? read_string(file, root.at("title"), "title") : s.id;
  if (!root.contains("kind")) throw InputError(file + ": needs 'kind' (monotonic_shear, cyclic_shear or tension)");
  const std::string kind = read_string(file, root.at("kind"), "kind");
  if (kind == "monotonic_shear") s.kind = SeriesKind::monotonic_shear;
  else if (kind == "cyclic_shear") s.kind = SeriesKind::cyclic_shear;
  else if (kind == "tension") s.kind = SeriesKind::tension;
  else
    throw InputError(position_of(file, root.at("kind")) + ": kind \"" + kind +
                     "\" is not one of monotonic_shear, cyclic_shear, tension");
  if (root.contains("scheme")) {
    const std::string scheme = read_string(file, root.at("scheme"), "scheme");
    if (scheme == "modified-euler") s.scheme = Scheme::modified_euler;
    else if (scheme == "forward-euler") s.scheme = Scheme::forward_euler;
    else
      throw InputError(position_of(file, root.at("scheme")) + ": scheme \"" + scheme +
                       "\" is not modified-euler or forward-euler");
  }
  if (root.contains("stol")) {
    s.stol = read_number(file, root.at("stol"), "stol");
    if (!(s.stol > 0 && s.stol < 1))
      throw InputError(position_of(file, root.at("stol")) + ": stol must lie in (0, 1)");
  }
  if (!root.contains("case") || !root.at("case").is_array() || root.at("case").as_array().empty())
    throw InputError(file + ": a series needs at least one [[case]]");
  int index = 0;
  for (const toml::value& c : root.at("case").as_array()) s.cases.push_back(read_case(file, dir, c, ++index));
  return s;
}

}  // namespace

std::vector<SeriesSpec> read_calibration_data(const std::string& data_dir, const std::vector<std::string>& only) {
  std::error_code ec;
  if (!fs::is_directory(data_dir, ec))
    throw InputError(data_dir + ": not a directory (the calibration data folder; see --data)");
  std::vector<fs::path> dirs;
  for (const auto& entry : fs::directory_iterator(data_dir))
    if (entry.is_directory() && fs::exists(entry.path() / "series.toml")) dirs.push_back(entry.path());
  std::sort(dirs.begin(), dirs.end());
  std::vector<SeriesSpec> out;
  for (const fs::path& d : dirs)
    if (only.empty() || std::find(only.begin(), only.end(), d.filename().string()) != only.end())
      out.push_back(read_series(d));
  for (const std::string& name : only) {
    const bool found = std::any_of(out.begin(), out.end(), [&](const SeriesSpec& s) { return s.id == name; });
    if (!found) {
      std::string known;
      for (const fs::path& d : dirs) known += (known.empty() ? "" : ", ") + d.filename().string();
      throw InputError(data_dir + ": no series '" + name + "' (series found: " + known + ")");
    }
  }
  if (out.empty()) throw InputError(data_dir + ": no series found (sub-folders with a series.toml)");
  return out;
}

}  // namespace mortar::harness
