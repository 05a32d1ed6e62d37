// Low-poly inputs, where the field v cannot place cuts (a face spans a
// whole feature, the curvature sits in a few vertices): the greedy splits
// bring a cube, a box and an octahedron close to their nets by default, and
// keep off forbidden edges; a cube meets tight bounds. (The splits under a
// bound that no λ reaches run in test_distortion_bound's unreachable bound.)
// With CGAL's data set, the low-poly models of issue 12 reach E_d <= 4.5 by
// default, and <= 4.2 under that bound with fewer charts than xatlas makes.
// Every result is a valid atlas (check_cut_result(): no flip, no crossing
// border, disks). The split step keeps the first candidate accepted, or
// (best_candidate, the bound search's second split trial) the one that
// lowers E_d the most per unit of seam length, and counts every
// candidate's work either way.
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/greedy_splits.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/relax.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

template <typename Mesh>
class Low_poly : public ::testing::Test
{
};
TYPED_TEST_SUITE(Low_poly, Mesh_types);

namespace {

// E_d of the default run of the paper's method alone on these models: the
// cube 6.53, the octahedron 6.21 (CGAL's cube.off and octahedron.off)
constexpr double default_target = 4.5;

template <typename Mesh>
Chart_report<Mesh> run_and_check(const Mesh& mesh, Cut_run<Mesh>& run, double bound = 0.)
{
  if(bound > 0.) run.run(SMP::parameters::distortion_bound(bound));
  else run.run();
  return check_cut_result(mesh, run);
}

} // namespace

TYPED_TEST(Low_poly, polyhedra_unfold_close_to_their_nets)
{
  for(const auto& [name, soup] : std::map<std::string, Soup>{{"cube", box_soup()},
                                                            {"box 1x2x3", box_soup(1., 2., 3.)},
                                                            {"octahedron", sphere_soup(1)}})
  {
    SCOPED_TRACE(name);
    const TypeParam mesh = make_mesh<TypeParam>(soup);
    Cut_run<TypeParam> run(mesh);
    const Chart_report<TypeParam> charts = run_and_check(mesh, run);
    EXPECT_LE(run.result.distortion, default_target);
    EXPECT_EQ(charts.number_of_charts, 1u); // a net, not a chart per side
  }
}

TYPED_TEST(Low_poly, a_cube_meets_tight_bounds)
{
  const TypeParam mesh = make_mesh<TypeParam>(box_soup());
  for(double bound : {4.2, 4.05})
  {
    SCOPED_TRACE("bound " + to_text(bound));
    Cut_run<TypeParam> run(mesh);
    run_and_check(mesh, run, bound);
    EXPECT_TRUE(run.result.distortion_bound_met);
    EXPECT_LE(run.result.distortion, bound);
  }
}

TYPED_TEST(Low_poly, splits_keep_off_forbidden_edges)
{
  // the edges of the cube's top side may not be cut: the splits reach its
  // corners through the vertical edges (the net is a cross around the top)
  const TypeParam mesh = make_mesh<TypeParam>(box_soup());
  auto vpm = get(CGAL::vertex_point, mesh);
  std::unordered_map<typename boost::graph_traits<TypeParam>::edge_descriptor, bool> forbidden;
  for(auto e : edges(mesh))
    forbidden[e] = CGAL::to_double(get(vpm, source(e, mesh)).z()) == 1. && CGAL::to_double(get(vpm, target(e, mesh)).z()) == 1.;
  Cut_run<TypeParam> run(mesh);
  run.run(SMP::parameters::forbidden_seam_edge_map(boost::make_assoc_property_map(forbidden)));
  check_cut_result(mesh, run);
  for(auto e : edges(mesh)) EXPECT_FALSE(run.is_seam(e) && forbidden.at(e));
  EXPECT_LE(run.result.distortion, default_target);
}

namespace {

template <typename Mesh>
bool read_cgal_model(const std::string& name, Mesh& mesh)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) return false;
  if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/" + name), mesh) || num_faces(mesh) == 0) return false;
  return CGAL::Polygon_mesh_processing::triangulate_faces(mesh); // pyramid.off has a square side
}

} // namespace

