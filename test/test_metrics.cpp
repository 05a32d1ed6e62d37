// Public metrics (parameterization_metrics.h) on hand-computed cases:
// face_distortion / distortion_energy (E_d), number_of_flipped_faces,
// surface_area, seam_length (E_s), number_of_border_crossings, uv_area,
// uv_overlap_area, with vertex- and halfedge-keyed UV maps.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <CGAL/Exact_rational.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

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

/// Gives every corner of `mesh` the UV of its vertex in `vertex_uv`.
template <typename Mesh, typename VertexUV, typename HalfedgeUV>
void copy_to_corners(const Mesh& mesh, const VertexUV& vertex_uv, HalfedgeUV& corner_uv)
{
  for(auto f : faces(mesh))
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) put(corner_uv, h, get(vertex_uv, target(h, mesh)));
}

/// The strip grid_soup(4, 1) (point (i, j) is j * 5 + i) bent along the
/// path (0,0) -> (4,0) -> (4,3) -> (2,3) -> (2,-2), width 1, turning left at
/// each corner (mitered): its last leg crosses its first leg. No flipped
/// face; the sides x = 1.5 and x = 2.5 of the last leg cross the sides
/// y = -0.5 and y = 0.5 of the first: 4 border crossings. UV area: the
/// trapezoids 4 + 3 + 2 + 5 = 14.
const double strip_loop_uv[2][5][2] = {{{0, -0.5}, {4.5, -0.5}, {4.5, 3.5}, {1.5, 3.5}, {1.5, -2}},  // j = 0 (outer side)
                                       {{0, 0.5}, {3.5, 0.5}, {3.5, 2.5}, {2.5, 2.5}, {2.5, -2}}}; // j = 1 (inner side)

/// Sign of the orientation of (p, q, r) in exact rational arithmetic: a
/// predicate of the test's own, independent of the library's.
int exact_orientation(const SMP::internal::cut::Vector2& p, const SMP::internal::cut::Vector2& q,
                      const SMP::internal::cut::Vector2& r)
{
  using Q = CGAL::Exact_rational;
  const Q d = (Q(q.x()) - Q(p.x())) * (Q(r.y()) - Q(p.y())) - (Q(q.y()) - Q(p.y())) * (Q(r.x()) - Q(p.x()));
  return int(CGAL::sign(d));
}

/// Brute force: pairs of the faces' UV edges, in different faces, that cross
/// properly (each segment's endpoints strictly on both sides of the other's line).
template <typename Mesh, typename HalfedgeUV>
std::size_t crossings_of_separate_faces(const Mesh& mesh, const HalfedgeUV& corner_uv)
{
  std::vector<std::array<SMP::internal::cut::Vector2, 2>> edges_uv;
  std::vector<std::size_t> face_index;
  std::size_t k = 0;
  for(auto f : faces(mesh))
  {
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      edges_uv.push_back({SMP::internal::cut::corner_uv(mesh, corner_uv, prev(h, mesh)),
                          SMP::internal::cut::corner_uv(mesh, corner_uv, h)});
      face_index.push_back(k);
    }
    ++k;
  }
  std::size_t n = 0;
  for(std::size_t a = 0; a < edges_uv.size(); ++a)
    for(std::size_t b = a + 1; b < edges_uv.size(); ++b)
    {
      const auto& s = edges_uv[a];
      const auto& t = edges_uv[b];
      if(face_index[a] != face_index[b] &&
         exact_orientation(s[0], s[1], t[0]) * exact_orientation(s[0], s[1], t[1]) < 0 &&
         exact_orientation(t[0], t[1], s[0]) * exact_orientation(t[0], t[1], s[1]) < 0)
        ++n;
    }
  return n;
}

} // namespace

template <typename Mesh>
class MetricsTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(MetricsTyped, Mesh_types);

