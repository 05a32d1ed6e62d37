// Charts whose map overlaps itself much are cut into pieces that do not
// (atlas/overlap_partition.h), instead of being solved again from their Tutte map
// under the border barrier: the overlap test on UV triangles, the pieces of
// a ramp laid flat over three turns, and the final solve that uses them.
#include "generators.h"
#include "test_support.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/overlap_partition.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;
using Kernel = CGAL::Simple_cartesian<double>;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;

namespace {

using Triangle = std::array<ic::Vector2, 3>;

Triangle triangle(double ax, double ay, double bx, double by, double cx, double cy)
{
  return {ic::Vector2(ax, ay), ic::Vector2(bx, by), ic::Vector2(cx, cy)};
}

/// A ramp of three turns (spiral_ramp_soup()), one chart, and its map solved
/// without the border barrier from its Tutte map: laid flat, it winds about
/// three times around the same center.
struct Flat_ramp
{
  Surface_mesh mesh;
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state state;
  ic::Work_log log;

  Flat_ramp()
  {
    build_mesh(spiral_ramp_soup(96, 4, 3.), mesh);
    if(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) != ic::Indexing_status::OK)
      throw std::runtime_error("index_surface");
    state.is_cut.assign(surface.edges.size(), 0);
    ic::build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
    if(ic::disk_charts_embedding(state.chart, state.x) != ic::Embedding_status::OK)
      throw std::runtime_error("disk_charts_embedding");
    const std::vector<double> weights(state.chart.number_of_faces(), 1.);
    ic::Distortion_minimizer(state.chart, weights).minimize(state.x, 500, 1e-9);
  }
};

int number_of_charts(const ic::Chart_mesh& chart)
{
  int charts = 0;
  ic::chart_of_faces(chart, charts);
  return charts;
}

} // namespace

// Touching is not overlapping (a shared edge, the two sides of a slit),
// unless asked for a gap; a shared vertex does not hide an overlap.
TEST(OverlapPartition, triangles_overlap_tells_overlap_from_touch_and_gap)
{
  const Triangle a = triangle(0., 0., 1., 0., 0., 1.);
  EXPECT_FALSE(ic::triangles_overlap(a, triangle(2., 0., 3., 0., 2., 1.), 1e-9));  // apart
  EXPECT_FALSE(ic::triangles_overlap(a, triangle(2., 0., 3., 0., 2., 1.), -0.5));  // 1 apart, more than 0.5
  const Triangle edge_neighbor = triangle(1., 0., 1., 1., 0., 1.);
  EXPECT_FALSE(ic::triangles_overlap(a, edge_neighbor, 1e-9));                       // a shared edge: touching
  EXPECT_TRUE(ic::triangles_overlap(a, edge_neighbor, -0.1));                        // closer than 0.1
  EXPECT_TRUE(ic::triangles_overlap(a, triangle(0.2, 0.2, 1.2, 0.2, 0.2, 1.2), 1e-9)); // across
  EXPECT_TRUE(ic::triangles_overlap(a, triangle(0.1, 0.1, 0.3, 0.1, 0.1, 0.3), 1e-9)); // inside
  // a shared vertex, the second triangle inside the first one's angle there
  // (a fan that turns more than a full turn around a border vertex)
  EXPECT_TRUE(ic::triangles_overlap(a, triangle(0., 0., 0.9, 0.05, 0.05, 0.9), 1e-9));
  EXPECT_FALSE(ic::triangles_overlap(a, triangle(0., 0., -1., 0., 0., -1.), 1e-9)); // the opposite angle
  // 0.05 above a's top corner: apart by more than 0.01, not by more than 0.1
  const Triangle above = triangle(0., 1.05, 1., 1.05, 0., 2.);
  EXPECT_FALSE(ic::triangles_overlap(a, above, 1e-9));
  EXPECT_FALSE(ic::triangles_overlap(a, above, -0.01));
  EXPECT_TRUE(ic::triangles_overlap(a, above, -0.1));
  EXPECT_EQ(ic::triangles_overlap(a, above, -0.1), ic::triangles_overlap(above, a, -0.1));
}

