// distortion_bound: the result's E_d is within the bound when a seam cost
// reaches it (a deep bowl at 4.2), a loose bound never lengthens the seams
// of the default run, a bound no run reaches (4 on a curved surface, also
// after the greedy splits that follow the λ search) keeps the lowest E_d
// found and says so, and bounds below 4 are refused. The search's trials
// run two or three at a time, and the split trial that judges several
// candidates per split judges them at once: the result is the same for any
// number of threads, and a progress callback sees one trial at a time (the
// split trials report each split judged) and can cancel. The split
// trials (internal split_from_start()), from the search's prepared start,
// reach a reachable bound by cutting, whichever split they keep. Every
// result is a valid atlas (check_cut_result()).
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <string>
#include <thread>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

template <typename Mesh>
class Distortion_bound : public ::testing::Test
{
};
TYPED_TEST_SUITE(Distortion_bound, Mesh_types);

namespace {

// a spherical cap reaching 150 degrees from its pole: seams needed
Soup wide_cap() { return sphere_cap_soup(10, 32, 5. * pi / 6.); }

} // namespace

TYPED_TEST(Distortion_bound, a_reachable_bound_holds)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  check_cut_result(mesh, plain);
  ASSERT_GT(plain.result.distortion, 4.2); // the bound asks for more than the default gives

  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(4.2));
  check_cut_result(mesh, bounded);
  EXPECT_TRUE(bounded.result.distortion_bound_met);
  EXPECT_LE(bounded.result.distortion, 4.2);
  EXPECT_GT(bounded.result.seam_length, plain.result.seam_length); // it took more seams
}

TYPED_TEST(Distortion_bound, a_loose_bound_never_lengthens_the_seams)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(plain.result.distortion + 0.5));
  check_cut_result(mesh, bounded);
  EXPECT_TRUE(bounded.result.distortion_bound_met);
  EXPECT_LE(bounded.result.distortion, plain.result.distortion + 0.5);
  EXPECT_LE(bounded.result.seam_length, plain.result.seam_length + 1e-12);
}

TYPED_TEST(Distortion_bound, an_unreachable_bound_keeps_the_lowest_distortion)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(4.));
  check_cut_result(mesh, bounded);
  EXPECT_FALSE(bounded.result.distortion_bound_met);
  EXPECT_GT(bounded.result.distortion, 4.);
  EXPECT_LE(bounded.result.distortion, plain.result.distortion); // the default λ was one of the runs
  EXPECT_TRUE(plain.result.distortion_bound_met);                // no bound: nothing to miss
}

TYPED_TEST(Distortion_bound, bounds_below_four_are_refused)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  for(double bad : {3.9, -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    SCOPED_TRACE("bound " + to_text(bad));
    Cut_run<TypeParam> run(mesh);
    run.fill_sentinels();
    run.run(SMP::parameters::distortion_bound(bad, SMP::parameters::face_discontinuity_map(run.v())));
    EXPECT_EQ(run.result.error, SMP::ERROR_WRONG_PARAMETER);
    run.expect_outputs_untouched();
  }
}

// The search runs its trials in pairs at once; the pair's results are read
// in order, so the chosen trial and its map do not depend on the threads
// (one mesh type: the threads do not depend on it; 43 s under the sanitizers;
// skipped without TBB).
TEST(Distortion_bound_threads, the_result_is_the_same_for_any_number_of_threads)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(wide_cap());
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    const auto& result = run.run(SMP::parameters::distortion_bound(4.2));
    check_cut_result(mesh, run);
    return result;
  });
}

TYPED_TEST(Distortion_bound, a_progress_callback_sees_one_trial_at_a_time_and_can_cancel)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  std::atomic<int> inside{0}, overlaps{0}, calls{0}, splits{0};
  auto watch = [&](const SMP::Cut_and_parameterize_progress& p) {
    if(inside.fetch_add(1) != 0) ++overlaps;
    if(std::string(p.phase) == "split") ++splits;
    std::this_thread::sleep_for(std::chrono::microseconds(200)); // room for another trial to come in
    ++calls;
    inside.fetch_sub(1);
    return true;
  };
  Cut_run<TypeParam> run(mesh);
  ASSERT_TRUE(run.run(SMP::parameters::progress_callback(watch, SMP::parameters::distortion_bound(4.2))).ok());
  EXPECT_GT(calls.load(), 2 * 12); // several trials: 12 alternations each, or a report per split judged
  EXPECT_GT(splits.load(), 0);     // the split trials report (and can be canceled) too
  EXPECT_EQ(overlaps.load(), 0);

  int seen = 0;
  auto cancel = [&](const SMP::Cut_and_parameterize_progress&) { return ++seen < 20; };
  Cut_run<TypeParam> canceled(mesh);
  canceled.fill_sentinels();
  canceled.run(SMP::parameters::progress_callback(cancel, SMP::parameters::distortion_bound(4.2,
                 SMP::parameters::face_discontinuity_map(canceled.v()))));
  EXPECT_EQ(canceled.result.error, SMP::ERROR_CANCELED);
  canceled.expect_outputs_untouched();
}

