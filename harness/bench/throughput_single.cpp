// The single-precision VUINTERACTION next to the double one in one program:
// the harness links the double routine as vuinteraction_, and
// mj_vuinteraction_single_renamed (harness/CMakeLists.txt) is the same
// source compiled in single precision under the name below. This file sees
// vuinteraction.h as a single-precision caller does.
#undef MJ_DOUBLE_PRECISION
#define vuinteraction_ mj_vuinteraction_single_
#define vuinter_ mj_vuinter_single_
#include "vuinteraction.h"

#include "bench/throughput_call.hpp"

namespace mortar::harness {

VuinteractionRoutine<float> single_precision_routine() { return &mj_vuinteraction_single_; }

}  // namespace mortar::harness
