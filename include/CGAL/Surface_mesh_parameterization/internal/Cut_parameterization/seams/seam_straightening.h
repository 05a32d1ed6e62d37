// Seams rerouted along shorter edge paths in their corridor. The cuts that
// the field v opens follow its low band through the mesh's edges, and edge
// paths zigzag: the same seam, taken along the shortest edge path between
// its ends within a few rings of where it runs, costs less seam length for
// almost the same distortion (the map is solved again and judged by the
// caller).
//
// The seams are split into paths between nodes: vertices where the seam
// graph branches or ends, vertices on the mesh border, and vertices of
// seams the user gave (never moved). Each path is replaced by the cheapest
// path (Cut_rules: the λ map, forbidden edges) between its two end nodes
// through the vertices within `rings` rings of it that touch no other seam
// and no border; the replacement is kept if it is cheaper and every chart
// is still a disk, with the same number of charts. Optionally, a path from
// the mesh border to a node off it may also end elsewhere on the border:
// at the border vertex of its corridor, on no other seam, that its inner
// end reaches most cheaply.
#ifndef CGAL_SMP_CUT_INTERNAL_SEAM_STRAIGHTENING_H
#define CGAL_SMP_CUT_INTERNAL_SEAM_STRAIGHTENING_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Cut_rules.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Edge_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_paths.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Reroutes the seams of `is_cut` (see the file's comment); the edges
/// flagged in `keep` stay as they are; with `slide_border_ends`, the ends
/// of paths from the mesh border may move along it. Returns the number of
/// paths rerouted.
template <typename Surface>
int straighten_seams(const Surface& surface, const Cut_rules& rules, const std::vector<char>& keep, int rings,
                     std::vector<char>& is_cut, bool slide_border_ends = false)
{
  const int nv = int(surface.number_of_vertices());
  const std::vector<char> on_border = surface.border_vertices();
  std::vector<std::vector<int>> neighbors(nv);
  std::vector<char> on_old(surface.edges.size(), 0);
  std::vector<std::vector<int>> edges_around(nv); // face-edges leaving each vertex
  std::vector<int> face_edge_of(surface.edges.size(), -1);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe);
    if(surface.twin[fe] < fe) // each edge once
    {
      neighbors[a].push_back(b);
      neighbors[b].push_back(a);
    }
    edges_around[a].push_back(fe);
    if(face_edge_of[surface.edge_of[fe]] < 0) face_edge_of[surface.edge_of[fe]] = fe;
  }
  auto charts_are_disks = [&](const std::vector<char>& cut, int& charts) {
    Chart_mesh chart;
    std::vector<int> corner_uv;
    build_chart_mesh(surface, cut, chart, corner_uv);
    const Chart_topology topology = chart_topology(chart);
    charts = topology.number_of_charts;
    for(int c = 0; c < topology.number_of_charts; ++c)
      if(!topology.is_disk(c)) return false;
    return true;
  };
  int charts_before = 0;
  if(!charts_are_disks(is_cut, charts_before)) return 0;

  int rerouted = 0;
  std::vector<int> ring_of(nv, -1);
  Shortest_paths scratch;
  for(const Seam_path& old_path : seam_paths(surface, is_cut, keep))
  {
    const int s = old_path.vertices.front(), t = old_path.vertices.back();
    if(s == t || old_path.edges.size() < 2) continue;
    // the corridor: vertices within `rings` rings of the path
    std::vector<int> corridor = old_path.vertices;
    for(int v : corridor) ring_of[v] = 0;
    for(std::size_t i = 0; i < corridor.size(); ++i)
    {
      const int v = corridor[i];
      if(ring_of[v] >= rings) continue;
      for(int w : neighbors[v])
        if(ring_of[w] < 0)
        {
          ring_of[w] = ring_of[v] + 1;
          corridor.push_back(w);
        }
    }
    // the vertices a new path may use: in the corridor, on no other seam, off the
    // border (the nodes of the seam graph include the border's vertices)
    std::vector<char> on_this_path(nv, 0);
    for(int v : old_path.vertices) on_this_path[v] = 1;
    for(int e : old_path.edges) on_old[e] = 1;
    const Seam_graph g = seam_graph(surface, is_cut, keep);
    // with `slide_border_ends`, a path from the mesh border to a vertex off it
    // may end at any border vertex of its corridor on no other seam: it runs
    // from its inner end to a sink joined to those vertices' interior edges
    const bool slide = slide_border_ends && on_border[s] != on_border[t];
    const int border_end = on_border[s] ? s : t, inner_end = on_border[s] ? t : s;
    auto usable = [&](int v) {
      if(slide && v == border_end) return false;
      if(v == s || v == t) return true;
      if(ring_of[v] < 0 || g.node[v]) return false;
      return g.arcs[v].empty() || on_this_path[v];
    };
    // an interior edge that may be cut: not forbidden, not on another seam
    auto open = [&](int fe) {
      const int e = surface.edge_of[fe];
      return surface.twin[fe] >= 0 && !rules.is_forbidden(e) && (!is_cut[e] || on_old[e]);
    };
    Edge_graph graph(nv);
    for(int v : corridor)
      for(int fe : edges_around[v])
      {
        const int w = surface.edge_target(fe);
        if(v < w && ring_of[w] >= 0 && open(fe) && usable(v) && usable(w))
          graph.add_edge(v, w, surface.edge_of[fe], rules.cost(surface, fe));
      }
    int sink = -1;
    if(slide)
    {
      auto on_a_seam = [&](int v) { // the user's seams included
        for(int fe : edges_around[v])
          if(is_cut[surface.edge_of[fe]]) return true;
        return false;
      };
      sink = graph.add_vertex();
      for(int v : corridor)
        for(int fe : edges_around[v])
        {
          const int b = surface.edge_target(fe);
          if(on_border[b] && ring_of[b] >= 0 && (b == border_end || !on_a_seam(b)) && !on_border[v] && open(fe)
             && usable(v))
            graph.add_edge(v, sink, surface.edge_of[fe], rules.cost(surface, fe));
        }
    }
    for(int v : corridor) ring_of[v] = -1;
    // (scratch is resized where the graph has a sink)
    const std::vector<int> new_edges = slide ? graph.shortest_path(inner_end, sink, scratch) : graph.shortest_path(s, t, scratch);
    for(int e : old_path.edges) on_old[e] = 0;
    if(new_edges.empty()) continue;
    double old_cost = 0., new_cost = 0.;
    for(int e : old_path.edges) old_cost += rules.cost(surface, face_edge_of[e]);
    for(int e : new_edges) new_cost += rules.cost(surface, face_edge_of[e]);
    if(!(new_cost < (1. - 1e-9) * old_cost)) continue;
    std::vector<char> trial = is_cut;
    for(int e : old_path.edges) trial[e] = 0;
    for(int e : new_edges) trial[e] = 1;
    int charts_after = 0;
    if(!charts_are_disks(trial, charts_after) || charts_after != charts_before) continue;
    is_cut.swap(trial);
    ++rerouted;
  }
  return rerouted;
}

