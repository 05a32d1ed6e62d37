// Cutting the mesh: the initial cut (make_disks()), more cuts on a map
// state (apply_cuts()), charts cut into overlap-free pieces
// (cut_into_overlap_free_pieces()), the map carried over each time.
//
// Initial cut: makes every connected component of the cut mesh a
// topological disk, with short cuts, so that the joint optimization can
// start from a Tutte embedding.
//
// - A component that is already a disk is left alone.
// - Otherwise a tree-cotree decomposition cuts short loops through the
//   handles and short paths joining the boundary loops (see cut_graph()).
// - A closed genus-0 component needs no loop: it is opened along a path
//   between two far-apart vertices (two Dijkstra sweeps), from which the
//   optimization grows its seams.
//
// Forbidden edges (per surface edge; an empty vector: none) are never cut:
// the paths avoid them, the tree of the tree-cotree decomposition takes one
// only where a vertex cannot be reached otherwise, and the cotree takes them
// first. A forbidden edge left out of the cotree closes a dual cycle of
// forbidden edges that no cut graph can avoid (the cycle is non-separating,
// since the tree reaches both its sides), so make_disks() then fails rather
// than cut it.
#ifndef CGAL_SMP_CUT_INTERNAL_CUT_MESH_H
#define CGAL_SMP_CUT_INTERNAL_CUT_MESH_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Edge_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_paths.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>

#include <algorithm>
#include <cmath>
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

/// Edge graph on the surface's vertices, with the edges flagged in `use_edge`
/// weighted by their cost (`rules`), plus `penalty` for the forbidden ones.
template <typename Surface>
Edge_graph surface_edge_graph(const Surface& surface, const std::vector<char>& use_edge,
                              const Cut_rules& rules = Cut_rules(), double penalty = 0.)
{
  Edge_graph graph(surface.number_of_vertices());
  std::vector<char> added(surface.edges.size(), 0);
  for(int fe = 0; fe < int(surface.edge_of.size()); ++fe)
  {
    const int e = surface.edge_of[fe];
    if(!use_edge[e] || added[e]) continue;
    added[e] = 1;
    graph.add_edge(surface.edge_source(fe), surface.edge_target(fe), e,
                   rules.cost(surface, fe) + (rules.is_forbidden(e) ? penalty : 0.));
  }
  return graph;
}

/// Cuts a path between two far-apart vertices of the faces in
/// `component_faces`, on edges that are not forbidden. Returns false if no
/// such path of two edges or more exists.
template <typename Surface>
bool cut_diameter_path(const Surface& surface, const std::vector<int>& component_faces,
                       const Cut_rules& rules, std::vector<char>& is_cut)
{
  std::vector<char> usable(surface.edges.size(), 0);
  int start = -1;
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k)
    {
      const int e = surface.edge_of[3*f + k];
      if(rules.is_forbidden(e)) continue;
      usable[e] = 1;
      if(start < 0) start = surface.edge_source(3*f + k);
    }
  if(start < 0) return false;
  const Edge_graph graph = surface_edge_graph(surface, usable, rules);
  const int a = graph.shortest_paths({start}).farthest();
  const Shortest_paths from_a = graph.shortest_paths({a});
  const int b = from_a.farthest();
  std::vector<int> path = from_a.path_edges(b);
  // a single cut edge opens a two-sided hole, not a disk with a usable border
  if(path.size() < 2)
    for(int end : {b, a})
      for(const auto& arc : graph.arcs(end))
        if(path.size() < 2 && (path.empty() || arc.edge != path.front())) path.push_back(arc.edge);
  if(path.size() < 2) return false;
  for(int e : path) is_cut[e] = 1;
  return true;
}