TYPED_TEST(Low_poly, cgal_low_poly_models)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) GTEST_SKIP() << "CGAL_DATA_DIR not set";
  // charts of xatlas on the three models issue 12 measured it on
  const std::map<std::string, std::size_t> xatlas_charts{{"cross.off", 14}, {"joint.off", 18}, {"part.off", 11}};
  for(const std::string name : {"cube.off", "cross.off", "octahedron.off", "icosahedron.off", "pyramid.off",
                                "hedra.off", "joint.off", "part.off"})
  {
    SCOPED_TRACE(name);
    TypeParam mesh;
    ASSERT_TRUE(read_cgal_model(name, mesh)) << "cannot read " << name;
    Cut_run<TypeParam> plain(mesh);
    run_and_check(mesh, plain);
    EXPECT_LE(plain.result.distortion, default_target);
    Cut_run<TypeParam> bounded(mesh);
    const Chart_report<TypeParam> charts = run_and_check(mesh, bounded, 4.2);
    EXPECT_TRUE(bounded.result.distortion_bound_met);
    EXPECT_LE(bounded.result.distortion, 4.2);
    const auto xatlas = xatlas_charts.find(name);
    if(xatlas != xatlas_charts.end()) EXPECT_LT(charts.number_of_charts, xatlas->second);
  }
}

namespace {

/// `surface` indexed from `mesh`, and `state` its uncut Tutte map (one
/// circle per component) with its E_d: the start of the split tests.
void uncut_tutte_start(const Surface_mesh& mesh, ic::Indexed_surface<Surface_mesh>& surface, ic::Map_state& state)
{
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  state.is_cut.assign(surface.edges.size(), 0);
  ic::build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(state.chart, state.x) == ic::Embedding_status::OK);
  state.distortion = ic::mean_distortion(state.chart, state.x);
}

} // namespace

// One split of a hemisphere's Tutte map among the three most distorted
// vertices, judged by a stand-in solve that makes the second candidate
// lower E_d 100 times more per unit of seam length than the others.
TEST(Greedy_splits, the_best_candidate_or_the_first_accepted_is_kept)
{
  Surface_mesh mesh;
  build_mesh(hemisphere_soup(8, 24), mesh);
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state start;
  ASSERT_NO_FATAL_FAILURE(uncut_tutte_start(mesh, surface, start));

  for(bool best : {false, true})
  {
    SCOPED_TRACE(best ? "best candidate" : "first accepted");
    ic::Split_settings settings;
    settings.max_splits = 1;
    settings.candidates = 3;
    settings.best_candidate = best;
    std::vector<std::vector<char>> judged; // the cut of each candidate, in the order judged
    ic::Work_log log;
    auto solve = [&](ic::Map_state& trial, ic::Work_log& trial_log, const std::vector<char>& faces) {
      // the faces to solve: those on the candidate's new cut, and only those
      EXPECT_EQ(faces, ic::faces_on_new_cuts(surface, start.is_cut, trial.is_cut));
      EXPECT_NE(std::count(faces.begin(), faces.end(), char(1)), 0);
      const double added = ic::seam_length_3d(surface, trial.is_cut);
      trial.distortion = start.distortion - (judged.size() == 1 ? 1. : 0.01) * added;
      trial_log.work.iterations += 10; // the work of a judgment
      judged.push_back(trial.is_cut);
      return SMP::OK;
    };
    auto accept = [](double before, double after, double) { return after < before; };
    ic::Map_state state = start;
    int kept = 0;
    ASSERT_EQ(ic::split_greedily(surface, settings, 0., solve, accept, state, log, kept), SMP::OK);
    EXPECT_EQ(kept, 1);
    ASSERT_EQ(judged.size(), best ? std::size_t(3) : std::size_t(1));
    EXPECT_EQ(state.is_cut, judged[best ? 1 : 0]);
    EXPECT_GT(ic::seam_length_3d(surface, state.is_cut), 0.);
    EXPECT_EQ(log.work.iterations, 10 * judged.size()); // every judgment counted
    if(best)
    {
      EXPECT_NE(judged[0], judged[1]);
      EXPECT_NE(judged[1], judged[2]);
    }
  }
}