TYPED_TEST(MetricsTyped, right_triangle_with_known_scale_factors)
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
    SCOPED_TRACE("a=" + to_text(a) + " b=" + to_text(b) + " s1=" + to_text(s1) + " s2=" + to_text(s2));
    Soup soup;
    soup.add_point(o[0], o[1], o[2]);
    soup.add_point(o[0] + a * e1[0], o[1] + a * e1[1], o[2] + a * e1[2]);
    soup.add_point(o[0] + b * e2[0], o[1] + b * e2[1], o[2] + b * e2[2]);
    soup.add_triangle(0, 1, 2);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    const double angle = 0.8, ca = std::cos(angle), sa = std::sin(angle);
    auto place = [&](double x, double y) { return Point_2(10. + ca * x - sa * y, -3. + sa * x + ca * y); };
    put(uv, vertex_of[0], place(0., 0.));
    put(uv, vertex_of[1], place(s1 * a, 0.));
    put(uv, vertex_of[2], place(0., s2 * b));
    const double expected = ed_of_singular_values(s1, s2);
    EXPECT_REL(SMP::face_distortion(*faces(mesh).begin(), mesh, uv), expected, 1e-10);
    EXPECT_REL(SMP::distortion_energy(mesh, uv), expected, 1e-10);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    EXPECT_REL(SMP::surface_area(mesh), 0.5 * a * b, 1e-12);
  }
}

TYPED_TEST(MetricsTyped, sheared_triangle)
{
  // (x, y) -> (x + k y, y): singular values with s1² + s2² = 2 + k² and
  // s1 s2 = 1, so E_d = 2 (2 + k²) = 4 + 2k², whatever the triangle
  for(double k : {0., 0.5, 1., 3.})
  {
    SCOPED_TRACE("k=" + to_text(k));
    Soup soup;
    soup.add_point(0, 0, 0);
    soup.add_point(2, 0.5, 0);
    soup.add_point(-0.5, 1.5, 0);
    soup.add_triangle(0, 1, 2);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    for(std::size_t i = 0; i < 3; ++i)
      put(uv, vertex_of[i], Point_2(soup.points[i][0] + k * soup.points[i][1], soup.points[i][1]));
    EXPECT_REL(SMP::distortion_energy(mesh, uv), 4. + 2. * k * k, 1e-12);
    // the same map scaled by 3 (a packed atlas), measured with uv_scale(3)
    for(std::size_t i = 0; i < 3; ++i)
      put(uv, vertex_of[i], Point_2(3. * (soup.points[i][0] + k * soup.points[i][1]), 3. * soup.points[i][1]));
    EXPECT_TRUE(SMP::distortion_energy(mesh, uv) > 4. + 2. * k * k + 1.);
    EXPECT_REL(SMP::distortion_energy(mesh, uv, SMP::parameters::uv_scale(3.)), 4. + 2. * k * k, 1e-12);
    EXPECT_REL(SMP::face_distortion(*faces(mesh).begin(), mesh, uv, SMP::parameters::uv_scale(3.)), 4. + 2. * k * k, 1e-12);
  }
}

TYPED_TEST(MetricsTyped, distortion_is_the_area_weighted_mean)
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
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  const auto t1 = face_of(mesh, vertex_of[0], vertex_of[1]);
  const auto t2 = face_of(mesh, vertex_of[1], vertex_of[3]);
  EXPECT_TRUE(t1 != t2);
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
  EXPECT_REL(SMP::face_distortion(t1, mesh, corner_uv), 4., 1e-14);
  EXPECT_REL(SMP::face_distortion(t2, mesh, corner_uv), 8.5, 1e-14);
  EXPECT_REL(SMP::distortion_energy(mesh, corner_uv), 7.375, 1e-14);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, corner_uv), std::size_t(0));
  EXPECT_REL(SMP::surface_area(mesh), 2., 1e-14);

  // one UV per vertex: the identity gives 4 exactly on both
  auto uv = vertex_uv_map(mesh);
  for(auto v : vertices(mesh)) put(uv, v, Point_2(get(vpm, v).x(), get(vpm, v).y()));
  EXPECT_REL(SMP::distortion_energy(mesh, uv), 4., 1e-14);
}

