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
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Joint_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>

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
  // more than 1: each split first tries this many of the most distorted
  // vertices at once (paths apart from each other, one trial, one solve:
  // large meshes, where every trial is a solve of the whole map); if that
  // is not accepted, the candidates are tried one at a time as above
  int batch = 1;
  // without a bound, a split pays for its seams if it lowers E_d by at
  // least this per unit of E_s it adds. Measured per split (ΔE_d / ΔE_s),
  // cube.off: 1.82, 0.90, 0.25, 0.26, 0.20 (E_d 6.53 -> 4.04; at 0.25 it
  // stopped at 4.55); icosahedron.off 0.35 ... 0.20, then 0.10 (stops at
  // 4.13); cross.off (7.20 before) stops at 4.41 with 0.15, 0.12 or 0.10
  // alike (4.39, 4.36).
  double gain = 0.15;
};

/// Where every candidate is judged (Split_settings::best_candidate), a
/// vertex judged at an earlier split is judged again only if its E_d
/// decrease then, over the length of its path to the boundary now, times
/// this, could beat the best gain found at this split: a split elsewhere
/// rarely makes a split worth more, except by shortening its path (which
/// the bound takes into account). Under OptCuts' 11 bounds (2 cores),
/// planck1: 198 -> 151 candidates judged; the same seams on 10 of the 11,
/// duck1's shorter (E_s 1.0653 -> 1.0647); geometric mean of OptCuts' time
/// over ours 1.33x -> 1.48x (median of 3 runs; planck1 4.85 -> 4.22 s,
/// armadillo_i_f10000 38.8 -> 34.1 s, bimba_i_f10000 22.5 -> 19.4 s). With
/// 1 instead of 1.25, 141 judged on planck1.
constexpr double lazy_judging_margin = 1.25;

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

