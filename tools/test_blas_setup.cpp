// The BLAS set-up of the programs (blas_setup.h): once a program runs on one
// BLAS thread, the worker threads that OpenBLAS started when it loaded are
// stopped, so that none spins beside TBB's threads during a run.
#include "blas_setup.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
#include <cholmod.h>
#endif

namespace {

std::size_t threads_of_this_process()
{
  std::size_t n = 0;
  for([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

TEST(BlasSetup, one_blas_thread_leaves_no_blas_worker_running)
{
  if(!std::filesystem::exists("/proc/self/task")) GTEST_SKIP() << "no /proc/self/task to count threads";
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  // the BLAS comes with CHOLMOD, as in uv_unwrap (a call keeps the library linked)
  cholmod_common common;
  cholmod_start(&common);
  cholmod_finish(&common);
#endif
  const std::size_t before = threads_of_this_process();
  if(!cut_tools::use_one_blas_thread()) GTEST_SKIP() << "the BLAS is not OpenBLAS, or its threads are set by the environment";
  if(before < 2) GTEST_SKIP() << "OpenBLAS started no worker thread (one core, or its threads set to one)";
  ASSERT_TRUE(cut_tools::stop_blas_worker_threads());
  EXPECT_EQ(threads_of_this_process(), 1u) << before << " threads before";
}

} // namespace