TYPED_TEST(MetricsTyped, flipped_faces_are_counted)
{
  const Soup soup = square_fan_soup();
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  for(std::size_t i = 0; i < 5; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  EXPECT_REL(SMP::distortion_energy(mesh, uv), 4., 1e-14);

  // the center moved below the bottom edge: exactly the bottom face flips
  put(uv, vertex_of[4], Point_2(0.5, -0.2));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  EXPECT_TRUE(std::isinf(SMP::distortion_energy(mesh, uv)));
  const auto bottom = face_of(mesh, vertex_of[0], vertex_of[1]);
  const auto right = face_of(mesh, vertex_of[1], vertex_of[2]);
  EXPECT_TRUE(std::isinf(SMP::face_distortion(bottom, mesh, uv)));
  EXPECT_TRUE(std::isfinite(SMP::face_distortion(right, mesh, uv)));

  // the center on the bottom edge: a collapsed face counts as flipped
  put(uv, vertex_of[4], Point_2(0.5, 0.));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  EXPECT_TRUE(std::isinf(SMP::distortion_energy(mesh, uv)));

  // the center beyond the bottom-left corner: the bottom and left faces flip
  put(uv, vertex_of[4], Point_2(-0.1, -0.1));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(2));

  // a mirrored map flips everything
  for(std::size_t i = 0; i < 5; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], -soup.points[i][1]));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(4));
  EXPECT_TRUE(std::isinf(SMP::distortion_energy(mesh, uv)));
}

TYPED_TEST(MetricsTyped, zero_area_faces_have_no_weight_in_distortion)
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
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  put(uv, vertex_of[0], Point_2(0, 0));
  put(uv, vertex_of[1], Point_2(2, 0));
  put(uv, vertex_of[2], Point_2(0, 1));
  put(uv, vertex_of[3], Point_2(1, -1));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  EXPECT_REL(SMP::distortion_energy(mesh, uv), ed_of_singular_values(2., 1.), 1e-14);
  EXPECT_TRUE(std::isinf(SMP::face_distortion(face_of(mesh, vertex_of[0], vertex_of[3]), mesh, uv)));
  EXPECT_REL(SMP::surface_area(mesh), 0.5, 1e-15);

  // a needle (height 1e-6 of its longest side, below the documented 1e-4) counts as degenerate too;
  // a thin but proper face (height 1e-2) does not
  for(double height : {1e-6, 1e-2})
  {
    SCOPED_TRACE("height " + to_text(height));
    Soup thin = soup;
    thin.points[3] = {1.5, -height * 2., 0.}; // T2's longest side p0 p3 has length ~2
    TypeParam thin_mesh;
    const auto v = build_mesh(thin, thin_mesh);
    auto thin_uv = vertex_uv_map(thin_mesh);
    for(std::size_t i = 0; i < 4; ++i) put(thin_uv, v[i], get(uv, vertex_of[i]));
    const double t2 = SMP::face_distortion(face_of(thin_mesh, v[0], v[3]), thin_mesh, thin_uv);
    const double ed = SMP::distortion_energy(thin_mesh, thin_uv);
    if(height < 1e-4)
    {
      EXPECT_TRUE(std::isinf(t2));
      EXPECT_REL(ed, ed_of_singular_values(2., 1.), 1e-14);
    }
    else
    {
      EXPECT_TRUE(std::isfinite(t2));
      EXPECT_TRUE(ed > ed_of_singular_values(2., 1.));
    }
  }
}

