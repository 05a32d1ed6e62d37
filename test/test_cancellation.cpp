// Cancellation in every phase that reports progress: a progress callback
// returning false at the first report of a phase stops the run with
// ERROR_CANCELED and leaves every output (seams, UVs, v) as it was. The
// phases: "initialize", "alternate", "cut", "final" (default mode), "split"
// (the distortion bound's split trials), and the alternation and final
// solve of a multiresolution run (the alternation on the simplified copy).
// Canceling from uv_unwrap (SIGINT): tools/tests/interrupt.cmake.
// face_visibility() too: its progress callback (the fraction of the faces
// done) returning false, at its first call or between two blocks of faces,
// gives ERROR_CANCELED and leaves the visibility map as it was; a callback
// that never cancels changes nothing in the result.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/face_visibility.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

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

/// A visibility map filled with values face_visibility() never writes (it
/// writes values in [0, 1]), kept to check that a canceled call left them.
struct Visibility_output
{
  using face_descriptor = boost::graph_traits<Surface_mesh>::face_descriptor;
  std::unordered_map<face_descriptor, double> storage;
  std::unordered_map<face_descriptor, double> sentinel;

  explicit Visibility_output(const Surface_mesh& mesh)
  {
    double k = 0.;
    for(face_descriptor f : faces(mesh)) storage[f] = -0.375 - k++;
    sentinel = storage;
  }
  boost::associative_property_map<std::unordered_map<face_descriptor, double>> map()
  {
    return boost::associative_property_map<std::unordered_map<face_descriptor, double>>(storage);
  }
  std::size_t changed() const
  {
    std::size_t n = 0;
    for(const auto& [f, value] : storage) n += std::memcmp(&value, &sentinel.at(f), sizeof(double)) != 0 ? 1 : 0;
    return n;
  }
};

/// A spike on a disk: 3,008 faces, some hidden by the spike; three blocks
/// of faces between reports at 64 rays (1,024 faces each).
Surface_mesh visibility_mesh()
{
  return make_mesh<Surface_mesh>(spike_disk_soup(24, 64, 1.5, 0.2));
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

TEST(Cancellation, of_face_visibility_at_its_first_call)
{
  const Surface_mesh mesh = visibility_mesh();
  Visibility_output out(mesh);
  std::vector<double> calls;
  const std::function<bool(double)> cancel = [&](double done) {
    calls.push_back(done);
    return false;
  };
  EXPECT_EQ(SMP::face_visibility(mesh, out.map(), SMP::parameters::progress_callback(cancel)), SMP::ERROR_CANCELED);
  EXPECT_EQ(calls, std::vector<double>{0.});
  EXPECT_EQ(out.changed(), std::size_t(0)) << "visibility written on cancel";
}

TEST(Cancellation, of_face_visibility_between_two_blocks_of_faces)
{
  const Surface_mesh mesh = visibility_mesh();
  ASSERT_GT(num_faces(mesh), std::size_t(2 * 1024));
  Visibility_output out(mesh);
  std::vector<double> calls;
  // the second call comes after the first block of faces: cancel there
  auto cancel = [&](double done) {
    calls.push_back(done);
    return calls.size() < 2;
  };
  EXPECT_EQ(SMP::face_visibility(mesh, out.map(), SMP::parameters::progress_callback(cancel)), SMP::ERROR_CANCELED);
  ASSERT_EQ(calls.size(), std::size_t(2));
  EXPECT_GT(calls[1], 0.);
  EXPECT_LT(calls[1], 1.);
  EXPECT_EQ(out.changed(), std::size_t(0)) << "visibility written on cancel";
}

TEST(Cancellation, of_face_visibility_not_asked_for)
{
  const Surface_mesh mesh = visibility_mesh();
  Visibility_output plain(mesh), watched(mesh);
  ASSERT_EQ(SMP::face_visibility(mesh, plain.map()), SMP::OK);
  std::vector<double> calls;
  auto go_on = [&](double done) {
    calls.push_back(done);
    return true;
  };
  ASSERT_EQ(SMP::face_visibility(mesh, watched.map(), SMP::parameters::progress_callback(go_on)), SMP::OK);
  // 0, then one report per block of 1,024 faces, the last at 1
  const std::size_t blocks = (num_faces(mesh) + 1023) / 1024;
  ASSERT_EQ(calls.size(), 1 + blocks);
  EXPECT_EQ(calls.front(), 0.);
  EXPECT_EQ(calls.back(), 1.);
  EXPECT_TRUE(std::is_sorted(calls.begin(), calls.end()));
  std::size_t differ = 0, hidden = 0;
  for(auto f : faces(mesh))
  {
    const double a = plain.storage.at(f), b = watched.storage.at(f);
    differ += std::memcmp(&a, &b, sizeof(double)) != 0 ? 1 : 0;
    hidden += a < 1. ? 1 : 0;
  }
  EXPECT_EQ(differ, std::size_t(0));
  EXPECT_GT(hidden, std::size_t(0)); // a result worth comparing: the spike hides some faces
}
