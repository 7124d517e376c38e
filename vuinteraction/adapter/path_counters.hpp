// How many points each path of the explicit routines took, per thread: the
// elastic lanes, the per-point elastic shortcut, the full path, and the
// points not integrated (no opposite surface). Test builds only
// (MJ_PATH_COUNTERS, tests/abi): elsewhere MJ_COUNT_PATH compiles to nothing.
#pragma once

#if defined(MJ_PATH_COUNTERS) && MJ_PATH_COUNTERS
namespace mj_adapter {
struct PathCounts {
  long lanes = 0, shortcut = 0, full = 0, unpaired = 0;
  long total() const { return lanes + shortcut + full + unpaired; }
};
inline PathCounts& path_counts() {
  thread_local PathCounts counts;
  return counts;
}
}  // namespace mj_adapter
#define MJ_COUNT_PATH(path) (++::mj_adapter::path_counts().path)
#else
#define MJ_COUNT_PATH(path) ((void)0)
#endif
