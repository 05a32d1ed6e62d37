// A texture atlas: a mesh of several parts (26 bones) unwrapped into the unit
// square, one chart or more per part, packed without overlap with a gap of a
// few texels between charts. Then the same mesh with the bounding-box term,
// which pulls each chart into a square so that the atlas is filled better.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
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
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bones.off");
  const std::string output = (argc > 2) ? argv[2] : "texture_atlas.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  // A 512 x 512 texture with 4 texels between charts (and to the borders).
  // Global injectivity is on by default: no chart overlaps itself or another.
  const auto atlas = SMP::cut_and_parameterize(mesh, seams, uvmap,
                                               SMP::parameters::texture_size(512, SMP::parameters::padding(4.)));
  if(!atlas.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(atlas.error) << std::endl;
    return EXIT_FAILURE;
  }

  // Every UV lies in the unit square; border crossings are recounted on the map.
  bool in_unit_square = true;
  for(auto h : halfedges(mesh))
  {
    const Point_2& uv = uvmap[h];
    in_unit_square = in_unit_square && uv.x() >= 0. && uv.x() <= 1. && uv.y() >= 0. && uv.y() <= 1.;
  }
  const std::size_t crossings = SMP::number_of_border_crossings(mesh, uvmap);

  std::cout << filename << ": " << num_faces(mesh) << " faces\n"
            << "  charts:            " << atlas.number_of_charts << "\n"
            << "  coverage:          " << atlas.uv_coverage << " (uv_area: " << SMP::uv_area(mesh, uvmap) << ")\n"
            << "  border crossings:  " << atlas.border_crossings << " (recounted: " << crossings << ")\n"
            << "  uv_scale:          " << atlas.uv_scale << " UV per 3D unit\n"
            << "  E_d (3D units):    " << atlas.distortion << "\n"
            << "  UVs in [0,1]^2:    " << (in_unit_square ? "yes" : "no") << std::endl;

  if(!SMP::write_OBJ_with_uvs(output, mesh, uvmap))
  {
    std::cerr << "Cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << std::endl;

  // The same mesh with an explicit 1:1 bounding box: each chart is pulled
  // tightly into a square of its own area, at some distortion cost (the
  // default box is a gentle square). Start from no seam again.
  for(auto e : edges(mesh)) seams[e] = false;
  const auto boxed = SMP::cut_and_parameterize(mesh, seams, uvmap,
                                               SMP::parameters::texture_size(512, SMP::parameters::padding(4.,
                                               SMP::parameters::bounding_box_aspect_ratio(1.))));
  if(!boxed.ok())
  {
    std::cerr << "Failed: " << SMP::error_message(boxed.error) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "with bounding_box_aspect_ratio(1):\n"
            << "  coverage:          " << boxed.uv_coverage << " (default box: " << atlas.uv_coverage << ")\n"
            << "  E_d (3D units):    " << boxed.distortion << " (default box: " << atlas.distortion << ")\n"
            << "  border crossings:  " << boxed.border_crossings << std::endl;

  return in_unit_square && crossings == 0 && atlas.border_crossings == 0 && boxed.border_crossings == 0
           ? EXIT_SUCCESS : EXIT_FAILURE;
}
