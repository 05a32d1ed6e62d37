// Symmetric_dirichlet_parameterizer_3 is a model of CGAL's Parameterizer_3:
// CGAL::Surface_mesh_parameterization::parameterize() takes it as it takes
// CGAL's own parameterizers. Here it flattens a disk (a mesh with one
// border) with a vertex UV map, after CGAL's Tutte map for comparison.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Symmetric_dirichlet_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using UV_map = Mesh::Property_map<Mesh::Vertex_index, Point_2>;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/nefertiti.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const auto border = PMP::longest_border(mesh).first;
  if(border == Mesh::null_halfedge())
  {
    std::cerr << "The mesh has no border: cut it first (see seam_mesh_parameterizer.cpp)" << std::endl;
    return EXIT_FAILURE;
  }

  // CGAL's Tutte map (uniform weights, border on a circle), for comparison
  UV_map tutte = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:tutte").first;
  if(SMP::parameterize(mesh, SMP::Barycentric_mapping_parameterizer_3<Mesh>(), border, tutte) != SMP::OK)
  {
    std::cerr << "Tutte map failed" << std::endl;
    return EXIT_FAILURE;
  }

  // the symmetric Dirichlet minimizer, through the same interface
  UV_map uvmap = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
  const SMP::Error_code status =
    SMP::parameterize(mesh, SMP::Symmetric_dirichlet_parameterizer_3<Mesh>(), border, uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "Symmetric Dirichlet parameterizer failed: " << SMP::error_message(status) << std::endl;
    return EXIT_FAILURE;
  }

  const double tutte_energy = SMP::distortion_energy(mesh, tutte);
  const double energy = SMP::distortion_energy(mesh, uvmap);
  const std::size_t flipped = SMP::number_of_flipped_faces(mesh, uvmap);
  std::cout << num_faces(mesh) << " faces\n"
            << "  Tutte map:           E_d " << tutte_energy << "\n"
            << "  symmetric Dirichlet: E_d " << energy << ", " << flipped << " flipped faces" << std::endl;
  return (flipped == 0 && energy <= tutte_energy) ? EXIT_SUCCESS : EXIT_FAILURE;
}
