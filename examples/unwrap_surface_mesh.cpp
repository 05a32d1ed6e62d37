// Cuts a disk-like mesh and computes its UV map with cut_and_parameterize().
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
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Seams: input (none here) and output. UVs: one per corner, keyed by the
  // halfedge whose target is the corner's vertex.
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  const SMP::Cut_and_parameterize_result result =
    SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::lambda(1.));
  if(!result.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << filename << ": " << num_faces(mesh) << " faces\n"
            << "  seam edges:         " << result.number_of_seam_edges << "\n"
            << "  seam length E_s:    " << result.seam_length << "\n"
            << "  distortion E_d:     " << result.distortion
            << " (Tutte start: " << result.initial_distortion << ")\n";

  // The metrics recompute E_d from the maps (in 3D units: the atlas is
  // scaled by uv_scale into the unit square) and count flipped UV triangles.
  const std::size_t flipped = SMP::number_of_flipped_faces(mesh, uvmap);
  std::cout << "  E_d (recomputed):   "
            << SMP::distortion_energy(mesh, uvmap, SMP::parameters::uv_scale(result.uv_scale)) << "\n"
            << "  flipped faces:      " << flipped << std::endl;
  return flipped == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
