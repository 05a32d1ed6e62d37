// One scan of a FaceGraph into flat arrays (positions, corners, twins,
// edges), so that everything downstream works on indices, whatever the
// mesh type (Surface_mesh, Polyhedron_3, Seam_mesh, ...).
//
// Conventions: corner k of face f sits at target(h_k), h_0 = halfedge(f),
// h_{k+1} = next(h_k). Face-edge k of f runs from corner k to corner k+1,
// i.e. it is the halfedge h_{k+1}.
#ifndef CGAL_SMP_CUT_INTERNAL_INDEXED_SURFACE_H
#define CGAL_SMP_CUT_INTERNAL_INDEXED_SURFACE_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

template <typename TriangleMesh>
struct Indexed_surface
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  std::vector<vertex_descriptor> vertices;
  std::vector<face_descriptor> faces;
  std::vector<edge_descriptor> edges;
  std::vector<Vector3> points;                      // per vertex
  std::vector<std::array<int, 3>> corner_vertex;    // per face
  std::vector<std::array<halfedge_descriptor, 3>> corner_halfedge; // h_k per face
  std::vector<int> twin;                            // face-edge 3f+k -> twin face-edge, -1 on the border
  std::vector<int> edge_of;                         // face-edge -> edge index
  std::unordered_map<halfedge_descriptor, int> halfedge_corner; // h_k -> 3f+k (face halfedges only)
  std::size_t isolated_vertices = 0;                // vertices in no face, left out

  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t number_of_vertices() const { return vertices.size(); }
  int edge_source(int face_edge) const { return corner_vertex[face_edge / 3][face_edge % 3]; }
  int edge_target(int face_edge) const { return corner_vertex[face_edge / 3][(face_edge % 3 + 1) % 3]; }
  double edge_length(int face_edge) const
  {
    return (points[edge_target(face_edge)] - points[edge_source(face_edge)]).norm();
  }
  /// 1 for each vertex on the mesh's border (an end of a face-edge without twin).
  std::vector<char> border_vertices() const
  {
    std::vector<char> on_border(number_of_vertices(), 0);
    for(int fe = 0; fe < int(twin.size()); ++fe)
      if(twin[fe] < 0) on_border[edge_source(fe)] = on_border[edge_target(fe)] = 1;
    return on_border;
  }
  /// Halfedge of the input mesh that face-edge 3f+k stands for.
  halfedge_descriptor face_edge_halfedge(int face_edge) const
  {
    return corner_halfedge[face_edge / 3][(face_edge % 3 + 1) % 3];
  }
};

enum class Indexing_status { OK, EMPTY, NOT_TRIANGLE, NOT_FINITE, NON_MANIFOLD };

/// The three halfedges of face f (h_0 = halfedge(f)); false if f is not a triangle.
template <typename TriangleMesh, typename Halfedge>
bool triangle_halfedges(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                        const TriangleMesh& mesh, std::array<Halfedge, 3>& h)
{
  int k = 0;
  for(Halfedge hf : halfedges_around_face(halfedge(f, mesh), mesh))
  {
    if(k == 3) return false;
    h[k++] = hf;
  }
  return k == 3;
}

/// False at a pinched vertex, whose faces form several fans: its
/// circulation meets more than one border halfedge (the fans are linked
/// through the border), or misses some of the `corners` faces at v.
template <typename TriangleMesh, typename Vertex>
bool is_manifold_vertex(Vertex v, const TriangleMesh& mesh, int corners)
{
  int around = 0, border = 0;
  for(auto h : halfedges_around_target(halfedge(v, mesh), mesh))
    ++(is_border(h, mesh) ? border : around);
  return around == corners && border <= 1;
}

