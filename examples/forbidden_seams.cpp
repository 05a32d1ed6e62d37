// Forbidden seams: edges that no seam may use, such as a face, a logo or a
// region to be painted in one piece. Here the protected region is the top
// third of the mesh (by height); every edge inside it is forbidden, and the
// result is checked: a valid atlas whose seams all lie outside the region.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <limits>
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

  // the region: vertices in the top third of the height (z)
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for(auto v : vertices(mesh))
  {
    low = (std::min)(low, mesh.point(v).z());
    high = (std::max)(high, mesh.point(v).z());
  }
  const double limit = high - (high - low) / 3.;
  auto forbidden = mesh.add_property_map<Mesh::Edge_index, bool>("e:forbidden", false).first;
  std::size_t forbidden_edges = 0;
  for(auto e : edges(mesh))
    if(mesh.point(source(e, mesh)).z() > limit && mesh.point(target(e, mesh)).z() > limit)
    {
      forbidden[e] = true;
      ++forbidden_edges;
    }

  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  const auto result = SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::forbidden_seam_edge_map(forbidden));
  if(!result.ok())
  {
    // ERROR_FORBIDDEN_EDGES_BLOCK_CUT if no cut can open the mesh without them
    std::cerr << "Failed: " << SMP::error_message(result.error) << std::endl;
    return EXIT_FAILURE;
  }

  std::size_t seams_in_region = 0;
  for(auto e : edges(mesh))
    if(seams[e] && forbidden[e]) ++seams_in_region;
  std::cout << forbidden_edges << " edges forbidden (z > " << limit << ")\n"
            << "  " << result.number_of_charts << " charts, " << result.number_of_seam_edges << " seam edges, "
            << seams_in_region << " of them forbidden\n"
            << "  E_d " << result.distortion << ", E_s " << result.seam_length << std::endl;
  return seams_in_region == 0 && result.number_of_seam_edges > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
