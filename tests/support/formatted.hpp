// printf's formatting into a string, for a test's INFO: what a check
// measured is shown when the check fails, not printed on every run
// (measurements belong in the bench).
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace mj_test {

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
inline std::string formatted(const char* format, ...) {
  std::va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  std::string text(n > 0 ? size_t(n) : 0, '\0');
  if (n > 0) std::vsnprintf(&text[0], text.size() + 1, format, again);
  va_end(again);
  va_end(args);
  return text;
}

}  // namespace mj_test