TEST(Distortion_bound_splits, split_trials_reach_a_reachable_bound_by_cutting)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(wide_cap());
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  const SMP::Cut_parameterization_options options;
  ic::Run_args settings = ic::default_run_args(options);
  settings.bound = 4.2;
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  ic::Map_state start;
  ic::Work_log log;
  start.is_cut.assign(surface.edges.size(), 0);
  ASSERT_EQ(ic::prepare_first_u_step(surface, face_lambda, options, {}, start, log), SMP::OK);
  ASSERT_TRUE(start.first_u_step_done);
  ASSERT_GT(ic::mean_distortion(start.chart, start.x), 4.2); // the start's map is above the bound
  for(bool best : {false, true})
  {
    SCOPED_TRACE(best ? "best of the candidates" : "first accepted");
    ic::Map_state trial = start;
    ic::Work_log trial_log;
    ASSERT_EQ(ic::split_from_start(surface, face_lambda, options, {}, settings, best, trial, trial_log), SMP::OK);
    EXPECT_LE(trial.distortion, 4.2);
    EXPECT_NEAR(trial.distortion, ic::mean_distortion(trial.chart, trial.x), 1e-12);
    EXPECT_GT(ic::seam_length_3d(surface, trial.is_cut), ic::seam_length_3d(surface, start.is_cut));
    EXPECT_GT(trial_log.work.iterations, std::size_t(0));
    EXPECT_TRUE(trial.x.allFinite());
    EXPECT_EQ(ic::number_of_flipped_faces(trial.chart, trial.x), 0);
    const ic::Chart_topology topology = ic::chart_topology(trial.chart);
    for(int c = 0; c < topology.number_of_charts; ++c) EXPECT_TRUE(topology.is_disk(c));
  }
}

// Without a bound, a map left above the default target whose splits do not
// pay for their seams (here: a gain no split reaches) is still split down to
// the target: once none pays, the splits that lower E_d are kept, as under a
// bound (ArtDemo.obj of the OptCuts set: E_d 4.695 -> 4.595).
TEST(Default_target_splits, splits_that_do_not_pay_still_reach_the_target)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(wide_cap());
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  const SMP::Cut_parameterization_options options;
  ic::Run_args settings = ic::default_run_args(options);
  settings.split.gain = 1e9;
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  ic::Map_state start;
  ic::Work_log log;
  start.is_cut.assign(surface.edges.size(), 0);
  ASSERT_EQ(ic::prepare_first_u_step(surface, face_lambda, options, {}, start, log), SMP::OK);
  ASSERT_EQ(ic::final_solve(surface, settings.final, false, start, log), SMP::OK);
  start.distortion = ic::mean_distortion(start.chart, start.x);
  ASSERT_GT(start.distortion, ic::tuning::default_distortion_target); // the solved map of the initial cut is above it
  ic::Map_state split = start;
  ASSERT_EQ(ic::split_where_distorted(surface, options, {}, settings, settings.final, split, log), SMP::OK);
  EXPECT_LE(split.distortion, ic::tuning::default_distortion_target) << "from " << start.distortion;
  EXPECT_NEAR(split.distortion, ic::mean_distortion(split.chart, split.x), 1e-12);
  EXPECT_GT(ic::seam_length_3d(surface, split.is_cut), ic::seam_length_3d(surface, start.is_cut));
  EXPECT_TRUE(split.x.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(split.chart, split.x), 0);
  const ic::Chart_topology topology = ic::chart_topology(split.chart);
  for(int c = 0; c < topology.number_of_charts; ++c) EXPECT_TRUE(topology.is_disk(c));
}
