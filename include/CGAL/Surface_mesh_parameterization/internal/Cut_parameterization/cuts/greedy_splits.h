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
// that lowers E_d the most per unit of seam length added is kept; those
// judged at an earlier split only where they can still win), and the
// splits stop when none is accepted. On large meshes, where each trial is a
// solve of the whole map, a batch of candidates whose paths do not meet is
// tried first, all cut in one trial (Split_settings::batch).
#ifndef CGAL_SMP_CUT_INTERNAL_GREEDY_SPLITS_H
#define CGAL_SMP_CUT_INTERNAL_GREEDY_SPLITS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/vertex_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// How far the splits go (the defaults: tuning.h).
struct Split_settings
{
  int max_splits = tuning::split_max_splits;             // splits kept at most
  int candidates = tuning::split_candidates;             // most distorted vertices tried per split
  int newton_iterations = tuning::split_newton_iterations; // Newton iterations that judge a split
  // false: the first accepted candidate is kept; true: every candidate is
  // judged, and the one with the largest E_d decrease per unit of seam
  // length added is kept
  bool best_candidate = false;
  // more than 1: each split first tries this many of the most distorted
  // vertices at once (paths apart, one trial: large meshes); if that is not
  // accepted, the candidates are tried one at a time as above
  int batch = 1;
  // without a bound, a split pays for its seams if it lowers E_d by at least
  // this per unit of E_s it adds
  double gain = tuning::split_gain;
};

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

/// The candidates among `order` (ranked, most distorted first; `paths`
/// their paths to the boundary, all empty at first and found here) cut
/// together by a batch split: at most `batch` of the first 4 × `batch`,
/// each path's vertices off every path taken before it (the boundary
/// vertices aside), so that the cuts do not meet.
template <typename Surface>
std::vector<std::size_t> batch_candidates(const Surface& surface, const std::vector<int>& order, int batch,
                                          const Boundary_paths& boundary, std::vector<Cut_path>& paths)
{
  std::vector<int> face_edge_of(surface.edges.size(), -1);
  for(int fe = 0; fe < int(surface.edge_of.size()); ++fe) face_edge_of[surface.edge_of[fe]] = fe;
  std::vector<char> taken(surface.number_of_vertices(), 0);
  std::vector<std::size_t> chosen;
  const std::size_t looked_at = (std::min)(order.size(), std::size_t(4 * batch));
  for(std::size_t i = 0; i < looked_at && int(chosen.size()) < batch; ++i)
  {
    if(paths[i].edges.empty()) paths[i].edges = boundary.path_edges(order[i]);
    std::vector<int> inner; // the path's vertices off the boundary
    for(int e : paths[i].edges)
      for(int v : {surface.edge_source(face_edge_of[e]), surface.edge_target(face_edge_of[e])})
        if(boundary.paths.distance[v] > 0.) inner.push_back(v);
    if(paths[i].edges.empty() || std::any_of(inner.begin(), inner.end(), [&](int v) { return taken[v] != 0; }))
      continue;
    for(int v : inner) taken[v] = 1;
    chosen.push_back(i);
  }
  return chosen;
}

/// The faces of `surface` on an edge cut in `after` but not in `before`.
template <typename Surface>
std::vector<char> faces_on_new_cuts(const Surface& surface, const std::vector<char>& before,
                                    const std::vector<char>& after)
{
  std::vector<char> flagged(surface.number_of_faces(), 0);
  for(int fe = 0; fe < int(surface.edge_of.size()); ++fe)
  {
    const int e = surface.edge_of[fe];
    if(after[e] && !before[e]) flagged[fe / 3] = 1;
  }
  return flagged;
}

/// The candidates of one split: surface vertices ranked most distorted
/// first, the first `tried` judged one at a time, and their paths to the
/// boundary (found when needed).
struct Split_candidates
{
  std::vector<int> order;
  std::size_t tried = 0;
  std::vector<Cut_path> paths;
};

