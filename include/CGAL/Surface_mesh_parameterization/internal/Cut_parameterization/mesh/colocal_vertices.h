// Colocal vertices welded on the indexed surface: vertices of the input that
// lie at the same position (within a tolerance relative to the bounding box)
// become one vertex of the unwrapping, and border edges that then join the
// same two vertices, in opposite directions, become one interior edge. A
// mesh exported with split normals (each sharp edge's vertices duplicated)
// is unwrapped as the surface it stands for; the input mesh is untouched:
// corners keep their halfedges, and the outputs are written per corner.
#ifndef CGAL_SMP_CUT_INTERNAL_COLOCAL_VERTICES_H
#define CGAL_SMP_CUT_INTERNAL_COLOCAL_VERTICES_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Union-find whose root is the smallest index (the first vertex of a
/// class in the mesh's order, for determinism).
struct Min_root_sets
{
  std::vector<int> parent;
  explicit Min_root_sets(int n) : parent(std::size_t(n)) { for(int i = 0; i < n; ++i) parent[std::size_t(i)] = i; }
  int find(int a)
  {
    while(parent[std::size_t(a)] != a) a = parent[std::size_t(a)] = parent[std::size_t(parent[std::size_t(a)])];
    return a;
  }
  void unite(int a, int b)
  {
    a = find(a); b = find(b);
    if(a != b) parent[std::size_t((std::max)(a, b))] = (std::min)(a, b);
  }
};

/// Per vertex of `surface`, the first vertex within `tolerance` of it
/// (transitively): a grid of cells of side `tolerance`, each point compared
/// with the points of its 27 neighbouring cells.
template <typename Surface>
std::vector<int> colocal_classes(const Surface& surface, double tolerance)
{
  const int n = int(surface.number_of_vertices());
  Min_root_sets sets(n);
  std::unordered_map<std::uint64_t, std::vector<int>> cell_points;
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(x) * 73856093u) ^ (std::uint64_t(y) * 19349663u) ^ (std::uint64_t(z) * 83492791u);
  };
  for(int v = 0; v < n; ++v)
  {
    const Vector3& p = surface.points[std::size_t(v)];
    const std::int64_t c[3] = {std::int64_t(std::floor(p.x() / tolerance)), std::int64_t(std::floor(p.y() / tolerance)),
                               std::int64_t(std::floor(p.z() / tolerance))};
    for(int dx = -1; dx <= 1; ++dx)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dz = -1; dz <= 1; ++dz)
        {
          const auto it = cell_points.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if(it == cell_points.end()) continue;
          for(int w : it->second)
            if((surface.points[std::size_t(w)] - p).norm() <= tolerance) sets.unite(v, w);
        }
    cell_points[key(c[0], c[1], c[2])].push_back(v);
  }
  std::vector<int> root(static_cast<std::size_t>(n));
  for(int v = 0; v < n; ++v) root[std::size_t(v)] = sets.find(v);
  // a face with two corners in one class (an edge shorter than the
  // tolerance) would collapse: its vertices' classes are not welded
  std::vector<char> undone(static_cast<std::size_t>(n), 0);
  for(const auto& cv : surface.corner_vertex)
    for(int k = 0; k < 3; ++k)
      if(root[std::size_t(cv[k])] == root[std::size_t(cv[(k + 1) % 3])]) undone[std::size_t(root[std::size_t(cv[k])])] = 1;
  for(int v = 0; v < n; ++v)
    if(undone[std::size_t(root[std::size_t(v)])]) root[std::size_t(v)] = v;
  return root;
}

/// Joins face-edges without twin that run between the same two (welded)
/// vertices in opposite directions, where exactly two such face-edges and
/// no interior edge join them. Returns the face-edges glued.
template <typename Surface>
std::vector<int> glue_border_face_edges(Surface& surface)
{
  std::map<std::pair<int, int>, std::vector<int>> at_pair; // (min, max) vertex -> face-edges
  const int n_face_edges = int(surface.twin.size());
  for(int fe = 0; fe < n_face_edges; ++fe)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe);
    at_pair[{(std::min)(a, b), (std::max)(a, b)}].push_back(fe);
  }
  std::vector<int> glued;
  for(const auto& entry : at_pair)
  {
    const std::vector<int>& fes = entry.second;
    if(fes.size() != 2) continue;
    const int f = fes[0], g = fes[1];
    if(surface.twin[std::size_t(f)] >= 0 || surface.twin[std::size_t(g)] >= 0) continue;
    if(surface.edge_source(f) != surface.edge_target(g)) continue; // same direction: orientations disagree
    surface.twin[std::size_t(f)] = g;
    surface.twin[std::size_t(g)] = f;
    glued.push_back(f);
    glued.push_back(g);
  }
  std::sort(glued.begin(), glued.end());
  return glued;
}

