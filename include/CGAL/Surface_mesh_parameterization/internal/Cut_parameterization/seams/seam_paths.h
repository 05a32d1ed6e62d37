// The seams as a graph on the surface's vertices (interior cut edges, the
// user's seams left out), split into paths from node to node: what the seam
// rerouting (seam_straightening.h) and the zips (seam_merging.h) work on.
#ifndef CGAL_SMP_CUT_INTERNAL_SEAM_PATHS_H
#define CGAL_SMP_CUT_INTERNAL_SEAM_PATHS_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Cut_rules.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// A seam between two nodes: its surface edges and vertices in order
/// (vertices[i], vertices[i+1] are the ends of edges[i]).
struct Seam_path
{
  std::vector<int> edges;
  std::vector<int> vertices;
};

/// The seam graph of `is_cut` (interior cut edges, those flagged in `keep`
/// left out) on the surface's vertices: per vertex, its (edge, other
/// vertex) pairs; `node` flags the vertices where paths end.
struct Seam_graph
{
  std::vector<std::vector<std::array<int, 2>>> arcs;
  std::vector<char> fixed; // on the mesh border or on a seam of `keep`
  std::vector<char> node;  // fixed, or where the seams branch or end
};

template <typename Surface>
Seam_graph seam_graph(const Surface& surface, const std::vector<char>& is_cut, const std::vector<char>& keep)
{
  const int nv = int(surface.number_of_vertices());
  Seam_graph g;
  g.arcs.assign(nv, {});
  g.fixed.assign(nv, 0);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe), e = surface.edge_of[fe];
    if(surface.twin[fe] < 0 || (is_cut[e] && is_flagged(keep, e))) g.fixed[a] = g.fixed[b] = 1;
    else if(surface.twin[fe] > fe && is_cut[e])
    {
      g.arcs[a].push_back({e, b});
      g.arcs[b].push_back({e, a});
    }
  }
  g.node = g.fixed;
  for(int v = 0; v < nv; ++v)
    if(!g.arcs[v].empty() && g.arcs[v].size() != 2) g.node[v] = 1;
  return g;
}

/// The paths of the seam graph from node to node (closed loops through no
/// node are left out: nothing fixes their ends).
template <typename Surface>
std::vector<Seam_path> seam_paths(const Surface& surface, const std::vector<char>& is_cut, const std::vector<char>& keep)
{
  const Seam_graph g = seam_graph(surface, is_cut, keep);
  std::vector<char> used(surface.edges.size(), 0);
  std::vector<Seam_path> paths;
  for(int start = 0; start < int(g.arcs.size()); ++start)
  {
    if(!g.node[start]) continue;
    for(const auto& first : g.arcs[start])
    {
      if(used[first[0]]) continue;
      Seam_path path;
      path.vertices.push_back(start);
      int e = first[0], v = first[1];
      for(;;)
      {
        used[e] = 1;
        path.edges.push_back(e);
        path.vertices.push_back(v);
        if(g.node[v]) break;
        const auto& next = g.arcs[v][0][0] != e ? g.arcs[v][0] : g.arcs[v][1];
        e = next[0];
        v = next[1];
      }
      paths.push_back(std::move(path));
    }
  }
  return paths;
}

/// The paths that start at a tip (a vertex with one seam edge, off the
/// border and off the user's seams), tip first: the branches that zipping
/// closes. A path with two tips is listed once.
template <typename Surface>
std::vector<Seam_path> seam_branches(const Surface& surface, const std::vector<char>& is_cut,
                                     const std::vector<char>& keep)
{
  const Seam_graph g = seam_graph(surface, is_cut, keep);
  auto is_tip = [&](int v) { return g.arcs[v].size() == 1 && !g.fixed[v]; };
  std::vector<Seam_path> branches;
  for(Seam_path& path : seam_paths(surface, is_cut, keep))
  {
    if(!is_tip(path.vertices.front()) && is_tip(path.vertices.back()))
    {
      std::reverse(path.vertices.begin(), path.vertices.end());
      std::reverse(path.edges.begin(), path.edges.end());
    }
    if(is_tip(path.vertices.front())) branches.push_back(std::move(path));
  }
  return branches;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