/// The vertices off the boundary of the cut mesh, reachable from it, where
/// the map of `state` is distorted, ranked (ties by index, so that the
/// ranking does not depend on rounding).
template <typename Surface>
Split_candidates rank_split_candidates(const Surface& surface, const Split_settings& split, const Map_state& state,
                                       const Boundary_paths& boundary)
{
  const std::vector<double> excess = vertex_distortion_excess(surface, state.chart, state.x);
  const double largest = *std::max_element(excess.begin(), excess.end());
  Split_candidates c;
  std::vector<double> rank(excess.size(), 0.);
  for(int v = 0; v < int(excess.size()); ++v)
    if(boundary.paths.parent[v] >= 0 && excess[v] > 0.) // off the boundary, and reachable
    {
      c.order.push_back(v);
      rank[v] = std::round(1e9 * excess[v] / largest);
    }
  const std::size_t ranked = (std::min)(c.order.size(), std::size_t((std::max)(split.candidates, 4 * split.batch)));
  c.tried = (std::min)(c.order.size(), std::size_t(split.candidates));
  std::partial_sort(c.order.begin(), c.order.begin() + ranked, c.order.end(), [&](int a, int b) {
    return rank[a] > rank[b] || (rank[a] == rank[b] && a < b);
  });
  c.paths.resize(ranked);
  return c;
}

/// The E_s a trial's seams add to `seams` (3D lengths), over `unit`.
template <typename Surface>
double added_seam_length(const Surface& surface, const Map_state& trial, double seams, double unit)
{
  return (seam_length_3d(surface, trial.is_cut) - seams) / unit;
}

/// The batch split (Split_settings::batch): the candidates whose paths do
/// not meet, cut in one trial; `state` becomes it if `accept` takes it
/// (`kept` then counts its splits).
template <typename Surface, typename Solve, typename Accept>
Error_code try_batch_split(const Surface& surface, const Split_settings& split, Solve& solve, Accept& accept,
                           double seams, double unit, const Boundary_paths& boundary, Split_candidates& c,
                           Map_state& state, Work_log& log, int& kept, bool& taken)
{
  taken = false;
  const std::vector<std::size_t> chosen = batch_candidates(surface, c.order, split.batch, boundary, c.paths);
  if(chosen.size() <= 1) return OK;
  Map_state trial = state;
  Work_log trial_log; // its own work
  std::vector<Cut_path> cuts;
  for(std::size_t i : chosen) cuts.push_back(c.paths[i]);
  apply_cuts(surface, cuts, trial);
  const Error_code status = solve(trial, trial_log, faces_on_new_cuts(surface, state.is_cut, trial.is_cut));
  if(status != OK) return status;
  log.add(trial_log);
  const double added = added_seam_length(surface, trial, seams, unit);
  if(added > 0. && accept(state.distortion, trial.distortion, added))
  {
    state = std::move(trial);
    kept += int(chosen.size()) - 1; // the caller counts one
    taken = true;
  }
  return OK;
}

