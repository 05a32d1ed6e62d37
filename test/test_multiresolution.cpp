// Multiresolution (named parameter multiresolution_faces): on a mesh of more
// than twice that many faces, the cuts are decided on a simplified copy and
// carried back to the input, then the map is solved at full resolution. The
// result must be as valid as a full-resolution run's (cut_result_checks.h
// recomputes everything from the outputs), close to it in quality, keep the
// user's seams, not depend on the thread count, and reject a negative size.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>

#include <algorithm>
#include <iomanip>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = SMP::internal::cut;
using namespace cut_test;

namespace {

// small enough for a test, large enough for the copy to be much coarser
constexpr int coarse_faces = 600;

/// A closed torus of 4608 faces: the copy is simplified to 600 faces.
Soup test_torus() { return torus_soup(72, 32); }

} // namespace

// A closed genus-1 mesh goes through the copy: the result is a valid atlas
// (seams where the copy cut, a disk per chart, no flip, no crossing) whose
// E_d and E_s are close to the full-resolution run's.
template <typename Mesh>
class MultiresolutionTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(MultiresolutionTyped, Mesh_types);

TYPED_TEST(MultiresolutionTyped, coarse_cuts_give_a_valid_atlas_close_to_full_resolution)
{
  TypeParam mesh;
  build_mesh(test_torus(), mesh);
  ASSERT_TRUE(num_faces(mesh) > std::size_t(2 * coarse_faces));

  Cut_run<TypeParam> coarse(mesh);
  coarse.run(SMP::parameters::multiresolution_faces(coarse_faces));
  const Chart_report<TypeParam> report = check_cut_result(mesh, coarse);
  ASSERT_TRUE(report.valid);
  EXPECT_TRUE(coarse.result.number_of_seam_edges > 0);
  EXPECT_EQ(coarse.result.border_crossings, std::size_t(0));

  Cut_run<TypeParam> full(mesh);
  full.run(SMP::parameters::multiresolution_faces(0));
  ASSERT_TRUE(check_cut_result(mesh, full).valid);
  std::cout << std::setprecision(5) << "    full resolution: E_d " << full.result.distortion << ", E_s " << full.result.seam_length
            << ", " << full.result.newton_iterations << " Newton iterations; coarse copy: E_d "
            << coarse.result.distortion << ", E_s " << coarse.result.seam_length << ", "
            << coarse.result.newton_iterations << std::endl;
  EXPECT_TRUE(coarse.result.distortion < full.result.distortion + 0.1) << "E_d " << coarse.result.distortion << " vs " << full.result.distortion;
  EXPECT_TRUE(coarse.result.seam_length < 1.3 * full.result.seam_length) << "E_s " << coarse.result.seam_length << " vs " << full.result.seam_length;
  // the seams are not those of the full-resolution run: the copy decided them
  EXPECT_TRUE(coarse.seam_vector() != full.seam_vector());
}

// The field v of the copy is carried to the input's faces: in (0, 1], and
// lower along the seams (where the copy's v fell and it cut) than elsewhere.
TEST(Multiresolution, discontinuity_field_is_carried_to_the_input)
{
  using Mesh = Surface_mesh;
  const Mesh mesh = make_mesh<Mesh>(test_torus());
  std::unordered_map<Mesh::Face_index, double> v_storage;
  Cut_run<Mesh> run(mesh);
  ASSERT_TRUE(run.run(SMP::parameters::multiresolution_faces(coarse_faces,
                    SMP::parameters::face_discontinuity_map(boost::make_assoc_property_map(v_storage)))).ok());
  ASSERT_EQ(v_storage.size(), num_faces(mesh));
  double sum = 0., along_seams = 0.;
  std::size_t seam_sides = 0;
  for(const auto& fv : v_storage)
  {
    EXPECT_TRUE(fv.second > 0. && fv.second <= 1.);
    sum += fv.second;
  }
  for(auto e : edges(mesh))
    if(run.is_seam(e))
      for(auto h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)})
      {
        along_seams += v_storage.at(face(h, mesh));
        ++seam_sides;
      }
  ASSERT_TRUE(seam_sides > 0);
  const double mean = sum / double(v_storage.size()), mean_along_seams = along_seams / double(seam_sides);
  EXPECT_TRUE(mean_along_seams < mean - 1e-3) << "mean v " << mean << ", along the seams " << mean_along_seams;
}