/// At most `iterations` iterations of the inner `solver` (weights 1, no box,
/// no barrier) on the charts of `s` that hold a face flagged in `faces` (all charts if
/// `faces` is empty); the other charts keep their map, and `s.distortion`
/// becomes the E_d of the whole map. A trial split changes only the charts
/// its cut runs through, and the charts of this energy are independent:
/// solving those alone judges the split locally, at the cost of its charts
/// instead of the whole map's (a low-poly part beside a large mesh: a
/// 12-face box beside an 80k-face sphere).
inline Error_code relax_charts(int iterations, double tolerance, Inner_solver solver, const std::vector<char>& faces,
                               Joint_state& s)
{
  const Chart_mesh& full = s.chart;
  Chart_mesh part;
  std::vector<int> full_vertex; // of each vertex of `part`
  if(!faces.empty())
  {
    int charts = 0;
    const std::vector<int> chart_of_face = chart_of_faces(full, charts);
    std::vector<char> solved(std::size_t(charts), 0);
    for(std::size_t f = 0; f < full.number_of_faces(); ++f)
      if(faces[f]) solved[std::size_t(chart_of_face[f])] = 1;
    std::vector<int> part_vertex(std::size_t(full.number_of_vertices), -1);
    for(std::size_t f = 0; f < full.number_of_faces(); ++f)
    {
      if(!solved[std::size_t(chart_of_face[f])]) continue;
      std::array<int, 3> corners;
      for(int k = 0; k < 3; ++k)
      {
        int& v = part_vertex[std::size_t(full.faces[f][k])];
        if(v < 0)
        {
          v = int(full_vertex.size());
          full_vertex.push_back(full.faces[f][k]);
        }
        corners[k] = v;
      }
      part.faces.push_back(corners);
      part.rest_inverse.push_back(full.rest_inverse[f]);
      part.area.push_back(full.area[f]);
    }
    part.number_of_vertices = int(full_vertex.size());
  }
  const bool whole = faces.empty() || part.number_of_faces() == full.number_of_faces();
  const Chart_mesh& solved_mesh = whole ? full : part;
  UV_vector y;
  if(whole) y = s.x;
  else
  {
    y.resize(2 * Eigen::Index(full_vertex.size()));
    for(std::size_t v = 0; v < full_vertex.size(); ++v)
      y.template segment<2>(2 * Eigen::Index(v)) = s.x.template segment<2>(2 * Eigen::Index(full_vertex[v]));
  }
  Distortion_minimizer minimizer(solved_mesh, std::vector<double>(solved_mesh.number_of_faces(), 1.), false, 0., 0.,
                                 solver);
  const Newton_report report = minimizer.minimize(y, iterations, tolerance);
  s.count(report);
  if(whole) s.x = y;
  else
    for(std::size_t v = 0; v < full_vertex.size(); ++v)
      s.x.template segment<2>(2 * Eigen::Index(full_vertex[v])) = y.template segment<2>(2 * Eigen::Index(v));
  s.distortion = mean_distortion(s.chart, s.x);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// Splits `state` (a solved cut mesh, `state.distortion` its E_d) while its
/// E_d is above `stop_at` and `accept(E_d before, E_d after, E_s added)`
/// takes a split; `solve(state, faces)` solves a trial (at least the charts
/// holding a face flagged in `faces`: those on its new cuts) and sets its
/// `distortion`.
/// Returns OK or the first error of a solve (then `state` is the last
/// accepted one); `kept` counts the splits kept.
template <typename Surface, typename Solve, typename Accept>
Error_code split_greedily(const Surface& surface, const Split_settings& split, double stop_at, Solve solve,
                          Accept accept, Joint_state& state, int& kept)
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
    const std::size_t ranked = (std::min)(order.size(), std::size_t((std::max)(split.candidates, 4 * split.batch)));
    const std::size_t tried = (std::min)(order.size(), std::size_t(split.candidates));
    std::partial_sort(order.begin(), order.begin() + ranked, order.end(), [&](int a, int b) {
      return rank[a] > rank[b] || (rank[a] == rank[b] && a < b);
    });
    // each candidate's path to the boundary, found once
    std::vector<Cut_path> paths(ranked);
    if(split.batch > 1)
    {
      // the batch: one trial, kept if the rule accepts it for the seams of all its paths
      const std::vector<std::size_t> chosen = batch_candidates(surface, order, split.batch, boundary, paths);
      if(chosen.size() > 1)
      {
        Joint_state trial = state;
        trial.set_work({}); // its own work
        std::vector<Cut_path> cuts;
        for(std::size_t i : chosen) cuts.push_back(paths[i]);
        apply_cuts(surface, cuts, trial);
        const Error_code status = solve(trial, faces_on_new_cuts(surface, state.is_cut, trial.is_cut));
        if(status != OK) return status;
        state.add_work(trial);
        const double added = (seam_length_3d(surface, trial.is_cut) - seams) / unit;
        if(added > 0. && accept(state.distortion, trial.distortion, added))
        {
          trial.set_work(state.work());
          state = std::move(trial);
          kept += int(chosen.size()) - 1; // the loop counts one
          continue;
        }
      }
    }
    Joint_state best;
    double best_gain = -1.; // E_d decrease per unit of E_s added of `best`
    for(std::size_t i = 0; i < tried; ++i)
      if(paths[i].edges.empty()) paths[i].edges = boundary.path_edges(order[i]);
    // the trial of candidate i: `state` cut along its path, solved
    auto judge = [&](std::size_t i, Joint_state& trial) {
      trial = state;
      trial.set_work({}); // its own work
      apply_cuts(surface, {paths[i]}, trial);
      return solve(trial, faces_on_new_cuts(surface, state.is_cut, trial.is_cut));
    };
    std::size_t best_index = tried; // the candidate of `best` (the first of equal gains wins)
    // its work counted whatever is kept, then kept if it is accepted and the best so far
    auto weigh = [&](Joint_state& trial, std::size_t index) {
      state.add_work(trial);
      const double added = (seam_length_3d(surface, trial.is_cut) - seams) / unit;
      // (a path whose cut could not keep the charts disks is not cut: added 0)
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
      // Judged at once (each its own task; they read `state` only) and read
      // in order, so that the choice does not depend on the number of
      // threads. In the bound search this fills the core that the other
      // split trial leaves once done: under OptCuts' 11 bounds (2 cores),
      // 0.78-0.98x the time (bimba_i_f10000 26.9 -> 22.6 s,
      // circular_box_o_f20000 63.8 -> 53.7 s), the same seams.
      //
      // Lazily: a vertex judged at an earlier split, whose E_d decrease
      // then, over the length of its path now, times lazy_judging_margin,
      // cannot beat the best gain found, is not judged again (see
      // lazy_judging_margin). The never judged go first, all at once, then
      // the others by that bound, two at a time.
      std::vector<double> bound(tried);
      for(std::size_t i = 0; i < tried; ++i)
      {
        double length = 0.;
        for(int e : paths[i].edges) length += edge_length[e];
        const double last = last_decrease[order[i]];
        bound[i] = std::isnan(last) || !(length > 0.)
                     ? std::numeric_limits<double>::infinity()
                     : lazy_judging_margin * (std::max)(0., last) / (length / unit);
      }
      std::vector<std::size_t> by_bound(tried);
      std::iota(by_bound.begin(), by_bound.end(), std::size_t(0));
      std::stable_sort(by_bound.begin(), by_bound.end(), [&](std::size_t a, std::size_t b) { return bound[a] > bound[b]; });
      for(std::size_t next = 0; next < tried && !(best_gain >= 0. && best_gain >= bound[by_bound[next]]);)
      {
        std::size_t end = next + 1;
        if(std::isinf(bound[by_bound[next]]))
          while(end < tried && std::isinf(bound[by_bound[end]])) ++end;
        else
          end = (std::min)(tried, next + 2);
        std::vector<Joint_state> trials(end - next);
        std::vector<Error_code> statuses(end - next, OK);
        parallel_tasks(end - next, [&](std::size_t k) { statuses[k] = judge(by_bound[next + k], trials[k]); });
        for(std::size_t k = 0; k < end - next; ++k)
        {
          if(statuses[k] != OK) return statuses[k];
          last_decrease[order[by_bound[next + k]]] = state.distortion - trials[k].distortion;
          weigh(trials[k], by_bound[next + k]);
        }
        next = end;
      }
    }
    else
      for(std::size_t i = 0; i < tried && best_gain < 0.; ++i)
      {
        Joint_state trial;
        const Error_code status = judge(i, trial);
        if(status != OK) return status;
        weigh(trial, i);
      }
    const bool split_kept = best_gain >= 0.;
    if(split_kept)
    {
      best.set_work(state.work());
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
