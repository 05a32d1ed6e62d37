// CAD-like input, generated as the benchmark's hard-surface corpus is
// (benchmark/hard_surface_meshes.h: planar caps triangulated without
// Steiner points, fans around holes, slivers on the walls, sharp creases).
// A plate with holes laid flat in one chart crosses itself; its Tutte map,
// every hole's rim squashed onto one circle, is far above
// tuning::tutte_restart_max_distortion, so the final solve cuts the
// crossing chart into overlap-free pieces instead of solving it again from
// there under the border barrier (where each step stopped at a contact:
// 70 Newton iterations for this plate's final solve, 316 for a bracket with
// twelve holes, 506 for a plate with 48). The result is a valid atlas with
// E_d below the default target.
#include "cut_result_checks.h"
#include "generators.h"
#include "../benchmark/hard_surface_meshes.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/final_solve.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

// The Tutte map of a plate with holes, cut into one disk, is too distorted
// for the barrier's solve; a disk without holes is not.
TEST(Hard_surface, a_tutte_map_of_holes_on_one_circle_is_too_distorted_for_the_barrier)
{
  const Surface_mesh plate = cut_benchmark::hard_surface::plate(3, 2, 64, 0.1);
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(plate, get(CGAL::vertex_point, plate), surface) == ic::Indexing_status::OK);
  ic::Map_state state;
  state.is_cut.assign(surface.edges.size(), 0);
  ASSERT_TRUE(ic::make_disks(surface, state.is_cut, state.rules));
  ic::build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  const std::vector<double> tutte = ic::tutte_distortions(state);
  ASSERT_EQ(tutte.size(), 1u);
  EXPECT_GT(tutte[0], ic::tuning::tutte_restart_max_distortion);

  const Surface_mesh disk = make_mesh<Surface_mesh>(grid_soup(8, 8));
  ic::Indexed_surface<Surface_mesh> disk_surface;
  ASSERT_TRUE(ic::index_surface(disk, get(CGAL::vertex_point, disk), disk_surface) == ic::Indexing_status::OK);
  ic::Map_state disk_state;
  disk_state.is_cut.assign(disk_surface.edges.size(), 0);
  ic::build_chart_mesh(disk_surface, disk_state.is_cut, disk_state.chart, disk_state.corner_uv);
  EXPECT_LT(ic::tutte_distortions(disk_state)[0], 10.);
}

// With the defaults, the plate gives a valid atlas (no flip, no crossing,
// disks), E_d at most the default target, from a final solve of tens of
// Newton iterations.
TEST(Hard_surface, a_plate_with_holes_gives_a_valid_atlas_from_a_short_final_solve)
{
  const Surface_mesh plate = cut_benchmark::hard_surface::plate(3, 2, 64, 0.1);
  Cut_run<Surface_mesh> run(plate);
  run.run();
  check_cut_result(plate, run);
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  EXPECT_LT(run.result.final_solve_newton_iterations, std::size_t(40)); // measured: 11 (70 from the Tutte map)
}

// A CAD part is told from an organic mesh by its sharp creases: the gear's
// outline edges (a third of its edges, at 90 degrees) make it a hard
// surface, a sphere or a box (12 creases) is not.
TEST(Hard_surface, a_gear_is_a_hard_surface_and_a_sphere_is_not)
{
  auto indexed = [](const Surface_mesh& mesh, ic::Indexed_surface<Surface_mesh>& surface) {
    return ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK;
  };
  const Surface_mesh gear = cut_benchmark::hard_surface::gear(20, 6, 48, 0.3);
  ic::Indexed_surface<Surface_mesh> gear_surface;
  ASSERT_TRUE(indexed(gear, gear_surface));
  EXPECT_TRUE(ic::is_hard_surface(gear_surface));
  for(const Surface_mesh& mesh : {make_mesh<Surface_mesh>(sphere_soup(16)), make_mesh<Surface_mesh>(box_soup())})
  {
    ic::Indexed_surface<Surface_mesh> surface;
    ASSERT_TRUE(indexed(mesh, surface));
    EXPECT_FALSE(ic::is_hard_surface(surface));
  }
}

// The gear's splits (one or more per tooth) go in batches, in one round: a
// valid atlas at E_d at most the default target, from far fewer Newton
// iterations judging splits than one relaxation per split (586 before
// batches; see the bound below) and one final solve after them.
TEST(Hard_surface, a_gear_splits_in_batches_into_a_valid_atlas)
{
  const Surface_mesh gear = cut_benchmark::hard_surface::gear(20, 6, 48, 0.3);
  Cut_run<Surface_mesh> run(gear);
  run.run();
  check_cut_result(gear, run);
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  EXPECT_LT(run.result.relax_newton_iterations, std::size_t(400)); // measured: 176 (586 one split per trial)
}

// A plate with 8x6 holes is cut into 65 overlap-free pieces, more than
// tuning::box_max_pieces: no box's solve (it pushed each piece against its
// own border, 233 Newton iterations, for E_d 4.090 against 4.051 without),
// a valid atlas from a short final solve.
TEST(Hard_surface, a_plate_cut_into_many_pieces_gets_no_box)
{
  const Surface_mesh plate = cut_benchmark::hard_surface::plate(8, 6, 64, 0.1);
  Cut_run<Surface_mesh> run(plate);
  run.run();
  check_cut_result(plate, run);
  EXPECT_GT(run.result.number_of_charts, std::size_t(ic::tuning::box_max_pieces));
  EXPECT_EQ(run.result.box_newton_iterations, std::size_t(0));
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_LT(run.result.newton_iterations, std::size_t(250)); // measured: 143 (376 with the box)
}
