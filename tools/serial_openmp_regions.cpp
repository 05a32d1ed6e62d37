// OpenMP regions that would run on one thread run on the calling thread,
// without a team, in the programs of the project (uv_unwrap, the benchmark,
// the Python module and its C++ reference): linked into a program, this
// definition of libgomp's entry point GOMP_parallel comes first in the
// process's symbol lookup, so CHOLMOD's calls reach it.
//
// Debian's CHOLMOD opens an OpenMP region for each small loop of its
// supernodal factorization, tens of thousands per factorization. The library
// runs them with no active level (Serial_openmp_scope in
// linalg/Sparse_cholesky.h), but libgomp still starts and ends a team of one
// for each, whose last barrier makes a futex system call even with no
// thread to wake (measures: the manual, "Linear solvers").
//
// A region is run here only where libgomp would give it one thread: one
// thread asked (num_threads(1), or an if clause that is false), or no active
// level left (omp_get_active_level() >= omp_get_max_active_levels()). Any
// other region goes to libgomp's own GOMP_parallel. A program owns its
// process, so it may do this; the library does not.
#include "serial_openmp_regions.h"

#if CUT_PARAM_SERIAL_OPENMP_REGIONS
#include <dlfcn.h>

#include <atomic>

// libgomp's queries, if the process has an OpenMP runtime (weak references: null otherwise)
extern "C" int omp_get_active_level(void) __attribute__((weak));
extern "C" int omp_get_max_active_levels(void) __attribute__((weak));

namespace {

using Gomp_parallel = void (*)(void (*)(void*), void*, unsigned, unsigned);

std::atomic<unsigned long> regions_run_here{0};

bool one_thread_region(unsigned num_threads)
{
  if(num_threads == 1) return true;
  return omp_get_active_level != nullptr && omp_get_max_active_levels != nullptr
         && omp_get_active_level() >= omp_get_max_active_levels();
}

} // namespace

extern "C" __attribute__((visibility("default"))) void GOMP_parallel(void (*fn)(void*), void* data,
                                                                    unsigned num_threads, unsigned flags)
{
  if(one_thread_region(num_threads))
  {
    regions_run_here.fetch_add(1, std::memory_order_relaxed);
    fn(data);
    return;
  }
  // the runtime's own entry point, behind this one in the lookup order
  static const Gomp_parallel next = reinterpret_cast<Gomp_parallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  if(next != nullptr) next(fn, data, num_threads, flags);
  else fn(data); // no OpenMP runtime behind: the region has one thread
}

// The library's question (openmp_regions_without_team() in linalg/Sparse_cholesky.h): true where
// this definition is the one the process calls (not where libgomp was loaded before this program's
// object, as in Blender)
extern "C" __attribute__((visibility("default"))) int cut_param_openmp_regions_without_team()
{
  return dlsym(RTLD_DEFAULT, "GOMP_parallel") == reinterpret_cast<void*>(&GOMP_parallel) ? 1 : 0;
}

namespace cut_tools {

unsigned long openmp_regions_run_serially() { return regions_run_here.load(std::memory_order_relaxed); }

} // namespace cut_tools

#else

namespace cut_tools {

unsigned long openmp_regions_run_serially() { return 0; }

} // namespace cut_tools

#endif
