// Windows: Abaqus's exit utilities for the DLLs. A Windows DLL must resolve
// every symbol when it is linked, and Abaqus's library that exports
// xplb_exit_ / xit_ is not at hand then: the adapters' calls land here, and
// the utility (XPLB_EXIT, XIT, as Intel Fortran names it on Windows) is
// looked up among the process's modules when first needed, only on an error
// that stops the analysis; without it, one more line and abort().
// The rest: docs/adapters.md, section 11.
#include <windows.h>
// psapi.h after windows.h; version 2: the function is kernel32's.
#define PSAPI_VERSION 2
#include <psapi.h>

#include <cstdio>
#include <cstdlib>

namespace {

using ExitUtility = void (*)();

ExitUtility find_in_process(const char* name) {
  HMODULE modules[1024];
  DWORD bytes = 0;
  if (!K32EnumProcessModules(GetCurrentProcess(), modules, sizeof modules, &bytes)) return nullptr;
  const DWORD count = bytes / sizeof(HMODULE) < 1024 ? bytes / sizeof(HMODULE) : 1024;
  for (DWORD i = 0; i < count; ++i) {
    if (FARPROC p = GetProcAddress(modules[i], name)) return reinterpret_cast<ExitUtility>(reinterpret_cast<void*>(p));
  }
  return nullptr;
}

void call_exit_utility(const char* name) {
  if (ExitUtility utility = find_in_process(name)) {
    utility();
    return;
  }
  std::fprintf(stderr, "%s: no module of this process exports it; stopping the process with abort()\n", name);
  std::fflush(stderr);
  std::abort();
}

}  // namespace

extern "C" void xplb_exit_() { call_exit_utility("XPLB_EXIT"); }
extern "C" void xit_() { call_exit_utility("XIT"); }
