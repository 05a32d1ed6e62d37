// Turns the discontinuity field v into seam paths (the manual, "Cut
// extraction"): patches of faces with v < 1/2; in each patch a path of mesh
// edges found by Dijkstra searches on the patch's edge graph (near-linear,
// no all-pairs search); paths shorter than a fraction of the longest dropped.
//
// A patch that touches the boundary of the cut mesh gets the path from its
// vertex farthest from that boundary back to it, so the cut opens the chart
// instead of making a closed slit, and never leaves and re-enters the
// boundary (which would split a chart). Other patches get their diameter
// path, found by two sweeps. Forbidden edges are left out of the patch
// graphs, so no path uses one.
#ifndef CGAL_SMP_CUT_INTERNAL_CUT_EXTRACTION_H
#define CGAL_SMP_CUT_INTERNAL_CUT_EXTRACTION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Cut_rules.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Edge_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_paths.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Edge graph of one patch, on local vertex indices.
struct Patch_graph
{
  Edge_graph graph;
  std::vector<int> vertex;       // local -> surface vertex
  std::vector<char> on_boundary; // vertex lies on the cut mesh's boundary
};

/// Cut tree of one patch, grown one branch at a time: each branch is the
/// shortest path from the vertex farthest from the current sources (the cut
/// mesh's boundary, then also the branches so far) back to them. Branches
/// come out longest first; growth stops below `minimum_length`. A patch off
/// the boundary starts from its diameter path (two Dijkstra sweeps).
inline std::vector<Cut_path> patch_cut_tree(const Patch_graph& patch, double minimum_length, int max_branches)
{
  if(patch.vertex.empty()) return {}; // every edge of the patch forbidden
  std::vector<int> sources;
  for(int i = 0; i < int(patch.vertex.size()); ++i)
    if(patch.on_boundary[i]) sources.push_back(i);
  if(sources.empty())
    sources = {patch.graph.shortest_paths({0}).farthest()};
  std::vector<Cut_path> branches;
  while(int(branches.size()) < max_branches)
  {
    const Shortest_paths paths = patch.graph.shortest_paths(sources);
    const int tip = paths.farthest();
    if(tip < 0 || !(paths.distance[tip] > 0.) || paths.distance[tip] < minimum_length) break;
    for(int v = tip; paths.parent[v] >= 0; v = paths.parent[v]) sources.push_back(v);
    branches.push_back({paths.path_edges(tip), paths.distance[tip]});
  }
  return branches;
}

/// Faces with v < 1/2, grouped into patches connected across uncut edges.
template <typename Surface>
std::vector<std::vector<int>> low_v_patches(const Surface& surface, const std::vector<char>& is_cut,
                                            const Eigen::VectorXd& v)
{
  const int n = int(surface.number_of_faces());
  std::vector<int> patch_of(n, -1);
  std::vector<std::vector<int>> patches;
  for(int seed = 0; seed < n; ++seed)
  {
    if(patch_of[seed] >= 0 || !(v[seed] < 0.5)) continue;
    patches.emplace_back();
    std::vector<int> stack{seed};
    patch_of[seed] = int(patches.size()) - 1;
    while(!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      patches.back().push_back(f);
      for(int k = 0; k < 3; ++k)
      {
        const int tw = surface.twin[3*f + k];
        if(tw < 0 || is_cut[surface.edge_of[3*f + k]]) continue;
        const int g = tw / 3;
        if(patch_of[g] < 0 && v[g] < 0.5) { patch_of[g] = patch_of[f]; stack.push_back(g); }
      }
    }
  }
  return patches;
}

template <typename Surface>
Patch_graph patch_graph(const Surface& surface, const std::vector<char>& is_cut,
                        const std::vector<char>& on_boundary, const Cut_rules& rules,
                        const std::vector<int>& faces, std::vector<int>& local_index)
{
  Patch_graph patch;
  auto local = [&](int v) {
    if(local_index[v] < 0)
    {
      local_index[v] = patch.graph.add_vertex();
      patch.vertex.push_back(v);
      patch.on_boundary.push_back(on_boundary[v]);
    }
    return local_index[v];
  };
  for(int f : faces)
    for(int k = 0; k < 3; ++k)
    {
      const int fe = 3*f + k, tw = surface.twin[fe];
      // each edge once: from the face-edge with the larger index, or the only one
      if(tw >= 0 && tw > fe && std::binary_search(faces.begin(), faces.end(), tw / 3)) continue;
      const int e = surface.edge_of[fe];
      const bool boundary_edge = tw < 0 || is_cut[e];
      if(!boundary_edge && rules.is_forbidden(e)) continue;
      const int a = local(surface.edge_source(fe)); // sequenced: numbering must not depend on the compiler
      const int b = local(surface.edge_target(fe));
      patch.graph.add_edge(a, b, e, boundary_edge ? 0. : surface.edge_length(fe));
    }
  for(int v : patch.vertex) local_index[v] = -1;
  return patch;
}

/// Seam paths extracted from v, never on the forbidden edges of `rules`
/// (v already carries the λ factors); edges already cut are not repeated.
/// Paths shorter than `minimum_relative_length` times the longest are dropped.
template <typename Surface>
std::vector<Cut_path> extract_cut_paths(const Surface& surface, const std::vector<char>& is_cut,
                                        const Cut_rules& rules, const Eigen::VectorXd& v,
                                        double minimum_relative_length, int max_branches_per_patch = 32)
{
  const std::vector<char> on_boundary = cut_boundary_vertices(surface, is_cut);
  std::vector<int> local_index(surface.number_of_vertices(), -1);
  std::vector<Patch_graph> graphs;
  double longest = 0.;
  for(std::vector<int>& faces : low_v_patches(surface, is_cut, v))
  {
    std::sort(faces.begin(), faces.end());
    graphs.push_back(patch_graph(surface, is_cut, on_boundary, rules, faces, local_index));
    const std::vector<Cut_path> first = patch_cut_tree(graphs.back(), 0., 1);
    if(!first.empty()) longest = (std::max)(longest, first.front().length);
  }
  std::vector<Cut_path> paths;
  const double minimum_length = (std::max)(minimum_relative_length * longest, 1e-300);
  for(const Patch_graph& graph : graphs)
    for(Cut_path& path : patch_cut_tree(graph, minimum_length, max_branches_per_patch))
    {
      path.edges.erase(std::remove_if(path.edges.begin(), path.edges.end(),
                                      [&](int e) { return bool(is_cut[e]); }), path.edges.end());
      if(!path.edges.empty()) paths.push_back(std::move(path));
    }
  return paths;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
