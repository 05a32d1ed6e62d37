// Seams where nobody looks: the visibility of each face (ambient occlusion,
// face_visibility()) turned into a per-face λ (visibility_face_lambda()), so
// that cutting is cheap in cracks and dear on exposed surfaces; the mean
// visibility along the seams (seam_visibility()) with and without it.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/face_visibility.h>

#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  const double strength = (argc > 2) ? std::atof(argv[2]) : 6.;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // 1 where the whole sky above a face is free, 0 in a closed cavity
  auto visibility = mesh.add_property_map<Mesh::Face_index, double>("f:visibility").first;
  if(SMP::face_visibility(mesh, visibility, SMP::parameters::number_of_rays(64)) != SMP::OK) return EXIT_FAILURE;
  auto lambda = mesh.add_property_map<Mesh::Face_index, double>("f:lambda").first;
  if(SMP::visibility_face_lambda(mesh, visibility, lambda, strength) != SMP::OK) return EXIT_FAILURE;

  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  const auto plain = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!plain.ok()) return EXIT_FAILURE;
  const double seen_plain = SMP::seam_visibility(mesh, seams, visibility);

  for(auto e : edges(mesh)) seams[e] = false; // start again from no seam
  const auto hidden = SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::face_lambda_map(lambda));
  if(!hidden.ok()) return EXIT_FAILURE;
  const double seen_hidden = SMP::seam_visibility(mesh, seams, visibility);

  std::cout << filename << "\n"
            << "  without visibility: seam visibility " << seen_plain << ", E_d " << plain.distortion
            << ", E_s " << plain.seam_length << "\n"
            << "  with strength " << strength << ":    seam visibility " << seen_hidden << ", E_d "
            << hidden.distortion << ", E_s " << hidden.seam_length << std::endl;
  return seen_hidden < seen_plain ? EXIT_SUCCESS : EXIT_FAILURE;
}
