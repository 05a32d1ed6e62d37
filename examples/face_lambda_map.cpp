// Assisted cutting: a per-face factor on the seam cost λ. Faces with a large
// factor make seams expensive, so cuts move elsewhere (the paper uses this
// with ambient occlusion to hide seams). Here the region to protect is the
// neighbourhood of the seams a first, unweighted run found.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Seam_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Region_map = Mesh::Property_map<Mesh::Face_index, bool>;

namespace SMP = CGAL::Surface_mesh_parameterization;

// Seam edges with a face of the region on either side.
std::size_t seams_touching(const Mesh& mesh, const Seam_map& seams, const Region_map& region)
{
  std::size_t n = 0;
  for(auto e : edges(mesh))
  {
    if(!seams[e]) continue;
    const auto h = halfedge(e, mesh);
    if((!is_border(h, mesh) && region[face(h, mesh)]) ||
       (!is_border(opposite(h, mesh), mesh) && region[face(opposite(h, mesh), mesh)]))
      ++n;
  }
  return n;
}

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

  const auto plain = SMP::cut_and_parameterize(mesh, seams, uvmap);
  if(!plain.ok() || plain.number_of_seam_edges == 0)
  {
    std::cerr << "The first run found no seam to move" << std::endl;
    return EXIT_FAILURE;
  }

  // Protect the faces around the seams found: two rings around their vertices.
  auto near_seam = mesh.add_property_map<Mesh::Vertex_index, bool>("v:near_seam", false).first;
  for(auto e : edges(mesh))
    if(seams[e]) near_seam[source(e, mesh)] = near_seam[target(e, mesh)] = true;
  for(int ring = 0; ring < 2; ++ring)
  {
    std::vector<Mesh::Vertex_index> grown;
    for(auto vd : vertices(mesh))
      if(near_seam[vd])
        for(auto w : vertices_around_target(halfedge(vd, mesh), mesh)) grown.push_back(w);
    for(auto w : grown) near_seam[w] = true;
  }
  auto region = mesh.add_property_map<Mesh::Face_index, bool>("f:protected", false).first;
  auto face_lambda = mesh.add_property_map<Mesh::Face_index, double>("f:lambda", 1.).first;
  std::size_t protected_faces = 0;
  for(auto f : faces(mesh))
  {
    bool all = true;
    for(auto vd : vertices_around_face(halfedge(f, mesh), mesh)) all = all && near_seam[vd];
    region[f] = all;
    if(all) { face_lambda[f] = 20.; ++protected_faces; }
  }
  const std::size_t before = seams_touching(mesh, seams, region);

  for(auto e : edges(mesh)) seams[e] = false; // start from no seam again
  const auto weighted = SMP::cut_and_parameterize(mesh, seams, uvmap, SMP::parameters::face_lambda_map(face_lambda));
  if(!weighted.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(weighted.error) << std::endl;
    return EXIT_FAILURE;
  }
  const std::size_t after = seams_touching(mesh, seams, region);

  std::cout << protected_faces << " faces protected (lambda x20)\n"
            << "  without the map: " << plain.number_of_seam_edges << " seam edges, " << before
            << " in the region, E_d " << plain.distortion << "\n"
            << "  with the map:    " << weighted.number_of_seam_edges << " seam edges, " << after
            << " in the region, E_d " << weighted.distortion << std::endl;
  return after < before ? EXIT_SUCCESS : EXIT_FAILURE;
}
