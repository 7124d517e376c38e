// A reader for the subset of Abaqus input the harness writes (*NODE,
// *ELEMENT, *NSET/*ELSET, *SURFACE TYPE=ELEMENT, *SURFACE INTERACTION with
// its props, *AMPLITUDE, *BOUNDARY, *CLOAD, *STATIC, *RIGID BODY), written
// for the tests from the Keywords Reference's rules, not from the writer:
// keywords and parameters case-insensitive, "**" comments, data lines of
// comma-separated fields. Test code only.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace mortar::harness::test {

struct InpCard {
  std::string keyword;                       // upper case, e.g. "SURFACE INTERACTION"
  std::map<std::string, std::string> param;  // upper-case name -> value as written ("" for a flag)
  std::vector<std::vector<std::string>> data;
  int step = 0;                              // 0 in the model data, k inside the k-th *STEP
  bool has(const std::string& p) const { return param.count(p) > 0; }
  std::string at(const std::string& p) const { return param.count(p) ? param.at(p) : std::string(); }
};

inline std::string inp_trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

inline std::string inp_upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

inline std::vector<std::string> inp_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(inp_trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  if (out.empty()) out.push_back("");  // a blank data line is one empty field
  return out;
}

inline double inp_number(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

inline std::vector<InpCard> read_inp(const std::string& text) {
  std::vector<InpCard> cards;
  std::istringstream in(text);
  std::string line;
  int step = 0;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0) continue;
    if (!line.empty() && line[0] == '*') {
      std::vector<std::string> f = inp_fields(line.substr(1));
      InpCard c;
      c.keyword = inp_upper(f[0]);
      for (size_t i = 1; i < f.size(); ++i) {
        const size_t eq = f[i].find('=');
        c.param[inp_upper(inp_trim(f[i].substr(0, eq)))] = eq == std::string::npos ? "" : inp_trim(f[i].substr(eq + 1));
      }
      if (c.keyword == "STEP") ++step;
      c.step = c.keyword == "END STEP" ? 0 : step;
      cards.push_back(c);
      continue;
    }
    if (!cards.empty()) cards.back().data.push_back(inp_fields(line));
  }
  return cards;
}

// The model's geometry and sets, gathered from the cards.
struct InpModel {
  std::map<int, std::array<double, 3>> nodes;
  std::map<int, std::vector<int>> elements;           // element -> its nodes
  std::map<std::string, std::vector<int>> elsets, nsets;
  std::map<std::string, std::vector<std::pair<int, int>>> surfaces;  // (element, face 1..6)
  std::vector<InpCard> cards;

  explicit InpModel(const std::string& text) : cards(read_inp(text)) {
    for (const InpCard& c : cards) {
      if (c.keyword == "NODE")
        for (const auto& d : c.data) nodes[std::atoi(d[0].c_str())] = {inp_number(d[1]), inp_number(d[2]), inp_number(d[3])};
      if (c.keyword == "ELEMENT")
        for (const auto& d : c.data) {
          const int e = std::atoi(d[0].c_str());
          for (size_t i = 1; i < d.size(); ++i) elements[e].push_back(std::atoi(d[i].c_str()));
          if (c.has("ELSET")) elsets[inp_upper(c.at("ELSET"))].push_back(e);
        }
      if (c.keyword == "NSET" || c.keyword == "ELSET") {
        auto& set = (c.keyword == "NSET" ? nsets[inp_upper(c.at("NSET"))] : elsets[inp_upper(c.at("ELSET"))]);
        for (const auto& d : c.data)
          for (const auto& f : d)
            if (!f.empty()) set.push_back(std::atoi(f.c_str()));
      }
      if (c.keyword == "SURFACE" && inp_upper(c.at("TYPE")) == "ELEMENT")
        for (const auto& d : c.data) surfaces[inp_upper(c.at("NAME"))].push_back({std::atoi(d[0].c_str()), std::atoi(d[1].c_str() + 1)});
    }
  }

  std::vector<const InpCard*> all(const std::string& keyword) const {
    std::vector<const InpCard*> out;
    for (const InpCard& c : cards)
      if (c.keyword == keyword) out.push_back(&c);
    return out;
  }

  // The nodes of one face of a C3D8/C3D8R element (the element library's
  // face numbering).
  std::vector<std::array<double, 3>> face_nodes(int element, int face) const {
    static const int kFaces[6][4] = {{1, 2, 3, 4}, {5, 8, 7, 6}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}};
    std::vector<std::array<double, 3>> out;
    for (int local : kFaces[face - 1]) out.push_back(nodes.at(elements.at(element)[static_cast<size_t>(local - 1)]));
    return out;
  }

  // Bounding box (lo, hi) of the nodes of an element set.
  std::array<std::array<double, 3>, 2> box_of(const std::string& elset) const {
    std::array<std::array<double, 3>, 2> b{{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}};
    for (int e : elsets.at(elset))
      for (int n : elements.at(e))
        for (int d = 0; d < 3; ++d) b[0][d] = std::min(b[0][d], nodes.at(n)[d]), b[1][d] = std::max(b[1][d], nodes.at(n)[d]);
    return b;
  }

  // The props of a *SURFACE INTERACTION: its data lines after the blank
  // first line Abaqus/Standard's USER interactions have.
  std::vector<double> props(const InpCard& c) const {
    std::vector<double> out;
    for (size_t i = 0; i < c.data.size(); ++i) {
      if (i == 0 && c.has("USER") && c.at("USER").empty()) continue;  // the thickness/area line
      for (const auto& f : c.data[i]) out.push_back(inp_number(f));
    }
    return out;
  }
};

}  // namespace mortar::harness::test
