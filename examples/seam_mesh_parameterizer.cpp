// Reuses the seams found by cut_and_parameterize() with CGAL's own
// parameterizers: the seams define a CGAL::Seam_mesh, which CGAL's
// parameterizers (here ARAP) flatten like any disk.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Seam_edge_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_map = Mesh::Property_map<Mesh::Vertex_index, bool>;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>;
using UV_map = Mesh::Property_map<Mesh::Halfedge_index, Point_2>;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  Seam_edge_map seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
  UV_map uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  const auto result = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!result.ok())
  {
    std::cerr << "cut_and_parameterize failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  // The halfedge-keyed UV map is also a vertex UV map of the seam mesh.
  Seam_mesh seam_mesh = SMP::make_seam_mesh(mesh, seams, seam_vertices);
  std::cout << result.number_of_seam_edges << " seam edges, " << result.number_of_charts << " chart(s)\n"
            << "  symmetric Dirichlet: E_d " << SMP::distortion_energy(seam_mesh, uvmap) << ", "
            << SMP::number_of_flipped_faces(seam_mesh, uvmap) << " flipped faces\n";
  if(result.number_of_charts != 1)
  {
    std::cout << "  several charts: CGAL's parameterizers flatten one disk at a time, stopping here" << std::endl;
    return EXIT_SUCCESS;
  }

  // ARAP on the same cut, for comparison.
  UV_map arap_uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:arap_uv").first;
  const auto border = PMP::longest_border(seam_mesh).first;
  const SMP::Error_code status =
    SMP::parameterize(seam_mesh, SMP::ARAP_parameterizer_3<Seam_mesh>(), border, arap_uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "ARAP failed: " << SMP::error_message(status) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "  ARAP on the same seams: E_d " << SMP::distortion_energy(seam_mesh, arap_uvmap) << ", "
            << SMP::number_of_flipped_faces(seam_mesh, arap_uvmap) << " flipped faces" << std::endl;
  return EXIT_SUCCESS;
}
