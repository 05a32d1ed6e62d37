// Public metrics (parameterization_metrics.h) on hand-computed cases:
// face_distortion / distortion_energy (E_d), number_of_flipped_faces,
// surface_area, seam_length (E_s), with vertex- and halfedge-keyed UV maps.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

template <typename Mesh>
auto vertex_uv_map(const Mesh& mesh)
{
  return get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
}

template <typename Mesh>
auto halfedge_uv_map(const Mesh& mesh)
{
  return get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
}

template <typename Mesh>
auto seam_edge_map(const Mesh& mesh)
{
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, false);
  return sem;
}

double ed_of_singular_values(double s1, double s2)
{
  return s1 * s1 + s2 * s2 + 1. / (s1 * s1) + 1. / (s2 * s2);
}

/// The face of `mesh` whose corners are the given vertices (in any rotation).
template <typename Mesh>
typename boost::graph_traits<Mesh>::face_descriptor
face_of(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor a,
        typename boost::graph_traits<Mesh>::vertex_descriptor b)
{
  const auto h = halfedge(a, b, mesh);
  if(!h.second) throw std::runtime_error("face_of: no such edge");
  return face(h.first, mesh);
}

/// Unit square [0,1]², split into 4 triangles around its center (point 4).
Soup square_fan_soup()
{
  Soup s;
  s.add_point(0, 0, 0);
  s.add_point(1, 0, 0);
  s.add_point(1, 1, 0);
  s.add_point(0, 1, 0);
  s.add_point(0.5, 0.5, 0);
  for(std::size_t k = 0; k < 4; ++k) s.add_triangle(k, (k + 1) % 4, 4);
  return s;
}

} // namespace

CUT_TYPED_TEST(right_triangle_with_known_scale_factors, Mesh_types)
{
  // A right triangle with legs a, b in a tilted plane, mapped to a right
  // triangle with legs s1 a, s2 b, rotated and moved in UV: the singular
  // values of the map are s1 and s2, E_d = s1² + s2² + s1⁻² + s2⁻².
  const double cases[][4] = {{1., 1., 1., 1.}, {1., 1., 2., 1.}, {2., 0.5, 3., 0.25}, {0.3, 5., 0.7, 1.3},
                             {1e-3, 2e-3, 1e3, 1e-2}};
  // orthonormal frame of a tilted plane, and an origin
  const double r2 = std::sqrt(0.5), r6 = std::sqrt(1. / 6.);
  const double e1[3] = {r2, -r2, 0.}, e2[3] = {r6, r6, -2. * r6}, o[3] = {0.3, -2., 5.};
  for(const auto& c : cases)
  {
    const double a = c[0], b = c[1], s1 = c[2], s2 = c[3];
    Scoped_context ctx("a=" + to_text(a) + " b=" + to_text(b) + " s1=" + to_text(s1) + " s2=" + to_text(s2));
    Soup soup;
    soup.add_point(o[0], o[1], o[2]);
    soup.add_point(o[0] + a * e1[0], o[1] + a * e1[1], o[2] + a * e1[2]);
    soup.add_point(o[0] + b * e2[0], o[1] + b * e2[1], o[2] + b * e2[2]);
    soup.add_triangle(0, 1, 2);
    TestType mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    const double angle = 0.8, ca = std::cos(angle), sa = std::sin(angle);
    auto place = [&](double x, double y) { return Point_2(10. + ca * x - sa * y, -3. + sa * x + ca * y); };
    put(uv, vertex_of[0], place(0., 0.));
    put(uv, vertex_of[1], place(s1 * a, 0.));
    put(uv, vertex_of[2], place(0., s2 * b));
    const double expected = ed_of_singular_values(s1, s2);
    CHECK_REL(SMP::face_distortion(*faces(mesh).begin(), mesh, uv), expected, 1e-10);
    CHECK_REL(SMP::distortion_energy(mesh, uv), expected, 1e-10);
    CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    CHECK_REL(SMP::surface_area(mesh), 0.5 * a * b, 1e-12);
  }
}

CUT_TYPED_TEST(sheared_triangle, Mesh_types)
{
  // (x, y) -> (x + k y, y): singular values with s1² + s2² = 2 + k² and
  // s1 s2 = 1, so E_d = 2 (2 + k²) = 4 + 2k², whatever the triangle
  for(double k : {0., 0.5, 1., 3.})
  {
    Scoped_context ctx("k=" + to_text(k));
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(2, 0.5, 0);
    soup.add_point(-0.5, 1.5, 0);
    soup.add_triangle(0, 1, 2);
    TestType mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    for(std::size_t i = 0; i < 3; ++i)
      put(uv, vertex_of[i], Point_2(soup.points[i][0] + k * soup.points[i][1], soup.points[i][1]));
    CHECK_REL(SMP::distortion_energy(mesh, uv), 4. + 2. * k * k, 1e-12);
  }
}