TYPED_TEST(MetricsTyped, seam_length_on_tiny_meshes)
{
  {
    // unit square fan, area 1: a seam from the center to a corner (length
    // sqrt(1/2)) and a seam flag on a border edge, which is not counted
    const Soup soup = square_fan_soup();
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto sem = seam_edge_map(mesh);
    EXPECT_EQ(SMP::seam_length(mesh, sem), 0.);
    put(sem, edge(halfedge(vertex_of[4], vertex_of[0], mesh).first, mesh), true);
    EXPECT_REL(SMP::seam_length(mesh, sem), std::sqrt(0.5) / std::sqrt(1. / pi), 1e-14);
    put(sem, edge(halfedge(vertex_of[0], vertex_of[1], mesh).first, mesh), true);
    EXPECT_REL(SMP::seam_length(mesh, sem), std::sqrt(0.5) / std::sqrt(1. / pi), 1e-14);
  }
  {
    // octahedron of radius 1 (edges sqrt 2, area 8 * sqrt(3)/4 * 2 = 4 sqrt 3),
    // closed: the seam path from pole to pole has 2 edges
    const Soup soup = sphere_soup(1);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    EXPECT_EQ(num_faces(mesh), std::size_t(8));
    EXPECT_REL(SMP::surface_area(mesh), 4. * std::sqrt(3.), 1e-14);
    auto sem = seam_edge_map(mesh);
    for(auto e : soup_edges(mesh, vertex_of, soup.cut)) put(sem, e, true);
    const double expected = 2. * std::sqrt(2.) / std::sqrt(4. * std::sqrt(3.) / pi);
    EXPECT_REL(SMP::seam_length(mesh, sem), expected, 1e-14);
    // every edge flagged: 12 edges of length sqrt 2
    for(auto e : edges(mesh)) put(sem, e, true);
    EXPECT_REL(SMP::seam_length(mesh, sem), 12. * std::sqrt(2.) / std::sqrt(4. * std::sqrt(3.) / pi), 1e-14);
  }
}

TYPED_TEST(MetricsTyped, metrics_do_not_depend_on_scale)
{
  // a non-trivial map (the wavy disk flattened by dropping z, stretched),
  // and the same with mesh and UVs scaled: same E_d and E_s
  double reference_ed = 0., reference_es = 0.;
  for(double s : {1., 1e-3, 1e3})
  {
    SCOPED_TRACE("scale " + to_text(s));
    Soup soup = wavy_disk_soup(4, 12, 3);
    soup.scale(s);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      put(uv, vertex_of[i], Point_2(1.5 * soup.points[i][0] + 0.2 * soup.points[i][1], 0.7 * soup.points[i][1]));
    auto sem = seam_edge_map(mesh);
    for(auto e : shortest_edge_path(mesh, vertex_of[0], vertex_of.back())) put(sem, e, true);
    const double ed = SMP::distortion_energy(mesh, uv), es = SMP::seam_length(mesh, sem);
    EXPECT_TRUE(std::isfinite(ed) && ed > 4.);
    EXPECT_TRUE(es > 0.);
    EXPECT_REL(SMP::surface_area(mesh) / (s * s), SMP::surface_area(make_mesh<TypeParam>(wavy_disk_soup(4, 12, 3))), 1e-12);
    if(s == 1.)
    {
      reference_ed = ed;
      reference_es = es;
    }
    else
    {
      EXPECT_REL(ed, reference_ed, 1e-10);
      EXPECT_REL(es, reference_es, 1e-12);
    }
  }
}

TYPED_TEST(MetricsTyped, border_crossings_of_a_strip_looped_over_itself)
{
  const Soup soup = grid_soup(4, 1, 4., 1.);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  auto corner_uv = halfedge_uv_map(mesh);

  // laid out flat (the identity): no crossing
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  copy_to_corners(mesh, uv, corner_uv);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(0));
  EXPECT_REL(SMP::uv_area(mesh, uv), 4., 1e-14);

  // looped over itself: 4 crossings of its sides, none of the inner edges
  // (the diagonals and the rungs also cross the first leg) counted
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 5; ++i)
      put(uv, vertex_of[std::size_t(j * 5 + i)], Point_2(strip_loop_uv[j][i][0], strip_loop_uv[j][i][1]));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(4));
  EXPECT_REL(SMP::uv_area(mesh, uv), 14., 1e-14);
  // the same map keyed by halfedges: equal corner UVs make no seam
  copy_to_corners(mesh, uv, corner_uv);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(4));
  EXPECT_REL(SMP::uv_area(mesh, corner_uv), 14., 1e-14);

  // the last leg shortened to end at y = 0 (inside the first leg): its
  // sides cross only the inner side y = 0.5, and its end y = 0 crosses nothing
  put(uv, vertex_of[4], Point_2(1.5, 0.));
  put(uv, vertex_of[9], Point_2(2.5, 0.));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(2));
  // ending exactly on the outer side y = -0.5: touching is not crossing
  put(uv, vertex_of[4], Point_2(1.5, -0.5));
  put(uv, vertex_of[9], Point_2(2.5, -0.5));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(2));
}

