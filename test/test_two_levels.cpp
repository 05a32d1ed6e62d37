// Two levels (pipeline/two_levels.h): on a mesh of a few thousand faces the
// alternation's upper ε levels run on a simplified copy, whose map is
// carried back by undoing its collapses (pipeline/progressive_map.h). The
// carried map must have no flipped face by construction, keep the copy's
// vertices where they were, and the two-level run must give a valid atlas
// (no flip, finite UVs, disks), the same for any thread count. The plan
// does not call it (measured: doc/design/pipeline.dox). The final solve of a
// large mesh starts from a copy of its cut mesh solved and carried back.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/two_levels.h>

#include <algorithm>
#include <limits>
#include <map>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

namespace {

/// A closed torus of 4608 faces, above tuning::two_level_min_faces.
Soup two_level_torus() { return torus_soup(72, 32); }

/// The two-level torus, indexed, with its initial cut mesh (Tutte map).
struct Cut_torus
{
  Surface_mesh mesh = make_mesh<Surface_mesh>(two_level_torus());
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state state;
};

void make_cut_torus(Cut_torus& torus)
{
  ASSERT_TRUE(ic::index_surface(torus.mesh, get(CGAL::vertex_point, torus.mesh), torus.surface)
              == ic::Indexing_status::OK);
  torus.state.is_cut.assign(torus.surface.edges.size(), 0);
  ASSERT_EQ(ic::initial_map(torus.surface, torus.state), SMP::OK);
}

/// The two-level torus with its initial cut mesh (make_cut_torus()) and
/// seam costs 1.
class TwoLevelsTorus : public ::testing::Test
{
protected:
  void SetUp() override
  {
    make_cut_torus(torus);
    face_lambda.assign(surface.number_of_faces(), 1.);
  }

  Cut_torus torus;
  const ic::Indexed_surface<Surface_mesh>& surface = torus.surface;
  std::vector<double> face_lambda;
};

/// The input's initial cut mesh (Tutte map) in `state` and a copy of
/// `faces` faces keeping its cut, its collapses recorded, and the copy's own
/// initial cut mesh in `coarse_state`.
void initial_cut_and_copy(const ic::Indexed_surface<Surface_mesh>& surface, std::size_t faces, ic::Map_state& state,
                          ic::Coarse_surface& coarse, ic::Map_state& coarse_state)
{
  state.is_cut.assign(surface.edges.size(), 0);
  ASSERT_EQ(ic::initial_map(surface, state), SMP::OK);
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  ASSERT_TRUE(ic::simplify_for_carrying(surface, state.is_cut, {}, face_lambda, faces, coarse));
  ASSERT_FALSE(coarse.collapses.empty());
  coarse_state.is_cut = coarse.is_cut;
  ASSERT_EQ(ic::initial_map(coarse.surface, coarse_state), SMP::OK);
  ASSERT_TRUE(coarse_state.is_cut == coarse.is_cut); // the copy is cut where the input is
}

/// The two-level torus, indexed, with its initial cut mesh and a copy of
/// 1000 faces (initial_cut_and_copy()).
class TwoLevelsCopy : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
    initial_cut_and_copy(surface, 1000, state, coarse, coarse_state);
  }

  Surface_mesh mesh = make_mesh<Surface_mesh>(two_level_torus());
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state state, coarse_state;
  ic::Coarse_surface coarse;
};

/// The vertices of `chart` on its border (on an edge of one face), each once.
std::vector<int> border_vertices(const ic::Chart_mesh& chart)
{
  std::map<std::pair<int, int>, int> edge_faces;
  for(const auto& face : chart.faces)
    for(int k = 0; k < 3; ++k)
      ++edge_faces[std::minmax(face[std::size_t(k)], face[std::size_t((k + 1) % 3)])];
  std::vector<int> border;
  for(const auto& [edge, count] : edge_faces)
    if(count == 1) border.insert(border.end(), {edge.first, edge.second});
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());
  return border;
}

} // namespace