/// Cut graph of the faces in `component_faces` (see the file comment), by
/// a tree-cotree decomposition with greedy short loops (Erickson and
/// Whittlesey 2005): T = shortest-path forest from the cut mesh's boundary
/// (or from one root on a closed surface), C = dual spanning tree keeping
/// the longest loops uncut, and every edge in neither closes a loop
/// (through a handle, or joining two boundary loops) that is cut along T.
/// With forbidden edges (see the file comment) T uses them last and C first;
/// returns false if a loop to cut contains one.
template <typename Surface>
bool cut_graph(const Surface& surface, const std::vector<int>& component_faces,
               const Cut_rules& rules, std::vector<char>& is_cut)
{
  const std::vector<char> on_boundary = cut_boundary_vertices(surface, is_cut);
  std::vector<char> interior(surface.edges.size(), 0);
  std::vector<int> sources;
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k)
    {
      const int fe = 3*f + k;
      if(surface.twin[fe] >= 0 && !is_cut[surface.edge_of[fe]]) interior[surface.edge_of[fe]] = 1;
      if(on_boundary[surface.edge_source(fe)]) sources.push_back(surface.edge_source(fe));
    }
  if(sources.empty()) sources.push_back(surface.corner_vertex[component_faces.front()][0]);
  // a forbidden edge costs more than any path of allowed edges
  double penalty = 0.;
  if(!rules.forbidden.empty())
    for(int f : component_faces)
      for(int k = 0; k < 3; ++k) penalty += rules.cost(surface, 3*f + k);
  const Shortest_paths tree = surface_edge_graph(surface, interior, rules, penalty).shortest_paths(sources);
  std::vector<char> in_tree(surface.edges.size(), 0);
  for(int e : tree.parent_edge) if(e >= 0) in_tree[e] = 1;

  // cotree: Kruskal on the dual, longest loops first
  std::vector<int> candidates; // one face-edge per interior non-tree edge
  for(int f : component_faces)
    for(int k = 0; k < 3; ++k)
    {
      const int fe = 3*f + k;
      if(surface.twin[fe] > fe && interior[surface.edge_of[fe]] && !in_tree[surface.edge_of[fe]])
        candidates.push_back(fe);
    }
  auto loop_length = [&](int fe) {
    return tree.distance[surface.edge_source(fe)] + rules.cost(surface, fe) + tree.distance[surface.edge_target(fe)]; };
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) {
    const bool fa = rules.is_forbidden(surface.edge_of[a]), fb = rules.is_forbidden(surface.edge_of[b]);
    return fa != fb ? fa : loop_length(a) > loop_length(b); });
  std::vector<int> face_parent(surface.number_of_faces());
  std::iota(face_parent.begin(), face_parent.end(), 0);
  auto find = [&](int x) { while(face_parent[x] != x) x = face_parent[x] = face_parent[face_parent[x]]; return x; };
  for(int fe : candidates)
  {
    const int a = find(fe / 3), b = find(surface.twin[fe] / 3);
    if(a == b)
    { // closes a loop: cut it
      std::vector<int> loop{surface.edge_of[fe]};
      for(int end : {surface.edge_source(fe), surface.edge_target(fe)})
        for(int e : tree.path_edges(end)) loop.push_back(e);
      for(int e : loop)
      {
        if(rules.is_forbidden(e)) return false;
        is_cut[e] = 1;
      }
    }
    else
      face_parent[a] = b;
  }
  return true;
}

/// Joins each lone cut edge to the rest of the cut: an inner cut edge whose
/// two ends are inner vertices on no other cut edge (a seam given by the
/// user, for example) leaves the corners on its two sides joined at both
/// ends, so no map can open it, yet it would count as a seam. The cheapest
/// path of edges that are not forbidden (`rules`) from one of its ends to a
/// border or another cut is cut with it. Returns false if one cannot reach
/// any (a component with no border and no other cut).
template <typename Surface>
bool join_lone_cut_edges(const Surface& surface, std::vector<char>& is_cut, const Cut_rules& rules)
{
  const int nv = int(surface.number_of_vertices());
  std::vector<int> cut_degree(nv, 0);
  const std::vector<char> on_border = surface.border_vertices();
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe);
    if(is_cut[surface.edge_of[fe]] && (surface.twin[fe] < 0 || fe < surface.twin[fe])) { ++cut_degree[a]; ++cut_degree[b]; }
  }
  auto lone_end = [&](int v) { return cut_degree[v] == 1 && !on_border[v]; };
  std::vector<int> lone; // one face-edge per lone cut edge
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] > fe && is_cut[surface.edge_of[fe]] && lone_end(surface.edge_source(fe))
       && lone_end(surface.edge_target(fe)))
      lone.push_back(fe);
  if(lone.empty()) return true;
  std::vector<char> is_lone_end(nv, 0);
  for(int fe : lone) is_lone_end[surface.edge_source(fe)] = is_lone_end[surface.edge_target(fe)] = 1;
  std::vector<int> sources;
  for(int v = 0; v < nv; ++v)
    if((on_border[v] || cut_degree[v] > 0) && !is_lone_end[v]) sources.push_back(v);
  std::vector<char> usable(surface.edges.size(), 0);
  for(std::size_t e = 0; e < usable.size(); ++e) usable[e] = !rules.is_forbidden(int(e));
  const Shortest_paths paths = surface_edge_graph(surface, usable, rules).shortest_paths(sources);
  for(int fe : lone)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe);
    const int end = paths.distance[a] <= paths.distance[b] ? a : b;
    if(!std::isfinite(paths.distance[end])) return false;
    for(int e : paths.path_edges(end)) is_cut[e] = 1;
  }
  return true;
}

