// The C++ API's result on a mesh file, for tests/test_uv_unwrap.py: the
// Python module must give the same. Reads an OFF file whose vertices and
// faces need no repair (vertex i and face j stay those of the file), runs
// cut_and_parameterize() with its defaults and writes, as text:
//   distortion <E_d>  seam_length <E_s>  charts <n>
//   seam <a> <b>                 one line per seam edge (vertex indices, a < b)
//   corner <face> <vertex> <u> <v>  the UV of each corner of each face
// Usage: test_python_reference mesh.off output.txt
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <utility>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::cerr << "usage: test_python_reference mesh.off output.txt\n";
    return 2;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return 1;
  }
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvs = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  const SMP::Cut_and_parameterize_result r = SMP::cut_and_parameterize(mesh, seams, uvs);
  if(!r.ok())
  {
    std::cerr << SMP::error_name(r.error) << "\n";
    return 1;
  }
  std::ofstream out(argv[2]);
  out << std::setprecision(17);
  out << "distortion " << r.distortion << "\nseam_length " << r.seam_length << "\ncharts " << r.number_of_charts
      << "\n";
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(auto e : edges(mesh))
    if(seams[e])
    {
      const std::size_t a = source(e, mesh), b = target(e, mesh);
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(pairs.begin(), pairs.end());
  for(const auto& [a, b] : pairs) out << "seam " << a << ' ' << b << "\n";
  for(auto f : faces(mesh))
  {
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      out << "corner " << std::size_t(f) << ' ' << std::size_t(target(h, mesh)) << ' ' << uvs[h].x() << ' '
          << uvs[h].y() << "\n";
  }
  return out ? 0 : 1;
}