// The copy whose map is carried back (simplify_for_carrying()): about the
// faces asked for, the input's seams kept as seams with their vertices,
// every removed vertex recorded once, in a collapse into a vertex of its
// star, and the copy a manifold indexed without defect.
TEST_F(TwoLevelsTorus, the_carried_copy_keeps_the_seams_and_records_every_collapse)
{
  ic::Map_state& state = torus.state;
  ic::Coarse_surface coarse;
  ASSERT_TRUE(ic::simplify_for_carrying(surface, state.is_cut, {}, face_lambda, 1000, coarse));
  const ic::Indexed_surface<ic::Coarse_mesh>& cs = coarse.surface;
  EXPECT_NEAR(double(cs.number_of_faces()), 1000., 100.);
  EXPECT_EQ(coarse.collapses.size(), surface.number_of_vertices() - cs.number_of_vertices());
  const long seams = std::count(state.is_cut.begin(), state.is_cut.end(), char(1));
  ASSERT_GT(seams, 0);
  EXPECT_EQ(std::count(coarse.is_cut.begin(), coarse.is_cut.end(), char(1)), seams);
  std::vector<char> kept(surface.number_of_vertices(), 0), removed(surface.number_of_vertices(), 0);
  for(int v : coarse.fine_vertex) kept[std::size_t(v)] = 1;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(state.is_cut[std::size_t(surface.edge_of[fe])]) EXPECT_TRUE(kept[std::size_t(surface.edge_source(fe))]);
  for(const ic::Collapse& c : coarse.collapses)
  {
    EXPECT_FALSE(removed[std::size_t(c.removed)]);
    removed[std::size_t(c.removed)] = 1;
    EXPECT_FALSE(kept[std::size_t(c.removed)]);
    bool kept_in_star = false;
    for(const auto& s : c.star)
    {
      EXPECT_EQ(s[1], c.removed);
      kept_in_star = kept_in_star || s[0] == c.kept || s[2] == c.kept;
    }
    EXPECT_TRUE(kept_in_star);
    EXPECT_GE(c.star.size(), std::size_t(2));
  }
  EXPECT_EQ(coarse.face_lambda.size(), cs.number_of_faces());
}

// From the copy's Tutte map (many thin triangles: a hard start) and from
// its map after the upper ε levels, the collapses undone give a map of the
// input with no flipped face and no crossing, valid on every chart, that
// leaves each vertex of the copy where the copy had it.
TEST_F(TwoLevelsCopy, carried_map_has_no_flipped_face)
{
  SMP::Cut_parameterization_options o;
  for(int levels : {0, ic::number_of_eps_levels(o) - 1})
  {
    ic::Map_state solved = coarse_state;
    ic::Work_log log;
    if(levels > 0)
    {
      ASSERT_EQ(ic::alternate_levels(coarse.surface, coarse.face_lambda, 1., o, {}, 0, ic::Eps_levels{0, levels},
                                     solved, log),
                SMP::OK);
    }
    ASSERT_EQ(ic::number_of_flipped_faces(solved.chart, solved.x), 0);
    ic::Carried_map carried;
    ASSERT_TRUE(ic::undo_collapses(surface, coarse, solved.chart, solved.x, state.chart, carried));
    EXPECT_TRUE(carried.x.allFinite());
    EXPECT_EQ(ic::number_of_flipped_faces(state.chart, carried.x), 0) << levels << " levels on the copy";
    EXPECT_TRUE(std::all_of(carried.valid.begin(), carried.valid.end(), [](char v) { return v != 0; }));
    // a vertex of the copy (off the cut: one UV vertex) stays where the copy put it
    std::vector<int> fine_uv(surface.number_of_vertices(), -1), coarse_uv(coarse.surface.number_of_vertices(), -1);
    for(std::size_t f = 0; f < surface.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k) fine_uv[std::size_t(surface.corner_vertex[f][k])] = state.chart.faces[f][k];
    for(std::size_t f = 0; f < coarse.surface.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k) coarse_uv[std::size_t(coarse.surface.corner_vertex[f][k])] = solved.chart.faces[f][k];
    std::vector<char> on_cut(surface.number_of_vertices(), 0);
    for(int fe = 0; fe < int(surface.twin.size()); ++fe)
      if(state.is_cut[std::size_t(surface.edge_of[fe])])
        on_cut[std::size_t(surface.edge_source(fe))] = on_cut[std::size_t(surface.edge_target(fe))] = 1;
    int compared = 0;
    for(std::size_t v = 0; v < coarse_uv.size(); ++v)
    {
      const int fine = coarse.fine_vertex[v];
      if(on_cut[std::size_t(fine)]) continue;
      ++compared;
      EXPECT_TRUE(carried.x.segment<2>(2 * fine_uv[std::size_t(fine)]) == solved.x.segment<2>(2 * coarse_uv[v]));
    }
    EXPECT_GT(compared, 100);
  }
}