CUT_TYPED_TEST(distortion_is_the_area_weighted_mean, Mesh_types)
{
  // two triangles sharing the edge p1 p2: T1 = (p0 p1 p2), area 1/2, mapped
  // isometrically (4); T2 = (p1 p3 p2), area 3/2, scaled by 2 in UV
  // (4 + 4 + 1/4 + 1/4 = 8.5). E_d = (0.5 * 4 + 1.5 * 8.5) / 2 = 7.375.
  Soup soup;
  soup.add_point(0, 0, 0);
  soup.add_point(1, 0, 0);
  soup.add_point(0, 1, 0);
  soup.add_point(3, 1, 0);
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(1, 3, 2);
  TestType mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  const auto t1 = face_of(mesh, vertex_of[0], vertex_of[1]);
  const auto t2 = face_of(mesh, vertex_of[1], vertex_of[3]);
  CHECK(t1 != t2);
  // one UV per corner (halfedge-keyed): the two faces are separate in UV
  auto corner_uv = halfedge_uv_map(mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(auto h : halfedges_around_face(halfedge(t1, mesh), mesh))
  {
    const auto& p = get(vpm, target(h, mesh));
    put(corner_uv, h, Point_2(p.x(), p.y()));
  }
  for(auto h : halfedges_around_face(halfedge(t2, mesh), mesh))
  {
    const auto& p = get(vpm, target(h, mesh));
    put(corner_uv, h, Point_2(2. * p.x() + 7., 2. * p.y()));
  }
  CHECK_REL(SMP::face_distortion(t1, mesh, corner_uv), 4., 1e-14);
  CHECK_REL(SMP::face_distortion(t2, mesh, corner_uv), 8.5, 1e-14);
  CHECK_REL(SMP::distortion_energy(mesh, corner_uv), 7.375, 1e-14);
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, corner_uv), std::size_t(0));
  CHECK_REL(SMP::surface_area(mesh), 2., 1e-14);

  // one UV per vertex: the identity gives 4 exactly on both
  auto uv = vertex_uv_map(mesh);
  for(auto v : vertices(mesh)) put(uv, v, Point_2(get(vpm, v).x(), get(vpm, v).y()));
  CHECK_REL(SMP::distortion_energy(mesh, uv), 4., 1e-14);
}

CUT_TYPED_TEST(flipped_faces_are_counted, Mesh_types)
{
  const Soup soup = square_fan_soup();
  TestType mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  for(std::size_t i = 0; i < 5; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  CHECK_REL(SMP::distortion_energy(mesh, uv), 4., 1e-14);

  // the center moved below the bottom edge: exactly the bottom face flips
  put(uv, vertex_of[4], Point_2(0.5, -0.2));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  CHECK(std::isinf(SMP::distortion_energy(mesh, uv)));
  const auto bottom = face_of(mesh, vertex_of[0], vertex_of[1]);
  const auto right = face_of(mesh, vertex_of[1], vertex_of[2]);
  CHECK(std::isinf(SMP::face_distortion(bottom, mesh, uv)));
  CHECK(std::isfinite(SMP::face_distortion(right, mesh, uv)));

  // the center on the bottom edge: a collapsed face counts as flipped
  put(uv, vertex_of[4], Point_2(0.5, 0.));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  CHECK(std::isinf(SMP::distortion_energy(mesh, uv)));

  // the center beyond the bottom-left corner: the bottom and left faces flip
  put(uv, vertex_of[4], Point_2(-0.1, -0.1));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(2));

  // a mirrored map flips everything
  for(std::size_t i = 0; i < 5; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], -soup.points[i][1]));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(4));
  CHECK(std::isinf(SMP::distortion_energy(mesh, uv)));
}

