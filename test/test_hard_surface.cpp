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
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/atlas_validity.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/final_solve.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

// The plate with 3x2 holes, indexed, and its initial cut mesh with its
// Tutte map (the start of the pieces' tests).
struct Plate_start
{
  Surface_mesh plate = cut_benchmark::hard_surface::plate(3, 2, 64, 0.1);
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state start;

  bool make()
  {
    if(ic::index_surface(plate, get(CGAL::vertex_point, plate), surface) != ic::Indexing_status::OK) return false;
    start.is_cut.assign(surface.edges.size(), 0);
    return ic::initial_map(surface, start) == SMP::OK;
  }
};

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

// A CAD part cut on a simplified copy (here above 2000 faces) starts its
// final solve from its Tutte map, as one cut at full resolution: from that
// map, with its holes on one circle, the copy's solve under the barrier
// (start_from_solved_copy()) crawled (531 Newton iterations for this plate,
// 12 s; the fast preset cuts on a copy from 2000 faces up).
TEST(Hard_surface, a_plate_cut_on_a_copy_gives_a_valid_atlas_without_the_copys_solve)
{
  const Surface_mesh plate = cut_benchmark::hard_surface::plate(8, 6, 64, 0.1);
  ASSERT_GT(num_faces(plate), std::size_t(2000));
  Cut_run<Surface_mesh> run(plate);
  run.run(SMP::parameters::multiresolution_faces(1000));
  check_cut_result(plate, run);
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_LT(run.result.newton_iterations, std::size_t(300)); // measured: 150 (531 from the copy's solve)
}

// On a hard-surface part the barrier's solve of charts cut into overlap-free
// pieces is capped (Final_solve_args::pieces_max_iterations, set by the
// plan's final_args_on()): the plate's one chart, solved from its Tutte map
// without the barrier, crosses itself and is cut into pieces; their solve
// under the barrier then stops at the cap, below what it takes uncapped, and
// leaves a valid atlas (no flip, no border crossing, disks) near the
// uncapped E_d. An organic mesh keeps the uncapped solve.
TEST(Hard_surface, the_pieces_solve_is_capped_on_a_hard_surface_and_stays_valid)
{
  Plate_start p;
  ASSERT_TRUE(p.make());
  const ic::Indexed_surface<Surface_mesh>& surface = p.surface;
  const ic::Map_state& start = p.start;
  const ic::Final_solve_args defaults;
  EXPECT_EQ(defaults.pieces_max_iterations, 0);
  const ic::Final_solve_args args = ic::final_args_on(surface, defaults);
  ASSERT_EQ(args.pieces_max_iterations, ic::tuning::hard_surface_pieces_newton_iterations);
  const Surface_mesh sphere = make_mesh<Surface_mesh>(sphere_soup(16));
  ic::Indexed_surface<Surface_mesh> sphere_surface;
  ASSERT_TRUE(ic::index_surface(sphere, get(CGAL::vertex_point, sphere), sphere_surface) == ic::Indexing_status::OK);
  EXPECT_EQ(ic::final_args_on(sphere_surface, defaults).pieces_max_iterations, 0);

  // the pieces' solve (final_solve_box() after the cut), capped at `cap` (0: not)
  auto solve = [&](int cap, ic::Map_state& state, std::size_t& iterations) {
    state = start;
    ic::Final_solve_args a = args;
    a.pieces_max_iterations = cap;
    ic::Work_log log;
    ic::Unboxed_final_map unboxed;
    ASSERT_TRUE(ic::final_solve_without_box(surface, a, true, state, log, unboxed) == SMP::OK);
    ASSERT_GT(unboxed.pieces, 1); // cut into pieces
    const std::size_t before = log.final_work.iterations;
    ASSERT_TRUE(ic::final_solve_box(a, unboxed, state, log) == SMP::OK);
    iterations = log.final_work.iterations - before;
  };
  auto valid = [&](const ic::Map_state& state) {
    const std::vector<char> crossing = ic::Border_barrier_term(state.chart).charts_with_crossing(state.x);
    return ic::is_valid_atlas(surface, state) && std::count(crossing.begin(), crossing.end(), char(1)) == 0;
  };
  ic::Map_state uncapped, short_cap, tuned;
  std::size_t uncapped_iterations = 0, short_iterations = 0, tuned_iterations = 0;
  solve(0, uncapped, uncapped_iterations);
  const int cap = 3;
  solve(cap, short_cap, short_iterations);
  solve(ic::tuning::hard_surface_pieces_newton_iterations, tuned, tuned_iterations);
  EXPECT_GT(uncapped_iterations, std::size_t(cap));
  EXPECT_LE(short_iterations, std::size_t(cap));
  EXPECT_LE(tuned_iterations, std::size_t(ic::tuning::hard_surface_pieces_newton_iterations));
  EXPECT_TRUE(valid(uncapped));
  EXPECT_TRUE(valid(short_cap));
  EXPECT_TRUE(valid(tuned));
  EXPECT_LE(ic::mean_distortion(tuned.chart, tuned.x), ic::tuning::default_distortion_target);
}

