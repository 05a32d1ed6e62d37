// Error codes of symmetric_dirichlet_parameterize and cut_and_parameterize
// on bad input (never a crash; degenerate faces are accepted and clamped
// unless asked otherwise; isolated vertices are ignored), the Tutte
// fallback for zero-length boundary edges, and the package's message / name
// tables.
#include "cut_result_checks.h"
#include "wild_input_generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cstring>
#include <set>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

template <typename Mesh>
SMP::Error_code parameterize(const Mesh& mesh)
{
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  return SMP::symmetric_dirichlet_parameterize(mesh, uv);
}

template <typename Mesh>
SMP::Error_code parameterize_soup(const Soup& soup)
{
  Mesh mesh;
  build_mesh(soup, mesh);
  return parameterize(mesh);
}

/// Index of the grid point (i, j) of grid_soup(nx, ...).
std::size_t grid_point(int nx, int i, int j) { return std::size_t(j * (nx + 1) + i); }

} // namespace

template <typename Mesh>
class ErrorCodesTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(ErrorCodesTyped, Mesh_types);

TYPED_TEST(ErrorCodesTyped, empty_mesh)
{
  TypeParam mesh;
  EXPECT_EQ(parameterize(mesh), SMP::ERROR_EMPTY_MESH);
}

TYPED_TEST(ErrorCodesTyped, non_triangular_meshes)
{
  EXPECT_EQ(parameterize_soup<TypeParam>(quad_grid_soup(1, 1)), SMP::ERROR_NON_TRIANGULAR_MESH);
  EXPECT_EQ(parameterize_soup<TypeParam>(quad_grid_soup(3, 2)), SMP::ERROR_NON_TRIANGULAR_MESH);
  // triangles and one quad: two triangles of a grid merged
  Soup mixed = grid_soup(3, 3);
  const auto a = mixed.faces[0], b = mixed.faces[1]; // cell (0,0): (0,1,5) and (0,5,4)
  mixed.faces.erase(mixed.faces.begin(), mixed.faces.begin() + 2);
  mixed.faces.push_back({a[0], a[1], a[2], b[2]});
  EXPECT_EQ(parameterize_soup<TypeParam>(mixed), SMP::ERROR_NON_TRIANGULAR_MESH);
  // a pentagon fan center: one polygon of 5 sides
  Soup pentagon;
  for(int k = 0; k < 5; ++k) pentagon.add_point(std::cos(2. * pi * k / 5), std::sin(2. * pi * k / 5), 0.);
  pentagon.faces.push_back({0, 1, 2, 3, 4});
  EXPECT_EQ(parameterize_soup<TypeParam>(pentagon), SMP::ERROR_NON_TRIANGULAR_MESH);
}

