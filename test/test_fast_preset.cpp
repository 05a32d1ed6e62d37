// Preset::FAST (named parameter preset): the settings it changes, as
// documented (with_preset(): cuts decided on a copy of about
// fast_multiresolution_faces faces; the plan: no rerouting,
// final tolerances times tuning::fast_tolerance_factor, no default-target
// search, the copy made on the index arrays; the alternation: its u-steps
// after the first at that factor too), the default left as it was, and a fast run that keeps every
// guarantee of the atlas (check_cut_result(): no flipped face, no crossing
// border, no overlap, UVs in the unit square).
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;

TEST(FastPreset, settings_differ_from_the_default_as_documented)
{
  const SMP::Cut_parameterization_options defaults;
  EXPECT_EQ(defaults.preset, SMP::Preset::DEFAULT);
  const SMP::Cut_parameterization_options same = SMP::with_preset(defaults);
  EXPECT_EQ(same.iterations_per_epsilon, defaults.iterations_per_epsilon);
  EXPECT_EQ(same.multiresolution_faces, defaults.multiresolution_faces);
  const ic::Run_args default_run = ic::default_run_args(same);
  EXPECT_EQ(default_run.rerouting_rings, ic::tuning::rerouting_rings);
  EXPECT_EQ(default_run.final.tolerance_factor, 1.);

  SMP::Cut_parameterization_options o;
  o.preset = SMP::Preset::FAST;
  const SMP::Cut_parameterization_options fast = SMP::with_preset(o);
  EXPECT_EQ(fast.iterations_per_epsilon, defaults.iterations_per_epsilon);
  EXPECT_EQ(fast.multiresolution_faces, SMP::fast_multiresolution_faces);
  EXPECT_LT(fast.multiresolution_faces, defaults.multiresolution_faces);
  const ic::Run_args fast_run = ic::default_run_args(fast);
  EXPECT_EQ(fast_run.rerouting_rings, 0);
  EXPECT_EQ(fast_run.final.tolerance_factor, ic::tuning::fast_tolerance_factor);
  EXPECT_GT(fast_run.final.tolerance_factor, 1.);
  // the other fields are the user's; caps only lower them, and 0 (never simplify) stays
  o.multiresolution_faces = 0;
  o.lambda = 2.5;
  EXPECT_EQ(SMP::with_preset(o).multiresolution_faces, 0);
  EXPECT_EQ(SMP::with_preset(o).lambda, 2.5);
  o.multiresolution_faces = 700;
  EXPECT_EQ(SMP::with_preset(o).multiresolution_faces, 700);
  // the named parameter reaches the options
  EXPECT_EQ(SMP::cut_parameterization_options_from(SMP::parameters::preset(SMP::Preset::FAST)).preset,
            SMP::Preset::FAST);
}

TEST(FastPreset, fast_run_gives_a_valid_atlas)
{
  Surface_mesh mesh;
  build_mesh(hemisphere_soup(8, 24), mesh);
  Cut_run<Surface_mesh> run(mesh);
  run.run(SMP::parameters::preset(SMP::Preset::FAST));
  ASSERT_EQ(run.result.error, SMP::OK);
  check_cut_result(mesh, run);
}

// After the first u-step (the same in both runs: it decides the cuts) the
// preset's u-steps stop at tuning::fast_tolerance_factor times the
// tolerance: on a mesh cut at full resolution under both, the alternation
// does fewer Newton iterations, and the atlas keeps every guarantee.
TEST(FastPreset, later_u_steps_stop_at_the_looser_tolerance)
{
  Surface_mesh mesh;
  build_mesh(hemisphere_soup(12, 32), mesh);
  ASSERT_LE(num_faces(mesh), std::size_t(2 * SMP::fast_multiresolution_faces)); // no copy under the preset
  Cut_run<Surface_mesh> by_default(mesh), fast(mesh);
  by_default.run();
  fast.run(SMP::parameters::preset(SMP::Preset::FAST));
  ASSERT_EQ(by_default.result.error, SMP::OK);
  ASSERT_EQ(fast.result.error, SMP::OK);
  EXPECT_LT(fast.result.alternation_newton_iterations, by_default.result.alternation_newton_iterations);
  check_cut_result(mesh, fast);
}

// Above 2 x fast_multiresolution_faces faces the preset decides the cuts on
// a simplified copy, made on the index arrays (the default's is CGAL's edge
// collapse): the atlas keeps every guarantee there too.
TEST(FastPreset, fast_run_cut_on_a_copy_gives_a_valid_atlas)
{
  Surface_mesh mesh;
  build_mesh(hemisphere_soup(24, 64), mesh);
  ASSERT_GT(num_faces(mesh), std::size_t(2 * SMP::fast_multiresolution_faces));
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  SMP::Cut_parameterization_options fast_options;
  fast_options.preset = SMP::Preset::FAST;
  EXPECT_TRUE(ic::cuts_copy_on_index_arrays(surface, fast_options));
  EXPECT_FALSE(ic::cuts_copy_on_index_arrays(surface, SMP::Cut_parameterization_options()));
  Cut_run<Surface_mesh> run(mesh);
  run.run(SMP::parameters::preset(SMP::Preset::FAST));
  ASSERT_EQ(run.result.error, SMP::OK);
  check_cut_result(mesh, run);
}
