// Seam_mesh round trip: a closed mesh cut open by given seams (make_seam_mesh)
// is parameterized by symmetric_dirichlet_parameterize(seam_mesh, uvmap) with
// uvmap keyed by halfedges of the underlying mesh (CGAL's convention); the
// result is flip-free on the seam mesh, the two sides of a seam get distinct
// UVs, and the metrics agree between the seam mesh and a per-corner map of
// the underlying mesh.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <set>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

template <typename Mesh>
using edge_descriptor_t = typename boost::graph_traits<Mesh>::edge_descriptor;

template <typename Mesh>
double edge_length(const Mesh& mesh, edge_descriptor_t<Mesh> e)
{
  auto vpm = get(CGAL::vertex_point, mesh);
  return std::sqrt(CGAL::squared_distance(get(vpm, source(e, mesh)), get(vpm, target(e, mesh))));
}

/// Builds the seam mesh of `mesh` cut along `seams`, parameterizes it and
/// checks the round trip. `expect_disk` false: the cut does not give a disk,
/// the parameterizer must say so.
template <typename Mesh>
void seam_round_trip(const Mesh& mesh, const std::vector<edge_descriptor_t<Mesh>>& seams, bool expect_disk)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, false);
  for(auto e : seams) put(sem, e, true);
  const auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm);
  using Seam_mesh = std::remove_const_t<decltype(seam_mesh)>;
  using seam_halfedge = typename boost::graph_traits<Seam_mesh>::halfedge_descriptor;

  // the seam vertex map was filled: exactly the vertices on seams
  std::set<vertex_descriptor> on_seam;
  for(auto e : seams)
  {
    on_seam.insert(source(e, mesh));
    on_seam.insert(target(e, mesh));
  }
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(bool(get(svm, v)), on_seam.count(v) == 1);

  // the seam counter was set: edges and halfedges of the cut mesh
  EXPECT_EQ(num_edges(seam_mesh), num_edges(mesh) + seams.size());
  EXPECT_EQ(num_faces(seam_mesh), num_faces(mesh));
  std::size_t border_halfedges = 0;
  for(auto h : halfedges(seam_mesh))
    if(is_border(h, seam_mesh)) ++border_halfedges;
  EXPECT_EQ(border_halfedges, 2 * seams.size());
  const long chi = long(num_vertices(seam_mesh)) - long(num_edges(seam_mesh)) + long(num_faces(seam_mesh));

  auto uvmap = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh); // keyed by halfedges of `mesh`
  const SMP::Error_code status = SMP::symmetric_dirichlet_parameterize(seam_mesh, uvmap);
  if(!expect_disk)
  {
    EXPECT_TRUE(chi != 1);
    EXPECT_EQ(status, SMP::ERROR_NO_TOPOLOGICAL_DISC);
    return;
  }
  EXPECT_EQ(chi, 1L);
  ASSERT_EQ(status, SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uvmap), std::size_t(0));
  const double energy = SMP::distortion_energy(seam_mesh, uvmap);
  EXPECT_TRUE(std::isfinite(energy));
  EXPECT_TRUE(energy >= 4.);

  // one UV per corner of the underlying mesh, read through the seam mesh
  auto corner = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  for(auto f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const Point_2 p = get(uvmap, target(seam_halfedge(h), seam_mesh));
      EXPECT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
      put(corner, h, p);
    }
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, corner), std::size_t(0));
  EXPECT_REL(SMP::distortion_energy(mesh, corner), energy, 1e-12);

  // corners agree around a vertex except across seams; across a seam they
  // differ (the surface was opened there)
  double scale = 0.;
  for(auto f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
      scale = (std::max)(scale, std::abs(get(corner, h).x()) + std::abs(get(corner, h).y()));
  for(auto e : edges(mesh))
  {
    const halfedge_descriptor h = halfedge(e, mesh), o = opposite(h, mesh);
    if(is_border(h, mesh) || is_border(o, mesh)) continue;
    // the corner at target(h) in face(h) and the one at source(o) == target(h) in face(o)
    const Point_2 a = get(corner, h), b = get(corner, prev(o, mesh));
    const double gap = std::sqrt(CGAL::squared_distance(a, b));
    if(get(sem, e))
    {
      // the endpoint of a seam path that is a leaf (degree 1 on the seams) closes up
      std::size_t seam_degree = 0;
      for(auto g : halfedges_around_target(h, mesh))
        if(get(sem, edge(g, mesh))) ++seam_degree;
      if(seam_degree > 1) EXPECT_TRUE(gap > 1e-6 * scale) << "seam corners coincide, gap " << gap;
      else EXPECT_TRUE(gap <= 1e-12 * scale) << "corners at a seam's leaf differ, gap " << gap;
    }
    else // faces across an uncut edge are in the same sector around its ends
      EXPECT_TRUE(gap <= 1e-12 * scale) << "corners of an uncut edge differ, gap " << gap;
  }

  // restarting from the result through the seam mesh keeps it flip-free and no worse
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(seam_mesh, uvmap, SMP::parameters::initialize_from_uv_map(true)), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uvmap), std::size_t(0));
  EXPECT_TRUE(SMP::distortion_energy(seam_mesh, uvmap) <= energy * (1. + 1e-12));

  // E_s counts each seam edge once
  double length = 0.;
  for(auto e : seams) length += edge_length(mesh, e);
  EXPECT_REL(SMP::seam_length(mesh, sem), length / std::sqrt(SMP::surface_area(mesh) / pi), 1e-12);
}

} // namespace

