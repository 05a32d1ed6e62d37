// Forbidden seams: edges that no seam may use, such as a face, a logo or a
// region to be painted in one piece. Here the protected region is where a
// first run put its seams (their vertices and one ring around them): every
// edge inside it is forbidden, and the second run is checked to give a
// valid atlas whose seams all lie outside the region.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <cstdlib>
#include <iostream>
#include <vector>
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
  const auto first = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!first.ok() || first.number_of_seam_edges == 0)
  {
    std::cerr << "The first run found no seam" << std::endl;
    return EXIT_FAILURE;
  }

  // the region: the vertices of the seams found and their neighbours
  auto in_region = mesh.add_property_map<Mesh::Vertex_index, bool>("v:protected", false).first;
  for(auto e : edges(mesh))
    if(seams[e]) in_region[source(e, mesh)] = in_region[target(e, mesh)] = true;
  std::vector<Mesh::Vertex_index> ring;
  for(auto v : vertices(mesh))
    if(in_region[v])
      for(auto w : vertices_around_target(halfedge(v, mesh), mesh)) ring.push_back(w);
  for(auto w : ring) in_region[w] = true;
  auto forbidden = mesh.add_property_map<Mesh::Edge_index, bool>("e:forbidden", false).first;
  std::size_t forbidden_edges = 0;
  for(auto e : edges(mesh))
    if(in_region[source(e, mesh)] && in_region[target(e, mesh)])
    {
      forbidden[e] = true;
      ++forbidden_edges;
    }

  for(auto e : edges(mesh)) seams[e] = false; // start from no seam again
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
  std::cout << "first run: " << first.number_of_seam_edges << " seam edges, E_d " << first.distortion << ", E_s "
            << first.seam_length << "\n"
            << forbidden_edges << " edges around them forbidden\n"
            << "  " << result.number_of_charts << " charts, " << result.number_of_seam_edges << " seam edges, "
            << seams_in_region << " of them forbidden\n"
            << "  E_d " << result.distortion << ", E_s " << result.seam_length << std::endl;
  return seams_in_region == 0 && result.number_of_seam_edges > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
