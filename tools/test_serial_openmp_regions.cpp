// The programs' OpenMP regions of one thread (serial_openmp_regions.cpp):
// this program's GOMP_parallel is the one the process calls; a region that
// would have one thread runs on the calling thread without a team; any other
// region still gets libgomp's threads; CHOLMOD's regions come here, and the
// library then gives CHOLMOD smaller systems too.
#include "serial_openmp_regions.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>

#include <gtest/gtest.h>
#include <omp.h>

#include <dlfcn.h>

#include <string>
#include <vector>

namespace {

namespace cut = CGAL::Surface_mesh_parameterization::internal::cut;

#if CUT_PARAM_SERIAL_OPENMP_REGIONS
TEST(SerialOpenmpRegions, the_process_calls_this_programs_entry_point)
{
  void* entry = dlsym(RTLD_DEFAULT, "GOMP_parallel");
  ASSERT_NE(entry, nullptr);
  Dl_info info;
  ASSERT_NE(dladdr(entry, &info), 0);
  Dl_info main_info;
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&cut_tools::openmp_regions_run_serially), &main_info), 0);
  EXPECT_EQ(std::string(info.dli_fname), std::string(main_info.dli_fname)) << "GOMP_parallel resolved in another object";
}

TEST(SerialOpenmpRegions, a_region_of_one_thread_runs_without_a_team)
{
  const unsigned long before = cut_tools::openmp_regions_run_serially();
  int level = -1, threads = -1;
#pragma omp parallel num_threads(1)
  {
    level = omp_get_level(); // 1 inside a team of libgomp's, 0 here
    threads = omp_get_num_threads();
  }
  EXPECT_EQ(level, 0);
  EXPECT_EQ(threads, 1);
  EXPECT_EQ(cut_tools::openmp_regions_run_serially(), before + 1);
}

TEST(SerialOpenmpRegions, no_active_level_left_runs_without_a_team)
{
  const int saved = omp_get_max_active_levels();
  omp_set_max_active_levels(0);
  const unsigned long before = cut_tools::openmp_regions_run_serially();
  std::vector<int> hits(1000, 0);
#pragma omp parallel for num_threads(4)
  for(int i = 0; i < 1000; ++i) hits[std::size_t(i)] += 1 + omp_get_thread_num();
  omp_set_max_active_levels(saved);
  EXPECT_EQ(cut_tools::openmp_regions_run_serially(), before + 1);
  for(int h : hits) ASSERT_EQ(h, 1); // every iteration once, on thread 0
}

TEST(SerialOpenmpRegions, other_regions_get_their_threads)
{
  omp_set_max_active_levels(1);
  const unsigned long before = cut_tools::openmp_regions_run_serially();
  int threads = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    threads = omp_get_num_threads();
  }
  EXPECT_EQ(threads, 2);
  EXPECT_EQ(cut_tools::openmp_regions_run_serially(), before);
}
#endif

// A grid Laplacian plus the identity, of side x side unknowns, factored:
// the right solution; returns the regions run here meanwhile.
unsigned long factor_a_grid(int side, bool& cheap_solves)
{
  const int n = side * side;
  std::vector<Eigen::Triplet<double>> entries;
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j)
    {
      const int k = i * side + j;
      entries.emplace_back(k, k, 5.);
      if(i > 0) entries.emplace_back(k, k - side, -1.);
      if(j > 0) entries.emplace_back(k, k - 1, -1.);
    }
  cut::Sparse_matrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  const unsigned long before = cut_tools::openmp_regions_run_serially();
  cut::Sparse_cholesky cholesky;
  EXPECT_TRUE(cholesky.factorize(A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1., 1.);
  Eigen::VectorXd x;
  EXPECT_TRUE(cholesky.solve(b, x));
  const cut::Sparse_matrix full = A.selfadjointView<Eigen::Lower>();
  EXPECT_LT((full * x - b).norm(), 1e-10 * b.norm());
  cheap_solves = cholesky.solves_are_cheap();
  return cut_tools::openmp_regions_run_serially() - before;
}

// Above tuning::cholmod_threshold unknowns, CHOLMOD (its regions run here),
// without reuse of old factors.
TEST(SerialOpenmpRegions, a_large_factorization_solves_and_its_regions_run_here)
{
  bool cheap_solves = true;
  const unsigned long regions = factor_a_grid(100, cheap_solves);
#if CUT_PARAM_SERIAL_OPENMP_REGIONS && defined(CGAL_SMP_CUT_USE_CHOLMOD)
  EXPECT_GT(regions, 0u);
  EXPECT_FALSE(cheap_solves);
#else
  (void)regions;
#endif
}

// Where the regions run without a team, CHOLMOD takes systems from
// tuning::cholmod_threshold_without_team unknowns, and below
// tuning::cholmod_threshold its solves keep the reuse of old factors.
TEST(SerialOpenmpRegions, mid_sized_systems_go_to_cholmod_without_a_team)
{
  namespace tuning = CGAL::Surface_mesh_parameterization::internal::cut::tuning;
  bool cheap_solves = false;
  const int side = 50; // 2,500 unknowns: between the two thresholds
  static_assert(side * side >= tuning::cholmod_threshold_without_team && side * side < tuning::cholmod_threshold);
  const unsigned long regions = factor_a_grid(side, cheap_solves);
  EXPECT_TRUE(cheap_solves);
#if CUT_PARAM_SERIAL_OPENMP_REGIONS && defined(CGAL_SMP_CUT_USE_CHOLMOD)
  EXPECT_TRUE(cut::openmp_regions_without_team());
  EXPECT_EQ(cut::Sparse_cholesky::cholmod_threshold(), tuning::cholmod_threshold_without_team);
  EXPECT_GT(regions, 0u);
#else
  (void)regions;
#endif
}

} // namespace
