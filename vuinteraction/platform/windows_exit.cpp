// Windows: Abaqus's exit utilities for the DLLs (explicitU.dll,
// explicitU-D.dll, standardU.dll). On Linux the library leaves xplb_exit_ and
// xit_ undefined and the loader binds them to Abaqus's; a Windows DLL must
// resolve every symbol when it is linked, and the library of Abaqus that
// exports them is not at hand when this one is built. So the adapters' calls
// of xplb_exit_ / xit_ land here, and the utility is looked up, under the name
// Intel Fortran gives it on Windows (XPLB_EXIT, XIT: upper case, no
// underscore), among the modules loaded in the process when it is first
// needed: that is, only on an error that stops the analysis. Should no module
// export it, the message already written is followed by one more line, and
// the process is stopped with abort().
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
