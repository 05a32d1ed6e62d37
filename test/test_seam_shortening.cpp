// Seam shortening under a distortion bound (internal seam_straightening.h
// and seam_merging.h): a zigzag seam on a flat grid is rerouted along the
// straight row beside it (shorter, same ends, every chart still a disk),
// around forbidden edges, never moving the user's seams; a seam from the
// border may end at the border vertex nearest its tip; a slit opened by a
// Tutte map is pulled shut and zipped without flipping a face; a bounded
// run never ends above its bound; and without a bound, the final solve keeps
// rerouted seams only where E_d stays within the allowance.
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_merging.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_straightening.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

namespace {

const int N = 12; // grid of N x N squares on the unit square

/// The indexed N x N grid and a way to name its edges by grid coordinates.
struct Grid
{
  Surface_mesh mesh;
  ic::Indexed_surface<Surface_mesh> surface;

  /// `bump`: height of a Gaussian bump centred at (0.3, 0.65), just above
  /// the row y = 7/N (0: flat), so that moving a seam changes the distortion
  explicit Grid(double bump = 0.)
  {
    Soup soup = grid_soup(N, N);
    for(Soup::Point& p : soup.points)
      p[2] = bump * std::exp(-((p[0] - 0.3) * (p[0] - 0.3) + (p[1] - 0.65) * (p[1] - 0.65)) / 0.01);
    build_mesh(soup, mesh);
    index_ok = ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK;
  }
  bool index_ok = false;

  int vertex(int i, int j) const
  {
    for(int v = 0; v < int(surface.number_of_vertices()); ++v)
      if(std::abs(surface.points[v].x() - double(i) / N) < 1e-9 && std::abs(surface.points[v].y() - double(j) / N) < 1e-9)
        return v;
    return -1;
  }
  /// Edge between grid points (i, j) and (k, l); -1 if none.
  int edge(std::array<int, 2> a, std::array<int, 2> b) const
  {
    const int va = vertex(a[0], a[1]), vb = vertex(b[0], b[1]);
    for(int fe = 0; fe < int(surface.twin.size()); ++fe)
      if((surface.edge_source(fe) == va && surface.edge_target(fe) == vb)
         || (surface.edge_source(fe) == vb && surface.edge_target(fe) == va))
        return surface.edge_of[fe];
    return -1;
  }
  /// Cut flags of the path through `points`.
  std::vector<char> path(const std::vector<std::array<int, 2>>& points) const
  {
    std::vector<char> cut(surface.edges.size(), 0);
    for(std::size_t k = 0; k + 1 < points.size(); ++k)
    {
      const int e = edge(points[k], points[k + 1]);
      if(e >= 0) cut[e] = 1;
    }
    return cut;
  }
  double length(const std::vector<char>& cut) const { return ic::seam_length_3d(surface, cut); }
  bool charts_are_one_disk(const std::vector<char>& cut) const
  {
    ic::Chart_mesh chart;
    std::vector<int> corner_uv;
    ic::build_chart_mesh(surface, cut, chart, corner_uv);
    const ic::Chart_topology topology = ic::chart_topology(chart);
    return topology.number_of_charts == 1 && topology.is_disk(0);
  }
};

/// A square wave from the left border (0, 6) to the tip (6, 6): 10 edges.
const std::vector<std::array<int, 2>> wave = {{0, 6}, {1, 6}, {1, 7}, {2, 7}, {2, 6}, {3, 6},
                                              {3, 7}, {4, 7}, {4, 6}, {5, 6}, {6, 6}};

/// Seam edges at vertex v.
int seam_degree(const Grid& g, const std::vector<char>& cut, int v)
{
  int d = 0;
  for(int fe = 0; fe < int(g.surface.twin.size()); ++fe)
    if(g.surface.twin[fe] > fe && cut[g.surface.edge_of[fe]]
       && (g.surface.edge_source(fe) == v || g.surface.edge_target(fe) == v))
      ++d;
  return d;
}

} // namespace

TEST(Seam_shortening, a_zigzag_seam_is_rerouted_along_the_straight_row)
{
  const Grid g;
  ASSERT_TRUE(g.index_ok);
  std::vector<char> cut = g.path(wave);
  ASSERT_EQ(std::count(cut.begin(), cut.end(), 1), 10);
  ASSERT_TRUE(g.charts_are_one_disk(cut));
  const double before = g.length(cut);

  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 2, cut), 1);
  EXPECT_NEAR(g.length(cut), 6. / N, 1e-12); // the straight row from (0, 6) to (6, 6)
  EXPECT_LT(g.length(cut), before);
  EXPECT_TRUE(g.charts_are_one_disk(cut));
  EXPECT_EQ(seam_degree(g, cut, g.vertex(6, 6)), 1); // the tip stays where it was
  EXPECT_TRUE(cut[g.edge({5, 6}, {6, 6})]);
  // straight already: nothing more to do
  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 2, cut), 0);
}

