// Reads the discontinuity field v (one value per face, in (0,1]) that
// cut_and_parameterize() optimizes: faces with v < 1/2 are where the method
// wants to cut, and the seams run through them.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
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

  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  // Named "f:v" so that CGAL's PLY writer exports it as a face property.
  auto v = mesh.add_property_map<Mesh::Face_index, double>("f:v", 1.).first;

  const auto result = SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::face_discontinuity_map(v));
  if(!result.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  double v_min = 1.;
  std::size_t low = 0;
  for(auto f : faces(mesh))
  {
    v_min = (std::min)(v_min, v[f]);
    if(v[f] < 0.5) ++low;
  }

  // The seams run through the faces the field marked for cutting; a few more
  // may join a cut that ends inside the surface to the border (so that the
  // chart stays a disk) and cross high-v faces.
  std::size_t seams_in_low_v = 0;
  for(auto e : edges(mesh))
  {
    if(!seams[e]) continue;
    const auto h = halfedge(e, mesh);
    for(auto hh : {h, opposite(h, mesh)})
      if(!is_border(hh, mesh) && v[face(hh, mesh)] < 0.5) { ++seams_in_low_v; break; }
  }

  std::cout << "v: minimum " << v_min << ", " << low << " of " << num_faces(mesh) << " faces below 1/2\n"
            << result.number_of_seam_edges << " seam edges, " << seams_in_low_v
            << " of them next to a face with v < 1/2" << std::endl;

  // Look at the field in a viewer that colors PLY face properties.
  std::ofstream out("discontinuity_field.ply");
  if(!CGAL::IO::write_PLY(out, mesh))
  {
    std::cerr << "Cannot write discontinuity_field.ply" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote discontinuity_field.ply (face property v)" << std::endl;
  // Fails if the field marked faces but no seam followed them.
  return (low == 0 || seams_in_low_v > 0) ? EXIT_SUCCESS : EXIT_FAILURE;
}
