// Seams zipped back from their free ends (the merge step of OptCuts, Li et
// al. 2018, by stretches of seam instead of single vertex pairs): where the
// map has room left under a distortion bound, the seams that bought less
// than they cost are closed again.
//
// The seams form a graph on the surface's vertices. A branch starts at a
// tip (a vertex off the mesh border with one seam edge), follows the seam
// through vertices with two seam edges and ends at the first other vertex
// (a junction, the mesh border, another tip). Zipping the first k edges of a
// branch from its tip leaves every chart a disk, as long as the seams that
// remain still open every chart (checked: a closed surface needs some seam).
// The two copies of every zipped vertex become one, placed at their mean;
// where that would flip a face, the copies are first pulled together by
// springs minimized with the distortion (Seam_closing_term.h, whose
// flip-free steps keep every face valid), then joined. The map
// is then solved again (by the caller) and the zip kept if the rule of the
// caller accepts the distortion it leaves.
//
// Each branch is tried whole, then halved (5 lengths at most, down to one
// edge; two lengths at a time on two cores, the first accepted kept);
// branches are taken where the map is least distorted first (the
// distortion there is what the seam relieves).
#ifndef CGAL_SMP_CUT_INTERNAL_SEAM_MERGING_H
#define CGAL_SMP_CUT_INTERNAL_SEAM_MERGING_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Distortion_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/vertex_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/Projected_newton_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Seam_closing_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_paths.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// How far the merges go (the defaults: tuning.h).
struct Merge_settings
{
  int max_trials = tuning::merge_max_trials;               // zips solved at most
  int newton_iterations = tuning::merge_newton_iterations; // Newton iterations that judge a zip
};

/// The seams and the map after a zip.
struct Merge_step
{
  std::vector<char> is_cut;
  UV_vector x;
};

/// The mean of the distinct UV vertices of `from` (corners `from_corner_uv`)
/// that each UV vertex of `to` joins (corners `to_corner_uv`); `pairs` gets
/// the pairs of UV vertices of `from` that become one.
inline UV_vector joined_positions(const std::vector<int>& from_corner_uv, const UV_vector& from_x,
                                  const std::vector<int>& to_corner_uv, int to_vertices,
                                  std::vector<std::array<int, 2>>& pairs)
{
  UV_vector x = UV_vector::Zero(2 * to_vertices);
  std::vector<int> first(to_vertices, -1), count(to_vertices, 0);
  std::set<std::pair<int, int>> seen; // (new, old) pairs
  pairs.clear();
  for(std::size_t c = 0; c < from_corner_uv.size(); ++c)
  {
    const int n = to_corner_uv[c], o = from_corner_uv[c];
    if(!seen.insert({n, o}).second) continue;
    x.template segment<2>(2 * n) += from_x.template segment<2>(2 * o);
    ++count[n];
    if(first[n] < 0) first[n] = o;
    else pairs.push_back({first[n], o});
  }
  for(int n = 0; n < to_vertices; ++n) x.template segment<2>(2 * n) /= count[n];
  return x;
}

/// Pulls the UV vertices of each pair of `pairs` together in `x` (a map of
/// `chart` without flipped face) by springs of growing stiffness minimized
/// with the distortion, until the widest gap is below 1e-3 of the mean edge
/// length or the springs are 1e5 times the distortion's scale. Adds the
/// Newton work to `iterations` and `factorizations`; x stays flip-free.
inline bool pull_pairs_together(const Chart_mesh& chart, const std::vector<std::array<int, 2>>& pairs,
                                UV_vector& x, std::size_t& iterations, std::size_t& factorizations)
{
  const std::vector<double> ones(chart.number_of_faces(), 1.);
  Distortion_term distortion(chart, ones);
  Seam_closing_term springs(pairs, 1.);
  Projected_newton_solver solver({&distortion, &springs}, 2 * chart.number_of_vertices);
  double area = 0.;
  for(double a : chart.area) area += a;
  const double edge = std::sqrt(2. * area / double((std::max)(std::size_t(1), chart.number_of_faces())));
  Newton_settings settings;
  settings.max_iterations = 8;
  settings.tolerance = 1e-7;
  settings.energy_scale = distortion.weighted_area();
  for(double stiffness = 1.; stiffness <= 1e5 && springs.largest_gap(x) > 1e-3 * edge; stiffness *= 10.)
  {
    springs.set_stiffness(stiffness);
    const Newton_report report = solver.minimize(x, settings);
    iterations += report.iterations;
    factorizations += report.factorizations;
    if(!report.ok()) return false;
  }
  return true;
}

/// `state` with `edges` no longer cut: the chart mesh rebuilt, the copies of
/// each zipped vertex joined at their mean; where that would flip a face,
/// the copies are first pulled together (pull_pairs_together()). Returns
/// false (and leaves `zipped` undefined) if a chart would not be a disk or
/// a face would still flip.
template <typename Surface>
bool zip_seam(const Surface& surface, const Map_state& state, const std::vector<int>& edges, Map_state& zipped,
              Work_log& log)
{
  zipped = state;
  for(int e : edges) zipped.is_cut[e] = 0;
  build_chart_mesh(surface, zipped.is_cut, zipped.chart, zipped.corner_uv);
  const Chart_topology topology = chart_topology(zipped.chart);
  for(int c = 0; c < topology.number_of_charts; ++c)
    if(!topology.is_disk(c)) return false;
  std::vector<std::array<int, 2>> pairs;
  zipped.x = joined_positions(state.corner_uv, state.x, zipped.corner_uv, zipped.chart.number_of_vertices, pairs);
  if(number_of_flipped_faces(zipped.chart, zipped.x) == 0) return true;
  UV_vector pulled = state.x;
  if(!pull_pairs_together(state.chart, pairs, pulled, log.work.iterations, log.work.factorizations)) return false;
  zipped.x = joined_positions(state.corner_uv, pulled, zipped.corner_uv, zipped.chart.number_of_vertices, pairs);
  return number_of_flipped_faces(zipped.chart, zipped.x) == 0;
}