TEST(Seam_shortening, forbidden_edges_and_given_seams_are_respected)
{
  const Grid g;
  ASSERT_TRUE(g.index_ok);
  ic::Cut_rules rules;
  rules.forbidden.assign(g.surface.edges.size(), 0);
  rules.forbidden[g.edge({3, 6}, {4, 6})] = 1; // on the straight row, not on the wave
  std::vector<char> cut = g.path(wave);
  const double before = g.length(cut);
  ic::straighten_seams(g.surface, rules, {}, 2, cut);
  EXPECT_FALSE(cut[g.edge({3, 6}, {4, 6})]);
  EXPECT_LT(g.length(cut), before); // shorter elsewhere still
  EXPECT_TRUE(g.charts_are_one_disk(cut));

  // the wave given by the user (`keep`) is never moved
  std::vector<char> given = g.path(wave);
  std::vector<char> kept = given;
  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), given, 2, kept), 0);
  EXPECT_EQ(kept, given);
}

TEST(Seam_shortening, a_seam_from_the_border_may_end_elsewhere_on_it)
{
  const Grid g;
  ASSERT_TRUE(g.index_ok);
  // from the left border at (0, 9) down to the tip (2, 6); the border point
  // nearest the tip is (0, 6), two edges away
  const std::vector<std::array<int, 2>> hook = {{0, 9}, {1, 9}, {1, 8}, {1, 7}, {2, 7}, {2, 6}};
  std::vector<char> fixed_ends = g.path(hook), sliding = g.path(hook);
  ASSERT_EQ(std::count(sliding.begin(), sliding.end(), 1), 5);
  ASSERT_TRUE(g.charts_are_one_disk(sliding));

  // its ends fixed, the path stays between (0, 9) and (2, 6)
  ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 3, fixed_ends);
  EXPECT_GE(seam_degree(g, fixed_ends, g.vertex(0, 9)), 1);
  EXPECT_GT(g.length(fixed_ends), 2.5 / N);

  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 3, sliding, true), 1);
  EXPECT_NEAR(g.length(sliding), 2. / N, 1e-12); // (2, 6) -> (1, 6) -> (0, 6)
  EXPECT_TRUE(sliding[g.edge({0, 6}, {1, 6})]);
  EXPECT_EQ(seam_degree(g, sliding, g.vertex(0, 9)), 0);
  EXPECT_EQ(seam_degree(g, sliding, g.vertex(2, 6)), 1); // the tip stays where it was
  EXPECT_TRUE(g.charts_are_one_disk(sliding));
  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 3, sliding, true), 0);

  // never onto another seam: with a seam given from (0, 6) to (1, 8), a path
  // from (0, 2) up to the tip (2, 6) ends at (0, 5) through (1, 5), not at
  // (0, 6) (two edges away), and the given seam stays
  const std::vector<std::array<int, 2>> up = {{0, 2}, {1, 2}, {1, 3}, {2, 3}, {2, 4}, {2, 5}, {2, 6}};
  const std::vector<char> given = g.path({{0, 6}, {1, 7}, {1, 8}});
  ASSERT_EQ(std::count(given.begin(), given.end(), 1), 2);
  std::vector<char> both = g.path(up);
  for(std::size_t e = 0; e < both.size(); ++e) both[e] = both[e] || given[e];
  ASSERT_TRUE(g.charts_are_one_disk(both));
  EXPECT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), given, 3, both, true), 1);
  for(std::size_t e = 0; e < both.size(); ++e)
    if(given[e]) EXPECT_TRUE(both[e]);
  EXPECT_NEAR(g.length(both) - g.length(given), (1. + std::sqrt(2.)) / N, 1e-12);
  EXPECT_TRUE(both[g.edge({2, 6}, {1, 5})]);
  EXPECT_EQ(seam_degree(g, both, g.vertex(0, 6)), 1); // the given seam's alone
  EXPECT_EQ(seam_degree(g, both, g.vertex(0, 5)), 1);
  EXPECT_EQ(seam_degree(g, both, g.vertex(2, 6)), 1);
  EXPECT_TRUE(g.charts_are_one_disk(both));
}