/// Adds cuts, as cheap as `rules` make them and never on a forbidden edge,
/// so that every chart of the surface cut along `is_cut` is a topological
/// disk and every cut edge opens (join_lone_cut_edges()). Returns false if
/// some chart still is not (which the construction rules out for manifold
/// input without forbidden edges) or a forbidden edge
/// would have to be cut; `is_cut` may then hold part of the cuts.
template <typename Surface>
bool make_disks(const Surface& surface, std::vector<char>& is_cut, const Cut_rules& rules = Cut_rules())
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
    const bool done = topology.loops[c] == 0 && topology.euler[c] == 2
                        ? cut_diameter_path(surface, faces_of_chart[c], rules, is_cut)
                        : cut_graph(surface, faces_of_chart[c], rules, is_cut);
    if(!done) return false;
  }
  if(!join_lone_cut_edges(surface, is_cut, rules)) return false;
  for(std::size_t e = 0; e < rules.forbidden.size(); ++e)
    if(is_cut[e] && rules.forbidden[e]) return false;
  build_chart_mesh(surface, is_cut, chart, corner_uv);
  const Chart_topology result = chart_topology(chart);
  for(int c = 0; c < result.number_of_charts; ++c)
    if(!result.is_disk(c)) return false;
  return true;
}

/// Rebuilds the chart mesh of `state` from `state.is_cut`, which holds the
/// cuts of the current chart mesh and maybe more, and carries the UVs over:
/// both sides of a new cut start where the uncut vertex was, so the map
/// stays flip-free.
template <typename Surface>
void rebuild_cut_mesh(const Surface& surface, Map_state& state)
{
  const std::vector<int> old_corner_uv = state.corner_uv;
  const UV_vector old_x = state.x;
  build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  state.x.resize(2 * state.chart.number_of_vertices);
  for(std::size_t c = 0; c < old_corner_uv.size(); ++c)
    state.x.template segment<2>(2 * state.corner_uv[c]) = old_x.template segment<2>(2 * old_corner_uv[c]);
}

/// Cuts the edges of `paths`, then joins any closed slit (a path that does
/// not reach the boundary) to the boundary by a short path, so every chart
/// stays a topological disk (make_disks()). Rebuilds the chart mesh and
/// carries the UVs over (rebuild_cut_mesh()). With forbidden edges, a slit
/// may have no way to the boundary: then the paths are taken one at a time,
/// and those whose slit cannot be opened are left out.
template <typename Surface>
void apply_cuts(const Surface& surface, const std::vector<Cut_path>& paths, Map_state& state)
{
  const std::vector<char> before = state.is_cut;
  for(const Cut_path& path : paths)
    for(int e : path.edges) state.is_cut[e] = 1;
  if(!make_disks(surface, state.is_cut, state.rules))
  {
    state.is_cut = before;
    for(const Cut_path& path : paths)
    {
      std::vector<char> trial = state.is_cut;
      for(int e : path.edges) trial[e] = 1;
      if(make_disks(surface, trial, state.rules)) state.is_cut.swap(trial);
    }
  }
  rebuild_cut_mesh(surface, state);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