TYPED_TEST(ErrorCodesTyped, not_a_topological_disk)
{
  EXPECT_EQ(parameterize_soup<TypeParam>(sphere_soup(2)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(parameterize_soup<TypeParam>(sphere_soup(1)), SMP::ERROR_NO_TOPOLOGICAL_DISC); // octahedron
  EXPECT_EQ(parameterize_soup<TypeParam>(torus_soup(8, 5)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(parameterize_soup<TypeParam>(disk_with_holes_soup(5, 1)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(parameterize_soup<TypeParam>(disk_with_holes_soup(8, 2)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  // a disk plus a closed component
  Soup mixed = grid_soup(3, 3);
  mixed.append(sphere_soup(2).translate(3., 0., 0.));
  EXPECT_EQ(parameterize_soup<TypeParam>(mixed), SMP::ERROR_NO_TOPOLOGICAL_DISC);
}

TYPED_TEST(ErrorCodesTyped, disjoint_disks_are_accepted)
{
  // documented: several disjoint disks, each on its own circle
  TypeParam mesh;
  build_mesh(two_components_soup(3), mesh);
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  EXPECT_TRUE(SMP::distortion_energy(mesh, uv) - 4. <= 1e-6); // both flat
}

TYPED_TEST(ErrorCodesTyped, non_finite_coordinates)
{
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
  for(double bad : bad_values)
    for(int coordinate = 0; coordinate < 3; ++coordinate)
    {
      SCOPED_TRACE("value " + to_text(bad) + " in coordinate " + to_text(coordinate));
      Soup soup = grid_soup(3, 3);
      soup.points[grid_point(3, 1, 2)][coordinate] = bad; // an interior point
      EXPECT_EQ(parameterize_soup<TypeParam>(soup), SMP::ERROR_NON_FINITE_COORDINATE);
      Soup border = grid_soup(3, 3);
      border.points[0][coordinate] = bad; // a border point
      EXPECT_EQ(parameterize_soup<TypeParam>(border), SMP::ERROR_NON_FINITE_COORDINATE);
    }
}

/// Degenerate faces are accepted (documented): their rest shape is clamped,
/// the result is OK, flip-free and finite.
template <typename Mesh>
void check_degenerate_input_is_handled(const Soup& soup)
{
  Mesh mesh;
  build_mesh(soup, mesh);
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  const SMP::Error_code status = SMP::symmetric_dirichlet_parameterize(mesh, uv);
  ASSERT_EQ(status, SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  for(auto v : vertices(mesh))
    if(halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge()) EXPECT_TRUE(std::isfinite(get(uv, v).x()) && std::isfinite(get(uv, v).y()));
  // degenerate faces have no weight in E_d; the others give a finite value
  const double energy = SMP::distortion_energy(mesh, uv);
  if(num_faces(mesh) > 1) EXPECT_TRUE(std::isfinite(energy) && energy >= 4.);
}

TYPED_TEST(ErrorCodesTyped, degenerate_faces)
{
  {
    SCOPED_TRACE("an interior point moved onto its neighbor: two zero-area faces");
    Soup soup = grid_soup(3, 3);
    soup.points[grid_point(3, 1, 1)] = soup.points[grid_point(3, 2, 1)];
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
  {
    SCOPED_TRACE("an interior point moved onto the opposite edge of one of its faces");
    Soup soup = grid_soup(4, 4);
    // grid_soup splits cell (2,2) (i + j even) into (p, q, r) and (p, r, (2,3)),
    // p = (2,2), q = (3,2), r = (3,3): move p onto the segment q r
    const std::size_t p = grid_point(4, 2, 2), q = grid_point(4, 3, 2), r = grid_point(4, 3, 3);
    soup.points[p] = {soup.points[q][0], 0.5 * (soup.points[q][1] + soup.points[r][1]), 0.};
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
  {
    SCOPED_TRACE("a needle: height 1e-7 of the longest side");
    Soup soup = grid_soup(4, 4);
    const std::size_t p = grid_point(4, 2, 2), q = grid_point(4, 3, 2), r = grid_point(4, 3, 3);
    soup.points[p] = {soup.points[q][0] - 1e-7 * 0.25, 0.5 * (soup.points[q][1] + soup.points[r][1]), 0.};
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
  {
    SCOPED_TRACE("a single collinear triangle");
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(1, 1, 1);
    soup.add_point(2, 2, 2);
    soup.add_triangle(0, 1, 2);
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
  {
    SCOPED_TRACE("a triangle with two equal points");
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(1, 0, 0);
    soup.add_point(1, 0, 0);
    soup.add_triangle(0, 1, 2);
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
  {
    SCOPED_TRACE("a triangle with three equal points");
    Soup soup;
    for(int i = 0; i < 3; ++i) soup.add_point(0.5, 0.5, 0.5);
    soup.add_triangle(0, 1, 2);
    check_degenerate_input_is_handled<TypeParam>(soup);
  }
}

TYPED_TEST(ErrorCodesTyped, bad_parameters)
{
  TypeParam mesh;
  const auto vertex_of = build_mesh(grid_soup(3, 3), mesh);
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  // starting UVs with a flipped face (mirrored), or with a NaN
  for(auto v : vertices(mesh)) put(uv, v, Point_2(get(vpm, v).x(), -get(vpm, v).y()));
  EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::initialize_from_uv_map(true)), SMP::ERROR_NO_1_TO_1_MAPPING);
  for(auto v : vertices(mesh)) put(uv, v, Point_2(get(vpm, v).x(), get(vpm, v).y()));
  put(uv, vertex_of[5], Point_2(std::numeric_limits<double>::quiet_NaN(), 0.));
  EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::initialize_from_uv_map(true)), SMP::ERROR_NO_1_TO_1_MAPPING);
  // a valid start is accepted and stays isometric
  for(auto v : vertices(mesh)) put(uv, v, Point_2(get(vpm, v).x(), get(vpm, v).y()));
  EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::initialize_from_uv_map(true)), SMP::OK);
  EXPECT_NEAR(SMP::distortion_energy(mesh, uv), 4., 1e-12);

  // negative or non-finite face weights
  for(double bad : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    SCOPED_TRACE("weight " + to_text(bad));
    auto weight = get(CGAL::dynamic_face_property_t<double>(), mesh);
    for(auto f : faces(mesh)) put(weight, f, 1.);
    put(weight, *faces(mesh).begin(), bad);
    EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::face_weight_map(weight)), SMP::ERROR_WRONG_PARAMETER);
  }
}

TYPED_TEST(ErrorCodesTyped, tiny_and_odd_inputs)
{
  {
    SCOPED_TRACE("a single triangle: no interior vertex, reaches isometry");
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(2, 0, 0.5);
    soup.add_point(0.3, 1, -1);
    soup.add_triangle(0, 1, 2);
    TypeParam mesh;
    build_mesh(soup, mesh);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    EXPECT_NEAR(SMP::distortion_energy(mesh, uv), 4., 1e-6);
  }
  {
    SCOPED_TRACE("a grid plus an isolated vertex");
    Soup soup = grid_soup(3, 3);
    soup.add_point(5, 5, 5);
    TypeParam mesh;
    build_mesh(soup, mesh);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  }
  {
    SCOPED_TRACE("only isolated vertices");
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(1, 0, 0);
    TypeParam mesh;
    build_mesh(soup, mesh);
    EXPECT_EQ(parameterize(mesh), SMP::ERROR_EMPTY_MESH);
  }
}

/// Two triangle fans sharing only their center: a pinched vertex.
Soup pinched_fans()
{
  Soup soup;
  soup.add_point(0, 0, 0);
  for(int side : {1, -1})
  {
    const std::size_t first = soup.points.size();
    for(int k = 0; k < 4; ++k)
      soup.add_point(side * (1. + 0.3 * k), 0.5 * k - 0.75, 0.);
    for(std::size_t k = 0; k + 1 < 4; ++k)
      if(side > 0) soup.add_triangle(0, first + k, first + k + 1);
      else soup.add_triangle(0, first + k + 1, first + k);
  }
  return soup;
}

TYPED_TEST(ErrorCodesTyped, non_manifold_vertex)
{
  TypeParam mesh;
  build_mesh(pinched_fans(), mesh);
  ASSERT_EQ(num_faces(mesh), std::size_t(6));
  EXPECT_EQ(parameterize(mesh), SMP::ERROR_NON_MANIFOLD);
  Cut_run<TypeParam> run(mesh);
  EXPECT_EQ(run.run().error, SMP::ERROR_NON_MANIFOLD);
  // two grids touching at one corner: the corner (0, 0) of the second grid
  // is the corner (2, 2) of the first
  TypeParam other;
  Soup corners = grid_soup(2, 2);
  const std::size_t shared = grid_point(2, 2, 2), offset = corners.points.size();
  Soup second = grid_soup(2, 2);
  second.translate(1., 1., 0.);
  for(const auto& p : second.points) corners.add_point(p[0], p[1], p[2]);
  for(auto f : second.faces)
  {
    for(std::size_t& i : f) i = (i == grid_point(2, 0, 0)) ? shared : i + offset;
    corners.faces.push_back(f);
  }
  build_mesh(corners, other);
  EXPECT_EQ(parameterize(other), SMP::ERROR_NON_MANIFOLD);
}

// Two quads folded over their common diagonal a-c, each split along it
// with Euler::split_face (which does not look for an existing edge): two
// edges join a and c. The library refuses this by name (the tools' input
// path splits such quads along their other diagonal).
TYPED_TEST(ErrorCodesTyped, two_edges_joining_the_same_vertices)
{
  TypeParam mesh;
  const Soup folded = folded_quads_soup();
  const auto vertex_of = build_mesh(folded, mesh);
  const auto a = vertex_of[0], c = vertex_of[2];
  std::vector<typename boost::graph_traits<TypeParam>::face_descriptor> quads(faces(mesh).begin(), faces(mesh).end());
  for(auto f : quads)
  {
    typename boost::graph_traits<TypeParam>::halfedge_descriptor ha, hc;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      if(target(h, mesh) == a) ha = h;
      if(target(h, mesh) == c) hc = h;
    }
    CGAL::Euler::split_face(ha, hc, mesh);
  }
  ASSERT_EQ(num_faces(mesh), std::size_t(4));
  ASSERT_EQ(num_edges(mesh), std::size_t(8)); // a-c twice
  EXPECT_EQ(parameterize(mesh), SMP::ERROR_NON_MANIFOLD);
  Cut_run<TypeParam> run(mesh);
  EXPECT_EQ(run.run().error, SMP::ERROR_NON_MANIFOLD);
}

// (the evenly spaced fallback is internal: what is checked is the map it gives)
TYPED_TEST(ErrorCodesTyped, tiny_boundary_ear_gives_a_flip_free_map)
{
  // A well-shaped ear 1e-10 wide at a corner of a unit square: arc-length
  // spacing puts its three corners on the circle within 1e-10 of each other,
  // where the circle's sagitta (1e-21) is below round-off, so the first
  // embedding has a zero-area or flipped face; evenly spaced boundary
  // vertices have none.
  const double t = 1e-10;
  Soup soup;
  soup.add_point(0, 0, 0); // 0: the corner
  soup.add_point(t, 0, 0); // 1
  soup.add_point(0, t, 0); // 2
  soup.add_point(1, 0, 0); // 3
  soup.add_point(1, 1, 0); // 4
  soup.add_point(0, 1, 0); // 5
  soup.add_point(0.5, 0.5, 0); // 6: interior
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(1, 3, 6);
  soup.add_triangle(3, 4, 6);
  soup.add_triangle(4, 5, 6);
  soup.add_triangle(5, 2, 6);
  soup.add_triangle(2, 1, 6);
  check_degenerate_input_is_handled<TypeParam>(soup); // OK, no flip, finite
  TypeParam mesh;
  build_mesh(soup, mesh);
  // (check_cut_result() would compare E_d with the library's, which uses the
  // clamped rest shape of the needle (2, 1, 6))
  Cut_run<TypeParam> run(mesh);
  ASSERT_TRUE(run.run().ok());
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, run.uvs()), std::size_t(0));
  EXPECT_TRUE(run.result.number_of_degenerate_faces >= 1);
}

TYPED_TEST(ErrorCodesTyped, cut_and_parameterize_on_bad_input)
{
  {
    TypeParam empty;
    Cut_run<TypeParam> run(empty);
    EXPECT_EQ(run.run().error, SMP::ERROR_EMPTY_MESH);
  }
  {
    TypeParam quads;
    build_mesh(quad_grid_soup(3, 2), quads);
    Cut_run<TypeParam> run(quads);
    EXPECT_EQ(run.run().error, SMP::ERROR_NON_TRIANGULAR_MESH);
  }
  {
    Soup soup = sphere_soup(3);
    soup.points[5][1] = std::numeric_limits<double>::quiet_NaN();
    TypeParam mesh;
    build_mesh(soup, mesh);
    Cut_run<TypeParam> run(mesh);
    run.fill_sentinels();
    EXPECT_EQ(run.run(SMP::parameters::face_discontinuity_map(run.v())).error, SMP::ERROR_NON_FINITE_COORDINATE);
    run.expect_outputs_untouched();
  }
}

TYPED_TEST(ErrorCodesTyped, isolated_vertices_are_ignored)
{
  Soup soup = sphere_soup(3);
  soup.add_point(7, 7, 7);
  soup.add_point(std::numeric_limits<double>::quiet_NaN(), 0, 0); // never read
  TypeParam mesh;
  build_mesh(soup, mesh);
  Cut_run<TypeParam> run(mesh);
  run.run();
  check_cut_result(mesh, run);
  EXPECT_EQ(run.result.number_of_isolated_vertices, std::size_t(2));
  TypeParam disk;
  Soup grid = grid_soup(3, 3);
  grid.add_point(std::numeric_limits<double>::infinity(), 0, 0);
  build_mesh(grid, disk);
  auto disk_uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), disk);
  EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(disk, disk_uv), SMP::OK);
}