// The carried map relaxed (relax_carried_map()): from the copy's Tutte map
// carried back (crushed faces), the energy of the flagged chart falls and
// its worst face gets better, no face flips, the border vertices stay where
// they were; a chart not flagged is left as it is.
TEST_F(TwoLevelsCopy, the_carried_map_relaxed_is_less_distorted_and_keeps_its_border)
{
  ic::Carried_map carried;
  ASSERT_TRUE(ic::undo_collapses(surface, coarse, coarse_state.chart, coarse_state.x, state.chart, carried));
  ASSERT_TRUE(carried.valid == std::vector<char>(1, 1));
  const ic::Chart_mesh& chart = state.chart;
  auto energy = [&](const ic::UV_vector& x, double& worst) {
    double sum = 0.;
    worst = 0.;
    for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
    {
      const double psi = ic::symmetric_dirichlet(chart.jacobian(x, f));
      sum += chart.area[f] * psi;
      worst = (std::max)(worst, psi);
    }
    return sum;
  };
  double worst_before = 0., worst_after = 0.;
  const double before = energy(carried.x, worst_before);
  ASSERT_TRUE(std::isfinite(before));
  ASSERT_GT(worst_before, ic::tuning::carried_relaxation_energy); // something to relax

  ic::UV_vector untouched = carried.x;
  ic::relax_carried_map(chart, std::vector<char>(1, 0), untouched);
  EXPECT_TRUE(untouched == carried.x);

  ic::UV_vector relaxed = carried.x;
  ic::relax_carried_map(chart, carried.valid, relaxed);
  EXPECT_TRUE(relaxed.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(chart, relaxed), 0);
  const double after = energy(relaxed, worst_after);
  EXPECT_LT(after, before);
  EXPECT_LT(worst_after, worst_before);
  // the border vertices (those of an edge of one face) have not moved
  const std::vector<int> border = border_vertices(chart);
  for(int v : border) EXPECT_TRUE(relaxed.segment<2>(2 * v) == carried.x.segment<2>(2 * v)) << "border vertex " << v;
  int moved = 0;
  for(int v = 0; v < chart.number_of_vertices; ++v) moved += relaxed.segment<2>(2 * v) != carried.x.segment<2>(2 * v);
  EXPECT_FALSE(border.empty());
  EXPECT_GT(moved, 0);
  const std::vector<char> crossing = ic::Border_barrier_term(chart).charts_with_crossing(relaxed);
  EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
}