template <typename Mesh>
class SeamMeshTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(SeamMeshTyped, Mesh_types);

TYPED_TEST(SeamMeshTyped, sphere_cut_along_a_path)
{
  const Soup soup = sphere_soup(4);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  const auto seams = soup_edges(mesh, vertex_of, soup.cut);
  seam_round_trip(mesh, seams, true);
}

TYPED_TEST(SeamMeshTyped, sphere_cut_along_a_tree)
{
  // the pole-to-pole path plus a branch from the +y pole to the path's midpoint (+x)
  const Soup soup = sphere_soup(4);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto seams = soup_edges(mesh, vertex_of, soup.cut);
  const auto mid = vertex_of[soup.cut[3].second]; // (n, 0, 0)
  auto vpm = get(CGAL::vertex_point, mesh);
  ASSERT_TRUE(get(vpm, mid).x() > 0.999);
  typename boost::graph_traits<TypeParam>::vertex_descriptor y_pole = mid;
  for(auto v : vertices(mesh))
    if(get(vpm, v).y() > 0.999) y_pole = v;
  ASSERT_TRUE(y_pole != mid);
  const auto branch = shortest_edge_path(mesh, y_pole, mid);
  ASSERT_EQ(branch.size(), std::size_t(4));
  seams.insert(seams.end(), branch.begin(), branch.end());
  seam_round_trip(mesh, seams, true);
}

TYPED_TEST(SeamMeshTyped, torus_cut_along_meridian_and_longitude)
{
  const Soup soup = torus_soup(16, 8);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  seam_round_trip(mesh, soup_edges(mesh, vertex_of, soup.cut), true);
}

TYPED_TEST(SeamMeshTyped, insufficient_cuts_are_not_disks)
{
  {
    SCOPED_TRACE("torus cut along one longitude only: an annulus");
    const Soup soup = torus_soup(12, 6);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    std::vector<std::pair<std::size_t, std::size_t>> longitude(soup.cut.begin(), soup.cut.begin() + 12);
    seam_round_trip(mesh, soup_edges(mesh, vertex_of, longitude), false);
  }
  {
    SCOPED_TRACE("sphere cut along a closed loop: two disks");
    const Soup soup = sphere_soup(3);
    TypeParam mesh;
    build_mesh(soup, mesh);
    // the equator z = 0
    std::vector<typename boost::graph_traits<TypeParam>::edge_descriptor> equator;
    auto vpm = get(CGAL::vertex_point, mesh);
    for(auto e : edges(mesh))
      if(std::abs(get(vpm, source(e, mesh)).z()) < 1e-12 && std::abs(get(vpm, target(e, mesh)).z()) < 1e-12)
        equator.push_back(e);
    ASSERT_EQ(equator.size(), std::size_t(12));
    // two disks: the parameterizer embeds disjoint disks side by side
    auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(auto e : edges(mesh)) put(sem, e, false);
    for(auto e : equator) put(sem, e, true);
    const auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm);
    auto uvmap = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
    const SMP::Error_code status = SMP::symmetric_dirichlet_parameterize(seam_mesh, uvmap);
    EXPECT_EQ(status, SMP::OK);
    if(status == SMP::OK) EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uvmap), std::size_t(0));
  }
  {
    SCOPED_TRACE("closed sphere, no seam");
    TypeParam mesh;
    build_mesh(sphere_soup(3), mesh);
    seam_round_trip(mesh, {}, false);
  }
}

