// Cuts added one at a time where the map is most distorted (the split step
// of OptCuts, Li et al. 2018, on paths instead of single edges): for the
// inputs where the field v cannot say where to cut (faces so large that one
// face spans a whole feature: low-poly models, whose curvature sits in a few
// vertices), and to reach a distortion bound that the seam cost λ alone
// cannot reach.
//
// One split: the vertex off the seams around which the map is the most
// distorted (the area-weighted excess of E_d over 4 of its faces) is joined
// to the boundary of the cut mesh by its cheapest path of uncut, allowed
// edges; the map carried over the new cut is solved again (by the caller).
// A split is kept if the rule of the caller accepts the distortion it
// leaves for the seam length it adds; the first few most distorted vertices
// are tried in turn (the first accepted is kept), or all of them (the one
// that lowers E_d the most per unit of seam length added is kept), and the
// splits stop when none is accepted.
#ifndef CGAL_SMP_CUT_INTERNAL_GREEDY_SPLITS_H
#define CGAL_SMP_CUT_INTERNAL_GREEDY_SPLITS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Joint_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// How far the splits go (the defaults are what `cut_and_parameterize()` uses).
struct Split_settings
{
  int max_splits = 64;     // splits kept at most
  int candidates = 3;      // most distorted vertices tried per split
  int newton_iterations = 30; // Newton iterations that judge a split
  // false: the first accepted candidate is kept; true: every candidate is
  // judged, and the one with the largest E_d decrease per unit of seam
  // length added is kept
  bool best_candidate = false;
};