/// Gives each fan of corners around a vertex (corners linked across twins)
/// its own vertex: welding may pinch a vertex (two pieces touching at a
/// point), which the unwrapping cannot take.
template <typename Surface>
void split_pinched_vertices(Surface& surface)
{
  const int n_corners = int(surface.twin.size());
  Min_root_sets fans(n_corners);
  for(int fe = 0; fe < n_corners; ++fe)
  {
    const int tw = surface.twin[std::size_t(fe)];
    if(tw < fe) continue;
    const int f = fe / 3, k = fe % 3, g = tw / 3, l = tw % 3;
    fans.unite(3 * f + k, 3 * g + (l + 1) % 3);
    fans.unite(3 * f + (k + 1) % 3, 3 * g + l);
  }
  std::vector<int> fan_of_vertex(surface.number_of_vertices(), -1);
  std::map<int, int> vertex_of_fan;
  for(int c = 0; c < n_corners; ++c)
  {
    int& v = surface.corner_vertex[std::size_t(c / 3)][std::size_t(c % 3)];
    const int fan = fans.find(c);
    if(fan_of_vertex[std::size_t(v)] < 0) fan_of_vertex[std::size_t(v)] = fan;
    if(fan_of_vertex[std::size_t(v)] == fan) continue;
    const auto it = vertex_of_fan.find(fan);
    if(it != vertex_of_fan.end()) { v = it->second; continue; }
    const int w = int(surface.vertices.size());
    surface.vertices.push_back(surface.vertices[std::size_t(v)]);
    surface.points.push_back(surface.points[std::size_t(v)]);
    fan_of_vertex.push_back(fan);
    vertex_of_fan.emplace(fan, w);
    v = w;
  }
}

/// Numbers the edges again from the twins, in face-edge order (as
/// index_surface() does); false if two edges join the same two vertices.
template <typename Surface>
bool renumber_edges(const std::vector<typename Surface::edge_descriptor>& old_edges, const std::vector<int>& old_edge_of,
                    Surface& surface)
{
  const int n_face_edges = int(surface.twin.size());
  surface.edge_of.assign(std::size_t(n_face_edges), -1);
  surface.edges.clear();
  std::unordered_map<std::uint64_t, int> joined;
  for(int fe = 0; fe < n_face_edges; ++fe)
  {
    if(surface.edge_of[std::size_t(fe)] >= 0) continue;
    surface.edge_of[std::size_t(fe)] = int(surface.edges.size());
    surface.edges.push_back(old_edges[std::size_t(old_edge_of[std::size_t(fe)])]);
    if(surface.twin[std::size_t(fe)] >= 0) surface.edge_of[std::size_t(surface.twin[std::size_t(fe)])] = surface.edge_of[std::size_t(fe)];
    const std::uint64_t a = std::uint64_t(surface.edge_source(fe)), b = std::uint64_t(surface.edge_target(fe));
    if(!joined.emplace(((std::min)(a, b) << 32) | (std::max)(a, b), fe).second) return false;
  }
  return true;
}

/// Welds the vertices of `surface` closer than `relative_tolerance` times
/// its bounding box diagonal, and glues the border edges that then match
/// (see the file's comment). `glued` receives the face-edges glued (each
/// pair's two): their input halfedges are border halfedges of the mesh,
/// whose outputs (seam flag, border UV) the entry writes as well.
/// Returns the number of vertices the welding removed (0: `surface`
/// unchanged, e.g. when the welded surface would not be a manifold mesh).
/// \pre `surface` was filled by index_surface()
/// \post every vertex has one fan of faces; no two edges join the same two vertices
template <typename Surface>
std::size_t weld_colocal_vertices(Surface& surface, double relative_tolerance, std::vector<int>& glued)
{
  glued.clear();
  if(surface.number_of_vertices() < 2) return 0;
  Vector3 lo = surface.points[0], hi = surface.points[0];
  for(const Vector3& p : surface.points) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  const double tolerance = (hi - lo).norm() * relative_tolerance;
  if(!(tolerance > 0.) || !std::isfinite(tolerance)) return 0;

  const std::vector<int> root = colocal_classes(surface, tolerance);
  std::vector<int> new_index(surface.number_of_vertices(), -1);
  int n = 0;
  for(std::size_t v = 0; v < root.size(); ++v)
    if(root[v] == int(v)) new_index[v] = n++;
  if(std::size_t(n) == surface.number_of_vertices()) return 0;

  Surface welded = surface;
  welded.vertices.clear();
  welded.points.clear();
  for(std::size_t v = 0; v < root.size(); ++v)
    if(root[v] == int(v)) { welded.vertices.push_back(surface.vertices[v]); welded.points.push_back(surface.points[v]); }
  for(auto& cv : welded.corner_vertex)
    for(int& v : cv) v = new_index[std::size_t(root[std::size_t(v)])];
  std::vector<int> glued_face_edges = glue_border_face_edges(welded);
  split_pinched_vertices(welded);
  if(!renumber_edges(surface.edges, surface.edge_of, welded)) return 0;
  const std::size_t removed = surface.number_of_vertices() - welded.number_of_vertices();
  if(removed == 0) return 0;
  surface = std::move(welded);
  glued = std::move(glued_face_edges);
  return removed;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