// A face crushed by the carrying (tuning::carried_crushed_energy and above)
// is opened again by relax_carried_map() after its sweeps over all
// vertices: no face of the chart is crushed, none flips, the border has not
// moved. On a flat disk's map, a vertex near its middle pressed against the
// opposite edge of one of its faces (10^-7 of its height left, inside its
// fan's kernel), and a single sweep over all vertices, which alone leaves
// that face at an energy of 7e11: the sweeps over the crushed faces' fans
// open it.
TEST(CarriedRelaxation, a_crushed_face_is_opened_again)
{
  Surface_mesh mesh = make_mesh<Surface_mesh>(flat_disk_soup(16, 32));
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  ic::Map_state state;
  state.is_cut.assign(surface.edges.size(), 0);
  ASSERT_EQ(ic::initial_map(surface, state), SMP::OK);
  const ic::Chart_mesh& chart = state.chart;
  ASSERT_EQ(ic::number_of_flipped_faces(chart, state.x), 0);
  auto worst_energy = [&](const ic::UV_vector& x) {
    double worst = 0.;
    for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
      worst = (std::max)(worst, ic::symmetric_dirichlet(chart.jacobian(x, f)));
    return worst;
  };
  // the vertex nearest the map's middle, and a face of its fan
  ic::Vector2 middle = ic::Vector2::Zero();
  for(int v = 0; v < chart.number_of_vertices; ++v) middle += state.x.segment<2>(2 * v);
  middle /= double(chart.number_of_vertices);
  int center = 0;
  for(int v = 1; v < chart.number_of_vertices; ++v)
    if((state.x.segment<2>(2 * v) - middle).norm() < (state.x.segment<2>(2 * center) - middle).norm()) center = v;
  const auto face = std::find_if(chart.faces.begin(), chart.faces.end(), [&](const std::array<int, 3>& f) {
    return std::find(f.begin(), f.end(), center) != f.end();
  });
  ASSERT_TRUE(face != chart.faces.end());
  ic::Vector2 opposite = ic::Vector2::Zero(); // the midpoint of the edge across from the vertex
  for(int v : *face)
    if(v != center) opposite += 0.5 * state.x.segment<2>(2 * v);
  ic::UV_vector crushed = state.x;
  crushed.segment<2>(2 * center) = opposite + 1e-7 * (state.x.segment<2>(2 * center) - opposite);
  ASSERT_EQ(ic::number_of_flipped_faces(chart, crushed), 0);
  ASSERT_GT(worst_energy(crushed), 1e6 * ic::tuning::carried_crushed_energy);

  ic::UV_vector relaxed = crushed;
  ic::relax_carried_map(chart, std::vector<char>(1, 1), relaxed, 1);
  EXPECT_TRUE(relaxed.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(chart, relaxed), 0);
  EXPECT_LE(worst_energy(relaxed), ic::tuning::carried_crushed_energy);
  const std::vector<int> border = border_vertices(chart);
  EXPECT_FALSE(border.empty());
  for(int v : border) EXPECT_TRUE(relaxed.segment<2>(2 * v) == crushed.segment<2>(2 * v)) << "border vertex " << v;
}

// The stage (the plan does not call it: measured worse, doc/design/pipeline.dox)
// gives a valid cut mesh from the carried map: the copy made, cut as the
// input, its map carried; after the input's last ε level and its cuts, a
// map without flip, finite, every chart a disk.
TEST(TwoLevels, two_level_cuts_give_a_valid_cut_mesh)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(two_level_torus());
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  SMP::Cut_parameterization_options o;
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  std::vector<std::vector<char>> cuts;
  std::vector<ic::UV_vector> maps;
  for(int threads : {1, 2})
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
    ic::Map_state state;
    state.is_cut.assign(surface.edges.size(), 0);
    ic::Work_log log;
    SMP::Error_code status = SMP::OK;
    ASSERT_TRUE(ic::decide_cuts_on_two_levels(surface, face_lambda, o.lambda, o, {}, state, log, status));
    ASSERT_EQ(status, SMP::OK);
    EXPECT_TRUE(state.x.allFinite());
    EXPECT_EQ(ic::number_of_flipped_faces(state.chart, state.x), 0);
    const ic::Chart_topology topology = ic::chart_topology(state.chart);
    for(int c = 0; c < topology.number_of_charts; ++c) EXPECT_TRUE(topology.is_disk(c));
    EXPECT_GT(std::count(state.is_cut.begin(), state.is_cut.end(), char(1)), 0);
    cuts.push_back(state.is_cut);
    maps.push_back(state.x);
  }
  // the same on 1 and 2 threads, bit for bit
  EXPECT_TRUE(cuts[0] == cuts[1]);
  EXPECT_TRUE(maps[0].size() == maps[1].size() && maps[0] == maps[1]);
}

