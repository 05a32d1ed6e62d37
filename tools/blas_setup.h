// The BLAS set-up of the programs of the project (uv_unwrap, the benchmark):
// one BLAS thread, and OpenBLAS's vector kernels where it does not know the
// processor.
//
// Threads.
// From 8,000 unknowns the Newton systems are factored by CHOLMOD, whose
// dense blocks go through BLAS (Debian: OpenBLAS). OpenBLAS's own threads
// then compete with TBB's (assembly) and keep spinning between calls: on
// bimba_i_f10000 refined to 160k faces (2 cores), a profile of the final solve
// showed 48% of the time in the kernel and sched_yield, and the run took
// 244 s with OpenBLAS's default threads against 164 s with one. A program
// owns its process, so it may set this; the library does not.
//
// Kernels. Debian's OpenBLAS (0.3.21) picks its kernels by the processor's
// model number at load time, and on a model it does not know (the Xeon of
// the machines this project is measured on: family 6, model 207) it falls
// back to its generic SSE3 kernels ("Prescott") even where AVX2, FMA and
// AVX-512 are there. OPENBLAS_CORETYPE, read when the library loads, chooses
// them instead: the same results, 7-16% faster on the benchmark meshes of
// 8k-20k faces (the measures: the manual, "Linear solvers").
#ifndef CUT_PARAM_TOOLS_BLAS_SETUP_H
#define CUT_PARAM_TOOLS_BLAS_SETUP_H

#include <cstdlib>
#include <cstring>

#if defined(__GNUC__) && defined(__ELF__)
#include <unistd.h>
// OpenBLAS's control, if the BLAS loaded is OpenBLAS (a weak reference: null otherwise)
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" char* openblas_get_corename(void) __attribute__((weak));
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));
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

/// Stops the worker threads that OpenBLAS started when it loaded, once the
/// process runs on one BLAS thread (use_one_blas_thread() returned true):
/// each spins on sched_yield for a while before it sleeps, taking a core
/// from TBB's threads during the first part of every run. A BLAS call on one
/// thread does not start them again. Not for a process that gives the
/// threads back later (the Python module). Returns true if they were stopped.
inline bool stop_blas_worker_threads()
{
#if defined(__GNUC__) && defined(__ELF__)
  if(blas_thread_shutdown_ != nullptr)
  {
    blas_thread_shutdown_();
    return true;
  }
#endif
  return false;
}

/// Where OpenBLAS runs its generic "Prescott" kernels on an x86-64 processor
/// with AVX-512 (F, BW, DQ, VL) or AVX2 and FMA (a model it does not know),
/// starts the program again (the same arguments, /proc/self/exe) with
/// OPENBLAS_CORETYPE=SkylakeX or Haswell, and does not return. Does nothing
/// if OPENBLAS_CORETYPE is set (by the user, or by this call before the new
/// start), if the BLAS is not OpenBLAS, or under valgrind (whose tools would
/// not follow the new start); returns if the new start fails. Call it first
/// in main(), before any output.
inline void use_vector_blas_kernels(char** argv)
{
#if defined(__GNUC__) && defined(__ELF__) && (defined(__x86_64__) || defined(__i386__))
  if(openblas_get_corename == nullptr || std::getenv("OPENBLAS_CORETYPE") != nullptr) return;
  const char* core = openblas_get_corename();
  if(core == nullptr || std::strcmp(core, "Prescott") != 0) return;
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw")
                      && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if(!avx512 && !avx2) return;
  const char* preload = std::getenv("LD_PRELOAD");
  if(preload != nullptr && std::strstr(preload, "vgpreload") != nullptr) return;
  if(setenv("OPENBLAS_CORETYPE", avx512 ? "SkylakeX" : "Haswell", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OPENBLAS_CORETYPE"); // the new start failed: go on as we are
#else
  (void)argv;
#endif
}

} // namespace cut_tools

#endif
