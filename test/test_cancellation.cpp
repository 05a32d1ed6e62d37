// Cancellation in every phase that reports progress: a progress callback
// returning false at the first report of a phase stops the run with
// ERROR_CANCELED and leaves every output (seams, UVs, v) as it was. The
// phases: "initialize", "alternate", "cut", "final" (default mode), "split"
// (the distortion bound's split trials), and the alternation and final
// solve of a multiresolution run (the alternation on the simplified copy).
// Canceling from uv_unwrap (SIGINT): tools/tests/interrupt.cmake.
#include "cut_result_checks.h"

#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

/// Runs with `np` plus a callback that cancels at the first report of
/// `phase` (at alternation `alternation` or later for "alternate"), and
/// checks the error and the untouched outputs.
template <typename NamedParameters>
void expect_canceled_in(const Surface_mesh& mesh, const std::string& phase, const NamedParameters& np,
                        int alternation = 0)
{
  SCOPED_TRACE("canceled in phase " + phase);
  bool canceled = false;
  std::string last;
  auto cancel = [&](const SMP::Cut_and_parameterize_progress& p) {
    last = p.phase;
    canceled = last == phase && (phase != "alternate" || p.alternation >= alternation);
    return !canceled;
  };
  Cut_run<Surface_mesh> run(mesh);
  run.fill_sentinels();
  run.run(SMP::parameters::progress_callback(cancel, SMP::parameters::face_discontinuity_map(run.v(), np)));
  ASSERT_TRUE(canceled) << "the run never reported phase " << phase << " (last: " << last << ")";
  EXPECT_EQ(run.result.error, SMP::ERROR_CANCELED);
  run.expect_outputs_untouched();
}

} // namespace

TEST(Cancellation, in_each_phase_of_the_default_mode)
{
  // a tall cone: the alternation cuts it to its apex, so that "cut" is reported
  const Surface_mesh mesh = make_mesh<Surface_mesh>(cone_soup(12, 32, 1., 6.));
  for(const char* phase : {"initialize", "alternate", "cut", "final"})
    expect_canceled_in(mesh, phase, CGAL::parameters::default_values(), 3);
}

TEST(Cancellation, in_the_split_trials_of_the_bound_mode)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(sphere_cap_soup(10, 32, 5. * pi / 6.));
  expect_canceled_in(mesh, "split", SMP::parameters::distortion_bound(4.2));
}

TEST(Cancellation, in_a_multiresolution_run)
{
  // the tall cone at 3,008 faces, simplified to about 600 for the alternation
  const Surface_mesh mesh = make_mesh<Surface_mesh>(cone_soup(24, 64, 1., 6.));
  ASSERT_GT(num_faces(mesh), std::size_t(2 * 600));
  // (its final solve, on the whole mesh, is the default mode's: left out to keep the sanitizers' run short)
  for(const char* phase : {"alternate", "cut"})
    expect_canceled_in(mesh, phase, SMP::parameters::multiresolution_faces(600), 2);
}