TYPED_TEST(MetricsTyped, a_seam_is_a_uv_border)
{
  // the strip [0,3] x [0,1] of 3 squares; the faces of the last square get
  // their own UVs (halfedge-keyed map), so the edge x = 2 is a seam
  const Soup soup = grid_soup(3, 1, 3., 1.);
  TypeParam mesh;
  build_mesh(soup, mesh);
  auto corner_uv = halfedge_uv_map(mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  auto place = [&](double dx, double dy) {
    for(auto f : faces(mesh))
    {
      double cx = 0.;
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) cx += get(vpm, target(h, mesh)).x() / 3.;
      const bool last = cx > 2.;
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const auto& p = get(vpm, target(h, mesh));
        put(corner_uv, h, Point_2(p.x() + (last ? dx : 0.), p.y() + (last ? dy : 0.)));
      }
    }
  };

  // no shift: equal UVs on both sides, one chart, no crossing
  place(0., 0.);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(0));
  // the last square moved away: two charts, no crossing
  place(10., 0.);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(0));
  EXPECT_REL(SMP::uv_area(mesh, corner_uv), 3., 1e-14);
  // moved to [1.5,2.5] x [0.5,1.5]: its seam side x = 1.5 crosses the top
  // y = 1 of the rest, and its bottom y = 0.5 crosses the rest's seam side
  // x = 2; both crossings involve a seam side
  place(-0.5, 0.5);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, corner_uv), std::size_t(0));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(2));
  EXPECT_REL(SMP::uv_area(mesh, corner_uv), 3., 1e-14);
  // moved up only ([2,3] x [0.5,1.5]): the seam sides overlap along x = 2
  // and the bottom y = 0.5 ends on the seam side x = 2: no proper crossing
  place(0., 0.5);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), std::size_t(0));
}

TYPED_TEST(MetricsTyped, border_crossings_of_overlapping_pieces)
{
  // two components, one square each (grid_soup(1, 1): two triangles): laid
  // as a '+' their sides cross 4 times; the diagonals are not borders
  Soup soup = grid_soup(1, 1);
  soup.append(grid_soup(1, 1));
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  auto lay = [&](double x0, double y0, double w0, double h0, double x1, double y1, double w1, double h1) {
    for(std::size_t i = 0; i < 8; ++i)
    {
      const bool second = i >= 4;
      const double x = soup.points[i][0], y = soup.points[i][1];
      put(uv, vertex_of[i], second ? Point_2(x1 + w1 * x, y1 + h1 * y) : Point_2(x0 + w0 * x, y0 + h0 * y));
    }
  };
  lay(0., 1., 3., 1., 1., 0., 1., 3.); // '+'
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(4));
  EXPECT_REL(SMP::uv_area(mesh, uv), 6., 1e-14);
  lay(0., 1., 3., 1., 1., 0., 1., 1.5); // 'T' upside down: the vertical one ends inside
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(2));
  lay(0., 0., 1., 1., 2., 0., 1., 1.); // side by side
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  lay(0., 0., 1., 1., 1., 0., 1., 1.); // sharing a side (different vertices, equal UVs)
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  lay(0., 1., 3., 1., 3., 0., 1., 3.); // T-junction: a corner on the other's side
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  lay(0., 0., 1., 1., 0., 0., 1., 1.); // one on top of the other: collinear overlaps only
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_REL(SMP::uv_area(mesh, uv), 2., 1e-14);
}

