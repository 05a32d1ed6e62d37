// 1-to-4 midpoint subdivision of a triangle mesh: every triangle is split into
// four by the midpoints of its edges, a midpoint shared by the faces on both
// sides of its edge. The surface is unchanged (flat pieces of the same
// triangles); the benchmark uses it to grow a mesh by 4x its faces.
#ifndef CUT_PARAM_BENCHMARK_MIDPOINT_SUBDIVISION_H
#define CUT_PARAM_BENCHMARK_MIDPOINT_SUBDIVISION_H

#include <CGAL/Surface_mesh.h>

#include <array>
#include <stdexcept>
#include <vector>

namespace cut_benchmark {

/// The subdivided mesh: the vertices of `mesh` first (in order), then one per
/// edge (in edge order); four faces per face, oriented like it. Throws
/// std::invalid_argument if `mesh` has a face that is not a triangle.
template <typename Point>
CGAL::Surface_mesh<Point> midpoint_subdivision(const CGAL::Surface_mesh<Point>& mesh)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  using Vertex = typename Mesh::Vertex_index;
  Mesh out;
  out.reserve(mesh.number_of_vertices() + mesh.number_of_edges(),
              2 * mesh.number_of_edges() + 3 * mesh.number_of_faces(), 4 * mesh.number_of_faces());
  // indexed by the input's indices (which may have gaps after removals)
  std::vector<Vertex> corner(mesh.num_vertices()), midpoint(mesh.num_edges());
  for(auto v : mesh.vertices()) corner[std::size_t(v)] = out.add_vertex(mesh.point(v));
  for(auto e : mesh.edges())
  {
    const auto h = mesh.halfedge(e);
    midpoint[std::size_t(e)] = out.add_vertex(CGAL::midpoint(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
  }
  for(auto f : mesh.faces())
  {
    if(mesh.degree(f) != 3) throw std::invalid_argument("midpoint_subdivision: a face is not a triangle");
    // corners a, b, c and the midpoints of ab, bc, ca
    const auto h0 = mesh.halfedge(f), h1 = mesh.next(h0), h2 = mesh.next(h1);
    const Vertex a = corner[std::size_t(mesh.source(h0))], b = corner[std::size_t(mesh.target(h0))],
                 c = corner[std::size_t(mesh.target(h1))];
    const Vertex ab = midpoint[std::size_t(mesh.edge(h0))], bc = midpoint[std::size_t(mesh.edge(h1))],
                 ca = midpoint[std::size_t(mesh.edge(h2))];
    const std::array<std::array<Vertex, 3>, 4> pieces = {{{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}}};
    for(const auto& p : pieces)
      if(out.add_face(p[0], p[1], p[2]) == Mesh::null_face())
        throw std::invalid_argument("midpoint_subdivision: the input is not a manifold triangle mesh");
  }
  return out;
}

} // namespace cut_benchmark

#endif
