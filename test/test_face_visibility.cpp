// face_visibility(), visibility_face_lambda() and seam_visibility(): a face
// inside a closed surface sees nothing (0), a lone face everything (1), the
// outside of a convex surface everything; a maximum distance lets a face see
// past farther faces; the result is the same with 1 and 2 threads; bad
// parameters and non-triangle meshes are refused; λ grows with visibility,
// with a geometric mean of 1; seam visibility is the length-weighted mean
// over the seam edges.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/face_visibility.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <map>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

// A sphere of radius 1 and, inside it, a small triangle at its center (the
// soup's last face).
Soup sphere_with_inner_triangle()
{
  Soup s = sphere_soup(4);
  s.cut.clear();
  const std::size_t base = s.points.size();
  s.add_point(-0.1, -0.1, 0.);
  s.add_point(0.1, -0.1, 0.);
  s.add_point(0., 0.1, 0.);
  s.faces.push_back({base, base + 1, base + 2});
  return s;
}

template <typename Mesh>
std::vector<double> visibility_of(const Mesh& mesh, int rays = 64, double max_distance = 0.)
{
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  std::map<face_descriptor, double> values;
  auto map = boost::make_assoc_property_map(values);
  const SMP::Error_code status =
    max_distance > 0. ? SMP::face_visibility(mesh, map, SMP::parameters::number_of_rays(rays,
                                                        SMP::parameters::maximum_distance(max_distance)))
                      : SMP::face_visibility(mesh, map, SMP::parameters::number_of_rays(rays));
  EXPECT_EQ(status, SMP::OK);
  std::vector<double> out;
  for(face_descriptor f : faces(mesh)) out.push_back(values[f]);
  return out;
}

template <typename Mesh>
class Face_visibility : public ::testing::Test
{
};
TYPED_TEST_SUITE(Face_visibility, Mesh_types);

TYPED_TEST(Face_visibility, lone_triangle_sees_everything)
{
  Soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(0, 1, 0);
  s.add_triangle(0, 1, 2);
  TypeParam mesh;
  build_mesh(s, mesh);
  for(int rays : {1, 16, 64}) EXPECT_EQ(visibility_of(mesh, rays), std::vector<double>{1.});
}

TYPED_TEST(Face_visibility, inside_a_closed_surface_sees_nothing)
{
  TypeParam mesh;
  build_mesh(sphere_with_inner_triangle(), mesh);
  const std::vector<double> vis = visibility_of(mesh);
  ASSERT_EQ(vis.size(), num_faces(mesh));
  EXPECT_EQ(vis.back(), 0.); // the inner triangle
  for(std::size_t f = 0; f + 1 < vis.size(); ++f) EXPECT_EQ(vis[f], 1.) << "face " << f; // convex outside
  // the sphere is about 1 away: within 0.5, nothing blocks
  EXPECT_EQ(visibility_of(mesh, 64, 0.5).back(), 1.);
}

TYPED_TEST(Face_visibility, same_result_with_one_and_two_threads)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "built without TBB: one thread only";
#endif
  TypeParam mesh;
  build_mesh(thickened_soup(wavy_disk_soup(6, 16, 3), 0.05), mesh);
  std::vector<double> one, two;
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
#endif
    one = visibility_of(mesh);
  }
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
#endif
    two = visibility_of(mesh);
  }
  EXPECT_EQ(one, two);
  // a thin closed slab: some faces see less than everything, none less than nothing
  EXPECT_LT(*std::min_element(one.begin(), one.end()), 1.);
  EXPECT_GE(*std::min_element(one.begin(), one.end()), 0.);
}

