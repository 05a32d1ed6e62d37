// Unwraps a bumpy grid with the installed package: exits with 0 when the
// result is a valid atlas (no flipped face, no crossing border, UVs in [0,1]).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <cmath>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMP = CGAL::Surface_mesh_parameterization;

int main()
{
  Mesh mesh;
  const int n = 12;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      v.push_back(mesh.add_vertex({double(i) / n, double(j) / n,
                                   0.3 * std::sin(3.0 * i / n) * std::cos(2.0 * j / n)}));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const Mesh::Vertex_index a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1],
                               c = v[(j + 1) * (n + 1) + i], d = v[(j + 1) * (n + 1) + i + 1];
      mesh.add_face(a, b, d);
      mesh.add_face(a, d, c);
    }
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  const SMP::Cut_and_parameterize_result result = SMP::cut_and_parameterize(mesh, seams, uv);
  if(!result.ok())
  {
    std::cerr << "error: " << SMP::error_message(result.error) << std::endl;
    return 1;
  }
  const std::size_t flips = SMP::number_of_flipped_faces(mesh, uv);
  const std::size_t crossings = SMP::number_of_border_crossings(mesh, uv);
  bool in_square = true;
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh) && !(uv[h].x() >= 0 && uv[h].x() <= 1 && uv[h].y() >= 0 && uv[h].y() <= 1))
      in_square = false;
  std::cout << "E_d " << result.distortion << ", flipped faces " << flips << ", border crossings " << crossings
            << ", UVs in [0,1]: " << (in_square ? "yes" : "no") << std::endl;
  return flips == 0 && crossings == 0 && in_square ? 0 : 1;
}