/// One split judged candidate by candidate: the first accepted, or with
/// `split.best_candidate` the one that lowers E_d the most per unit of E_s
/// added (candidates judged two at a time, those judged at an earlier split
/// only where their last decrease, with lazy_judging_margin, can still win).
/// `state` becomes the split kept (`taken`).
template <typename Surface, typename Solve, typename Accept>
Error_code judge_single_splits(const Surface& surface, const Split_settings& split, Solve& solve, Accept& accept,
                               double seams, double unit, const std::vector<double>& edge_length,
                               const Boundary_paths& boundary, Split_candidates& c,
                               std::vector<double>& last_decrease, Map_state& state, Work_log& log, bool& taken)
{
  const std::size_t tried = c.tried;
  Map_state best;
  double best_gain = -1.; // E_d decrease per unit of E_s added of `best`
  for(std::size_t i = 0; i < tried; ++i)
    if(c.paths[i].edges.empty()) c.paths[i].edges = boundary.path_edges(c.order[i]);
  auto judge = [&](std::size_t i, Map_state& trial, Work_log& trial_log) {
    trial = state;
    apply_cuts(surface, {c.paths[i]}, trial);
    return solve(trial, trial_log, faces_on_new_cuts(surface, state.is_cut, trial.is_cut));
  };
  std::size_t best_index = tried; // the candidate of `best` (the first of equal gains wins)
  auto weigh = [&](Map_state& trial, const Work_log& trial_log, std::size_t index) {
    log.add(trial_log);
    const double added = added_seam_length(surface, trial, seams, unit);
    if(added > 0. && accept(state.distortion, trial.distortion, added))
    {
      const double gain = (state.distortion - trial.distortion) / added;
      if(gain > best_gain || (gain == best_gain && index < best_index))
      {
        best_gain = gain;
        best_index = index;
        best = std::move(trial);
      }
    }
  };
  if(split.best_candidate)
  {
    // the most a candidate can gain, from its last judged decrease (infinite: never judged)
    std::vector<double> bound(tried);
    for(std::size_t i = 0; i < tried; ++i)
    {
      double length = 0.;
      for(int e : c.paths[i].edges) length += edge_length[e];
      const double last = last_decrease[c.order[i]];
      bound[i] = std::isnan(last) || !(length > 0.)
                   ? std::numeric_limits<double>::infinity()
                   : tuning::lazy_judging_margin * (std::max)(0., last) / (length / unit);
    }
    std::vector<std::size_t> by_bound(tried);
    std::iota(by_bound.begin(), by_bound.end(), std::size_t(0));
    std::stable_sort(by_bound.begin(), by_bound.end(), [&](std::size_t a, std::size_t b) { return bound[a] > bound[b]; });
    // the never judged all at once, then two at a time, until none can beat the best
    for(std::size_t next = 0; next < tried && !(best_gain >= 0. && best_gain >= bound[by_bound[next]]);)
    {
      std::size_t end = next + 1;
      if(std::isinf(bound[by_bound[next]]))
        while(end < tried && std::isinf(bound[by_bound[end]])) ++end;
      else
        end = (std::min)(tried, next + 2);
      std::vector<Map_state> trials(end - next);
      std::vector<Work_log> logs(end - next);
      std::vector<Error_code> statuses(end - next, OK);
      parallel_tasks(end - next, [&](std::size_t k) { statuses[k] = judge(by_bound[next + k], trials[k], logs[k]); });
      for(std::size_t k = 0; k < end - next; ++k)
      {
        if(statuses[k] != OK) return statuses[k];
        last_decrease[c.order[by_bound[next + k]]] = state.distortion - trials[k].distortion;
        weigh(trials[k], logs[k], by_bound[next + k]);
      }
      next = end;
    }
  }
  else
    for(std::size_t i = 0; i < tried && best_gain < 0.; ++i)
    {
      Map_state trial;
      Work_log trial_log;
      const Error_code status = judge(i, trial, trial_log);
      if(status != OK) return status;
      weigh(trial, trial_log, i);
    }
  taken = best_gain >= 0.;
  if(taken) state = std::move(best);
  return OK;
}

/// Splits `state` (a solved cut mesh, `state.distortion` its E_d) while its
/// E_d is above `stop_at` and `accept(E_d before, E_d after, E_s added)`
/// takes a split; `solve(state, log, faces)` solves a trial (at least the
/// charts holding a face flagged in `faces`: those on its new cuts) and sets
/// its `distortion`. Returns OK or the first error of a solve (then `state`
/// is the last accepted one); `kept` counts the splits kept.
template <typename Surface, typename Solve, typename Accept>
Error_code split_greedily(const Surface& surface, const Split_settings& split, double stop_at, Solve solve,
                          Accept accept, Map_state& state, Work_log& log, int& kept)
{
  const double total_area = std::accumulate(state.chart.area.begin(), state.chart.area.end(), 0.);
  const double unit = std::sqrt(total_area / M_PI); // E_s is a length over this
  std::vector<double> edge_length(surface.edges.size(), 0.);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe) edge_length[surface.edge_of[fe]] = surface.edge_length(fe);
  // per vertex: the E_d decrease of its split when last judged (NaN: never)
  std::vector<double> last_decrease(surface.number_of_vertices(), std::numeric_limits<double>::quiet_NaN());
  for(kept = 0; kept < split.max_splits && state.distortion > stop_at; ++kept)
  {
    const double seams = seam_length_3d(surface, state.is_cut);
    const Boundary_paths boundary = paths_to_cut_boundary(surface, state.is_cut, state.rules);
    Split_candidates c = rank_split_candidates(surface, split, state, boundary);
    bool taken = false;
    Error_code status = OK;
    if(split.batch > 1)
    {
      status = try_batch_split(surface, split, solve, accept, seams, unit, boundary, c, state, log, kept, taken);
      if(status != OK) return status;
      if(taken) continue;
    }
    status = judge_single_splits(surface, split, solve, accept, seams, unit, edge_length, boundary, c,
                                 last_decrease, state, log, taken);
    if(status != OK) return status;
    if(!taken) break;
  }
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