// Below twice the copy's size, nothing changes: the result is the
// full-resolution run's, bit for bit.
TEST(Multiresolution, small_meshes_are_not_simplified)
{
  using Mesh = Surface_mesh;
  const Mesh mesh = make_mesh<Mesh>(test_torus());
  Cut_run<Mesh> a(mesh), b(mesh);
  ASSERT_TRUE(a.run(SMP::parameters::multiresolution_faces(int(num_faces(mesh)) / 2)).ok());
  ASSERT_TRUE(b.run(SMP::parameters::multiresolution_faces(0)).ok());
  EXPECT_TRUE(a.seam_vector() == b.seam_vector());
  EXPECT_TRUE(a.result.distortion == b.result.distortion);
}

// Seams given by the user stay seams: the copy keeps them as edges (they
// constrain its simplification) and the full-resolution cut contains them.
TYPED_TEST(MultiresolutionTyped, user_seams_are_kept_through_the_copy)
{
  const Soup soup = test_torus();
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  // the meridian of the torus' cut (soup.cut: the longitude's 72 edges, then the meridian's 32)
  const std::vector<std::pair<std::size_t, std::size_t>> meridian(soup.cut.begin() + 72, soup.cut.end());
  ASSERT_EQ(meridian.size(), std::size_t(32));
  const auto given = soup_edges(mesh, vertex_of, meridian);
  Cut_run<TypeParam> run(mesh);
  for(auto e : given) run.seam_storage[e] = true;
  run.run(SMP::parameters::multiresolution_faces(coarse_faces));
  ASSERT_TRUE(check_cut_result(mesh, run).valid);
  for(auto e : given) EXPECT_TRUE(run.is_seam(e));
}

// The simplification is sequential and the rest is deterministic: the same
// seams and UVs for any number of threads (skipped without TBB).
TEST(Multiresolution, coarse_copy_is_deterministic_across_thread_counts)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(test_torus());
  expect_same_result_for_thread_counts(mesh, {1, 2}, [](Cut_run<Surface_mesh>& run) {
    return run.run(SMP::parameters::multiresolution_faces(coarse_faces));
  });
}

// The copy that decides the cuts of a very large mesh, made in two stages
// (simplify_surface_in_two_stages()): about the faces asked for, every
// vertex a distinct vertex of the input at its position, the user's seams
// kept as edges of the copy between seam vertices of the input.
TEST(Multiresolution, the_copy_in_two_stages_keeps_input_vertices_and_seams)
{
  const Soup soup = test_torus();
  Surface_mesh mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  // the meridian of the torus' cut as the input's seams
  const std::vector<std::pair<std::size_t, std::size_t>> meridian(soup.cut.begin() + 72, soup.cut.end());
  std::vector<char> is_cut(surface.edges.size(), 0), on_seam(surface.number_of_vertices(), 0);
  const auto given = soup_edges(mesh, vertex_of, meridian);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(std::find(given.begin(), given.end(), surface.edges[std::size_t(surface.edge_of[std::size_t(fe)])]) != given.end())
    {
      is_cut[std::size_t(surface.edge_of[std::size_t(fe)])] = 1;
      on_seam[std::size_t(surface.edge_source(fe))] = on_seam[std::size_t(surface.edge_target(fe))] = 1;
    }
  ASSERT_EQ(std::count(is_cut.begin(), is_cut.end(), char(1)), 32);
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  ic::Coarse_surface coarse;
  ASSERT_TRUE(ic::simplify_surface_in_two_stages(surface, is_cut, {}, face_lambda, 2000, 300, coarse));
  const auto& cs = coarse.surface;
  EXPECT_LE(cs.number_of_faces(), std::size_t(330));
  EXPECT_GE(cs.number_of_faces(), std::size_t(250));
  ASSERT_EQ(coarse.fine_vertex.size(), cs.number_of_vertices());
  std::vector<int> fine = coarse.fine_vertex;
  std::sort(fine.begin(), fine.end());
  EXPECT_TRUE(std::adjacent_find(fine.begin(), fine.end()) == fine.end());
  for(std::size_t v = 0; v < cs.number_of_vertices(); ++v)
  {
    const int f = coarse.fine_vertex[v];
    ASSERT_TRUE(f >= 0 && std::size_t(f) < surface.number_of_vertices());
    EXPECT_TRUE(cs.points[v] == surface.points[std::size_t(f)]);
  }
  int seams = 0;
  for(int fe = 0; fe < int(cs.twin.size()); ++fe)
  {
    if(!coarse.is_cut[std::size_t(cs.edge_of[std::size_t(fe)])]) continue;
    ++seams;
    EXPECT_TRUE(on_seam[std::size_t(coarse.fine_vertex[std::size_t(cs.edge_source(fe))])]);
    EXPECT_TRUE(on_seam[std::size_t(coarse.fine_vertex[std::size_t(cs.edge_target(fe))])]);
  }
  EXPECT_GT(seams, 0);
  EXPECT_EQ(coarse.face_lambda.size(), cs.number_of_faces());
}

