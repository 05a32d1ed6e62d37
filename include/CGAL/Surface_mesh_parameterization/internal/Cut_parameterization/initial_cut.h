// Initial cut: makes every connected component of the cut mesh a
// topological disk, with short cuts, so that the joint optimization can
// start from a Tutte embedding.
//
// - A component that is already a disk is left alone.
// - Otherwise the faces are joined by a dual spanning tree that crosses the
//   longest edges first (Kruskal, maximum primal length); the edges it does
//   not cross form a cut graph whose cutting leaves a disk. Pruning its
//   dangling branches keeps only what the topology needs: loops through
//   the handles and paths joining the boundary loops.
// - A closed genus-0 component needs no loop: it is opened along a path
//   between two far-apart vertices (two Dijkstra sweeps), from which the
//   optimization grows its seams.
#ifndef CGAL_SMP_CUT_INTERNAL_INITIAL_CUT_H
#define CGAL_SMP_CUT_INTERNAL_INITIAL_CUT_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Indexed_surface.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Per chart of a chart mesh: Euler characteristic and number of boundary loops.
struct Chart_topology
{
  std::vector<int> chart_of_face;
  std::vector<int> euler, loops;
  int number_of_charts = 0;
  bool is_disk(int c) const { return euler[c] == 1 && loops[c] == 1; }
};

inline Chart_topology chart_topology(const Chart_mesh& mesh)
{
  Chart_topology t;
  t.chart_of_face = chart_of_faces(mesh, t.number_of_charts);
  t.euler.assign(t.number_of_charts, 0);
  t.loops.assign(t.number_of_charts, 0);
  std::vector<int> chart_of_vertex(mesh.number_of_vertices, -1);
  std::unordered_map<std::uint64_t, int> undirected;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const int c = t.chart_of_face[f];
    t.euler[c] += 1;
    for(int k = 0; k < 3; ++k)
    {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k+1)%3];
      if(chart_of_vertex[a] < 0) { chart_of_vertex[a] = c; t.euler[c] += 1; }
      if(undirected.emplace(directed_edge_key((std::min)(a, b), (std::max)(a, b)), c).second) t.euler[c] -= 1;
    }
  }
  for(const auto& loop : boundary_loops(mesh)) t.loops[chart_of_vertex[loop.front()]] += 1;
  return t;
}

class Edge_graph
{
public:
  struct Arc { int to, edge; double length; };
  std::vector<std::vector<Arc>> arcs; // per surface vertex

  template <typename Surface>
  Edge_graph(const Surface& surface, const std::vector<char>& use_edge)
    : arcs(surface.number_of_vertices())
  {
    std::vector<char> added(surface.edges.size(), 0);
    for(int fe = 0; fe < int(surface.edge_of.size()); ++fe)
    {
      const int e = surface.edge_of[fe];
      if(!use_edge[e] || added[e]) continue;
      added[e] = 1;
      const int a = surface.edge_source(fe), b = surface.edge_target(fe);
      const double l = surface.edge_length(fe);
      arcs[a].push_back({b, e, l});
      arcs[b].push_back({a, e, l});
    }
  }

