// Validates a mesh before unwrapping it: lists degenerate faces with
// is_degenerate_face(), asks cut_and_parameterize() to refuse them
// (reject_degenerate_faces), and falls back to the default, which clamps
// them, once the user has been told. Prints every error by name.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

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
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/degtri_sliding.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  std::size_t degenerate = 0;
  for(Mesh::Face_index f : faces(mesh))
    if(SMP::is_degenerate_face(f, mesh) && degenerate++ < 5)
      std::cout << "degenerate face " << std::size_t(f) << "\n";
  std::cout << filename << ": " << num_faces(mesh) << " faces, " << degenerate << " degenerate\n";

  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  // Strict mode: any degenerate face stops the run before any work.
  SMP::Cut_and_parameterize_result result =
    SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::reject_degenerate_faces(true));
  std::cout << "strict run:  " << SMP::error_name(result.error) << "\n";
  if(result.error == SMP::ERROR_DEGENERATE_FACE)
  {
    // Default mode: degenerate faces get a clamped rest shape.
    result = SMP::cut_and_parameterize(mesh, seams, uvmap);
    std::cout << "default run: " << SMP::error_name(result.error) << ", "
              << result.number_of_degenerate_faces << " faces clamped\n";
  }
  if(!result.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "E_d = " << result.distortion << ", E_s = " << result.seam_length << ", "
            << result.number_of_isolated_vertices << " isolated vertices ignored\n";
  return SMP::number_of_flipped_faces(mesh, uvmap) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
