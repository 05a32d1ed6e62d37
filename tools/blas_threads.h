// One BLAS thread for the programs of the project (uv_unwrap, the benchmark).
//
// From 8,000 unknowns the Newton systems are factored by CHOLMOD, whose
// dense blocks go through BLAS (Debian: OpenBLAS). OpenBLAS's own threads
// then compete with TBB's (assembly) and keep spinning between calls: on
// bimba_i_f10000 refined to 160k faces (2 cores), a profile of the final solve
// showed 48% of the time in the kernel and sched_yield, and the run took
// 244 s with OpenBLAS's default threads against 164 s with one. A program
// owns its process, so it may set this; the library does not.
#ifndef CUT_PARAM_TOOLS_BLAS_THREADS_H
#define CUT_PARAM_TOOLS_BLAS_THREADS_H

#include <cstdlib>

#if defined(__GNUC__) && defined(__ELF__)
// OpenBLAS's control, if the BLAS loaded is OpenBLAS (a weak reference: null otherwise)
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
#endif

namespace cut_tools {

/// Asks the BLAS for one thread, if it is OpenBLAS and the environment does
/// not say otherwise (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS). Returns true if set.
inline bool use_one_blas_thread()
{
#if defined(__GNUC__) && defined(__ELF__)
  if(openblas_set_num_threads != nullptr && std::getenv("OPENBLAS_NUM_THREADS") == nullptr
     && std::getenv("OMP_NUM_THREADS") == nullptr)
  {
    openblas_set_num_threads(1);
    return true;
  }
#endif
  return false;
}

} // namespace cut_tools

#endif