  /// Dijkstra from one source; fills distances and the edge reaching each vertex.
  void shortest_paths(int source, std::vector<double>& distance, std::vector<int>& parent,
                      std::vector<int>& parent_edge) const
  {
    distance.assign(arcs.size(), std::numeric_limits<double>::infinity());
    parent.assign(arcs.size(), -1);
    parent_edge.assign(arcs.size(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    distance[source] = 0.;
    queue.push({0., source});
    while(!queue.empty())
    {
      const auto [d, u] = queue.top();
      queue.pop();
      if(d > distance[u]) continue;
      for(const Arc& arc : arcs[u])
        if(d + arc.length < distance[arc.to])
        {
          distance[arc.to] = d + arc.length;
          parent[arc.to] = u;
          parent_edge[arc.to] = arc.edge;
          queue.push({distance[arc.to], arc.to});
        }
    }
  }
};

inline int farthest_reached(const std::vector<double>& distance)
{
  int best = -1;
  for(int i = 0; i < int(distance.size()); ++i)
    if(std::isfinite(distance[i]) && (best < 0 || distance[i] > distance[best])) best = i;
  return best;
}

/// Cuts a path between two far-apart vertices of the faces in `component_faces`.
template <typename Surface>
void cut_diameter_path(const Surface& surface, const std::vector<int>& component_faces,
                       std::vector<char>& is_cut)
{
  std::vector<char> in_component(surface.edges.size(), 0);
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k) in_component[surface.edge_of[3*f + k]] = 1;
  const Edge_graph graph(surface, in_component);
  std::vector<double> distance;
  std::vector<int> parent, parent_edge;
  graph.shortest_paths(surface.corner_vertex[component_faces.front()][0], distance, parent, parent_edge);
  const int a = farthest_reached(distance);
  graph.shortest_paths(a, distance, parent, parent_edge);
  const int b = farthest_reached(distance);
  int edges_cut = 0;
  for(int v = b; parent[v] >= 0; v = parent[v], ++edges_cut) is_cut[parent_edge[v]] = 1;
  // a single cut edge opens a two-sided hole, not a disk with a usable border
  for(const auto& arc : graph.arcs[b])
    if(edges_cut < 2 && !is_cut[arc.edge]) { is_cut[arc.edge] = 1; ++edges_cut; }
}

/// Cut graph of the faces in `component_faces` (see the file comment):
/// sets is_cut on its interior edges.
template <typename Surface>
void cut_graph(const Surface& surface, const std::vector<int>& component_faces, std::vector<char>& is_cut)
{
  // dual maximum spanning tree, Kruskal on uncut interior edges by decreasing length
  std::vector<int> dual_edges;
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k)
    {
      const int fe = 3*f + k, tw = surface.twin[fe];
      if(tw > fe && !is_cut[surface.edge_of[fe]]) dual_edges.push_back(fe);
    }
  std::sort(dual_edges.begin(), dual_edges.end(), [&](int a, int b) {
    return surface.edge_length(a) > surface.edge_length(b); });
  std::vector<int> parent(surface.number_of_faces());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) { while(parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  std::vector<char> crossed(surface.edges.size(), 0);
  for(int fe : dual_edges)
  {
    const int a = find(fe / 3), b = find(surface.twin[fe] / 3);
    if(a == b) continue;
    parent[a] = b;
    crossed[surface.edge_of[fe]] = 1;
  }
  // cut graph = edges of the component not crossed; prune dangling branches
  std::vector<char> in_graph(surface.edges.size(), 0);
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k)
      if(!crossed[surface.edge_of[3*f + k]]) in_graph[surface.edge_of[3*f + k]] = 1;
  const Edge_graph graph(surface, in_graph);
  std::vector<int> degree(surface.number_of_vertices(), 0);
  std::vector<int> leaves;
  for(std::size_t v = 0; v < graph.arcs.size(); ++v)
    if((degree[v] = int(graph.arcs[v].size())) == 1) leaves.push_back(int(v));
  while(!leaves.empty())
  {
    const int v = leaves.back();
    leaves.pop_back();
    for(const auto& arc : graph.arcs[v])
      if(in_graph[arc.edge])
      {
        in_graph[arc.edge] = 0;
        --degree[v];
        if(--degree[arc.to] == 1) leaves.push_back(arc.to);
      }
  }
  for(std::size_t e = 0; e < in_graph.size(); ++e)
    if(in_graph[e]) is_cut[e] = 1;
}

/// Adds cuts so that every chart of the surface cut along `is_cut` is a
/// topological disk. Returns false if some chart still is not (which the
/// construction rules out for manifold input).
template <typename Surface>
bool make_disks(const Surface& surface, std::vector<char>& is_cut)
{
  Chart_mesh chart;
  std::vector<int> corner_uv;
  build_chart_mesh(surface, is_cut, chart, corner_uv);
  const Chart_topology topology = chart_topology(chart);
  std::vector<std::vector<int>> faces_of_chart(topology.number_of_charts);
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f) faces_of_chart[topology.chart_of_face[f]].push_back(int(f));
  for(int c = 0; c < topology.number_of_charts; ++c)
  {
    if(topology.is_disk(c)) continue;
    if(topology.loops[c] == 0 && topology.euler[c] == 2)
      cut_diameter_path(surface, faces_of_chart[c], is_cut);
    else
      cut_graph(surface, faces_of_chart[c], is_cut);
  }
  build_chart_mesh(surface, is_cut, chart, corner_uv);
  const Chart_topology result = chart_topology(chart);
  for(int c = 0; c < result.number_of_charts; ++c)
    if(!result.is_disk(c)) return false;
  return true;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