// The final solve's start of a large mesh (start_from_solved_copy(), called
// by the plan where the cuts were decided on a copy): the input's cut mesh
// simplified to a copy cut where it is, solved there and carried back. Every
// chart starts from the carried map: no flipped face, no crossing border,
// less distorted than the Tutte map and within 5% of the input's minimum,
// and the input's solve under the
// border barrier converges from it in fewer Newton iterations than from
// the Tutte map, to the same E_d.
TEST_F(TwoLevelsTorus, the_final_solve_starts_from_a_solved_copy)
{
  ic::Map_state& state = torus.state;
  const ic::UV_vector tutte = state.x;
  ic::Work_log log;
  ic::Carried_map from_copy;
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 1000, 1000, ic::Final_solve_args{}, state, log, &from_copy),
            SMP::OK);
  ASSERT_TRUE(from_copy.valid == std::vector<char>(1, 1));
  EXPECT_TRUE(from_copy.x == state.x);
  EXPECT_TRUE(state.x.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(state.chart, state.x), 0);
  const std::vector<char> crossing = ic::Border_barrier_term(state.chart).charts_with_crossing(state.x);
  EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
  const double carried_distortion = ic::mean_distortion(state.chart, state.x);
  EXPECT_LT(carried_distortion, ic::mean_distortion(state.chart, tutte));
  int iterations[2] = {0, 0};
  double distortion[2] = {0., 0.};
  for(int from_copy : {0, 1})
  {
    ic::UV_vector x = from_copy ? state.x : tutte;
    ic::Distortion_minimizer minimizer(state.chart, std::vector<double>(state.chart.number_of_faces(), 1.), true);
    const ic::Newton_report report = minimizer.minimize(x, 500, ic::tuning::constrained_tolerance);
    ASSERT_TRUE(report.ok());
    EXPECT_EQ(ic::number_of_flipped_faces(state.chart, x), 0);
    iterations[from_copy] = report.iterations;
    distortion[from_copy] = ic::mean_distortion(state.chart, x);
  }
  EXPECT_LT(iterations[1], iterations[0]) << "from the copy " << iterations[1] << ", from Tutte " << iterations[0];
  EXPECT_NEAR(distortion[1], distortion[0], 1e-3 * distortion[0]);
  // the carried map is near the input's minimum already
  EXPECT_LT(carried_distortion, 1.05 * distortion[1]);
}

// A large mesh starts from a chain of solved copies, each of
// tuning::solved_copy_level_ratio times the faces of the one that starts its
// solve (solved_copy_faces()): 640k faces from 160k, 40k and 10k; below 8
// times the smallest, one copy of the smallest, as before the chain.
TEST_F(TwoLevelsTorus, the_solved_copies_form_a_chain_on_large_meshes)
{
  EXPECT_EQ(ic::solved_copy_faces(640000, 10000), 160000u);
  EXPECT_EQ(ic::solved_copy_faces(160000, 10000), 40000u);
  EXPECT_EQ(ic::solved_copy_faces(159999, 10000), 40000u);
  EXPECT_EQ(ic::solved_copy_faces(79999, 10000), 10000u);
  EXPECT_EQ(ic::solved_copy_faces(20000, 10000), 10000u);
  EXPECT_EQ(ic::solved_copy_faces(5000, 10000), 10000u);
  EXPECT_EQ(ic::solved_copy_faces(2560000, 10000), 640000u);

  // a copy of 2000 faces started from one of 500: every chart carried, no
  // flip, no crossing border, near the input's minimum as from one copy
  ic::Map_state chain = torus.state, single = torus.state;
  ic::Work_log chain_log, single_log;
  ic::Carried_map from_chain, from_single;
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 500, ic::Final_solve_args{}, chain, chain_log,
                                       &from_chain),
            SMP::OK);
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 2000, ic::Final_solve_args{}, single, single_log,
                                       &from_single),
            SMP::OK);
  ASSERT_TRUE(from_chain.valid == std::vector<char>(1, 1));
  EXPECT_TRUE(chain.x.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(chain.chart, chain.x), 0);
  const std::vector<char> crossing = ic::Border_barrier_term(chain.chart).charts_with_crossing(chain.x);
  EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
  // the chain solved one more copy than the single level
  EXPECT_GT(chain_log.final_work.iterations, 0u);
  EXPECT_FALSE(chain.x == single.x);
  const double chain_distortion = ic::mean_distortion(chain.chart, chain.x);
  const double single_distortion = ic::mean_distortion(single.chart, single.x);
  EXPECT_LT(chain_distortion, 1.02 * single_distortion) << "single copy " << single_distortion;
  EXPECT_LT(chain_distortion, ic::mean_distortion(chain.chart, torus.state.x));
}

