// Freed memory kept by the process, for the programs of the project
// (uv_unwrap, the benchmark).
//
// glibc's malloc serves blocks over 32 MB by mmap and returns them to the
// system when freed, and trims the heap above 128 kB: every Newton iteration
// of a large mesh then gets its big blocks (a new Hessian pattern, CHOLMOD's
// work space) as fresh pages, each zeroed by the kernel on first touch. On
// bimba_i_f10000 refined to 160k faces (2 cores), 1.06 million page faults,
// 16 s of system time: the run took 67 s, and 58.6 s with the heap kept
// (129k page faults; peak memory 524 instead of 498 MB).
//
// No fast bins either (M_MXFAST 0; the thread caches stay): Debian's
// CHOLMOD opens an OpenMP region for each small loop of its factorization
// (tens of thousands per factorization, run serial, see Sparse_cholesky.h),
// and libgomp allocates and frees a team for each region run by one thread,
// a block of a few kB. Each such allocation made glibc consolidate its fast
// bins first: malloc_consolidate, _int_free and memalign took 8% of a
// bimba_i_f10000 run (perf). Without fast bins, benchmark meshes from 8,000
// unknowns (CHOLMOD) ran 3-5% faster (2 cores, best of 2 runs each: bimba_i_f10000
// 2.92 -> 2.84 s, armadillo_i_f10000 4.14 -> 3.93 s, lion_o_f10000 5.50 ->
// 5.27 s, tooth 1.30 -> 1.24 s), the smaller ones within 1.5%; refined to
// 160k faces 21.8 -> 21.5 s; the same E_d and E_s on all 21.
//
// A program owns its process, so it may set this; the library does not.
#ifndef CUT_PARAM_TOOLS_MALLOC_SETTINGS_H
#define CUT_PARAM_TOOLS_MALLOC_SETTINGS_H

#include <cstdlib>

#if defined(__GLIBC__) // defined by <cstdlib> on glibc
#include <malloc.h>
#endif

namespace cut_tools {

/// Serves every block from the heap, keeps up to 1 GB of freed memory in it
/// and uses no fast bins (glibc only), unless the environment sets malloc's
/// own variables (GLIBC_TUNABLES, MALLOC_MMAP_MAX_, MALLOC_TRIM_THRESHOLD_).
/// Returns true if set.
inline bool keep_freed_memory()
{
#if defined(__GLIBC__) && defined(M_MMAP_MAX) && defined(M_TRIM_THRESHOLD) && defined(M_MXFAST)
  if(std::getenv("GLIBC_TUNABLES") == nullptr && std::getenv("MALLOC_MMAP_MAX_") == nullptr
     && std::getenv("MALLOC_TRIM_THRESHOLD_") == nullptr)
    return mallopt(M_MMAP_MAX, 0) == 1 && mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1 && mallopt(M_MXFAST, 0) == 1;
#endif
  return false;
}

} // namespace cut_tools

#endif
