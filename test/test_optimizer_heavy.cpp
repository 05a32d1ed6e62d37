// Bigger generated meshes (thousands of faces) through the distortion
// optimizer: flip-free, below Tutte, developable patches at E_d = 4, closed
// surfaces opened by seams. Only built in optimized builds (label "heavy").
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

template <typename Mesh>
class OptimizerHeavyTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(OptimizerHeavyTyped, Mesh_types);

TYPED_TEST(OptimizerHeavyTyped, large_disks_are_flip_free_and_below_tutte)
{
  const std::pair<const char*, Soup> disks[] = {{"wavy disk", wavy_disk_soup(30, 100, 9)},
                                                {"hemisphere", hemisphere_soup(25, 90)},
                                                {"cone", cone_soup(30, 80, 1., 2.)}};
  for(const auto& disk : disks)
  {
    SCOPED_TRACE(disk.first);
    TypeParam mesh;
    build_mesh(disk.second, mesh);
    ASSERT_TRUE(num_faces(mesh) > 4000);
    auto tutte = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, tutte, CGAL::parameters::number_of_iterations(0)), SMP::OK);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    const double energy = SMP::distortion_energy(mesh, uv);
    EXPECT_TRUE(std::isfinite(energy) && energy >= 4.);
    EXPECT_TRUE(energy < SMP::distortion_energy(mesh, tutte));
  }
}

TYPED_TEST(OptimizerHeavyTyped, large_developable_patches_reach_isometry)
{
  Soup flat = grid_soup(60, 40, 3., 2.);
  jitter_xy(flat, 0.01, 3);
  const std::pair<const char*, Soup> patches[] = {{"jittered grid", flat},
                                                  {"cylinder patch", cylinder_patch_soup(80, 30, 1., 4., 1.5)}};
  for(const auto& patch : patches)
  {
    SCOPED_TRACE(patch.first);
    TypeParam mesh;
    build_mesh(patch.second, mesh);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    const double energy = SMP::distortion_energy(mesh, uv);
    EXPECT_TRUE(energy >= 4. && energy - 4. <= 1e-6) << "E_d - 4 = " << energy - 4.;
  }
}

TYPED_TEST(OptimizerHeavyTyped, large_closed_surfaces_opened_by_seams)
{
  const std::pair<const char*, Soup> closed[] = {{"sphere", sphere_soup(16)}, {"torus", torus_soup(64, 24)}};
  for(const auto& c : closed)
  {
    SCOPED_TRACE(c.first);
    TypeParam mesh;
    const auto vertex_of = build_mesh(c.second, mesh);
    auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(auto e : edges(mesh)) put(sem, e, false);
    for(auto e : soup_edges(mesh, vertex_of, c.second.cut)) put(sem, e, true);
    const auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm);
    auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(seam_mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uv), std::size_t(0));
    // what the optimizer reaches with this one seam path (measured), plus a margin
    const double bound = std::string(c.first) == "sphere" ? 4.79 : 4.28; // reached: 4.6092, 4.2081
    EXPECT_LT(SMP::distortion_energy(seam_mesh, uv), bound);
  }
}

