// The adapters' one-line reports on stderr: routine, interaction, then what
// broke which rule (docs/robustness.md lists the messages). Each message is
// one write, so that threads calling on disjoint blocks do not interleave
// within a line.
#pragma once

#include <cstdio>

#include "mortar/parameters.hpp"

namespace mj_adapter {

// Who is calling, for messages.
struct Caller {
  const char* routine;  // "VUINTERACTION", "VUINTER" or "UINTER"
  const char* name;     // the interaction's name, not NUL-terminated
  int name_length;      // trailing blanks removed
};

// A CHARACTER*80 name as Fortran passes it: blank padded, its hidden length
// appended to the argument list (80 if the caller passes nonsense).
inline Caller make_caller(const char* routine, const char* surf_int, int hidden_length) {
  int n = (hidden_length > 0 && hidden_length <= 80) ? hidden_length : 80;
  if (!surf_int) return {routine, "?", 1};
  while (n > 0 && (surf_int[n - 1] == ' ' || surf_int[n - 1] == '\0')) --n;
  return {routine, surf_int, n};
}

inline void report(const Caller& c, const char* what) {
  char line[640];
  std::snprintf(line, sizeof line, "%s, interaction '%.*s': %s\n", c.routine, c.name_length, c.name, what);
  std::fputs(line, stderr);
}

// The first argument of a call that breaks a rule.
struct ArgumentError {
  int code = 0;  // 0: none, else an AdapterCode
  const char* argument = "";
  long value = 0;
  const char* rule = "";
};

inline void report_argument(const Caller& c, const ArgumentError& e) {
  char what[400];
  std::snprintf(what, sizeof what, "argument %s = %ld violates the rule: %s", e.argument, e.value, e.rule);
  report(c, what);
}

inline void report_property(const Caller& c, const mortar::ValidationError& e) {
  char what[480];
  std::snprintf(what, sizeof what, "property '%s' (props(%d)) = %.9g violates the rule: %s", e.name, e.index + 1,
                e.value, e.rule);
  report(c, what);
}

}  // namespace mj_adapter
