// Unwraps a mesh and saves it as an OBJ with texture coordinates, ready for
// a 3D package: seams appear as texture vertices that differ on each side.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  const std::string output = (argc > 2) ? argv[2] : "unwrapped.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  const auto result = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!result.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  if(!SMP::write_OBJ_with_uvs(output, mesh, uvmap))
  {
    std::cerr << "Cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces, " << result.number_of_seam_edges << " seam edges, E_d " << result.distortion
            << std::endl;
  return EXIT_SUCCESS;
}
