// Compares two record files of the Fortran callers value by value (the
// Windows build's, written under Wine, against this build's):
//   records_compare WINDOWS_FILE LINUX_FILE RTOL ATOL
// Line ends CR LF read as LF. Words that are not numbers must be equal;
// numbers must be equal or within |a - b| <= RTOL max(|a|, |b|) + ATOL
// (RTOL = ATOL = 0: identical). Prints the lines, the values, how many differ
// and the largest relative difference; exit code 1 on any failure.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> read_lines(const char* path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

bool as_number(const std::string& word, double& x) {
  char* end = nullptr;
  x = std::strtod(word.c_str(), &end);
  return end && *end == '\0' && end != word.c_str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: records_compare WINDOWS_FILE LINUX_FILE RTOL ATOL\n");
    return 2;
  }
  const std::vector<std::string> w = read_lines(argv[1]), l = read_lines(argv[2]);
  const double rtol = std::atof(argv[3]), atol = std::atof(argv[4]);
  if (w.empty() || w.size() != l.size()) {
    std::printf("%s: %zu lines, %s: %zu lines\n", argv[1], w.size(), argv[2], l.size());
    return 1;
  }
  long values = 0, differ = 0, beyond = 0;
  double worst = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    std::istringstream a(w[i]), b(l[i]);
    std::string x, y;
    while (true) {
      const bool more_a = static_cast<bool>(a >> x), more_b = static_cast<bool>(b >> y);
      if (more_a != more_b) {
        std::printf("line %zu: different number of words\n", i + 1);
        return 1;
      }
      if (!more_a) break;
      ++values;
      if (x == y) continue;
      ++differ;
      double u, v;
      if (!as_number(x, u) || !as_number(y, v)) {
        std::printf("line %zu: '%s' against '%s'\n", i + 1, x.c_str(), y.c_str());
        return 1;
      }
      const double scale = std::max(std::abs(u), std::abs(v));
      worst = std::max(worst, std::abs(u - v) / scale);
      if (!(std::abs(u - v) <= rtol * scale + atol) && ++beyond <= 5)
        std::printf("line %zu: %s against %s\n", i + 1, x.c_str(), y.c_str());
    }
  }
  std::printf("%zu lines, %ld values, %ld differ (largest relative difference %.3g), %ld beyond rtol %g, atol %g\n",
              w.size(), values, differ, worst, beyond, rtol, atol);
  return beyond == 0 ? 0 : 1;
}