TYPED_TEST(MetricsTyped, a_folded_face_crosses_the_border)
{
  // T1 = (p0 p1 p2), T2 = (p1 p3 p2) sharing p1 p2; p3 folded over the
  // shared edge to (-0.5, 0.3): T2 flips and its side p1 p3 crosses T1's
  // side p2 p0 at (0, 0.2)
  Soup soup;
  soup.add_point(0, 0, 0);
  soup.add_point(1, 0, 0);
  soup.add_point(0, 1, 0);
  soup.add_point(1, 1, 0);
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(1, 3, 2);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  for(std::size_t i = 0; i < 4; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_REL(SMP::uv_area(mesh, uv), 1., 1e-14);
  put(uv, vertex_of[3], Point_2(-0.5, 0.3));
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(1));
  // unsigned areas: 0.5 + |(-1.5, 0.3) x (-1, 1)| / 2 = 0.5 + 0.6
  EXPECT_REL(SMP::uv_area(mesh, uv), 1.1, 1e-14);
  // a non-finite UV makes its segments cross nothing
  put(uv, vertex_of[3], Point_2(std::numeric_limits<double>::quiet_NaN(), 0.3));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_TRUE(std::isnan(SMP::uv_area(mesh, uv)));
}

TYPED_TEST(MetricsTyped, border_crossings_match_brute_force)
{
  // every face its own chart at a random place (halfedge-keyed): all face
  // edges are borders; the count must match the quadratic one
  const Soup soup = grid_soup(6, 5);
  TypeParam mesh;
  build_mesh(soup, mesh);
  auto corner_uv = halfedge_uv_map(mesh);
  for(std::uint64_t seed : {1u, 2u, 3u})
  {
    SCOPED_TRACE("seed " + to_text(double(seed)));
    Rng rng(seed);
    for(auto f : faces(mesh))
    {
      const double cx = rng.uniform(0., 3.), cy = rng.uniform(0., 3.);
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        put(corner_uv, h, Point_2(cx + rng.uniform(-0.4, 0.4), cy + rng.uniform(-0.4, 0.4)));
    }
    const std::size_t expected = crossings_of_separate_faces(mesh, corner_uv);
    EXPECT_TRUE(expected > 0);
    EXPECT_EQ(SMP::number_of_border_crossings(mesh, corner_uv), expected);
  }
}

TYPED_TEST(MetricsTyped, uv_area_of_known_layouts)
{
  const Soup soup = square_fan_soup();
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  // identity, scaled, mirrored (unsigned areas), moved
  const double cases[][4] = {{1., 1., 0., 1.}, {2., 2., 0., 4.}, {1., -1., 0., 1.}, {0.5, -0.25, 7., 0.125}};
  for(const auto& c : cases)
  {
    SCOPED_TRACE("sx=" + to_text(c[0]) + " sy=" + to_text(c[1]));
    for(std::size_t i = 0; i < 5; ++i)
      put(uv, vertex_of[i], Point_2(c[2] + c[0] * soup.points[i][0], c[1] * soup.points[i][1]));
    EXPECT_REL(SMP::uv_area(mesh, uv), c[3], 1e-14);
    EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  }
  // the center moved out of the square: the bottom face flips and the
  // unsigned areas add up to more than the square's (bottom, left and right
  // 0.25, top 0.75); the fold is inside, the border (the square's sides)
  // stays simple: no crossing
  put(uv, vertex_of[4], Point_2(0.5, -0.5));
  for(std::size_t i = 0; i < 4; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  double expected = 0.;
  for(std::size_t k = 0; k < 4; ++k)
  {
    const Point_2 a = get(uv, vertex_of[k]), b = get(uv, vertex_of[(k + 1) % 4]), c = get(uv, vertex_of[4]);
    expected += 0.5 * std::abs((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
  }
  EXPECT_REL(SMP::uv_area(mesh, uv), expected, 1e-14);
  EXPECT_REL(expected, 1.5, 1e-14);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(1));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));

  // corner UVs: T1 = (p0 p1 p2) as is (area 1/2), T2 = (p1 p3 p2) scaled by 2 (3D area 3/2, UV area 6)
  Soup two;
  two.add_point(0, 0, 0);
  two.add_point(1, 0, 0);
  two.add_point(0, 1, 0);
  two.add_point(3, 1, 0);
  two.add_triangle(0, 1, 2);
  two.add_triangle(1, 3, 2);
  TypeParam mesh2;
  const auto v2 = build_mesh(two, mesh2);
  auto corner_uv = halfedge_uv_map(mesh2);
  auto vpm = get(CGAL::vertex_point, mesh2);
  const auto t1 = face_of(mesh2, v2[0], v2[1]);
  for(auto f : faces(mesh2))
    for(auto h : halfedges_around_face(halfedge(f, mesh2), mesh2))
    {
      const auto& p = get(vpm, target(h, mesh2));
      put(corner_uv, h, f == t1 ? Point_2(p.x(), p.y()) : Point_2(2. * p.x() + 7., 2. * p.y()));
    }
  EXPECT_REL(SMP::uv_area(mesh2, corner_uv), 6.5, 1e-14);
  EXPECT_EQ(SMP::number_of_border_crossings(mesh2, corner_uv), std::size_t(0));
}