// The cap is for an E_d that has settled: the plate with 3x2 holes cut into
// overlap-free pieces, each restarted from its Tutte map (E_d far above the
// target, as a crossing piece restarts); capped at a few iterations, their
// solve goes on a cap at a time while E_d stays above the default target
// and falls, and ends below it, valid (one round stops above it).
TEST(Hard_surface, a_capped_pieces_solve_goes_on_while_its_distortion_is_above_the_target)
{
  Plate_start p;
  ASSERT_TRUE(p.make());
  const ic::Indexed_surface<Surface_mesh>& surface = p.surface;
  ic::Map_state state = p.start;
  ic::Final_solve_args args = ic::final_args_on(surface, ic::Final_solve_args{});
  args.box = ic::Box{}; // the pieces' solve alone
  const int cap = 4;
  args.pieces_max_iterations = cap;
  ic::Work_log log;
  ic::Unboxed_final_map unboxed;
  ASSERT_TRUE(ic::final_solve_without_box(surface, args, true, state, log, unboxed) == SMP::OK);
  ASSERT_GT(unboxed.pieces, 1);
  // every piece from its Tutte map, as restart_crossing_charts() puts a crossing one
  ASSERT_TRUE(ic::disk_charts_embedding(state.chart, state.x) == ic::Embedding_status::OK);
  ASSERT_GT(ic::mean_distortion(state.chart, state.x), ic::tuning::default_distortion_target);
  unboxed.restart = true;
  ic::Map_state once = state; // one round of `cap` iterations: above the target
  {
    ic::Final_solve_args one_round = args;
    one_round.max_iterations = cap;
    ic::Work_log l;
    ASSERT_TRUE(ic::final_solve_box(one_round, unboxed, once, l) == SMP::OK);
    ASSERT_GT(ic::mean_distortion(once.chart, once.x), ic::tuning::default_distortion_target);
  }
  const std::size_t before = log.final_work.iterations;
  ASSERT_TRUE(ic::final_solve_box(args, unboxed, state, log) == SMP::OK);
  EXPECT_GT(log.final_work.iterations - before, std::size_t(cap));
  EXPECT_LE(log.final_work.iterations - before, std::size_t(args.max_iterations));
  EXPECT_LE(ic::mean_distortion(state.chart, state.x), ic::tuning::default_distortion_target);
  const std::vector<char> crossing = ic::Border_barrier_term(state.chart).charts_with_crossing(state.x);
  EXPECT_TRUE(ic::is_valid_atlas(surface, state));
  EXPECT_EQ(std::count(crossing.begin(), crossing.end(), char(1)), 0);
}

// Under the fast preset the cuts of a mesh above 2000 faces are decided on a
// copy of fast_multiresolution_faces faces, which cannot hold a CAD part's
// holes and creases (the plate with 20x16 holes: E_d 10.7 against 4.2 by
// default). The plan gives a hard-surface part the default's copy, made as
// the default makes it (CGAL's edge collapse, not the index arrays); an
// organic mesh of the same size, and the default preset, keep theirs.
TEST(Hard_surface, the_fast_preset_gives_a_hard_surface_part_the_default_copy)
{
  const int default_faces = SMP::Cut_parameterization_options().multiresolution_faces;
  SMP::Cut_parameterization_options fast;
  fast.preset = SMP::Preset::FAST;
  fast = SMP::with_preset(fast);
  ASSERT_EQ(fast.multiresolution_faces, SMP::fast_multiresolution_faces);
  ASSERT_LT(SMP::fast_multiresolution_faces, default_faces);

  const Surface_mesh plate = cut_benchmark::hard_surface::plate(8, 6, 64, 0.1);
  ic::Indexed_surface<Surface_mesh> plate_surface;
  ASSERT_TRUE(ic::index_surface(plate, get(CGAL::vertex_point, plate), plate_surface) == ic::Indexing_status::OK);
  ASSERT_GT(plate_surface.number_of_faces(), std::size_t(2 * SMP::fast_multiresolution_faces));
  EXPECT_EQ(ic::options_on(plate_surface, fast).multiresolution_faces, default_faces);
  EXPECT_FALSE(ic::cuts_copy_on_index_arrays(plate_surface, fast));
  SMP::Cut_parameterization_options small_copy = fast; // a copy even smaller, asked for
  small_copy.multiresolution_faces = 700;
  EXPECT_EQ(ic::options_on(plate_surface, small_copy).multiresolution_faces, default_faces);
  SMP::Cut_parameterization_options none = fast; // no copy, asked for
  none.multiresolution_faces = 0;
  EXPECT_EQ(ic::options_on(plate_surface, none).multiresolution_faces, 0);
  const SMP::Cut_parameterization_options defaults;
  SMP::Cut_parameterization_options small_default = defaults;
  small_default.multiresolution_faces = 700;
  EXPECT_EQ(ic::options_on(plate_surface, small_default).multiresolution_faces, 700);

  const Surface_mesh sphere = make_mesh<Surface_mesh>(sphere_soup(30));
  ic::Indexed_surface<Surface_mesh> sphere_surface;
  ASSERT_TRUE(ic::index_surface(sphere, get(CGAL::vertex_point, sphere), sphere_surface) == ic::Indexing_status::OK);
  ASSERT_GT(sphere_surface.number_of_faces(), std::size_t(2 * SMP::fast_multiresolution_faces));
  EXPECT_EQ(ic::options_on(sphere_surface, fast).multiresolution_faces, SMP::fast_multiresolution_faces);
  EXPECT_TRUE(ic::cuts_copy_on_index_arrays(sphere_surface, fast));
}
