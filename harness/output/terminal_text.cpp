#include "output/terminal_text.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace mortar::harness {

namespace {

using Lines = std::vector<std::string>;

std::vector<std::string> words_of(const std::string& s) {
  std::vector<std::string> words;
  std::istringstream in(s);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// Greedy wrap at spaces; a word longer than `width` stays whole.
Lines wrap(const std::string& s, size_t width, const std::string& indent = "") {
  Lines out;
  std::string line;
  for (const std::string& w : words_of(s)) {
    const std::string lead = out.empty() ? "" : indent;
    if (!line.empty() && display_width(lead + line) + 1 + display_width(w) > width) {
      out.push_back(lead + line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + w;
  }
  if (!line.empty() || out.empty()) out.push_back((out.empty() ? "" : indent) + line);
  return out;
}

// Cuts a word longer than the column into pieces of `width` code points.
Lines wrap_cell(const std::string& s, size_t width) {
  Lines out;
  for (const std::string& l : wrap(s, width)) {
    std::string piece;
    for (size_t i = 0; i < l.size(); ++i) {
      const bool starts_point = (static_cast<unsigned char>(l[i]) & 0xC0) != 0x80;
      if (starts_point && display_width(piece) == width) out.push_back(piece), piece.clear();
      piece += l[i];
    }
    out.push_back(piece);
  }
  return out;
}

bool is_table_line(const std::string& l) { return l.size() >= 2 && l.front() == '|' && l.back() == '|'; }

bool is_rule(const std::string& l) { return l.find_first_not_of("|-: ") == std::string::npos; }

// "| a | b |" -> {a, b}; cells are separated by " | " (a '|' inside a cell,
// as in tan(phir)|sigma_n|, has no spaces around it).
std::vector<std::string> cells_of(const std::string& l) {
  std::vector<std::string> cells;
  const std::string inner = l.substr(1, l.size() - 2);
  size_t start = 0;
  for (size_t at; (at = inner.find(" | ", start)) != std::string::npos; start = at + 3)
    cells.push_back(inner.substr(start, at - start));
  cells.push_back(inner.substr(start));
  for (std::string& c : cells) {
    const size_t a = c.find_first_not_of(' '), b = c.find_last_not_of(' ');
    c = a == std::string::npos ? "" : c.substr(a, b - a + 1);
  }
  return cells;
}

std::string pad(const std::string& s, size_t width) {
  return s + std::string(width - std::min(width, display_width(s)), ' ');
}

// A table as rows of wrapped cells: the widest column gives way first.
void redraw_table(const Lines& table, size_t width, Lines& out) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& l : table)
    if (!is_rule(l)) rows.push_back(cells_of(l));
  size_t columns = 0;
  for (const auto& r : rows) columns = std::max(columns, r.size());
  for (auto& r : rows) r.resize(columns);
  std::vector<size_t> w(columns, 1);
  for (const auto& r : rows)
    for (size_t j = 0; j < columns; ++j) w[j] = std::max(w[j], display_width(r[j]));
  // With "| a | b |" borders while the words fit so, else plain columns.
  std::vector<size_t> word(columns, 1);
  for (const auto& r : rows)
    for (size_t j = 0; j < columns; ++j)
      for (const std::string& x : words_of(r[j])) word[j] = std::max(word[j], display_width(x));
  size_t floors = 1;
  for (size_t j = 0; j < columns; ++j) floors += std::max<size_t>(word[j], std::min<size_t>(w[j], 8)) + 3;
  const bool borders = floors <= width;
  const std::string left = borders ? "| " : "", gap = borders ? " | " : "  ", right = borders ? " |" : "";
  auto total = [&] {
    size_t t = left.size() + right.size() + gap.size() * (columns - 1);
    for (size_t x : w) t += x;
    return t;
  };
  // A column gives way down to its longest word, then down to 8.
  for (size_t floor_pass = 0; floor_pass < 2 && total() > width; ++floor_pass)
    while (total() > width) {
      size_t widest = columns;
      for (size_t j = 0; j < columns; ++j)
        if (w[j] > (floor_pass == 0 ? std::max<size_t>(word[j], 8) : 8) && (widest == columns || w[j] > w[widest]))
          widest = j;
      if (widest == columns) break;
      --w[widest];
    }
  std::string rule = borders ? "|" : "";
  for (size_t j = 0; j < columns; ++j)
    rule += borders ? std::string(w[j] + 2, '-') + "|" : std::string(w[j], '-') + (j + 1 < columns ? "  " : "");
  bool wrapped = false;
  std::vector<std::vector<Lines>> cells(rows.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < columns; ++j) {
      cells[i].push_back(wrap_cell(rows[i][j], w[j]));
      wrapped = wrapped || cells[i].back().size() > 1;
    }
  for (size_t i = 0; i < rows.size(); ++i) {
    size_t height = 1;
    for (const Lines& c : cells[i]) height = std::max(height, c.size());
    for (size_t k = 0; k < height; ++k) {
      std::string l = left;
      for (size_t j = 0; j < columns; ++j)
        l += pad(k < cells[i][j].size() ? cells[i][j][k] : "", w[j]) + (j + 1 < columns ? gap : right);
      out.push_back(borders ? l : l.substr(0, l.find_last_not_of(' ') + 1));
    }
    if (i == 0 || (wrapped && i + 1 < rows.size())) out.push_back(rule);
  }
}

}  // namespace

size_t display_width(const std::string& line) {
  return static_cast<size_t>(std::count_if(line.begin(), line.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

std::string fit_to_width(const std::string& text, size_t width) {
  Lines lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  Lines out;
  for (size_t i = 0; i < lines.size();) {
    if (is_table_line(lines[i])) {
      Lines table;
      while (i < lines.size() && is_table_line(lines[i])) table.push_back(lines[i++]);
      size_t widest = 0;
      for (const std::string& l : table) widest = std::max(widest, display_width(l));
      if (widest <= width)
        out.insert(out.end(), table.begin(), table.end());
      else
        redraw_table(table, width, out);
      continue;
    }
    const std::string& l = lines[i++];
    if (display_width(l) <= width) {
      out.push_back(l);
      continue;
    }
    const size_t lead = std::min(l.find_first_not_of(' '), l.size());
    const bool bullet = l.compare(lead, 2, "- ") == 0;
    const std::string indent(lead + (bullet ? 2 : 0), ' ');
    const Lines pieces = wrap(l, width - std::min(width / 2, lead), indent);
    for (size_t k = 0; k < pieces.size(); ++k) out.push_back(k == 0 ? std::string(lead, ' ') + pieces[k] : pieces[k]);
  }
  std::string result;
  for (const std::string& l : out) result += l + "\n";
  if (!text.empty() && text.back() != '\n' && !result.empty()) result.pop_back();
  return result;
}

std::string terminal_text(const std::string& text, bool wide) { return wide ? text : fit_to_width(text); }

}  // namespace mortar::harness