// The ramp laid flat overlaps itself on most of its faces; cut into pieces,
// none overlaps itself or touches itself (the border barrier can start from
// it), every face keeps its UVs, and a piece is about a turn.
TEST(OverlapPartition, pieces_of_a_map_that_overlaps_itself_do_not)
{
  Flat_ramp ramp;
  ic::Map_state& state = ramp.state;
  const std::size_t nf = state.chart.number_of_faces();
  ASSERT_EQ(number_of_charts(state.chart), 1);
  ASSERT_EQ(ic::number_of_flipped_faces(state.chart, state.x), 0);
  const std::vector<std::size_t> before = ic::self_overlapping_face_counts(state.chart, state.x);
  ASSERT_EQ(before.size(), 1u);
  ASSERT_GT(before[0], nf / 2) << "the test map does not overlap itself much";
  EXPECT_EQ(ic::Border_barrier_term(state.chart).charts_with_crossing(state.x), std::vector<char>(1, 1));

  int pieces = 0;
  const std::vector<int> piece = ic::overlap_free_pieces(state.chart, state.x, std::vector<char>(nf, 1), pieces);
  EXPECT_GE(pieces, 3); // three turns
  EXPECT_LE(pieces, 5);
  for(int p : piece) EXPECT_TRUE(p >= 0 && p < pieces);

  const std::vector<int> corner_uv = state.corner_uv;
  const ic::UV_vector x = state.x;
  ASSERT_TRUE(ic::cut_into_overlap_free_pieces(ramp.surface, std::vector<char>(1, 1), state));
  EXPECT_EQ(number_of_charts(state.chart), pieces);
  const std::vector<std::size_t> after = ic::self_overlapping_face_counts(state.chart, state.x);
  EXPECT_EQ(after, std::vector<std::size_t>(std::size_t(pieces), 0));
  EXPECT_EQ(ic::Border_barrier_term(state.chart).charts_with_crossing(state.x), std::vector<char>(std::size_t(pieces), 0));
  EXPECT_EQ(ic::number_of_flipped_faces(state.chart, state.x), 0);
  for(std::size_t c = 0; c < corner_uv.size(); ++c)
    EXPECT_EQ(state.x.segment<2>(2 * state.corner_uv[c]), x.segment<2>(2 * corner_uv[c])) << "corner " << c;
  // each piece is a disk (make_disks())
  const ic::Chart_topology topology = ic::chart_topology(state.chart);
  for(int c = 0; c < topology.number_of_charts; ++c) EXPECT_TRUE(topology.is_disk(c)) << "piece " << c;
}

// Where the pieces would cut a forbidden edge, nothing is cut.
TEST(OverlapPartition, pieces_never_cut_a_forbidden_edge)
{
  Flat_ramp ramp;
  ramp.state.rules.forbidden.assign(ramp.surface.edges.size(), 1);
  const std::vector<char> is_cut = ramp.state.is_cut;
  const ic::UV_vector x = ramp.state.x;
  EXPECT_FALSE(ic::cut_into_overlap_free_pieces(ramp.surface, std::vector<char>(1, 1), ramp.state));
  EXPECT_EQ(ramp.state.is_cut, is_cut);
  EXPECT_EQ(ramp.state.x, x);
}

// The final solve from the ramp's overlapping map: with the pieces, no
// border crosses and the barrier starts from the pieces' own map, in fewer
// Newton iterations than from the Tutte map of the whole ramp; without them
// (overlap_partition_faces 0), one chart from its Tutte map.
TEST(OverlapPartition, the_final_solve_cuts_a_chart_that_overlaps_itself_much)
{
  Flat_ramp pieces, whole;
  ic::Final_solve_args settings = ic::default_run_args(SMP::Cut_parameterization_options()).final;
  settings.overlap_partition_faces = 10;
  ASSERT_EQ(ic::final_solve(pieces.surface, settings, false, pieces.state, pieces.log), SMP::OK);
  settings.overlap_partition_faces = 0;
  ASSERT_EQ(ic::final_solve(whole.surface, settings, false, whole.state, whole.log), SMP::OK);

  EXPECT_GE(number_of_charts(pieces.state.chart), 3);
  EXPECT_EQ(number_of_charts(whole.state.chart), 1);
  for(const ic::Map_state* s : {&pieces.state, &whole.state})
  {
    EXPECT_EQ(ic::number_of_flipped_faces(s->chart, s->x), 0);
    const std::vector<char> crossing = ic::Border_barrier_term(s->chart).charts_with_crossing(s->x);
    EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
  }
  EXPECT_LT(pieces.log.work.iterations, whole.log.work.iterations);
  // the pieces keep the low distortion of the map without the barrier
  EXPECT_LT(ic::mean_distortion(pieces.state.chart, pieces.state.x), ic::mean_distortion(whole.state.chart, whole.state.x));

  // a threshold above the overlapping faces: the whole ramp again
  Flat_ramp high;
  settings.overlap_partition_faces = int(high.state.chart.number_of_faces());
  ASSERT_EQ(ic::final_solve(high.surface, settings, false, high.state, high.log), SMP::OK);
  EXPECT_EQ(number_of_charts(high.state.chart), 1);
}

// Rerouted seams (final_solve_with_rerouting()) are not tried for a map that
// overlaps itself: they would be solved from a Tutte map beside the first
// map's own restart. The map of one turn of the ramp does not overlap itself.
TEST(OverlapPartition, no_rerouted_seams_for_a_map_that_overlaps_itself)
{
  Flat_ramp ramp;
  EXPECT_TRUE(ic::overlaps_itself(true, ramp.state));
  EXPECT_FALSE(ic::overlaps_itself(false, ramp.state)); // without global injectivity

  Surface_mesh mesh;
  build_mesh(spiral_ramp_soup(32, 4, 0.8), mesh);
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  ic::Map_state state;
  state.is_cut.assign(surface.edges.size(), 0);
  ic::build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(state.chart, state.x) == ic::Embedding_status::OK);
  ic::Distortion_minimizer(state.chart, std::vector<double>(state.chart.number_of_faces(), 1.)).minimize(state.x, 500, 1e-9);
  EXPECT_FALSE(ic::overlaps_itself(true, state));
}