TEST(Seam_shortening, the_final_solve_keeps_rerouted_seams_within_the_allowance)
{
  const Grid g(0.15); // a bump: a seam moved off it costs distortion
  ASSERT_TRUE(g.index_ok);
  ic::Map_state start;
  start.is_cut = g.path(wave);
  ic::build_chart_mesh(g.surface, start.is_cut, start.chart, start.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(start.chart, start.x) == ic::Embedding_status::OK);
  ic::Run_args settings = ic::default_run_args(SMP::Cut_parameterization_options());
  ASSERT_EQ(settings.rerouting_rings, 1);
  ic::Work_log wave_log, row_log, log;

  // the wave's own final solve (from its map, as after the alternation), and
  // its straight row's (rerouted within a ring, from a Tutte map)
  ic::Map_state wave_solved = start;
  ASSERT_EQ(ic::final_solve(g.surface, settings.final, false, wave_solved, wave_log), SMP::OK);
  const double wave_distortion = ic::mean_distortion(wave_solved.chart, wave_solved.x);
  ic::Map_state row_solved = start;
  ASSERT_EQ(ic::straighten_seams(g.surface, ic::Cut_rules(), {}, 1, row_solved.is_cut), 1);
  ic::build_chart_mesh(g.surface, row_solved.is_cut, row_solved.chart, row_solved.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(row_solved.chart, row_solved.x) == ic::Embedding_status::OK);
  ASSERT_EQ(ic::final_solve(g.surface, settings.final, true, row_solved, row_log), SMP::OK);
  const double row_distortion = ic::mean_distortion(row_solved.chart, row_solved.x);
  ASSERT_LT(g.length(row_solved.is_cut), g.length(start.is_cut));
  // away from the bump the straight row costs distortion (what makes the next checks tell)
  ASSERT_GT(row_distortion, wave_distortion);

  // an allowance above that cost: the straight row, solved, without flips
  settings.rerouting_allowance = 2. * (row_distortion - wave_distortion);
  ic::Map_state generous = start;
  ic::Work_log generous_log;
  ASSERT_EQ(ic::final_solve_rerouted(g.surface, settings.final, settings, {}, false, generous, generous_log), SMP::OK);
  EXPECT_EQ(generous.is_cut, row_solved.is_cut);
  EXPECT_NEAR(ic::mean_distortion(generous.chart, generous.x), row_distortion, 1e-12);
  EXPECT_EQ(ic::number_of_flipped_faces(generous.chart, generous.x), 0);
  // both solves counted
  EXPECT_EQ(generous_log.work.iterations, wave_log.work.iterations + row_log.work.iterations);

  // an allowance below it: the wave and its own map
  settings.rerouting_allowance = 0.5 * (row_distortion - wave_distortion);
  ic::Map_state strict = start;
  ASSERT_EQ(ic::final_solve_rerouted(g.surface, settings.final, settings, {}, false, strict, log), SMP::OK);
  EXPECT_EQ(strict.is_cut, start.is_cut);
  EXPECT_NEAR(ic::mean_distortion(strict.chart, strict.x), wave_distortion, 1e-12);

  // the user's seams (`keep`) are never rerouted; seams solved from a Tutte
  // map (carried from a simplified copy) are not either; no rings, no rerouting
  settings.rerouting_allowance = 1.;
  ic::Map_state given = start;
  ASSERT_EQ(ic::final_solve_rerouted(g.surface, settings.final, settings, start.is_cut, false, given, log), SMP::OK);
  EXPECT_EQ(given.is_cut, start.is_cut);
  ic::Map_state carried = start;
  ASSERT_EQ(ic::final_solve_rerouted(g.surface, settings.final, settings, {}, true, carried, log), SMP::OK);
  EXPECT_EQ(carried.is_cut, start.is_cut);
  settings.rerouting_rings = 0;
  ic::Map_state off = start;
  ASSERT_EQ(ic::final_solve_rerouted(g.surface, settings.final, settings, {}, false, off, log), SMP::OK);
  EXPECT_EQ(off.is_cut, start.is_cut);
}