// A mesh of more than tuning::staged_cut_copy_min_ratio times the copy's
// faces goes through the copy in two stages: a valid atlas, the user's seams
// kept, the same for any thread count.
TEST(Multiresolution, a_copy_in_two_stages_gives_a_valid_atlas)
{
  const Soup soup = test_torus();
  Surface_mesh mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  const int faces = 140;
  {
    ic::Indexed_surface<Surface_mesh> surface;
    ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
    SMP::Cut_parameterization_options o;
    o.multiresolution_faces = faces;
    ASSERT_TRUE(ic::cuts_copy_in_two_stages(surface, o));
  }
  const std::vector<std::pair<std::size_t, std::size_t>> meridian(soup.cut.begin() + 72, soup.cut.end());
  const auto given = soup_edges(mesh, vertex_of, meridian);
  Cut_run<Surface_mesh> run(mesh);
  for(auto e : given) run.seam_storage[e] = true;
  run.run(SMP::parameters::multiresolution_faces(faces));
  ASSERT_TRUE(check_cut_result(mesh, run).valid);
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  for(auto e : given) EXPECT_TRUE(run.is_seam(e));
  expect_same_result_for_thread_counts(mesh, {1, 2}, [faces](Cut_run<Surface_mesh>& r) {
    return r.run(SMP::parameters::multiresolution_faces(faces));
  });
}

TEST(Multiresolution, negative_size_is_a_wrong_parameter)
{
  using Mesh = Surface_mesh;
  const Mesh mesh = make_mesh<Mesh>(test_torus());
  Cut_run<Mesh> run(mesh);
  EXPECT_EQ(run.run(SMP::parameters::multiresolution_faces(-1)).error, SMP::ERROR_WRONG_PARAMETER);
}


// A large mesh whose map ends above the default target is split on the
// copy (internal split_on_coarse_copy()), where a trial is a solve of the copy's
// map, not of the input's: the seams of the splits go back with the
// copy's cuts and the input ends at most at the target. Without splits it
// ends above it; at full resolution a large mesh is split only above
// low_poly_distortion.
TEST(Multiresolution, splits_are_decided_on_the_copy)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(sphere_cap_soup(24, 80, 5. * pi / 6.));
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  ASSERT_TRUE(surface.number_of_faces() > std::size_t(2 * coarse_faces));
  const std::vector<double> face_lambda(surface.number_of_faces(), 1.);
  auto run = [&](bool greedy_splits, ic::Map_state& state) {
    SMP::Cut_parameterization_options options;
    options.multiresolution_faces = coarse_faces;
    ic::Run_args settings = ic::default_run_args(options);
    settings.splits = greedy_splits;
    state.is_cut.assign(surface.edges.size(), 0);
    ic::Work_log log;
    return ic::optimize_cut_mesh(surface, face_lambda, options, {}, settings, state, log);
  };
  ic::Map_state split, unsplit;
  ASSERT_EQ(run(true, split), SMP::OK);
  ASSERT_EQ(run(false, unsplit), SMP::OK);
  std::cout << std::setprecision(5) << "    without splits: E_d " << unsplit.distortion << ", E_s "
            << ic::seam_length_3d(surface, unsplit.is_cut) << "; split on the copy: E_d " << split.distortion << ", E_s "
            << ic::seam_length_3d(surface, split.is_cut) << std::endl;
  ASSERT_GT(unsplit.distortion, ic::tuning::default_distortion_target);
  EXPECT_LE(split.distortion, ic::tuning::default_distortion_target);
  EXPECT_GT(ic::seam_length_3d(surface, split.is_cut), ic::seam_length_3d(surface, unsplit.is_cut));
  EXPECT_NEAR(split.distortion, ic::mean_distortion(split.chart, split.x), 1e-12);
  EXPECT_TRUE(split.x.allFinite());
  EXPECT_EQ(ic::number_of_flipped_faces(split.chart, split.x), 0);
  const std::vector<char> crossing = ic::Border_barrier_term(split.chart).charts_with_crossing(split.x);
  EXPECT_TRUE(std::none_of(crossing.begin(), crossing.end(), [](char c) { return c != 0; }));
  const ic::Chart_topology topology = ic::chart_topology(split.chart);
  for(int c = 0; c < topology.number_of_charts; ++c) EXPECT_TRUE(topology.is_disk(c));
}