// A batch (Split_settings::batch): the most distorted vertices whose paths
// do not meet, cut in one trial, judged once and kept together.
TEST(Greedy_splits, a_batch_is_cut_and_judged_in_one_trial)
{
  Surface_mesh mesh;
  build_mesh(hemisphere_soup(8, 24), mesh);
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state state;
  ASSERT_NO_FATAL_FAILURE(uncut_tutte_start(mesh, surface, state));
  ic::Split_settings settings;
  settings.max_splits = 4;
  settings.batch = 4;
  int judged = 0;
  std::vector<char> first_cut;
  ic::Work_log log;
  auto solve = [&](ic::Map_state& trial, ic::Work_log&, const std::vector<char>&) {
    if(judged++ == 0) first_cut = trial.is_cut;
    trial.distortion = 4.; // every trial pays
    return SMP::OK;
  };
  auto accept = [](double before, double after, double) { return after < before; };
  int kept = 0;
  ASSERT_EQ(ic::split_greedily(surface, settings, 4.5, solve, accept, state, log, kept), SMP::OK);
  EXPECT_EQ(judged, 1); // one trial: E_d 4 is below the stop
  EXPECT_GE(kept, 2);
  EXPECT_LE(kept, 4);
  EXPECT_EQ(state.is_cut, first_cut);
  EXPECT_GT(ic::seam_length_3d(surface, state.is_cut), 0.);
}

// relax_charts() solves the charts holding a flagged face and leaves the
// others' map as it was; E_d is that of the whole map.
TEST(Greedy_splits, relax_charts_solves_the_flagged_charts_alone)
{
  Surface_mesh mesh;
  build_mesh(two_components_soup(6), mesh);
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Map_state s;
  ASSERT_NO_FATAL_FAILURE(uncut_tutte_start(mesh, surface, s)); // circles: distorted
  int charts = 0;
  const std::vector<int> chart_of_face = ic::chart_of_faces(s.chart, charts);
  ASSERT_EQ(charts, 2);
  std::vector<char> flagged(s.chart.number_of_faces(), 0);
  flagged[0] = 1;
  const ic::UV_vector before = s.x;
  const double distortion_before = ic::mean_distortion(s.chart, s.x);
  ic::Work_log log;
  ASSERT_EQ(ic::relax_charts(30, 1e-9, SMP::Inner_solver::NEWTON, flagged, s, log), SMP::OK);
  EXPECT_LT(s.distortion, distortion_before);
  EXPECT_DOUBLE_EQ(s.distortion, ic::mean_distortion(s.chart, s.x));
  EXPECT_GT(log.work.iterations, std::size_t(0));
  for(std::size_t f = 0; f < s.chart.number_of_faces(); ++f)
    for(int v : s.chart.faces[f])
    {
      const bool moved = s.x.segment<2>(2 * v) != before.segment<2>(2 * v);
      if(chart_of_face[f] != chart_of_face[0]) EXPECT_FALSE(moved) << "face " << f << " of the other chart moved";
    }
  // no flag: the whole map, as relax_map()
  ic::Map_state whole = s;
  ASSERT_EQ(ic::relax_charts(30, 1e-9, SMP::Inner_solver::NEWTON, {}, whole, log), SMP::OK);
  EXPECT_LT(whole.distortion, s.distortion);
}

// A dense model that the method leaves a little above E_d 4.6 (CGAL's
// femur.off, 7,798 faces, closed: 4.787 without the default target) is split
// until its E_d is at most 4.6 (pipeline/plan.h's
// default_distortion_target; measured: 4.564, E_s 3.73 -> 4.02, where the
// final solve after a first round of splits ended at 4.60023 and a second
// round followed), into a valid atlas (check_cut_result()).
TEST(Default_target, a_map_left_above_it_is_split_down_to_it)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) GTEST_SKIP() << "CGAL_DATA_DIR not set";
  Surface_mesh mesh;
  ASSERT_TRUE(read_cgal_model("femur.off", mesh));
  Cut_run<Surface_mesh> run(mesh);
  run_and_check(mesh, run);
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_GT(run.result.distortion, 4.);
}