TEST(Seam_shortening, a_slit_is_pulled_shut_and_zipped_without_flips)
{
  const Grid g;
  ASSERT_TRUE(g.index_ok);
  ic::Map_state state;
  state.is_cut = g.path(wave);
  ic::build_chart_mesh(g.surface, state.is_cut, state.chart, state.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(state.chart, state.x) == ic::Embedding_status::OK);
  ASSERT_EQ(ic::number_of_flipped_faces(state.chart, state.x), 0);
  // the slit's copies of the vertex next to the tip are apart in the Tutte map
  const std::vector<ic::Seam_path> branches = ic::seam_branches(g.surface, state.is_cut, {});
  ASSERT_EQ(branches.size(), std::size_t(1));
  ASSERT_EQ(branches[0].vertices.front(), g.vertex(6, 6));

  for(std::size_t k : {std::size_t(3), branches[0].edges.size() - 1})
  {
    SCOPED_TRACE("zipped edges " + to_text(k));
    ic::Map_state zipped;
    ic::Work_log log;
    const std::vector<int> edges(branches[0].edges.begin(), branches[0].edges.begin() + k);
    ASSERT_TRUE(ic::zip_seam(g.surface, state, edges, zipped, log));
    EXPECT_EQ(ic::number_of_flipped_faces(zipped.chart, zipped.x), 0);
    EXPECT_TRUE(zipped.x.allFinite());
    EXPECT_EQ(zipped.chart.number_of_vertices, state.chart.number_of_vertices - int(k));
    EXPECT_NEAR(g.length(zipped.is_cut), g.length(state.is_cut) - ic::seam_length_3d(g.surface, [&] {
                  std::vector<char> c(g.surface.edges.size(), 0);
                  for(int e : edges) c[e] = 1;
                  return c;
                }()), 1e-12);
  }
  // zipping the whole slit leaves no seam; the grid is a disk without it
  ic::Map_state whole;
  ic::Work_log log;
  EXPECT_TRUE(ic::zip_seam(g.surface, state, branches[0].edges, whole, log));
  EXPECT_EQ(ic::number_of_flipped_faces(whole.chart, whole.x), 0);
}

TEST(Seam_shortening, springs_close_the_gap_and_keep_faces_valid)
{
  const Grid g;
  ASSERT_TRUE(g.index_ok);
  ic::Chart_mesh chart;
  std::vector<int> corner_uv;
  const std::vector<char> cut = g.path(wave);
  ic::build_chart_mesh(g.surface, cut, chart, corner_uv);
  ic::UV_vector x;
  ASSERT_TRUE(ic::disk_charts_embedding(chart, x) == ic::Embedding_status::OK);
  // the pairs: the copies of each slit vertex but the tip
  std::vector<ic::Seam_path> branches = ic::seam_branches(g.surface, cut, {});
  ASSERT_EQ(branches.size(), std::size_t(1));
  ic::Chart_mesh uncut;
  std::vector<int> uncut_corner_uv;
  ic::build_chart_mesh(g.surface, std::vector<char>(g.surface.edges.size(), 0), uncut, uncut_corner_uv);
  std::vector<std::array<int, 2>> pairs;
  ic::joined_positions(corner_uv, x, uncut_corner_uv, uncut.number_of_vertices, pairs);
  ASSERT_EQ(pairs.size(), std::size_t(10)); // the wave's vertices but its tip
  ic::Seam_closing_term springs(pairs, 1.);
  const double gap = springs.largest_gap(x);
  ASSERT_GT(gap, 1e-2 / N);
  std::size_t iterations = 0, factorizations = 0;
  ASSERT_TRUE(ic::pull_pairs_together(chart, pairs, x, iterations, factorizations));
  EXPECT_GT(iterations, std::size_t(0));
  EXPECT_LT(springs.largest_gap(x), 1e-2 * gap);
  EXPECT_EQ(ic::number_of_flipped_faces(chart, x), 0);
  EXPECT_TRUE(x.allFinite());
}

template <typename Mesh>
class Seam_shortening_runs : public ::testing::Test
{
};
TYPED_TEST_SUITE(Seam_shortening_runs, Mesh_types);

TYPED_TEST(Seam_shortening_runs, bounded_runs_stay_within_their_bound)
{
  // a spherical cap to 150 degrees: it needs seams, and bounds leave room to shorten them
  const TypeParam mesh = make_mesh<TypeParam>(sphere_cap_soup(10, 32, 5. * pi / 6.));
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  ASSERT_GT(plain.result.distortion, 4.2);
  for(double bound : {plain.result.distortion + 0.05, 4.2})
  {
    SCOPED_TRACE("bound " + to_text(bound));
    Cut_run<TypeParam> bounded(mesh);
    bounded.run(SMP::parameters::distortion_bound(bound));
    check_cut_result(mesh, bounded);
    EXPECT_TRUE(bounded.result.distortion_bound_met);
    EXPECT_LE(bounded.result.distortion, bound);
  }
}
