// A weighted graph on mesh edges (vertices are integers, each arc remembers
// the mesh edge it stands for) with multi-source Dijkstra: the one shortest
// path engine of the initial cut and of the cut extraction.
#ifndef CGAL_SMP_CUT_INTERNAL_EDGE_GRAPH_H
#define CGAL_SMP_CUT_INTERNAL_EDGE_GRAPH_H

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Shortest_paths
{
  std::vector<double> distance;  // +inf where unreached
  std::vector<int> parent;       // -1 for sources and unreached vertices
  std::vector<int> parent_edge;  // mesh edge from the parent

  /// Reached vertex with the largest distance (-1 if none).
  int farthest() const
  {
    int best = -1;
    for(int i = 0; i < int(distance.size()); ++i)
      if(std::isfinite(distance[i]) && (best < 0 || distance[i] > distance[best])) best = i;
    return best;
  }

  /// Mesh edges of the path from v back to its source.
  std::vector<int> path_edges(int v) const
  {
    std::vector<int> edges;
    for(; parent[v] >= 0; v = parent[v]) edges.push_back(parent_edge[v]);
    return edges;
  }
};

class Edge_graph
{
public:
  struct Arc { int to, edge; double weight; };

  explicit Edge_graph(std::size_t number_of_vertices = 0) : arcs_(number_of_vertices) {}

  int add_vertex()
  {
    arcs_.emplace_back();
    return int(arcs_.size()) - 1;
  }

  void add_edge(int a, int b, int edge, double weight)
  {
    arcs_[a].push_back({b, edge, weight});
    arcs_[b].push_back({a, edge, weight});
  }

  std::size_t number_of_vertices() const { return arcs_.size(); }
  const std::vector<Arc>& arcs(int v) const { return arcs_[v]; }

  /// Dijkstra from `sources`, all at distance 0.
  Shortest_paths shortest_paths(const std::vector<int>& sources) const
  {
    Shortest_paths result;
    result.distance.assign(arcs_.size(), std::numeric_limits<double>::infinity());
    result.parent.assign(arcs_.size(), -1);
    result.parent_edge.assign(arcs_.size(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for(int s : sources)
    {
      result.distance[s] = 0.;
      queue.push({0., s});
    }
    while(!queue.empty())
    {
      const auto [d, u] = queue.top();
      queue.pop();
      if(d > result.distance[u]) continue;
      for(const Arc& arc : arcs_[u])
        if(d + arc.weight < result.distance[arc.to])
        {
          result.distance[arc.to] = d + arc.weight;
          result.parent[arc.to] = u;
          result.parent_edge[arc.to] = arc.edge;
          queue.push({result.distance[arc.to], arc.to});
        }
    }
    return result;
  }

  /// Mesh edges of a shortest path from `s` to `t` (empty if `t` is not
  /// reachable or `s == t`). The search stops once `t` is settled, and
  /// `scratch` keeps its arrays between calls, so that many short paths on a
  /// large graph cost what they explore, not the size of the graph.
  std::vector<int> shortest_path(int s, int t, Shortest_paths& scratch) const
  {
    if(scratch.distance.size() != arcs_.size())
    {
      scratch.distance.assign(arcs_.size(), std::numeric_limits<double>::infinity());
      scratch.parent.assign(arcs_.size(), -1);
      scratch.parent_edge.assign(arcs_.size(), -1);
    }
    std::vector<int> touched{s};
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    scratch.distance[s] = 0.;
    queue.push({0., s});
    while(!queue.empty())
    {
      const auto [d, u] = queue.top();
      queue.pop();
      if(u == t) break;
      if(d > scratch.distance[u]) continue;
      for(const Arc& arc : arcs_[u])
        if(d + arc.weight < scratch.distance[arc.to])
        {
          if(!std::isfinite(scratch.distance[arc.to])) touched.push_back(arc.to);
          scratch.distance[arc.to] = d + arc.weight;
          scratch.parent[arc.to] = u;
          scratch.parent_edge[arc.to] = arc.edge;
          queue.push({scratch.distance[arc.to], arc.to});
        }
    }
    std::vector<int> edges;
    if(std::isfinite(scratch.distance[t])) edges = scratch.path_edges(t);
    for(int v : touched)
    {
      scratch.distance[v] = std::numeric_limits<double>::infinity();
      scratch.parent[v] = -1;
      scratch.parent_edge[v] = -1;
    }
    return edges;
  }

private:
  std::vector<std::vector<Arc>> arcs_;
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