TYPED_TEST(MetricsTyped, overlap_area_sees_stacked_and_nested_charts)
{
  // two squares of 4 x 4 cells (32 triangles each, vertices on the sample
  // grid's cell corners and centers' lines): apart, side by side, stacked,
  // nested, shifted by half; the crossing count misses the stacked and
  // nested layouts, the overlap area does not
  Soup soup = grid_soup(4, 4, 1., 1.);
  soup.append(grid_soup(4, 4, 1., 1.));
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  const std::size_t half = soup.points.size() / 2;
  auto lay = [&](double x1, double y1, double s1) {
    for(std::size_t i = 0; i < soup.points.size(); ++i)
    {
      const double x = soup.points[i][0], y = soup.points[i][1];
      put(uv, vertex_of[i], i < half ? Point_2(x, y) : Point_2(x1 + s1 * x, y1 + s1 * y));
    }
  };
  // 256 x 256 samples (the default, 1024, takes 16 times longer)
  lay(2., 0., 1.); // apart
  EXPECT_EQ(SMP::uv_overlap_area(mesh, uv), 0.);
  lay(1., 0., 1.); // sharing a side
  EXPECT_EQ(SMP::uv_overlap_area(mesh, uv, 256), 0.);
  EXPECT_EQ(SMP::uv_overlap_area(mesh, uv, 7), 0.); // samples on shared edges and vertices
  lay(0., 0., 1.); // stacked: the second square covers the first
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv, 256), 1., 1e-12); // samples at cell centers: exact here
  lay(0.25, 0.25, 0.5); // nested: a quarter of the area inside the first
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv, 256), 0.25, 1e-12);
  lay(0.5, 0., 1.); // shifted by half a side: [0.5, 1] x [0, 1] covered twice (bounding box 1.5 wide)
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv, 256), 0.5, 1.5 * 1.5 * 4. / 256.); // a column of cells either way
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv, 999), 0.5, 1.5 * 1.5 * 4. / 999.);
  // a point covered three times counts twice
  Soup three = grid_soup(1, 1, 1., 1.);
  three.append(grid_soup(1, 1, 1., 1.));
  three.append(grid_soup(1, 1, 1., 1.));
  TypeParam stack;
  const auto vertex_of_three = build_mesh(three, stack);
  auto uv3 = vertex_uv_map(stack);
  for(std::size_t i = 0; i < three.points.size(); ++i)
    put(uv3, vertex_of_three[i], Point_2(three.points[i][0], three.points[i][1]));
  EXPECT_NEAR(SMP::uv_overlap_area(stack, uv3, 64), 2., 1e-12);
  // a non-finite UV: NaN, like uv_area()
  put(uv3, vertex_of_three[0], Point_2(std::numeric_limits<double>::quiet_NaN(), 0.));
  EXPECT_TRUE(std::isnan(SMP::uv_overlap_area(stack, uv3, 64)));
}