namespace {

// CGAL's mpi.off (a low-poly head of 52 polygons) cut into two separate
// parts (each its own vertices) by the plane at the median height of its
// polygons' centroids along `axis`, then triangulated: the damage "parts" of
// scripts/wild_corpus.py.
bool mpi_cut_into_parts(int axis, Surface_mesh& mesh)
{
  Surface_mesh polygons;
  if(std::getenv("CGAL_DATA_DIR") == nullptr
     || !CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/mpi.off"), polygons) || num_faces(polygons) == 0)
    return false;
  std::vector<double> height;
  for(auto f : faces(polygons))
  {
    double sum = 0.;
    int n = 0;
    for(auto v : vertices_around_face(halfedge(f, polygons), polygons)) sum += polygons.point(v)[axis], ++n;
    height.push_back(sum / n);
  }
  std::vector<double> sorted = height;
  std::sort(sorted.begin(), sorted.end());
  const double cut = sorted[sorted.size() / 2];
  std::map<std::pair<Surface_mesh::Vertex_index, bool>, Surface_mesh::Vertex_index> copy;
  std::size_t i = 0;
  for(auto f : faces(polygons))
  {
    const bool upper = height[i++] > cut;
    std::vector<Surface_mesh::Vertex_index> corners;
    for(auto v : vertices_around_face(halfedge(f, polygons), polygons))
    {
      auto it = copy.find({v, upper});
      if(it == copy.end()) it = copy.emplace(std::make_pair(v, upper), mesh.add_vertex(polygons.point(v))).first;
      corners.push_back(it->second);
    }
    if(mesh.add_face(corners) == Surface_mesh::null_face()) return false;
  }
  return CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
}

} // namespace

// A low-poly model whose splits reach a low E_d only by maps that cross
// their own border, where the valid map the final solve starts again from
// stays far above: its crossing charts are cut into overlap-free pieces
// instead (pipeline/plan.h's final_solve_after_splits()). CGAL's mpi.off
// cut into parts along z (180 faces) ended at E_d 5.45 (measured before the
// pieces; now 4.43, E_s 7.62 -> 10.24), below the default target now, in a
// valid atlas (check_cut_result()), the same for 1, 2 and 4 threads.
TEST(Default_target, a_low_poly_model_in_parts_gets_overlap_free_pieces)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) GTEST_SKIP() << "CGAL_DATA_DIR not set";
  Surface_mesh mesh;
  ASSERT_TRUE(mpi_cut_into_parts(2, mesh));
  ASSERT_EQ(mesh.number_of_faces(), 180u);
  Cut_run<Surface_mesh> run(mesh);
  run_and_check(mesh, run);
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_GT(run.result.distortion, 4.);
  // the same seams, UVs and Newton iterations for any number of threads
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [](Cut_run<Surface_mesh>& r) {
    r.run();
    return r.result;
  });
}

// A low-poly model whose splits are judged on maps that cross their own
// border, and stay above the default target after its overlap-free pieces
// (CGAL's mpi_triang.off, 180 faces; its sibling mpi.off reaches 4.58 with
// the pieces, without the search, since they came)
// gets the bound search at the default target after its run
// (pipeline/plan.h's default_target_run(); measured here:
// E_d 4.5908 both), a valid atlas (check_cut_result()) whose Newton count
// holds both runs' work.
TEST(Default_target, a_low_poly_model_the_splits_leave_above_it_gets_the_bound_search)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) GTEST_SKIP() << "CGAL_DATA_DIR not set";
  Surface_mesh mesh;
  ASSERT_TRUE(read_cgal_model("mpi_triang.off", mesh));
  ASSERT_LE(mesh.number_of_faces(), ic::tuning::default_target_search_max_faces);
  Cut_run<Surface_mesh> run(mesh);
  run_and_check(mesh, run);
  EXPECT_LE(run.result.distortion, ic::tuning::default_distortion_target);
  EXPECT_GT(run.result.distortion, 4.);

  // the bound search alone (same input), whose work the default run includes
  Cut_run<Surface_mesh> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(ic::tuning::default_distortion_target));
  ASSERT_EQ(bounded.result.error, SMP::OK);
  EXPECT_DOUBLE_EQ(run.result.distortion, bounded.result.distortion);
  EXPECT_GT(run.result.newton_iterations, bounded.result.newton_iterations);
}