// The same start from the cut mesh without a map (initial_cut_mesh(), as
// the plan calls it): no Tutte map is needed where the copy starts every
// chart, and the map is the one started from the Tutte map, bit for bit.
TEST_F(TwoLevelsTorus, a_cut_mesh_without_a_map_starts_from_the_copy_alone)
{
  ic::Map_state with_tutte = torus.state;
  ic::Map_state without_map = torus.state;
  ASSERT_EQ(ic::initial_cut_mesh(surface, without_map), SMP::OK);
  ASSERT_EQ(without_map.x.size(), 0);
  ASSERT_TRUE(without_map.is_cut == with_tutte.is_cut);
  ic::Work_log log;
  ic::Carried_map from_copy[2];
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 1000, 1000, ic::Final_solve_args{}, with_tutte, log,
                                       &from_copy[0]),
            SMP::OK);
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 1000, 1000, ic::Final_solve_args{}, without_map, log,
                                       &from_copy[1]),
            SMP::OK);
  EXPECT_TRUE(from_copy[0].valid == std::vector<char>(1, 1));
  EXPECT_TRUE(from_copy[1].valid == std::vector<char>(1, 1));
  EXPECT_TRUE(without_map.x.size() == with_tutte.x.size() && without_map.x == with_tutte.x);
}

// The barrier from the first solve (final_solve_without_box()): a Tutte
// map above tuning::tutte_restart_max_distortion is too distorted for it,
// but the same map on a chart started from a solved copy (valid in the
// carried map) is not: the carrying crushes a few faces only.
TEST_F(TwoLevelsTorus, a_chart_started_from_the_copy_gets_the_barrier_from_the_first_solve)
{
  const ic::Map_state& state = torus.state;
  const ic::UV_vector shrunk = 0.01 * state.x; // E_d about 1e4
  ASSERT_GT(ic::mean_distortion(state.chart, shrunk), ic::tuning::tutte_restart_max_distortion);
  EXPECT_FALSE(ic::too_distorted_for_the_barrier(state.chart, state.x));
  EXPECT_TRUE(ic::too_distorted_for_the_barrier(state.chart, shrunk));
  ic::Carried_map carried;
  carried.x = shrunk;
  carried.valid.assign(1, 0);
  EXPECT_TRUE(ic::too_distorted_for_the_barrier(state.chart, shrunk, &carried));
  carried.valid.assign(1, 1);
  EXPECT_FALSE(ic::too_distorted_for_the_barrier(state.chart, shrunk, &carried));
}

// The box on a chain of solved copies: decided on the smallest copy (the
// final solve there, its budget judged against the map without box), then
// each larger copy and the input only fit the carried boxed map, by
// carried_box_solve() (at most carried_box_iterations() Newton
// iterations). The carried map says which box it was solved under; without
// a box, none; a chart not carried sends the input back to the full final
// solve.
TEST_F(TwoLevelsTorus, the_box_is_decided_on_the_smallest_copy_and_carried)
{
  ic::Final_solve_args boxed;
  boxed.box.aspect_ratio = 1.;
  boxed.box.stiffness = SMP::gentle_bounding_box_stiffness;
  ic::Map_state with_box = torus.state, without_box = torus.state;
  ic::Work_log box_log, plain_log;
  ic::Carried_map from_boxed, from_plain;
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 500, boxed, with_box, box_log, &from_boxed), SMP::OK);
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 500, ic::Final_solve_args{}, without_box, plain_log,
                                       &from_plain),
            SMP::OK);
  ASSERT_TRUE(from_boxed.valid == std::vector<char>(1, 1));
  ASSERT_TRUE(from_plain.valid == std::vector<char>(1, 1));
  EXPECT_EQ(from_boxed.box_stiffness, SMP::gentle_bounding_box_stiffness); // no budget: kept whole
  EXPECT_EQ(from_plain.box_stiffness, 0.);
  EXPECT_TRUE(ic::carried_under_the_box(from_boxed));
  EXPECT_FALSE(ic::carried_under_the_box(from_plain));
  EXPECT_GT(box_log.box_work.iterations, 0u);
  EXPECT_EQ(plain_log.box_work.iterations, 0u);

  // the copies' box shaped the carried map: it lies in its rectangle more than the map without box
  auto box_energy = [&](const ic::UV_vector& x) {
    ic::Bounding_box_term term(with_box.chart, 1., SMP::gentle_bounding_box_stiffness);
    term.update(x); // its rectangle on this map's border
    return term.value(x);
  };
  EXPECT_LT(box_energy(with_box.x), 0.5 * box_energy(without_box.x));

  // the input's solve fits it in a few iterations, valid
  const double before = ic::mean_distortion(with_box.chart, with_box.x);
  ic::Work_log fit_log;
  ASSERT_EQ(ic::carried_box_solve(boxed, from_boxed.box_stiffness, with_box, fit_log), SMP::OK);
  EXPECT_GT(fit_log.box_work.iterations, 0u);
  EXPECT_LE(fit_log.box_work.iterations, std::size_t(ic::carried_box_iterations(with_box.chart.number_of_faces())));
  EXPECT_TRUE(with_box.x.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(with_box.chart, with_box.x), 0);
  const std::vector<char> crossing = ic::Border_barrier_term(with_box.chart).charts_with_crossing(with_box.x);
  EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
  EXPECT_LT(ic::mean_distortion(with_box.chart, with_box.x), before + 0.05);

  // a chart the copy does not start: the input's own final solve
  ic::Carried_map partly = from_boxed;
  partly.valid.push_back(0);
  EXPECT_FALSE(ic::carried_under_the_box(partly));
}

