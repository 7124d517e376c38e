// Abaqus's exit utilities as the test programs export them, under their
// Windows names, for the DLLs to find in the process: each says that it was
// called and ends the program with code 3.
#include <cstdio>
#include <cstdlib>

extern "C" __declspec(dllexport) void XPLB_EXIT() {
  std::fflush(stderr);
  std::puts("XPLB_EXIT called");
  std::fflush(stdout);
  std::exit(3);
}

extern "C" __declspec(dllexport) void XIT() {
  std::fflush(stderr);
  std::puts("XIT called");
  std::fflush(stdout);
  std::exit(3);
}
