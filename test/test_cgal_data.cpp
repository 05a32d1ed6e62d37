// symmetric_dirichlet_parameterize on meshes of CGAL's data set (read through
// CGAL::data_file_path, i.e. CGAL_DATA_DIR): a disk, a mesh with holes, a
// closed mesh opened by a seam path, a quad mesh, degenerate meshes.
// Registered only when the data set is available (see test/CMakeLists.txt).
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

template <typename Mesh>
void read_cgal_mesh(const std::string& name, Mesh& mesh)
{
  const std::string path = CGAL::data_file_path("meshes/" + name);
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, mesh)) << "cannot read " << path;
  ASSERT_TRUE(num_faces(mesh) > 0);
}

} // namespace

template <typename Mesh>
class CgalDataTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(CgalDataTyped, Mesh_types);

TYPED_TEST(CgalDataTyped, nefertiti_disk)
{
  TypeParam mesh;
  read_cgal_mesh("nefertiti.off", mesh);
  ASSERT_EQ(number_of_border_cycles(mesh), std::size_t(1));
  auto tutte = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, tutte, CGAL::parameters::number_of_iterations(0)), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, tutte), std::size_t(0));
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  const double energy = SMP::distortion_energy(mesh, uv);
  EXPECT_TRUE(std::isfinite(energy) && energy >= 4.);
  EXPECT_TRUE(energy < SMP::distortion_energy(mesh, tutte));
}

TYPED_TEST(CgalDataTyped, meshes_that_are_not_disks)
{
  {
    TypeParam mesh; // several holes
    read_cgal_mesh("pig.off", mesh);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  }
  {
    TypeParam mesh; // closed
    read_cgal_mesh("sphere966.off", mesh);
    ASSERT_TRUE(CGAL::is_closed(mesh));
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  }
  {
    TypeParam mesh; // quads
    read_cgal_mesh("cube_quad.off", mesh);
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    EXPECT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::ERROR_NON_TRIANGULAR_MESH);
  }
}

TYPED_TEST(CgalDataTyped, closed_sphere_opened_by_a_seam_path)
{
  TypeParam mesh;
  read_cgal_mesh("sphere966.off", mesh);
  ASSERT_EQ(genus(mesh), 0L);
  // a path between two far apart vertices (farthest along x)
  auto vpm = get(CGAL::vertex_point, mesh);
  auto lo = *vertices(mesh).begin(), hi = lo;
  for(auto v : vertices(mesh))
  {
    if(get(vpm, v).x() < get(vpm, lo).x()) lo = v;
    if(get(vpm, v).x() > get(vpm, hi).x()) hi = v;
  }
  const auto path = shortest_edge_path(mesh, lo, hi);
  ASSERT_TRUE(path.size() > 3);
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, false);
  for(auto e : path) put(sem, e, true);
  const auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm);
  auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(seam_mesh, uv), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, uv), std::size_t(0));
  // what the optimizer reaches with this one seam path (measured), plus a margin
  EXPECT_LT(SMP::distortion_energy(seam_mesh, uv), 4.79); // reached: 4.6070
  EXPECT_TRUE(SMP::seam_length(mesh, sem) > 0.);
}

TYPED_TEST(CgalDataTyped, degenerate_meshes_never_crash)
{
  int tested = 0;
  for(const char* name : {"degtri_sliding.off", "fold.off"})
  {
    SCOPED_TRACE(name);
    TypeParam mesh;
    if(!CGAL::IO::read_polygon_mesh(CGAL::data_file_path(std::string("meshes/") + name), mesh))
      continue; // not a valid polygon mesh for this mesh type
    ++tested;
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    const SMP::Error_code status = SMP::symmetric_dirichlet_parameterize(mesh, uv);
    std::cout << "  " << name << ": " << SMP::error_name(status) << std::endl;
    // either a clean error, or a flip-free result
    if(status == SMP::OK) EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    else EXPECT_TRUE(std::string(SMP::error_name(status)) != "ERROR_UNKNOWN");
  }
  EXPECT_TRUE(tested > 0);
}