// final_solve_from_carried(), the plan's and each copy's start from a solved
// copy: a map solved under the box is only fitted (within
// carried_box_iterations()), unless its E_d ends above the limit,
// then the whole final solve runs from it; a map solved without box gets
// the whole final solve. Each result valid, the box it was solved under told.
TEST_F(TwoLevelsTorus, a_start_from_a_solved_copy_is_fitted_under_its_box_or_solved_whole)
{
  ic::Final_solve_args boxed;
  boxed.box.aspect_ratio = 1.;
  boxed.box.stiffness = SMP::gentle_bounding_box_stiffness;
  ic::Map_state start = torus.state, plain_start = torus.state;
  ic::Work_log copy_log;
  ic::Carried_map from_boxed, from_plain;
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 500, boxed, start, copy_log, &from_boxed), SMP::OK);
  ASSERT_EQ(ic::start_from_solved_copy(surface, face_lambda, 2000, 500, ic::Final_solve_args{}, plain_start, copy_log,
                                       &from_plain),
            SMP::OK);
  ASSERT_TRUE(ic::carried_under_the_box(from_boxed));
  ASSERT_FALSE(ic::carried_under_the_box(from_plain));
  auto valid = [](const ic::Map_state& s) {
    const std::vector<char> crossing = ic::Border_barrier_term(s.chart).charts_with_crossing(s.x);
    return s.x.allFinite() && ic::number_of_flipped_faces(s.chart, s.x) == 0
           && std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; });
  };

  // no limit: the fit alone
  ic::Map_state fitted = start;
  ic::Work_log fit_log;
  double stiffness = -1.;
  ASSERT_EQ(ic::final_solve_from_carried(surface, boxed, true, from_boxed, std::numeric_limits<double>::infinity(),
                                         fitted, fit_log, &stiffness),
            SMP::OK);
  EXPECT_EQ(stiffness, from_boxed.box_stiffness);
  EXPECT_GT(fit_log.box_work.iterations, 0u);
  EXPECT_LE(fit_log.box_work.iterations, std::size_t(ic::carried_box_iterations(fitted.chart.number_of_faces())));
  EXPECT_EQ(fit_log.final_work.iterations, 0u);
  EXPECT_TRUE(valid(fitted));

  // a limit below any E_d (4 is the least): the fit, then the whole final solve from it
  ic::Map_state whole = start;
  ic::Work_log whole_log;
  ASSERT_EQ(ic::final_solve_from_carried(surface, boxed, true, from_boxed, 4., whole, whole_log, &stiffness), SMP::OK);
  EXPECT_GT(whole_log.final_work.iterations, 0u);
  EXPECT_GT(whole_log.box_work.iterations, fit_log.box_work.iterations);
  EXPECT_TRUE(valid(whole));

  // solved without box: the whole final solve from the carried map, no box asked, none told
  ic::Map_state plain = plain_start;
  ic::Work_log plain_log;
  ASSERT_EQ(ic::final_solve_from_carried(surface, ic::Final_solve_args{}, true, from_plain,
                                         std::numeric_limits<double>::infinity(), plain, plain_log, &stiffness),
            SMP::OK);
  EXPECT_EQ(stiffness, 0.);
  EXPECT_GT(plain_log.final_work.iterations, 0u);
  EXPECT_EQ(plain_log.box_work.iterations, 0u);
  EXPECT_TRUE(valid(plain));
}
