// The generators of generators.h produce what they claim: topology (Euler
// characteristic, genus, borders, components), closedness, orientation,
// areas, and cuts that open closed surfaces into disks.
#include "generators.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/Seam_mesh.h>

namespace PMP = CGAL::Polygon_mesh_processing;
using namespace cut_test;

namespace {

template <typename Mesh>
void check_disk(const Mesh& mesh)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_triangle_mesh(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 1L);
  EXPECT_EQ(number_of_border_cycles(mesh), std::size_t(1));
  EXPECT_EQ(number_of_components(mesh), std::size_t(1));
}

/// Smallest 3D face area, to detect degenerate output.
template <typename Mesh>
double min_face_area(const Mesh& mesh)
{
  double m = std::numeric_limits<double>::infinity();
  for(auto f : faces(mesh)) m = (std::min)(m, PMP::face_area(f, mesh));
  return m;
}

/// Sum over faces of the signed volume of the tetrahedron (origin, face):
/// the enclosed volume for a closed, outward-oriented mesh.
template <typename Mesh>
double signed_volume(const Mesh& mesh)
{
  auto vpm = get(CGAL::vertex_point, mesh);
  double volume = 0.;
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    const auto& a = get(vpm, source(h, mesh));
    const auto& b = get(vpm, target(h, mesh));
    const auto& c = get(vpm, target(next(h, mesh), mesh));
    volume += CGAL::scalar_product(a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN)) / 6.;
  }
  return volume;
}

} // namespace

template <typename Mesh>
class GeneratorsTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(GeneratorsTyped, Mesh_types);

TYPED_TEST(GeneratorsTyped, grid_is_a_flat_disk_of_the_right_area)
{
  TypeParam mesh;
  build_mesh(grid_soup(4, 3, 2., 1.5), mesh);
  check_disk(mesh);
  EXPECT_EQ(num_vertices(mesh), std::size_t(5 * 4));
  EXPECT_EQ(num_faces(mesh), std::size_t(2 * 4 * 3));
  EXPECT_NEAR(PMP::area(mesh), 3., 1e-12);
  EXPECT_TRUE(min_face_area(mesh) > 0.);
  // every face is counterclockwise seen from +z
  for(auto f : faces(mesh))
  {
    const auto n = PMP::compute_face_normal(f, mesh);
    EXPECT_TRUE(n.z() > 0.99);
  }
}

TYPED_TEST(GeneratorsTyped, polar_disks_are_disks)
{
  const Soup soups[] = {flat_disk_soup(4, 12), hemisphere_soup(5, 16), cone_soup(4, 10),
                        wavy_disk_soup(6, 18, 7), cylinder_patch_soup(8, 5)};
  const char* names[] = {"flat", "hemisphere", "cone", "wavy", "cylinder"};
  for(int i = 0; i < 5; ++i)
  {
    SCOPED_TRACE(names[i]);
    TypeParam mesh;
    build_mesh(soups[i], mesh);
    check_disk(mesh);
    EXPECT_TRUE(min_face_area(mesh) > 1e-6);
  }
}

TYPED_TEST(GeneratorsTyped, generated_shapes_have_their_analytic_areas)
{
  {
    TypeParam mesh; // hemisphere of radius 2: area 2 π r² = 8π, approached from below
    build_mesh(hemisphere_soup(24, 96, 2.), mesh);
    const double a = PMP::area(mesh);
    EXPECT_TRUE(a < 8. * pi);
    EXPECT_REL(a, 8. * pi, 5e-3);
    auto vpm = get(CGAL::vertex_point, mesh);
    for(auto v : vertices(mesh))
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(get(vpm, v), Point_3(0, 0, 0))), 2., 1e-12);
  }
  {
    TypeParam mesh; // cylinder patch: 3 × (angle 1 × radius 2) = 6, chords shorten it
    build_mesh(cylinder_patch_soup(64, 4, 2., 1., 3.), mesh);
    EXPECT_REL(PMP::area(mesh), 64. * (2. * 2. * std::sin(0.5 / 64.)) * 3., 1e-12);
  }
  {
    TypeParam mesh; // cone: π R sqrt(R² + h²)
    build_mesh(cone_soup(8, 128, 1., 2.), mesh);
    EXPECT_REL(PMP::area(mesh), pi * std::sqrt(5.), 2e-3);
  }
}

TYPED_TEST(GeneratorsTyped, sphere_is_closed_genus_0_and_outward)
{
  const Soup soup = sphere_soup(4, 1.5);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 2L);
  EXPECT_EQ(genus(mesh), 0L);
  EXPECT_EQ(num_faces(mesh), std::size_t(8 * 16));
  EXPECT_TRUE(PMP::is_outward_oriented(mesh));
  const double v = signed_volume(mesh);
  EXPECT_TRUE(v > 0.);
  EXPECT_TRUE(v < 4. / 3. * pi * 1.5 * 1.5 * 1.5);
  // the cut is a simple path of 2n edges from pole to pole
  const auto cut = soup_edges(mesh, vertex_of, soup.cut);
  EXPECT_EQ(cut.size(), std::size_t(8));
  auto vpm = get(CGAL::vertex_point, mesh);
  EXPECT_NEAR(get(vpm, vertex_of[soup.cut.front().first]).z(), 1.5, 1e-12);
  EXPECT_NEAR(get(vpm, vertex_of[soup.cut.back().second]).z(), -1.5, 1e-12);
}