TYPED_TEST(MetricsTyped, overlap_area_of_folds_and_of_a_valid_fan)
{
  // the fan of square_fan_soup(): no overlap at any resolution (its
  // center and sides fall on samples at odd resolutions), corner-keyed too
  const Soup soup = square_fan_soup();
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto uv = vertex_uv_map(mesh);
  for(std::size_t i = 0; i < 5; ++i) put(uv, vertex_of[i], Point_2(soup.points[i][0], soup.points[i][1]));
  auto corner_uv = halfedge_uv_map(mesh);
  copy_to_corners(mesh, uv, corner_uv);
  for(std::size_t resolution : {1u, 2u, 3u, 5u, 64u, 255u})
  {
    SCOPED_TRACE("resolution " + to_text(double(resolution)));
    EXPECT_EQ(SMP::uv_overlap_area(mesh, uv, resolution), 0.);
    EXPECT_EQ(SMP::uv_overlap_area(mesh, corner_uv, resolution), 0.);
  }
  // the center moved out below the square: the bottom face flips. Signed
  // coverage is the border's winding number (1 in the square, 0 outside),
  // so the flipped bottom triangle, outside the square, lies under exactly
  // one other face: covered twice on its area 1/4, the rest once. No
  // border crosses another.
  put(uv, vertex_of[4], Point_2(0.5, -0.5));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, uv), std::size_t(0));
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv), 0.25, 1.5 * 3. / 1024.); // its perimeter times a cell side
  EXPECT_NEAR(SMP::uv_overlap_area(mesh, uv, 257), 0.25, 1.5 * 3. / 257.);
}

TEST(Metrics, overlap_area_scan_agrees_with_a_test_of_every_sample)
{
  // the raster scans each triangle's rows between its sides, with the exact
  // predicate near them only: the same count as testing every sample of its
  // bounding box, on random triangles with corners on the samples' lines
  // (rows through corners, sides through samples), far from the origin,
  // tiny, and on fans (shared sides and corners)
  namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
  using Triangles = std::vector<std::array<std::array<double, 2>, 3>>;
  auto every_sample = [](const Triangles& triangles, std::size_t n) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for(const auto& t : triangles)
      for(const auto& c : t)
        for(int d = 0; d < 2; ++d) { lo[d] = (std::min)(lo[d], c[d]); hi[d] = (std::max)(hi[d], c[d]); }
    const double h = (std::max)(hi[0] - lo[0], hi[1] - lo[1]) / double(n);
    std::vector<int> count(n * n, 0);
    std::size_t excess = 0;
    for(const auto& t : triangles)
    {
      CGAL::Epick::Point_2 a(t[0][0], t[0][1]), b(t[1][0], t[1][1]), c(t[2][0], t[2][1]);
      const CGAL::Orientation o = CGAL::orientation(a, b, c);
      if(o == CGAL::COLLINEAR) continue;
      if(o == CGAL::RIGHT_TURN) std::swap(b, c);
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i)
          if(ic::sample_in_ccw_triangle({lo[0] + (double(i) + 0.5) * h, lo[1] + (double(j) + 0.5) * h}, a, b, c)
             && count[j * n + i]++ > 0)
            ++excess;
    }
    return double(excess) * h * h;
  };
  Rng rng(3);
  std::size_t differ = 0, overlapping = 0;
  for(int trial = 0; trial < 400; ++trial)
  {
    const std::size_t n = 1 + std::size_t(rng.uniform() * 24.);
    const double offset = trial % 5 == 0 ? 1e5 : 0., scale = trial % 7 == 0 ? 1e-6 : 1.;
    Triangles triangles;
    if(trial % 4 == 3)
    {
      const int sides = 3 + trial % 7;
      for(int k = 0; k < sides; ++k)
      {
        const double a0 = 6.283185307179586 * k / sides, a1 = 6.283185307179586 * (k + 1) / sides;
        triangles.push_back({{{offset, offset},
                              {offset + scale * std::cos(a0), offset + scale * std::sin(a0)},
                              {offset + scale * std::cos(a1), offset + scale * std::sin(a1)}}});
      }
    }
    else
      for(int k = 0; k < 1 + trial % 6; ++k)
      {
        std::array<std::array<double, 2>, 3> t;
        for(auto& c : t)
          for(double& x : c)
            x = offset + scale * (trial % 4 == 0 ? rng.uniform(-1., 1.) : std::floor(rng.uniform() * 2. * double(n + 1)) / (2. * double(n)));
        triangles.push_back(t);
      }
    const double expected = every_sample(triangles, n);
    if(expected > 0.) ++overlapping;
    if(ic::overlap_area_of_triangles(triangles, n) != expected) ++differ;
  }
  EXPECT_EQ(differ, std::size_t(0));
  EXPECT_GT(overlapping, std::size_t(50)); // the cases do overlap
}