/// Per surface vertex: Σ A_f (e_f − 4) / 3 over its faces, e_f the E_d
/// integrand of face f in the map `x` of the chart mesh.
template <typename Surface>
std::vector<double> vertex_distortion_excess(const Surface& surface, const Chart_mesh& chart, const UV_vector& x)
{
  std::vector<double> excess(surface.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
  {
    const double e = chart.area[f] * (symmetric_dirichlet_measure(chart.jacobian(x, f)) - 4.) / 3.;
    for(int v : surface.corner_vertex[f]) excess[v] += e;
  }
  return excess;
}

/// Cheapest paths (cost of `rules`) from the boundary of the cut mesh over
/// uncut edges that are not forbidden.
struct Boundary_paths
{
  Edge_graph graph;
  Shortest_paths paths;

  /// Edges of a cheapest path from `v` to the boundary (empty if `v` is on
  /// it or cannot reach it). Where several paths cost the same up to
  /// rounding (a symmetric mesh), the one through the lowest vertex indices
  /// is taken, so that the choice does not depend on the mesh's scale.
  std::vector<int> path_edges(int v) const
  {
    std::vector<int> edges;
    const std::vector<double>& d = paths.distance;
    while(std::isfinite(d[v]) && d[v] > 0.)
    {
      int next = -1, edge = -1;
      for(const Edge_graph::Arc& arc : graph.arcs(v))
        if(d[arc.to] < d[v] && d[arc.to] + arc.weight <= d[v] * (1. + 1e-9) && (next < 0 || arc.to < next))
        {
          next = arc.to;
          edge = arc.edge;
        }
      if(next < 0) { next = paths.parent[v]; edge = paths.parent_edge[v]; }
      if(next < 0) break;
      edges.push_back(edge);
      v = next;
    }
    return edges;
  }
};

template <typename Surface>
Boundary_paths paths_to_cut_boundary(const Surface& surface, const std::vector<char>& is_cut, const Cut_rules& rules)
{
  std::vector<char> usable(surface.edges.size(), 0);
  for(std::size_t e = 0; e < usable.size(); ++e) usable[e] = !is_cut[e] && !rules.is_forbidden(int(e));
  const std::vector<char> on_boundary = cut_boundary_vertices(surface, is_cut);
  std::vector<int> sources;
  for(int v = 0; v < int(on_boundary.size()); ++v)
    if(on_boundary[v]) sources.push_back(v);
  Boundary_paths result{surface_edge_graph(surface, usable, rules), {}};
  result.paths = result.graph.shortest_paths(sources);
  return result;
}

/// Splits `state` (a solved cut mesh, `state.distortion` its E_d) while its
/// E_d is above `stop_at` and `accept(E_d before, E_d after, E_s added)`
/// takes a split; `solve(state)` solves a trial and sets its `distortion`.
/// Returns OK or the first error of a solve (then `state` is the last
/// accepted one); `kept` counts the splits kept.
template <typename Surface, typename Solve, typename Accept>
Error_code split_greedily(const Surface& surface, const Split_settings& split, double stop_at, Solve solve,
                          Accept accept, Joint_state& state, int& kept)
{
  const double total_area = std::accumulate(state.chart.area.begin(), state.chart.area.end(), 0.);
  const double unit = std::sqrt(total_area / M_PI); // E_s is a length over this
  for(kept = 0; kept < split.max_splits && state.distortion > stop_at; ++kept)
  {
    const double seams = seam_length_3d(surface, state.is_cut);
    const std::vector<double> excess = vertex_distortion_excess(surface, state.chart, state.x);
    const Boundary_paths boundary = paths_to_cut_boundary(surface, state.is_cut, state.rules);
    // ranked by excess rounded to 1e-9 of the largest, then by index: on a
    // symmetric mesh, equal excesses differ by rounding alone, which must not
    // pick the vertex (the same cuts at any scale of the mesh)
    const double largest = *std::max_element(excess.begin(), excess.end());
    std::vector<int> order;
    std::vector<double> rank(excess.size(), 0.);
    for(int v = 0; v < int(excess.size()); ++v)
      if(boundary.paths.parent[v] >= 0 && excess[v] > 0.) // off the boundary, and reachable
      {
        order.push_back(v);
        rank[v] = std::round(1e9 * excess[v] / largest);
      }
    const std::size_t tried = (std::min)(order.size(), std::size_t(split.candidates));
    std::partial_sort(order.begin(), order.begin() + tried, order.end(), [&](int a, int b) {
      return rank[a] > rank[b] || (rank[a] == rank[b] && a < b);
    });
    Joint_state best;
    double best_gain = -1.; // E_d decrease per unit of E_s added of `best`
    // the trial of candidate i: `state` cut along its path, solved
    auto judge = [&](std::size_t i, Joint_state& trial) {
      Cut_path path{boundary.path_edges(order[i]), 0.};
      trial = state;
      trial.newton_iterations = trial.factorizations = 0; // its own work
      apply_cuts(surface, {path}, trial);
      return solve(trial);
    };
    // its work counted whatever is kept, then kept if it is accepted and the best so far
    auto weigh = [&](Joint_state& trial) {
      state.newton_iterations += trial.newton_iterations;
      state.factorizations += trial.factorizations;
      const double added = (seam_length_3d(surface, trial.is_cut) - seams) / unit;
      // (a path whose cut could not keep the charts disks is not cut: added 0)
      if(added > 0. && accept(state.distortion, trial.distortion, added))
      {
        const double gain = (state.distortion - trial.distortion) / added;
        if(gain > best_gain)
        {
          best_gain = gain;
          best = std::move(trial);
        }
      }
    };
    if(split.best_candidate)
    {
      // every candidate is judged: all at once (each its own task; they read
      // `state` only), read in order, so that the choice does not depend on
      // the number of threads. In the bound search this fills the core that
      // the other split trial leaves once done: under OptCuts' 11 bounds
      // (2 cores), 0.78-0.98x the time (bimba_i_f10000 26.9 -> 22.6 s,
      // circular_box_o_f20000 63.8 -> 53.7 s), the same seams.
      std::vector<Joint_state> trials(tried);
      std::vector<Error_code> statuses(tried, OK);
      parallel_tasks(tried, [&](std::size_t i) { statuses[i] = judge(i, trials[i]); });
      for(std::size_t i = 0; i < tried; ++i)
      {
        if(statuses[i] != OK) return statuses[i];
        weigh(trials[i]);
      }
    }
    else
      for(std::size_t i = 0; i < tried && best_gain < 0.; ++i)
      {
        Joint_state trial;
        const Error_code status = judge(i, trial);
        if(status != OK) return status;
        weigh(trial);
      }
    const bool split_kept = best_gain >= 0.;
    if(split_kept)
    {
      best.newton_iterations = state.newton_iterations;
      best.factorizations = state.factorizations;
      state = std::move(best);
    }
    if(!split_kept) break;
  }
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