/// Fills `out` from `mesh`. Fails on an empty mesh, a non-triangle face, a
/// non-finite coordinate, a non-manifold (pinched) vertex or two edges
/// joining the same two vertices. Vertices in no
/// face are left out (counted in `isolated_vertices`): their coordinates are
/// not read and they get no UV.
template <typename TriangleMesh, typename VertexPointMap>
Indexing_status index_surface(const TriangleMesh& mesh, VertexPointMap vpm,
                              Indexed_surface<TriangleMesh>& out)
{
  using IS = Indexed_surface<TriangleMesh>;
  using halfedge_descriptor = typename IS::halfedge_descriptor;
  std::unordered_map<typename IS::vertex_descriptor, int> corners_at; // vertex -> number of corners
  for(auto f : faces(mesh))
  {
    std::array<halfedge_descriptor, 3> h;
    if(!triangle_halfedges(f, mesh, h)) return Indexing_status::NOT_TRIANGLE;
    out.faces.push_back(f);
    out.corner_halfedge.push_back(h);
    for(halfedge_descriptor hc : h) ++corners_at[target(hc, mesh)];
  }
  if(out.faces.empty()) return Indexing_status::EMPTY;

  std::unordered_map<typename IS::vertex_descriptor, int> vertex_index;
  for(auto v : vertices(mesh)) // in the mesh's order, for determinism
  {
    const auto used = corners_at.find(v);
    if(used == corners_at.end()) { ++out.isolated_vertices; continue; }
    if(!is_manifold_vertex(v, mesh, used->second)) return Indexing_status::NON_MANIFOLD;
    const auto& p = get(vpm, v);
    const Vector3 q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if(!q.allFinite()) return Indexing_status::NOT_FINITE;
    vertex_index.emplace(v, int(out.vertices.size()));
    out.vertices.push_back(v);
    out.points.push_back(q);
  }
  for(std::size_t fi = 0; fi < out.faces.size(); ++fi)
  {
    const auto& h = out.corner_halfedge[fi];
    out.corner_vertex.push_back({vertex_index.at(target(h[0], mesh)),
                                 vertex_index.at(target(h[1], mesh)),
                                 vertex_index.at(target(h[2], mesh))});
    for(int c = 0; c < 3; ++c) out.halfedge_corner.emplace(h[c], int(3 * fi) + c);
  }

  const int n_face_edges = int(3 * out.faces.size());
  out.twin.assign(n_face_edges, -1);
  out.edge_of.assign(n_face_edges, -1);
  for(int fe = 0; fe < n_face_edges; ++fe)
  {
    if(out.edge_of[fe] >= 0) continue;
    const halfedge_descriptor h = out.face_edge_halfedge(fe);
    out.edge_of[fe] = int(out.edges.size());
    out.edges.push_back(edge(h, mesh));
    const halfedge_descriptor o = opposite(h, mesh);
    if(is_border(o, mesh)) continue;
    // o = h'_{l+1} of its face, i.e. face-edge l = corner(o) - 1
    const int co = out.halfedge_corner.at(o);
    const int twin = 3 * (co / 3) + (co % 3 + 2) % 3;
    out.twin[fe] = twin;
    out.twin[twin] = fe;
    out.edge_of[twin] = out.edge_of[fe];
  }
  // two edges joining the same two vertices (a polygon split along a
  // diagonal that was already an edge): in the soup, an edge of 3 or 4
  // faces, which the chart meshes (indexed by vertex pairs) cannot hold
  std::unordered_set<std::uint64_t> joined;
  joined.reserve(out.edges.size());
  for(int fe = 0; fe < n_face_edges; ++fe)
  {
    if(out.twin[fe] >= 0 && out.twin[fe] < fe) continue; // each edge once
    const std::uint64_t a = std::uint64_t(out.edge_source(fe)), b = std::uint64_t(out.edge_target(fe));
    if(!joined.insert(((std::min)(a, b) << 32) | (std::max)(a, b)).second) return Indexing_status::NON_MANIFOLD;
  }
  return Indexing_status::OK;
}

/// Mean 3D edge length ℓ, each edge once; 1 if all edges have zero length.
/// The unit of the relative parameters, and the size given to faces whose
/// corners coincide.
template <typename TriangleMesh>
double mean_edge_length(const Indexed_surface<TriangleMesh>& surface)
{
  double sum = 0.;
  int n = 0;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < fe) { sum += surface.edge_length(fe); ++n; }
  return sum > 0. && std::isfinite(sum) ? sum / n : 1.;
}

/// Faces that Chart_mesh::set_rest_shape() clamps.
template <typename TriangleMesh>
std::size_t number_of_degenerate_faces(const Indexed_surface<TriangleMesh>& surface)
{
  std::size_t degenerate = 0;
  for(const auto& cv : surface.corner_vertex)
    if(is_degenerate_triangle(surface.points[cv[0]], surface.points[cv[1]], surface.points[cv[2]])) ++degenerate;
  return degenerate;
}

/// Chart mesh whose UV vertices are the corner classes of the surface cut
/// along the edges flagged in `is_cut` (indexed like `surface.edges`); also
/// returns the UV vertex of every corner. Returns the number of degenerate
/// faces, whose rest shapes were clamped (Chart_mesh::set_rest_shape()).
template <typename TriangleMesh>
std::size_t build_chart_mesh(const Indexed_surface<TriangleMesh>& surface, const std::vector<char>& is_cut,
                      Chart_mesh& chart, std::vector<int>& corner_uv)
{
  const int n_corners = int(3 * surface.number_of_faces());
  std::vector<int> parent(n_corners);
  for(int c = 0; c < n_corners; ++c) parent[c] = c;
  auto find = [&](int c) { while(parent[c] != c) c = parent[c] = parent[parent[c]]; return c; };
  auto unite = [&](int a, int b) { a = find(a); b = find(b); if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b); };
  for(int fe = 0; fe < n_corners; ++fe)
  {
    const int tw = surface.twin[fe];
    if(tw < fe || is_cut[surface.edge_of[fe]]) continue; // border (-1) or done or cut
    const int f = fe / 3, k = fe % 3, g = tw / 3, l = tw % 3;
    unite(3*f + k, 3*g + (l+1)%3);
    unite(3*f + (k+1)%3, 3*g + l);
  }
  // A vertex whose corners were not joined (fan broken only by cuts) keeps
  // several classes; that is the point of cutting.
  corner_uv.assign(n_corners, -1);
  std::vector<int> class_index(n_corners, -1);
  int n = 0;
  for(int c = 0; c < n_corners; ++c)
  {
    const int r = find(c);
    if(class_index[r] < 0) class_index[r] = n++;
    corner_uv[c] = class_index[r];
  }
  chart = Chart_mesh();
  chart.number_of_vertices = n;
  chart.resize_faces(surface.number_of_faces());
  const double mean_edge = mean_edge_length(surface);
  std::size_t degenerate = 0;
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f)
  {
    chart.faces[f] = {corner_uv[3*f], corner_uv[3*f+1], corner_uv[3*f+2]};
    const auto& cv = surface.corner_vertex[f];
    if(chart.set_rest_shape(f, surface.points[cv[0]], surface.points[cv[1]], surface.points[cv[2]], mean_edge))
      ++degenerate;
  }
  return degenerate;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