/// Zips the seams of `state` (a solved cut mesh, `state.distortion` its
/// E_d) while `accept(E_d before, E_d after)` takes a zip; `solve(state)`
/// solves a trial and sets its `distortion`. The edges flagged in `keep`
/// stay cut. Returns OK or the first error of a solve (then `state` is the
/// last accepted one); `kept` gets the seams and map after each zip kept.
template <typename Surface, typename Solve, typename Accept>
Error_code merge_greedily(const Surface& surface, const Merge_settings& merge, const std::vector<char>& keep,
                          Solve solve, Accept accept, Map_state& state, Work_log& log, std::vector<Merge_step>& kept)
{
  kept.clear();
  const bool at_once = surface.number_of_faces() <= tuning::two_states_at_once_max_faces;
  std::set<int> done; // tips whose branch was tried to the end
  for(int trials = 0; trials < merge.max_trials;)
  {
    const std::vector<Seam_path> branches = seam_branches(surface, state.is_cut, keep);
    const std::vector<double> excess = vertex_distortion_excess(surface, state.chart, state.x);
    // the branch around which the map is least distorted, per unit of its length
    int best = -1;
    double best_density = 0.;
    for(int b = 0; b < int(branches.size()); ++b)
    {
      if(done.count(branches[b].vertices.front())) continue;
      double sum = 0.;
      for(int v : branches[b].vertices) sum += excess[v];
      const double density = sum / double(branches[b].vertices.size());
      if(best < 0 || density < best_density) { best = b; best_density = density; }
    }
    if(best < 0) break;
    const Seam_path& branch = branches[best];
    done.insert(branch.vertices.front());
    // the lengths tried from the tip: whole, then halved
    std::vector<std::size_t> lengths;
    for(std::size_t k = branch.edges.size(); lengths.size() < 5 && k >= 1; k = k == 1 ? 0 : (k + 1) / 2)
      lengths.push_back(k);
    // Each length is zipped and solved from the same state: two at a time, at
    // once (in_pairs()), read in order; the first one accepted is
    // kept, as if they had been tried one after the other. The second of a
    // pair is solved even when the first is kept (its Newton work counts),
    // so the counts do not depend on the number of threads either.
    struct Attempt
    {
      bool zipped = false;
      Error_code status = OK;
      Map_state trial;
      Work_log log; // its own work
    };
    auto attempt = [&](std::size_t k, Attempt& a) {
      a.zipped = zip_seam(surface, state, std::vector<int>(branch.edges.begin(), branch.edges.begin() + k), a.trial,
                          a.log);
      if(a.zipped) a.status = solve(a.trial, a.log);
    };
    std::size_t newton_work = 0, factorization_work = 0; // of the attempts not kept
    bool zipped_some = false;
    for(std::size_t i = 0; i < lengths.size() && trials < merge.max_trials && !zipped_some; i += 2)
    {
      std::array<Attempt, 2> pair;
      in_pairs((std::min)(std::size_t(2), lengths.size() - i), [&](std::size_t j) { attempt(lengths[i + j], pair[j]); },
               at_once);
      for(std::size_t j = 0; j < 2 && i + j < lengths.size(); ++j)
      {
        Attempt& a = pair[j];
        const bool tried = a.zipped && !zipped_some && trials < merge.max_trials;
        if(tried)
        {
          ++trials;
          if(a.status != OK) return a.status;
          if(accept(state.distortion, a.trial.distortion))
          {
            state = std::move(a.trial);
            log.add(a.log);
            zipped_some = true;
            kept.push_back({state.is_cut, state.x});
            continue;
          }
        }
        if(a.zipped) // the work was done anyway
        {
          newton_work += a.log.work.iterations;
          factorization_work += a.log.work.factorizations;
        }
      }
    }
    log.work.iterations += newton_work;
    log.work.factorizations += factorization_work;
  }
  return OK;
}

/// Seams of the solved cut mesh in `state` (no box), whose E_d is within
/// `bound`, zipped back while the map stays within it: each zip is judged by
/// `relax(state, log)`; then `solve_within_bound(from_tutte_map, candidate,
/// state, log, kept)` runs the final solve again. If that ends above the
/// bound, the zips are undone from the last, halving their number (at most
/// tuning::merge_undo_tries final solves); with none left, `state` is left
/// as it was. The edges flagged in `keep` stay cut.
template <typename Surface, typename Relax, typename Solve_within_bound>
Error_code merge_under_bound(const Surface& surface, double bound, const std::vector<char>& keep, Relax relax,
                             Solve_within_bound solve_within_bound, Map_state& state, Work_log& log)
{
  if(!(bound > 0.) || state.distortion > bound) return OK;
  Map_state merged = state;
  std::vector<Merge_step> steps;
  Error_code status = merge_greedily(surface, Merge_settings(), keep, relax,
                                     [&](double, double after) { return after <= bound; }, merged, log, steps);
  if(status != OK) return status;
  bool kept = false;
  for(std::size_t k = steps.size(), tries = 0; k > 0 && tries < std::size_t(tuning::merge_undo_tries) && !kept;
      k /= 2, ++tries)
  {
    Map_state candidate = state;
    candidate.is_cut = steps[k - 1].is_cut;
    candidate.x = steps[k - 1].x;
    build_chart_mesh(surface, candidate.is_cut, candidate.chart, candidate.corner_uv);
    if((status = solve_within_bound(false, std::move(candidate), state, log, kept)) != OK) return status;
  }
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