CUT_TYPED_TEST(zero_area_faces_have_no_weight_in_distortion, Mesh_types)
{
  // T1 = (p0 p1 p2) a unit right triangle; T2 = (p1 p0 p3) with p3 on the
  // line p0 p1: zero 3D area. Its UV triangle is fine, but it has no weight.
  Soup soup;
  soup.add_point(0, 0, 0);
  soup.add_point(1, 0, 0);
  soup.add_point(0, 1, 0);
  soup.add_point(2, 0, 0);
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(1, 0, 3);
  TestType mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  put(uv, vertex_of[0], Point_2(0, 0));
  put(uv, vertex_of[1], Point_2(2, 0));
  put(uv, vertex_of[2], Point_2(0, 1));
  put(uv, vertex_of[3], Point_2(1, -1));
  CHECK_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  CHECK_REL(SMP::distortion_energy(mesh, uv), ed_of_singular_values(2., 1.), 1e-14);
  CHECK(std::isinf(SMP::face_distortion(face_of(mesh, vertex_of[0], vertex_of[3]), mesh, uv)));
  CHECK_REL(SMP::surface_area(mesh), 0.5, 1e-15);

  // a needle (height 1e-6 of its longest side, below the documented 1e-4) counts as degenerate too;
  // a thin but proper face (height 1e-2) does not
  for(double height : {1e-6, 1e-2})
  {
    Scoped_context ctx("height " + to_text(height));
    Soup thin = soup;
    thin.points[3] = {1.5, -height * 2., 0.}; // T2's longest side p0 p3 has length ~2
    TestType thin_mesh;
    const auto v = build_mesh(thin, thin_mesh);
    auto thin_uv = vertex_uv_map(thin_mesh);
    for(std::size_t i = 0; i < 4; ++i) put(thin_uv, v[i], get(uv, vertex_of[i]));
    const double t2 = SMP::face_distortion(face_of(thin_mesh, v[0], v[3]), thin_mesh, thin_uv);
    const double ed = SMP::distortion_energy(thin_mesh, thin_uv);
    if(height < 1e-4)
    {
      CHECK(std::isinf(t2));
      CHECK_REL(ed, ed_of_singular_values(2., 1.), 1e-14);
    }
    else
    {
      CHECK(std::isfinite(t2));
      CHECK(ed > ed_of_singular_values(2., 1.));
    }
  }
}

CUT_TYPED_TEST(seam_length_on_tiny_meshes, Mesh_types)
{
  {
    // unit square fan, area 1: a seam from the center to a corner (length
    // sqrt(1/2)) and a seam flag on a border edge, which is not counted
    const Soup soup = square_fan_soup();
    TestType mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto sem = seam_edge_map(mesh);
    CHECK_EQ(SMP::seam_length(mesh, sem), 0.);
    put(sem, edge(halfedge(vertex_of[4], vertex_of[0], mesh).first, mesh), true);
    CHECK_REL(SMP::seam_length(mesh, sem), std::sqrt(0.5) / std::sqrt(1. / pi), 1e-14);
    put(sem, edge(halfedge(vertex_of[0], vertex_of[1], mesh).first, mesh), true);
    CHECK_REL(SMP::seam_length(mesh, sem), std::sqrt(0.5) / std::sqrt(1. / pi), 1e-14);
  }
  {
    // octahedron of radius 1 (edges sqrt 2, area 8 * sqrt(3)/4 * 2 = 4 sqrt 3),
    // closed: the seam path from pole to pole has 2 edges
    const Soup soup = sphere_soup(1);
    TestType mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    CHECK_EQ(num_faces(mesh), std::size_t(8));
    CHECK_REL(SMP::surface_area(mesh), 4. * std::sqrt(3.), 1e-14);
    auto sem = seam_edge_map(mesh);
    for(auto e : soup_edges(mesh, vertex_of, soup.cut)) put(sem, e, true);
    const double expected = 2. * std::sqrt(2.) / std::sqrt(4. * std::sqrt(3.) / pi);
    CHECK_REL(SMP::seam_length(mesh, sem), expected, 1e-14);
    // every edge flagged: 12 edges of length sqrt 2
    for(auto e : edges(mesh)) put(sem, e, true);
    CHECK_REL(SMP::seam_length(mesh, sem), 12. * std::sqrt(2.) / std::sqrt(4. * std::sqrt(3.) / pi), 1e-14);
  }
}

CUT_TYPED_TEST(metrics_do_not_depend_on_scale, Mesh_types)
{
  // a non-trivial map (the wavy disk flattened by dropping z, stretched),
  // and the same with mesh and UVs scaled: same E_d and E_s
  double reference_ed = 0., reference_es = 0.;
  for(double s : {1., 1e-3, 1e3})
  {
    Scoped_context ctx("scale " + to_text(s));
    Soup soup = wavy_disk_soup(4, 12, 3);
    soup.scale(s);
    TestType mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      put(uv, vertex_of[i], Point_2(1.5 * soup.points[i][0] + 0.2 * soup.points[i][1], 0.7 * soup.points[i][1]));
    auto sem = seam_edge_map(mesh);
    for(auto e : shortest_edge_path(mesh, vertex_of[0], vertex_of.back())) put(sem, e, true);
    const double ed = SMP::distortion_energy(mesh, uv), es = SMP::seam_length(mesh, sem);
    CHECK(std::isfinite(ed) && ed > 4.);
    CHECK(es > 0.);
    CHECK_REL(SMP::surface_area(mesh) / (s * s), SMP::surface_area(make_mesh<TestType>(wavy_disk_soup(4, 12, 3))), 1e-12);
    if(s == 1.)
    {
      reference_ed = ed;
      reference_es = es;
    }
    else
    {
      CHECK_REL(ed, reference_ed, 1e-10);
      CHECK_REL(es, reference_es, 1e-12);
    }
  }
}

CUT_TEST_MAIN()
