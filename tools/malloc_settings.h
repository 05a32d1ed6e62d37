// Freed memory kept by the process, for the programs of the project
// (uv_unwrap, the benchmark).
//
// glibc's malloc serves blocks over 32 MB by mmap and returns them to the
// system when freed, and trims the heap above 128 kB: every Newton iteration
// of a large mesh then gets its big blocks (a new Hessian pattern, CHOLMOD's
// work space) as fresh pages, each zeroed by the kernel on first touch. On
// bimba_i_f10000 refined to 160k faces (2 cores), 1.06 million page faults,
// 16 s of system time: the run took 67 s, and 58.6 s with the heap kept
// (129k page faults; peak memory 524 instead of 498 MB). A program owns its
// process, so it may set this; the library does not.
#ifndef CUT_PARAM_TOOLS_MALLOC_SETTINGS_H
#define CUT_PARAM_TOOLS_MALLOC_SETTINGS_H

#include <cstdlib>

#if defined(__GLIBC__) // defined by <cstdlib> on glibc
#include <malloc.h>
#endif

namespace cut_tools {

/// Serves every block from the heap and keeps up to 1 GB of freed memory in
/// it (glibc only), unless the environment sets malloc's own variables
/// (GLIBC_TUNABLES, MALLOC_MMAP_MAX_, MALLOC_TRIM_THRESHOLD_). Returns true if set.
inline bool keep_freed_memory()
{
#if defined(__GLIBC__) && defined(M_MMAP_MAX) && defined(M_TRIM_THRESHOLD)
  if(std::getenv("GLIBC_TUNABLES") == nullptr && std::getenv("MALLOC_MMAP_MAX_") == nullptr
     && std::getenv("MALLOC_TRIM_THRESHOLD_") == nullptr)
    return mallopt(M_MMAP_MAX, 0) == 1 && mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1;
#endif
  return false;
}

} // namespace cut_tools

#endif