TYPED_TEST(ErrorCodesTyped, degenerate_faces_clamped_or_rejected)
{
  Soup soup = grid_soup(4, 4);
  soup.points[grid_point(4, 2, 2)] = soup.points[grid_point(4, 3, 2)]; // two zero-area faces
  TypeParam mesh;
  build_mesh(soup, mesh);
  Cut_run<TypeParam> clamped(mesh);
  clamped.run();
  check_cut_result(mesh, clamped);
  EXPECT_EQ(clamped.result.number_of_degenerate_faces, std::size_t(2));
  std::size_t flagged = 0;
  for(auto f : faces(mesh)) flagged += SMP::is_degenerate_face(f, mesh) ? 1 : 0;
  EXPECT_EQ(flagged, std::size_t(2));
  Cut_run<TypeParam> strict(mesh);
  strict.fill_sentinels();
  EXPECT_EQ(strict.run(SMP::parameters::reject_degenerate_faces(true, SMP::parameters::face_discontinuity_map(strict.v())))
              .error,
            SMP::ERROR_DEGENERATE_FACE);
  strict.expect_outputs_untouched();
  // a clean mesh passes the strict mode
  TypeParam clean;
  build_mesh(grid_soup(4, 4), clean);
  Cut_run<TypeParam> clean_run(clean);
  EXPECT_TRUE(clean_run.run(SMP::parameters::reject_degenerate_faces(true)).ok());
}

