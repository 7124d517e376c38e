// Terminal text within 100 columns: prose wrapped at spaces, wide markdown
// tables redrawn with every cell's words kept.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "output/terminal_text.hpp"

using namespace mortar::harness;

namespace {
size_t widest_line(const std::string& text) {
  std::istringstream in(text);
  size_t widest = 0;
  for (std::string l; std::getline(in, l);) widest = std::max(widest, display_width(l));
  return widest;
}
std::string words(const std::string& text) {
  std::istringstream in(text);
  std::string all;
  for (std::string w; in >> w;)
    if (w.find_first_not_of("|-") != std::string::npos) all += w + " ";
  return all;
}
}  // namespace

TEST_CASE("fit_to_width: a short text is left as it is", "[output]") {
  const std::string text = "# Title\n\n| a | b |\n|---|---|\n| 1 | 2 |\n";
  CHECK(fit_to_width(text) == text);
  CHECK(terminal_text(text, true) == text);
}

TEST_CASE("fit_to_width: prose and a wide table within 100 columns, no word lost", "[output]") {
  std::string prose = "- ";
  for (int i = 0; i < 40; ++i) prose += "word" + std::to_string(i) + " σn ";
  std::string table = "| parameter | how |\n|---|---|\n| kn | ";
  for (int i = 0; i < 30; ++i) table += "least squares ";
  table += "|\n";
  const std::string narrow = fit_to_width(prose + "\n\n" + table);
  CHECK(widest_line(narrow) <= 100);
  CHECK(narrow.find("\n  word") != std::string::npos);  // a bullet's lines are indented
  CHECK(words(narrow) == words(prose + "\n\n" + table));
}

TEST_CASE("fit_to_width: a long path stays whole on its own line", "[output]") {
  const std::string path(120, 'p');
  const std::string narrow = fit_to_width("bench: wrote " + path + "/bench.csv\n");
  CHECK(narrow == "bench: wrote\n" + path + "/bench.csv\n");
}
