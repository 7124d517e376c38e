// What the two Abaqus/Explicit entry points (vuinteraction.cpp, vuinter.cpp)
// share beyond the block: their exit utility and the routine descriptions
// the skeleton (adapter/guard.hpp) reports with.
#pragma once

#include "adapter/explicit_block.hpp"
#include "adapter/guard.hpp"

#ifndef MJ_STANDALONE
// Abaqus/Explicit's exit utility (Fortran: CALL XPLB_EXIT, no arguments),
// resolved when Abaqus loads the library.
extern "C" void xplb_exit_();
#endif

namespace mj_adapter {
namespace {  // the exit utility differs between the standalone and Abaqus builds

// Abaqus by default, so that the source behaves right wherever Abaqus links
// it; the standalone build (harness, tests) has no exit utility.
#ifdef MJ_STANDALONE
constexpr ExitUtility kExplicitExit = nullptr;
#else
constexpr ExitUtility kExplicitExit = xplb_exit_;
#endif

constexpr Routine explicit_routine(const char* name, const char* states_argument, const char* rotation_argument) {
  return {name,
          {"nDir", "nDir is 2 (2D) or 3 (3D)", states_argument, "nProps", rotation_argument},
          kExplicitDefaults,
          "block",
          kExplicitExit};
}

}  // namespace
}  // namespace mj_adapter