TEST(ErrorCodes, error_messages_and_names)
{
  const SMP::Error_code codes[] = {SMP::OK,
                                   SMP::ERROR_EMPTY_MESH,
                                   SMP::ERROR_NON_TRIANGULAR_MESH,
                                   SMP::ERROR_NO_TOPOLOGICAL_DISC,
                                   SMP::ERROR_NO_TOPOLOGICAL_BALL,
                                   SMP::ERROR_BORDER_TOO_SHORT,
                                   SMP::ERROR_NON_CONVEX_BORDER,
                                   SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM,
                                   SMP::ERROR_NO_1_TO_1_MAPPING,
                                   SMP::ERROR_WRONG_PARAMETER,
                                   SMP::ERROR_NON_FINITE_COORDINATE,
                                   SMP::ERROR_DEGENERATE_FACE,
                                   SMP::ERROR_NON_MANIFOLD,
                                   SMP::ERROR_CANCELED};
  std::set<std::string> messages, names, values;
  for(SMP::Error_code c : codes)
  {
    const char* m = SMP::error_message(c);
    const char* n = SMP::error_name(c);
    ASSERT_TRUE(m != nullptr && n != nullptr);
    EXPECT_TRUE(std::strlen(m) > 0);
    EXPECT_TRUE(std::string(m) != "Unknown error");
    EXPECT_TRUE(std::string(n) != "ERROR_UNKNOWN");
    messages.insert(m);
    names.insert(n);
    values.insert(to_text(int(c)));
  }
  const std::size_t n = sizeof(codes) / sizeof(codes[0]);
  EXPECT_EQ(values.size(), n); // the package's codes do not collide with CGAL's
  EXPECT_EQ(messages.size(), n);
  EXPECT_EQ(names.size(), n);
  // messages of CGAL's own codes match CGAL's documented meaning
  EXPECT_EQ(std::string(SMP::error_message(SMP::ERROR_NO_TOPOLOGICAL_DISC)), "Input mesh is not a topological disc");
  EXPECT_EQ(std::string(SMP::error_message(SMP::ERROR_WRONG_PARAMETER)), "A method received an unexpected parameter");
  EXPECT_EQ(std::string(SMP::error_name(SMP::ERROR_DEGENERATE_FACE)), "ERROR_DEGENERATE_FACE");
  EXPECT_EQ(std::string(SMP::error_message(SMP::Error_code(1000))), "Unknown error");
}