/// `rerouted` becomes the cut mesh of the seams of `state` rerouted by
/// straighten_seams() (`keep`, `rings`, `slide`: as there), with a Tutte map;
/// false if no path was rerouted or the Tutte map failed.
template <typename Surface>
bool rerouted_cut_mesh(const Surface& surface, const Map_state& state, const std::vector<char>& keep, int rings,
                       bool slide, Map_state& rerouted)
{
  rerouted.is_cut = state.is_cut;
  if(straighten_seams(surface, state.rules, keep, rings, rerouted.is_cut, slide) == 0) return false;
  build_chart_mesh(surface, rerouted.is_cut, rerouted.chart, rerouted.corner_uv);
  return disk_charts_embedding(rerouted.chart, rerouted.x) == Embedding_status::OK;
}

/// Seams of the solved cut mesh in `state`, whose E_d is within `bound`,
/// rerouted along shorter paths within `rings` rings, the map solved again
/// from a Tutte map by `solve_within_bound(from_tutte_map, candidate, state,
/// log, kept)`, which keeps it if its E_d is within the bound. Then once
/// more with the ends of the seams on the mesh border free to slide along
/// it: a second step, so that a slide that breaks the bound cannot undo the
/// reroutes.
template <typename Surface, typename Solve_within_bound>
Error_code straighten_under_bound(const Surface& surface, double bound, int rings, const std::vector<char>& keep,
                                  Solve_within_bound solve_within_bound, Map_state& state, Work_log& log)
{
  if(rings <= 0 || !(bound > 0.) || state.distortion > bound) return OK;
  for(bool slide : {false, true})
  {
    Map_state candidate = state;
    if(!rerouted_cut_mesh(surface, state, keep, rings, slide, candidate)) continue;
    bool kept = false;
    const Error_code status = solve_within_bound(true, std::move(candidate), state, log, kept);
    if(status != OK) return status;
  }
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
