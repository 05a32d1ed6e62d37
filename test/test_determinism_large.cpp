// Thread-count determinism where the large-mesh code runs: meshes whose
// Newton systems (two unknowns per UV vertex) are above the thresholds of
// the sparse Cholesky (Sparse_cholesky.h: CHOLMOD with OpenBLAS from
// cholmod_threshold unknowns, METIS ordering from metis_threshold), in the
// default mode and under a distortion bound. The same seams, UVs (bit for
// bit) and Newton iterations with 1, 2 and 4 TBB threads; skipped without
// TBB. Lean options (one alternation per ε from ε = 0.02, at most 10 Newton
// iterations per u-step) keep the runs short: determinism does not need a
// converged map.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

namespace ic = SMP::internal::cut;

// UV vertices of a run: at least the mesh's vertices (seams add copies)
template <typename Mesh>
long unknowns_at_least(const Mesh& mesh)
{
  return 2 * long(num_vertices(mesh));
}

/// The lean options of these runs.
auto lean_options()
{
  namespace P = SMP::parameters;
  return P::epsilon_start(0.02, P::iterations_per_epsilon(1, CGAL::parameters::number_of_iterations(10)));
}

} // namespace

// 16,201 vertices (32,402 unknowns, over metis_threshold): 32,220 faces,
// so the alternation runs on the multiresolution copy (10,000 faces,
// over cholmod_threshold) and the final solve on the whole mesh.
TEST(Determinism_large, default_mode_above_the_metis_threshold)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(90, 180, 1.5, 0.2));
  ASSERT_GE(unknowns_at_least(mesh), long(ic::Sparse_cholesky::metis_threshold));
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    const auto& result = run.run(lean_options());
    check_cut_result(mesh, run);
    return result;
  });
}

// 4,081 vertices (8,162 unknowns, over cholmod_threshold), under a
// distortion bound that the default run does not meet: a low spike
// (height 1), which the lean run leaves at E_d 4.845 before its default
// splits (tuning::default_distortion_target) and at 4.449
// after them, under the bound 4.4. Its split trials (two at a time, beside
// the run at the given λ) add cuts from the spike to the border until E_d
// is within the bound, each split judged by Newton iterations on the whole
// map (8,162 unknowns: CHOLMOD), then the seams are rerouted and zipped back
// within the bound. The test checks that this machinery ran: the default
// run above the bound, splits judged (the "split" reports of the split
// trials beyond their two baselines), seams cut, the bound met; and that the
// number of split reports is the same for every thread count.
// Measured (Release, 2 cores): 27 s wall for the whole test (34 s user,
// 20 s system: OpenBLAS's threads waiting). With the bound 4.7 before the
// default target existed: 15.6 s of CPU at load 2.6.
TEST(Determinism_large, bound_mode_above_the_cholmod_threshold)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(40, 102, 1., 0.2));
  ASSERT_GE(unknowns_at_least(mesh), long(ic::Sparse_cholesky::cholmod_threshold()));
  namespace P = SMP::parameters;
  const double bound = 4.4;
  {
    // the default run (no bound, same lean options) stays above the bound
    Cut_run<Surface_mesh> joint(mesh);
    ASSERT_TRUE(joint.run(lean_options()).ok());
    ASSERT_GT(joint.result.distortion, bound) << "the bound is met without splits: pick a lower one";
  }
  std::vector<int> split_reports;
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    std::atomic<int> splits{0};
    auto count_splits = [&](const SMP::Cut_and_parameterize_progress& p) {
      if(std::string(p.phase) == "split") ++splits;
      return true;
    };
    const auto& result = run.run(P::progress_callback(count_splits, P::distortion_bound(bound, lean_options())));
    check_cut_result(mesh, run);
    split_reports.push_back(splits.load());
    // the bound's machinery ran: splits judged beyond the two split trials'
    // baselines, and they cut what the joint method did not
    EXPECT_GT(splits.load(), 2);
    EXPECT_GT(result.number_of_seam_edges, std::size_t(0));
    EXPECT_TRUE(result.distortion_bound_met);
    EXPECT_LE(result.distortion, bound);
    return result;
  });
  for(std::size_t i = 1; i < split_reports.size(); ++i)
    EXPECT_EQ(split_reports[i], split_reports[0]) << "run " << i;
}

// The same above cholmod_threshold, on a spike (height 1.5) that the joint
// method cuts within the bound 4.6 (E_d 4.10): the run at the given λ is a
// candidate beside the split trials, and all are shortened.
// Measured on 2 shared cores: 165 s of CPU for the three runs (one run with
// one thread alone: 40 s, half of it OpenBLAS's threads waiting), beyond
// what CI's time allows: skipped unless CUT_PARAM_LONG_TESTS is set in the
// environment.
TEST(Determinism_large, bound_mode_above_the_cholmod_threshold_long)
{
  if(!std::getenv("CUT_PARAM_LONG_TESTS"))
    GTEST_SKIP() << "long (165 s of CPU): set CUT_PARAM_LONG_TESTS=1 to run it";
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(40, 102, 1.5, 0.2));
  ASSERT_GE(unknowns_at_least(mesh), long(ic::Sparse_cholesky::cholmod_threshold()));
  namespace P = SMP::parameters;
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    const auto& result = run.run(P::distortion_bound(4.6, lean_options()));
    check_cut_result(mesh, run);
    return result;
  });
}