TYPED_TEST(Face_visibility, bad_input_is_refused)
{
  using face_descriptor = typename boost::graph_traits<TypeParam>::face_descriptor;
  std::map<face_descriptor, double> values;
  auto map = boost::make_assoc_property_map(values);
  TypeParam empty;
  EXPECT_EQ(SMP::face_visibility(empty, map), SMP::ERROR_EMPTY_MESH);
  TypeParam quads;
  build_mesh(quad_grid_soup(2, 2), quads);
  EXPECT_EQ(SMP::face_visibility(quads, map), SMP::ERROR_NON_TRIANGULAR_MESH);
  TypeParam mesh;
  build_mesh(grid_soup(2, 2), mesh);
  EXPECT_EQ(SMP::face_visibility(mesh, map, SMP::parameters::number_of_rays(0)), SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(SMP::face_visibility(mesh, map, SMP::parameters::maximum_distance(0.)), SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(SMP::face_visibility(mesh, map, SMP::parameters::maximum_distance(-1.)), SMP::ERROR_WRONG_PARAMETER);
  EXPECT_TRUE(values.empty()); // nothing written on refusal
}

TYPED_TEST(Face_visibility, lambda_grows_with_visibility_around_one)
{
  using face_descriptor = typename boost::graph_traits<TypeParam>::face_descriptor;
  TypeParam mesh;
  build_mesh(grid_soup(4, 4), mesh); // 32 faces of equal area
  std::map<face_descriptor, double> vis, lambda;
  int k = 0;
  for(face_descriptor f : faces(mesh)) vis[f] = (k++ % 8) / 7.;
  auto vis_map = boost::make_assoc_property_map(vis);
  auto lambda_map = boost::make_assoc_property_map(lambda);
  ASSERT_EQ(SMP::visibility_face_lambda(mesh, vis_map, lambda_map, 3.), SMP::OK);
  double log_sum = 0.;
  for(face_descriptor f : faces(mesh))
    for(face_descriptor g : faces(mesh))
      if(vis[f] < vis[g]) EXPECT_LT(lambda[f], lambda[g]);
  for(face_descriptor f : faces(mesh)) log_sum += std::log(lambda[f]);
  EXPECT_NEAR(log_sum / double(num_faces(mesh)), 0., 1e-12); // geometric mean 1 (equal areas)
  // the contrast is exp(strength) between a face that sees all and one that sees nothing
  face_descriptor blind = *faces(mesh).begin(), open = blind;
  for(face_descriptor f : faces(mesh))
  {
    if(vis[f] == 0.) blind = f;
    if(vis[f] == 1.) open = f;
  }
  EXPECT_NEAR(lambda[open] / lambda[blind], std::exp(3.), 1e-9);
  ASSERT_EQ(SMP::visibility_face_lambda(mesh, vis_map, lambda_map, 0.), SMP::OK);
  for(face_descriptor f : faces(mesh)) EXPECT_EQ(lambda[f], 1.);
  EXPECT_EQ(SMP::visibility_face_lambda(mesh, vis_map, lambda_map, -1.), SMP::ERROR_WRONG_PARAMETER);
  vis[*faces(mesh).begin()] = 1.5;
  EXPECT_EQ(SMP::visibility_face_lambda(mesh, vis_map, lambda_map, 1.), SMP::ERROR_WRONG_PARAMETER);
}

TYPED_TEST(Face_visibility, seam_visibility_is_the_length_weighted_mean)
{
  using face_descriptor = typename boost::graph_traits<TypeParam>::face_descriptor;
  using edge_descriptor = typename boost::graph_traits<TypeParam>::edge_descriptor;
  TypeParam mesh;
  build_mesh(grid_soup(3, 3), mesh);
  std::map<face_descriptor, double> vis;
  std::map<edge_descriptor, bool> seams;
  int k = 0;
  for(face_descriptor f : faces(mesh)) vis[f] = (k++ % 3) / 2.;
  auto vis_map = boost::make_assoc_property_map(vis);
  auto seam_map = boost::make_assoc_property_map(seams);
  for(edge_descriptor e : edges(mesh)) seams[e] = false;
  EXPECT_EQ(SMP::seam_visibility(mesh, seam_map, vis_map), 0.); // no seam
  double length = 0., weighted = 0.;
  int n = 0;
  for(edge_descriptor e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    if(is_border_edge(h, mesh) || n++ % 2) continue;
    seams[e] = true;
    const auto p = get(CGAL::vertex_point, mesh, source(h, mesh)), q = get(CGAL::vertex_point, mesh, target(h, mesh));
    const double l = std::sqrt(CGAL::squared_distance(p, q));
    length += l;
    weighted += l * 0.5 * (vis[face(h, mesh)] + vis[face(opposite(h, mesh), mesh)]);
  }
  ASSERT_GT(length, 0.);
  EXPECT_NEAR(SMP::seam_visibility(mesh, seam_map, vis_map), weighted / length, 1e-14);
}

} // namespace