TYPED_TEST(GeneratorsTyped, torus_is_closed_genus_1)
{
  const Soup soup = torus_soup(12, 8);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 0L);
  EXPECT_EQ(genus(mesh), 1L);
  EXPECT_TRUE(signed_volume(mesh) > 0.); // outward
  EXPECT_EQ(soup_edges(mesh, vertex_of, soup.cut).size(), std::size_t(12 + 8));
}

/// Cutting a closed mesh along soup.cut gives a disk: checked on CGAL's Seam_mesh.
template <typename Mesh>
void check_cut_opens_to_disk(const Soup& soup)
{
  Mesh mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  using edge_descriptor = typename boost::graph_traits<Mesh>::edge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(edge_descriptor e : edges(mesh)) put(sem, e, false);
  for(vertex_descriptor v : vertices(mesh)) put(svm, v, false);
  using Seam_mesh = CGAL::Seam_mesh<Mesh, decltype(sem), decltype(svm)>;
  Seam_mesh seam_mesh(mesh, sem, svm);
  for(edge_descriptor e : soup_edges(mesh, vertex_of, soup.cut))
    seam_mesh.add_seam(source(e, mesh), target(e, mesh));
  // χ of the opened mesh is 1, one border cycle
  const long chi = long(num_vertices(seam_mesh)) - long(num_edges(seam_mesh)) + long(num_faces(seam_mesh));
  EXPECT_EQ(chi, 1L);
  std::size_t border_halfedges = 0;
  for(auto h : halfedges(seam_mesh))
    if(is_border(h, seam_mesh)) ++border_halfedges;
  EXPECT_EQ(border_halfedges, 2 * soup.cut.size());
}

TYPED_TEST(GeneratorsTyped, cuts_open_closed_surfaces_into_disks)
{
  {
    SCOPED_TRACE("sphere");
    check_cut_opens_to_disk<TypeParam>(sphere_soup(3));
  }
  {
    SCOPED_TRACE("torus");
    check_cut_opens_to_disk<TypeParam>(torus_soup(9, 6));
  }
}

TYPED_TEST(GeneratorsTyped, disk_with_holes_and_two_components)
{
  {
    TypeParam mesh;
    build_mesh(disk_with_holes_soup(8, 2), mesh);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_EQ(number_of_border_cycles(mesh), std::size_t(3));
    EXPECT_EQ(number_of_components(mesh), std::size_t(1));
    EXPECT_EQ(genus(mesh), 0L);
    EXPECT_EQ(num_faces(mesh), std::size_t(2 * (64 - 8)));
    EXPECT_EQ(num_vertices(mesh), std::size_t(81 - 2)); // the holes' center points are dropped
    EXPECT_NEAR(PMP::area(mesh), 1. - 8. / 64., 1e-12);
  }
  {
    TypeParam mesh;
    build_mesh(two_components_soup(3), mesh);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_EQ(number_of_components(mesh), std::size_t(2));
    EXPECT_EQ(number_of_border_cycles(mesh), std::size_t(2));
    EXPECT_EQ(euler_characteristic(mesh), 2L);
  }
  {
    TypeParam mesh;
    build_mesh(quad_grid_soup(3, 2), mesh);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_TRUE(!CGAL::is_triangle_mesh(mesh));
    EXPECT_TRUE(CGAL::is_quad_mesh(mesh));
    EXPECT_EQ(num_faces(mesh), std::size_t(6));
  }
}

TYPED_TEST(GeneratorsTyped, shortest_edge_path_connects_its_ends)
{
  const Soup soup = sphere_soup(4);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  // from the north pole to the south pole: 2n = 8 edges, a connected chain
  const auto north = vertex_of[soup.cut.front().first], south = vertex_of[soup.cut.back().second];
  const auto path = shortest_edge_path(mesh, north, south);
  ASSERT_EQ(path.size(), std::size_t(8));
  std::unordered_map<typename boost::graph_traits<TypeParam>::vertex_descriptor, int> degree;
  for(auto e : path)
  {
    ++degree[source(e, mesh)];
    ++degree[target(e, mesh)];
  }
  EXPECT_EQ(degree[north], 1);
  EXPECT_EQ(degree[south], 1);
  int ends = 0;
  for(const auto& d : degree)
  {
    EXPECT_TRUE(d.second == 1 || d.second == 2);
    if(d.second == 1) ++ends;
  }
  EXPECT_EQ(ends, 2);
  EXPECT_TRUE(shortest_edge_path(mesh, north, north).empty());
}

TEST(Generators, generators_are_deterministic)
{
  const Soup a = wavy_disk_soup(5, 13, 42), b = wavy_disk_soup(5, 13, 42), c = wavy_disk_soup(5, 13, 43);
  EXPECT_TRUE(a.points == b.points);
  EXPECT_TRUE(a.faces == b.faces);
  EXPECT_TRUE(!(a.points == c.points));
  Soup g1 = grid_soup(3, 3), g2 = grid_soup(3, 3);
  jitter_xy(g1, 0.05, 9);
  jitter_xy(g2, 0.05, 9);
  EXPECT_TRUE(g1.points == g2.points);
  Rng rng(1);
  double lo = 1., hi = 0.;
  for(int i = 0; i < 1000; ++i)
  {
    const double x = rng.uniform();
    lo = (std::min)(lo, x);
    hi = (std::max)(hi, x);
  }
  EXPECT_TRUE(lo >= 0. && lo < 0.01);
  EXPECT_TRUE(hi < 1. && hi > 0.99);
}

