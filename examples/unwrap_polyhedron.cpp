// cut_and_parameterize() on a CGAL::Polyhedron_3: any FaceGraph works, with
// property maps supplied by the caller (here associative maps).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <boost/property_map/property_map.hpp>

#include <cstdlib>
#include <iostream>
#include <string>
#include <unordered_map>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using halfedge_descriptor = boost::graph_traits<Polyhedron>::halfedge_descriptor;
using edge_descriptor = boost::graph_traits<Polyhedron>::edge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Polyhedron_3 has no property storage of its own: keep the maps outside.
  std::unordered_map<edge_descriptor, bool> seam_storage;
  for(edge_descriptor e : edges(mesh)) seam_storage[e] = false;
  std::unordered_map<halfedge_descriptor, Point_2> uv_storage;
  boost::associative_property_map<std::unordered_map<edge_descriptor, bool>> seams(seam_storage);
  boost::associative_property_map<std::unordered_map<halfedge_descriptor, Point_2>> uvmap(uv_storage);

  const auto result = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!result.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  const std::size_t flipped = SMP::number_of_flipped_faces(mesh, uvmap);
  std::cout << filename << " (Polyhedron_3): " << result.number_of_seam_edges << " seam edges, E_s "
            << result.seam_length << ", E_d " << result.distortion << ", " << flipped
            << " flipped faces" << std::endl;
  return flipped == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
