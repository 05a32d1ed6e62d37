// Symmetric_dirichlet_parameterizer_3 as a model of CGAL's Parameterizer_3:
// passed to CGAL::Surface_mesh_parameterization::parameterize() on the
// Seam_mesh of a closed mesh cut open by a seam, it returns OK, a flip-free
// map with finite UVs, and an energy below the Tutte map it starts from
// (and no higher than a given start map's).
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Symmetric_dirichlet_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <iostream>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

/// A border halfedge of `mesh` (the null halfedge if it has none).
template <typename Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor some_border_halfedge(const Mesh& mesh)
{
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh)) return h;
  return boost::graph_traits<Mesh>::null_halfedge();
}

/// Every UV of the seam mesh's vertices is finite.
template <typename Seam_mesh, typename UV_map>
bool all_uvs_finite(const Seam_mesh& seam_mesh, const UV_map& uvmap)
{
  for(auto v : vertices(seam_mesh))
  {
    const Point_2& p = get(uvmap, v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
  }
  return true;
}

/// Parameterizes the seam mesh of `mesh` cut along `cut` through
/// parameterize() and checks the map against its Tutte start and against a
/// restart from CGAL's own Tutte map.
template <typename Mesh>
void check_on_seam_mesh(const Mesh& mesh, const std::vector<typename boost::graph_traits<Mesh>::edge_descriptor>& cut)
{
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, false);
  for(auto e : cut) put(sem, e, true);
  auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm);
  using Seam_mesh = decltype(seam_mesh);
  const auto bhd = some_border_halfedge(seam_mesh);
  ASSERT_TRUE(bhd != boost::graph_traits<Seam_mesh>::null_halfedge());

  // the start: the Tutte embedding (no Newton iteration)
  auto tutte = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh); // seam mesh vertices = halfedges of mesh
  ASSERT_EQ(SMP::parameterize(seam_mesh, SMP::Symmetric_dirichlet_parameterizer_3<Seam_mesh>(0), bhd, tutte), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, tutte), std::size_t(0));
  const double tutte_energy = SMP::distortion_energy(seam_mesh, tutte);
  ASSERT_TRUE(std::isfinite(tutte_energy));

  auto uvmap = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::parameterize(seam_mesh, SMP::Symmetric_dirichlet_parameterizer_3<Seam_mesh>(), bhd, uvmap), SMP::OK);
  EXPECT_TRUE(all_uvs_finite(seam_mesh, uvmap));
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uvmap), std::size_t(0));
  const double energy = SMP::distortion_energy(seam_mesh, uvmap);
  EXPECT_TRUE(energy >= 4.);
  EXPECT_LT(energy, tutte_energy) << "E_d " << energy << " not below the Tutte map's " << tutte_energy;

  // from CGAL's Tutte map (barycentric, circular border): no higher than it
  auto cgal_tutte = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::parameterize(seam_mesh, SMP::Barycentric_mapping_parameterizer_3<Seam_mesh>(), bhd, cgal_tutte),
            SMP::OK);
  const double cgal_tutte_energy = SMP::distortion_energy(seam_mesh, cgal_tutte);
  ASSERT_TRUE(std::isfinite(cgal_tutte_energy));
  auto restarted = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  for(auto v : vertices(seam_mesh)) put(restarted, v, get(cgal_tutte, v));
  ASSERT_EQ(SMP::parameterize(seam_mesh, SMP::Symmetric_dirichlet_parameterizer_3<Seam_mesh>(500, 1e-9, true), bhd,
                              restarted),
            SMP::OK);
  EXPECT_TRUE(all_uvs_finite(seam_mesh, restarted));
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, restarted), std::size_t(0));
  EXPECT_LE(SMP::distortion_energy(seam_mesh, restarted), cgal_tutte_energy);
  std::cout << "  E_d: Tutte " << tutte_energy << " -> " << energy << "; CGAL's Tutte " << cgal_tutte_energy
            << " -> " << SMP::distortion_energy(seam_mesh, restarted) << std::endl;
  // both starts reach about the same minimum
  EXPECT_NEAR(SMP::distortion_energy(seam_mesh, restarted), energy, 1e-3 * energy);
}

} // namespace

template <typename Mesh>
class SymmetricDirichletParameterizer : public ::testing::Test
{
};
TYPED_TEST_SUITE(SymmetricDirichletParameterizer, Mesh_types);

TYPED_TEST(SymmetricDirichletParameterizer, sphere_cut_along_a_path)
{
  const Soup soup = sphere_soup(6);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  check_on_seam_mesh(mesh, soup_edges(mesh, vertex_of, soup.cut));
}

TYPED_TEST(SymmetricDirichletParameterizer, torus_cut_into_a_disk)
{
  const Soup soup = torus_soup(16, 8);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  check_on_seam_mesh(mesh, soup_edges(mesh, vertex_of, soup.cut));
}

TYPED_TEST(SymmetricDirichletParameterizer, flags_every_vertex_and_reports_a_non_disk)
{
  using Mesh = TypeParam;
  const Soup soup = torus_soup(12, 6);
  Mesh mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  // cut along one longitude only: an annulus, not a disk
  std::vector<std::pair<std::size_t, std::size_t>> longitude(soup.cut.begin(), soup.cut.begin() + 12);
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, false);
  for(auto e : soup_edges(mesh, vertex_of, longitude)) put(sem, e, true);
  auto annulus = SMP::make_seam_mesh(mesh, sem, svm);
  using Seam_mesh = decltype(annulus);
  auto uvmap = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), annulus);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), annulus);
  for(auto v : vertices(annulus)) put(vpmap, v, false);
  SMP::Symmetric_dirichlet_parameterizer_3<Seam_mesh> parameterizer;
  EXPECT_EQ(parameterizer.parameterize(annulus, some_border_halfedge(annulus), uvmap, vimap, vpmap),
            SMP::ERROR_NO_TOPOLOGICAL_DISC);
  for(auto v : vertices(annulus)) EXPECT_FALSE(get(vpmap, v));

  // both loops cut: a disk, every vertex parameterized
  for(auto e : soup_edges(mesh, vertex_of, soup.cut)) put(sem, e, true);
  auto disk = SMP::make_seam_mesh(mesh, sem, svm);
  auto disk_vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), disk);
  auto disk_vimap = get(CGAL::dynamic_vertex_property_t<int>(), disk);
  for(auto v : vertices(disk)) put(disk_vpmap, v, false);
  ASSERT_EQ(parameterizer.parameterize(disk, some_border_halfedge(disk), uvmap, disk_vimap, disk_vpmap), SMP::OK);
  for(auto v : vertices(disk)) EXPECT_TRUE(get(disk_vpmap, v));
  EXPECT_EQ(SMP::number_of_flipped_faces(disk, uvmap), std::size_t(0));
}
