// The Ambrosio–Tortorelli alternation, cut extraction and final solve
// (METHOD.md "Optimization" and "Cut extraction"), on index arrays.
#ifndef CGAL_SMP_CUT_INTERNAL_JOINT_OPTIMIZATION_H
#define CGAL_SMP_CUT_INTERNAL_JOINT_OPTIMIZATION_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/carried_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cut_extraction.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/initial_cut.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/discontinuity_field.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/greedy_splits.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Joint_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/multiresolution.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/overlap_partition.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seam_merging.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seam_straightening.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <algorithm>
#include <limits>
#include <functional>
#include <string>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Joint_progress
{
  const char* phase;
  int pass, alternation, alternations_per_pass;
  double epsilon, distortion;
};

struct Joint_settings
{
  double lambda = 1.;
  double epsilon_start = 0.1;
  double epsilon_end = 0.01;
  int iterations_per_epsilon = 3;
  double gamma = 1e-7;
  int passes = 1;
  double minimum_relative_cut_length = 0.2;
  int max_newton_iterations = 500;
  // The u-steps after the first only track a v that changes anyway: capping
  // them saves most of the time on hard inputs and leaves E_d unchanged on
  // the benchmark (measured: octopus 2.4x faster, bimba/lion/cat equal).
  int max_alternation_newton_iterations = 50;
  // Newton tolerances (decrease of the mean distortion, see Newton_settings).
  // Measured on the 15 disk meshes of the benchmark: 1e-5 / 1e-7 keep E_d
  // within 0.001 of tighter settings (better on bimba) with 25-35% fewer iterations.
  double alternation_tolerance = 1e-5; // u-steps inside the alternation
  double final_tolerance = 1e-7;       // final solve on the cut mesh
  // Final solves with the border barrier or the box: these terms make Newton
  // converge linearly only (the box's active set, barrier pairs coming close),
  // and 1e-7 took up to 500 iterations (lion_o_f10000, hand1). Measured on 7
  // benchmark meshes against 1e-7: E_d within 0.0015 where the same box
  // stiffness was kept, final solve 2-4x faster.
  double constrained_tolerance = 1e-5;
  // The alternation's u-steps stop in a slow tail (Slow_tail: after 100
  // iterations, less than 0.1% of the energy gained over the last 20): they
  // only decide where to cut. Measured (2 cores) on ArtDemo.obj (15.5k
  // faces, 26 charts): 49.7 -> 40.1 s, 3,587 -> 2,622 Newton iterations,
  // E_d 4.985 -> 4.695, E_s 15.95 -> 16.77 (its first u-step stops at 179
  // of 483 iterations; the final solve after the cut then leaves E_d 4.81
  // instead of 6.41, and 8 splits are kept instead of about 60); 3 of the
  // 21 benchmark meshes reach it (manual, "Inner solvers"). In the
  // final solves too: 37.3 s, the same E_d, but femur.off ended at E_d
  // 4.60023 after its splits (an output converged less). From the first
  // iteration on (no `after`) the rule moved armadillo_i_f10000's cuts
  // (E_d 4.4402 -> 4.4429, no longer as good as the baseline).
  Slow_tail slow_tail{100, 20, 1e-3};
  // The box's solve (the last of the final solve, from the converged map
  // without box) where the cuts were decided on a simplified copy (meshes
  // of more than twice multiresolution_faces faces), each of its Newton
  // iterations a solve of the whole mesh. Measured (2 cores) against 1e-5:
  // femur.off refined to 125k faces 73 -> 7 iterations, 61.5 -> 49.5 s of
  // CPU, E_d 4.632 -> 4.639, coverage 0.511 -> 0.519; bimba_i_f10000
  // refined to 160k 29 -> 16, 30.4 -> 25.4 s, E_d 4.2918 -> 4.2930,
  // coverage 0.672 -> 0.668. (1e-4: 22 iterations for bimba.)
  double large_mesh_box_tolerance = 1e-3;
  // the box's solve otherwise (optimize_cut_mesh() sets the one above
  // there). The box's term converges linearly only (its active set), and
  // it is a gentle preference: measured (2 cores) against 1e-5, the box's
  // solves of ArtDemo with holes (wild_corpus.py) replayed 271 -> 57, 179
  // -> 64, 158 -> 74, 122 -> 79 iterations, E_d +0.011, +0.006, +0.001,
  // 0.000; ArtDemo.obj 28.5 -> 25.1 s (E_d 4.596 -> 4.594); the 21
  // benchmark meshes E_d within +0.011 (sphere_f1522 4.3275 -> 4.3388, the
  // others within 0.002), E_s unchanged, Newton iterations fewer on 19
  // (sphere_f1522 91 -> 60, face_f10000 293 -> 244), geometric-mean
  // speedup 2.92x -> 3.09x (one run each).
  double box_tolerance = 1e-4;
  // Atlas: no chart overlaps itself (final_solve()), then packing into the unit square.
  bool global_injectivity = true;
  // With global injectivity: a chart whose map without the border barrier
  // overlaps itself on more than this many faces is cut into pieces that do
  // not (final_solve_without_box(); 0: never).
  int overlap_partition_faces = 10000;
  // With global injectivity, after greedy splits on a cut mesh of at most
  // this many faces: where the final solve started a crossing chart again
  // and ended above the splits' goal, the split map is also solved with its
  // crossing charts cut into overlap-free pieces (final_solve_after_splits();
  // 0: never).
  int split_pieces_max_faces = 1000;
  // Bounding box: the final solve pulls each chart into a rectangle of this
  // width / height, with this stiffness (0: off); the default is a gentle
  // square (see gentle_bounding_box_stiffness for the measures).
  double bounding_box_aspect_ratio = 1.;
  double bounding_box_stiffness = gentle_bounding_box_stiffness;
  // largest E_d increase the box may cost (see gentle_bounding_box_distortion_budget)
  double bounding_box_distortion_budget = gentle_bounding_box_distortion_budget;
  // the box is also weakened, then dropped, where it would take E_d above
  // this (a distortion bound's trials set it: the bound comes before the box)
  double bounding_box_distortion_ceiling = std::numeric_limits<double>::infinity();
  // Multiresolution: on a mesh of more than twice this many faces, the cuts
  // are decided on a copy simplified to about this many (0: never).
  int multiresolution_faces = 10000;
  // > 0: the result must have E_d <= this (distortion_bound.h searches λ); 0: no bound
  double distortion_bound = 0.;
  // greedy splits after the final solve (split_where_distorted())
  bool greedy_splits = true;
  Split_settings split;
  // under a bound: seams rerouted along shorter paths within this many rings
  // (straighten_under_bound(); 0: never), then zipped back where the bound
  // leaves room (merge_under_bound())
  int seam_straightening_rings = 3;
  bool seam_merging = true;
  // without a bound: the seams of the alternation are also rerouted within
  // this many rings and solved at once, and kept if E_d stays within the
  // allowance (final_solve_with_rerouting(); 0: never)
  int rerouting_rings = 1;
  double rerouting_allowance = 0.01;
  Merge_settings merge;
  Packing_settings packing;
  // the solver of every minimization of the UVs (u-steps, final solve, trials)
  Inner_solver inner_solver = Inner_solver::NEWTON;
  // with the quasi-Newton solver, the u-steps after the first are capped
  // at this many times max_alternation_newton_iterations (its iterations
  // cost a gradient and a solve, Newton's a factorization)
  int quasi_newton_iteration_factor = 3;
  std::function<bool(const Joint_progress&)> progress; // false: cancel

  bool valid() const
  {
    return lambda > 0. && epsilon_start > 0. && epsilon_end > 0. && epsilon_end <= epsilon_start
        && iterations_per_epsilon >= 1 && gamma > 0. && passes >= 0 && max_newton_iterations >= 1
        && minimum_relative_cut_length >= 0. && minimum_relative_cut_length <= 1.
        && bounding_box_aspect_ratio >= 0. && std::isfinite(bounding_box_aspect_ratio)
        && bounding_box_stiffness >= 0. && std::isfinite(bounding_box_stiffness)
        && bounding_box_distortion_budget >= 0. && multiresolution_faces >= 0 && overlap_partition_faces >= 0
        && split_pieces_max_faces >= 0 && rerouting_rings >= 0
        && rerouting_allowance >= 0. && std::isfinite(rerouting_allowance)
        && slow_tail.after >= 0 && slow_tail.window >= 1 && slow_tail.ratio >= 0. && std::isfinite(slow_tail.ratio)
        && (distortion_bound == 0. || (distortion_bound >= 4. && std::isfinite(distortion_bound)))
        && packing.texture_size >= 1 && packing.padding >= 0. && std::isfinite(packing.padding);
  }

  int alternations_per_pass() const
  {
    int n = 0;
    for(double eps = epsilon_start; eps > epsilon_end; eps *= 0.5) n += iterations_per_epsilon;
    return n;
  }
};

inline std::vector<double> face_distortions(const Chart_mesh& chart, const UV_vector& x)
{
  std::vector<double> psi(chart.number_of_faces());
  for(std::size_t f = 0; f < psi.size(); ++f) psi[f] = symmetric_dirichlet(chart.jacobian(x, f));
  return psi;
}

/// The alternation's u-step number `alternation` (0: the first) with the
/// weights v² + γ of `state.v`: a Newton minimization from `state.x`, capped
/// after the first (max_alternation_newton_iterations).
inline Error_code u_step(const Joint_settings& settings, int alternation, Distortion_minimizer& minimizer,
                         Joint_state& state)
{
  Scoped_timer timer(state.timings.u_steps);
  for(Eigen::Index f = 0; f < state.v.size(); ++f) minimizer.weights()[f] = state.v[f] * state.v[f] + settings.gamma;
  const int later_cap = settings.max_alternation_newton_iterations
                        * (settings.inner_solver == Inner_solver::NEWTON ? 1 : settings.quasi_newton_iteration_factor);
  const int cap = alternation == 0 ? settings.max_newton_iterations
                                    : (std::min)(settings.max_newton_iterations, later_cap);
  // Without the reweighted start: the first u-step's map decides the cuts,
  // and the start moved them, for no time gained on the benchmark (21
  // meshes, 2 cores, one run each: geometric-mean speedup 2.97x -> 2.99x;
  // planck1 E_d 4.5889 -> 4.5935, E_s 2.265 -> 2.522; camel_simple E_s 8.58
  // -> 9.76; ArtDemo.obj's first u-step 180 -> 119 iterations, but its run
  // 44 -> 58 s, other cuts asking for other splits). Without the longer
  // steps of the line search either (default_step_growth): they moved the
  // cuts too (planck1 E_d 4.5890 -> 4.5977, E_s 2.265 -> 2.468; venus E_s
  // 2.815 -> 3.088), 16/20 benchmark meshes meeting both targets -> 15.
  minimizer.set_reweighted_start(0.);
  minimizer.set_step_growth(1.);
  const Newton_report report = minimizer.minimize(state.x, cap, settings.alternation_tolerance, settings.slow_tail);
  state.u_step_work += state.count(report);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// One pass: the alternation at decreasing ε, then the cut paths from v.
/// If `state.first_u_step_done`, its first u-step is the one already done
/// (prepare_first_u_step()). Returns OK, ERROR_CANNOT_SOLVE_LINEAR_SYSTEM or
/// ERROR_CANCELED.
template <typename Surface>
Error_code alternate(const Surface& surface, const std::vector<double>& face_lambda,
                     const Joint_settings& settings, int pass, Joint_state& state,
                     std::vector<Cut_path>& paths)
{
  const std::size_t nf = surface.number_of_faces();
  const double mean_edge = mean_edge_length(surface);
  Scoped_timer u_setup(state.timings.u_steps);
  Distortion_minimizer minimizer(state.chart, std::vector<double>(nf, 1.), false, 0., 0., settings.inner_solver);
  u_setup.stop();
  Scoped_timer v_setup(state.timings.v_steps);
  Discontinuity_solver v_solver(dual_edges(surface, state.is_cut, face_lambda), state.chart.area, face_lambda);
  state.v = Eigen::VectorXd::Ones(nf);
  v_setup.stop();
  const bool first_done = state.first_u_step_done;
  state.first_u_step_done = false;
  int alternation = 0;
  for(double eps = settings.epsilon_start; eps > settings.epsilon_end; eps *= 0.5)
    for(int i = 0; i < settings.iterations_per_epsilon; ++i)
    {
      if(!(alternation == 0 && first_done))
      {
        const Error_code status = u_step(settings, alternation, minimizer, state);
        if(status != OK) return status;
      }
      Scoped_timer v_step(state.timings.v_steps);
      if(!v_solver.solve(face_distortions(state.chart, state.x), eps, settings.lambda, mean_edge, state.v))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      ++state.v_step_factorizations;
      v_step.stop();
      ++alternation;
      if(settings.progress && !settings.progress({"alternate", pass, alternation, settings.alternations_per_pass(),
                                                  eps, mean_distortion(state.chart, state.x)}))
        return ERROR_CANCELED;
    }
  Scoped_timer extraction(state.timings.cut_extraction);
  paths = extract_cut_paths(surface, state.is_cut, state.rules, state.v, settings.minimum_relative_cut_length);
  return OK;
}

/// One Newton minimization of the final solve on the cut mesh of `state`
/// (weights 1), with the border barrier if `injective` and a box of
/// `stiffness` (0: none). It ends at `settings.constrained_tolerance` under
/// the barrier or where a box's solve follows (`boxed`), else at
/// `settings.final_tolerance` (measured on CGAL's man.off, 35k faces: 247 ->
/// 115 Newton iterations for the solve before the box, the same E_d after it).
inline Error_code final_minimization(const Joint_settings& settings, bool injective, double stiffness, bool boxed,
                                     Joint_state& state)
{
  Distortion_minimizer minimizer(state.chart, std::vector<double>(state.chart.number_of_faces(), 1.), injective,
                                 stiffness > 0. ? settings.bounding_box_aspect_ratio : 0., stiffness,
                                 settings.inner_solver);
  const double tolerance = stiffness > 0. ? settings.box_tolerance
                           : (injective || boxed ? settings.constrained_tolerance : settings.final_tolerance);
  const Newton_report report = minimizer.minimize(state.x, settings.max_newton_iterations, tolerance);
  state.count(report);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// The box's stiffness of the final solve under `settings` (0: no box).
inline double final_box_stiffness(const Joint_settings& settings)
{
  return settings.bounding_box_aspect_ratio > 0. ? settings.bounding_box_stiffness : 0.;
}

/// What the final solve without box leaves to the box's solve.
struct Unboxed_final_map
{
  double distortion = 0.; // E_d of the map without box (before any restart)
  bool barrier = false;   // the border barrier is on (it stays on)
  bool restart = false;   // a chart crossed itself and starts again from its Tutte map
                          // or a carried map (`distortion` is then that of an invalid map)
};

/// The final solve on the cut mesh without the box, from the map of the
/// alternation. With global injectivity, if a chart's border then crosses
/// itself, the chart is put back to its Tutte embedding (whose border is
/// convex) for final_solve_box() to solve again, with the box at once and
/// the border barrier that keeps borders from crossing; or, where `carried`
/// holds a valid map of that chart (the map the splits started from, carried
/// over their cuts: carried_map.h), to that map. A crossing chart without
/// such a map that overlaps itself on more than
/// `settings.overlap_partition_faces` faces is cut into pieces that do not
/// (cut_into_overlap_free_pieces()), each starting from its part of the map
/// (`carried` is then set aside: its charts are those of the mesh before).
/// The other charts start from where they are. The alternation's map is no start for it: its
/// new cuts are slits of zero width, whose sides touch (with the scaffold
/// used before the barrier, a slit opened just a little stayed almost
/// closed: venus E_d 4.77 from there, 4.37 from Tutte; hand1 7.5 and 4.58).
///
/// From a Tutte map (`from_tutte_map`: the multiresolution path, where the
/// alternation ran on the simplified copy, the rerouted seams, or no pass at
/// all) the barrier is on from the first solve: the solve without it would
/// only find out whether a border crosses, then start again from the same
/// map. Measured (2 cores), final solve without / with the barrier first:
/// bimba_i_f10000 refined to 160k faces 17 + 62 -> 29 + 39 Newton
/// iterations (the second number: the box's solve), 29.2 -> 23.8 s, E_d
/// 4.2811 both; refined_elephant.off 62 + 173 -> 78 + 67, 33.8 -> 21.1 s,
/// E_d 4.1910 -> 4.1874; refined to 40k 20 + 44 -> 35 + 31, 4.3 -> 4.6 s,
/// E_d 4.3275 -> 4.3271.
template <typename Surface>
Error_code final_solve_without_box(const Surface& surface, const Joint_settings& settings, bool from_tutte_map,
                                   Joint_state& state, Unboxed_final_map& unboxed, const Carried_map* carried = nullptr)
{
  const bool barrier_first = settings.global_injectivity && from_tutte_map;
  const Error_code status = final_minimization(settings, barrier_first, 0., final_box_stiffness(settings) > 0., state);
  if(status != OK) return status;
  unboxed.distortion = mean_distortion(state.chart, state.x);
  unboxed.barrier = barrier_first;
  if(!settings.global_injectivity || barrier_first) return OK;
  std::vector<char> crossing = Border_barrier_term(state.chart).charts_with_crossing(state.x);
  if(std::find(crossing.begin(), crossing.end(), 1) == crossing.end()) return OK;
  // a chart starts again from the carried map where that is valid, else from Tutte
  auto carried_valid = [&](int c) { return carried != nullptr && carried->valid[std::size_t(c)]; };
  // or, where it overlaps itself much, it is cut into pieces that do not
  if(settings.overlap_partition_faces > 0)
  {
    const std::vector<std::size_t> overlapping = self_overlapping_face_counts(state.chart, state.x);
    std::vector<char> cut_up(crossing.size(), 0);
    for(std::size_t c = 0; c < crossing.size(); ++c)
      cut_up[c] = crossing[c] && !carried_valid(int(c))
                  && overlapping[c] > std::size_t(settings.overlap_partition_faces);
    if(std::find(cut_up.begin(), cut_up.end(), 1) != cut_up.end() && cut_into_overlap_free_pieces(surface, cut_up, state))
    {
      carried = nullptr; // its charts are those of the chart mesh before
      crossing = Border_barrier_term(state.chart).charts_with_crossing(state.x);
      unboxed.barrier = unboxed.restart = true;
    }
  }
  bool need_tutte = false;
  for(int c = 0; c < int(crossing.size()); ++c) need_tutte = need_tutte || (crossing[c] && !carried_valid(c));
  UV_vector tutte;
  if(need_tutte)
  {
    const Embedding_status embedding = disk_charts_embedding(state.chart, tutte);
    if(embedding == Embedding_status::NOT_DISKS) return ERROR_NO_TOPOLOGICAL_DISC;
    if(embedding == Embedding_status::SOLVE_FAILED) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    if(embedding == Embedding_status::FLIPPED) return ERROR_NO_1_TO_1_MAPPING;
  }
  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(state.chart, charts);
  for(std::size_t f = 0; f < state.chart.number_of_faces(); ++f)
    if(crossing[chart_of_face[f]])
    {
      const UV_vector& start = carried_valid(chart_of_face[f]) ? carried->x : tutte;
      for(int v : state.chart.faces[f]) state.x.segment<2>(2 * v) = start.segment<2>(2 * v);
    }
  unboxed.barrier = unboxed.restart = true;
  return OK;
}

/// The rest of the final solve after final_solve_without_box(): the charts
/// put back to their Tutte map solved again under the barrier, and the
/// bounding box's solve. The box comes last, from the converged map without
/// it: pulled by the box from the alternation's map, a chart crossed itself
/// more often (bunny, tooth), and every crossing costs an injective solve
/// from Tutte.
///
/// Charts put back to their Tutte map are solved without the box first:
/// the box's cost is judged against that valid map, not against the map
/// that crossed itself (lower than any valid one: the box was then always
/// weakened twice and dropped, three solves for nothing). Measured (2
/// cores, with the reweighted start at an intermediate setting) on
/// ArtDemo.obj: 58.5 -> 29.4 s, 3,110 -> 1,918 Newton iterations,
/// E_d 4.589 -> 4.596, coverage 0.487 -> 0.532; ArtDemo with holes
/// (wild_corpus.py): coverage 0.198 -> 0.552, E_d 4.590 -> 4.559, 40.0 ->
/// 43.9 s.
///
/// With global injectivity the box's solve runs under the barrier at once (a
/// box solve that crossed was done twice: bunnyhead 23 + 39 + 38 -> 23 + 38
/// Newton iterations, bunny 204 -> 168 in all, the same E_d; the other
/// meshes of the benchmark did not cross and are unchanged); without global
/// injectivity, without the barrier. If the box raises E_d over the map
/// without it by more than the budget (or above the ceiling, where the map
/// without box is below it), it is weakened (stiffness x 0.7) and the solve
/// redone from the boxed map, at most twice, then dropped: the map without
/// box is the result (it was solved again from the boxed map, to the same
/// tolerance: CGAL's ALSTOM_TEST4.off refined to 130k faces, 55 Newton
/// iterations, 12 s of its 38 s).
inline Error_code final_solve_box(const Joint_settings& settings, const Unboxed_final_map& unboxed, Joint_state& state)
{
  double stiffness = final_box_stiffness(settings);
  const bool barrier = unboxed.barrier || (stiffness > 0. && settings.global_injectivity);
  auto solve = [&](double s) { return final_minimization(settings, barrier, s, true, state); };
  Error_code status = OK;
  double unboxed_distortion = unboxed.distortion;
  if(unboxed.restart && stiffness > 0.)
  {
    status = solve(0.);
    unboxed_distortion = mean_distortion(state.chart, state.x);
  }
  // the map without box, converged: where the box is dropped, the result
  UV_vector without_box;
  if(stiffness > 0.) without_box = state.x;
  if(status == OK && (unboxed.restart || stiffness > 0.)) status = solve(stiffness);
  // the box's cost in distortion, over the map without box, stays within the budget
  // and below the ceiling where the map without box is
  const double ceiling = unboxed_distortion <= settings.bounding_box_distortion_ceiling
                           ? settings.bounding_box_distortion_ceiling : std::numeric_limits<double>::infinity();
  const double highest = (std::min)(unboxed_distortion + settings.bounding_box_distortion_budget, ceiling);
  for(int weaker = 0; status == OK && stiffness > 0. && weaker < 3 && mean_distortion(state.chart, state.x) > highest;
      ++weaker)
  {
    stiffness = weaker < 2 ? 0.7 * stiffness : 0.;
    if(stiffness > 0.) status = solve(stiffness);
    else state.x = std::move(without_box);
  }
  return status;
}

/// The final solve: final_solve_without_box(), then final_solve_box().
/// `restarted`, if given, tells whether a chart crossed itself and started again.
template <typename Surface>
Error_code final_solve(const Surface& surface, const Joint_settings& settings, bool from_tutte_map, Joint_state& state,
                       const Carried_map* carried = nullptr, bool* restarted = nullptr)
{
  Unboxed_final_map unboxed;
  const Error_code status = final_solve_without_box(surface, settings, from_tutte_map, state, unboxed, carried);
  if(restarted != nullptr) *restarted = unboxed.restart;
  return status != OK ? status : final_solve_box(settings, unboxed, state);
}

/// `rerouted` becomes the cut mesh of the seams of `state` rerouted by
/// straighten_seams() (`keep`, `rings`, `slide`: as there), with a Tutte map;
/// false if no path was rerouted or the Tutte map failed.
template <typename Surface>
bool rerouted_cut_mesh(const Surface& surface, const Joint_state& state, const std::vector<char>& keep, int rings,
                       bool slide, Joint_state& rerouted)
{
  rerouted.is_cut = state.is_cut;
  if(straighten_seams(surface, state.rules, keep, rings, rerouted.is_cut, slide) == 0) return false;
  build_chart_mesh(surface, rerouted.is_cut, rerouted.chart, rerouted.corner_uv);
  return disk_charts_embedding(rerouted.chart, rerouted.x) == Embedding_status::OK;
}

/// True if, with global injectivity, a chart of `state` overlaps itself
/// (self_overlapping_faces()): its final solve will start again from its
/// Tutte map under the border barrier, or cut it into pieces
/// (final_solve_without_box()).
inline bool overlaps_itself(const Joint_settings& settings, const Joint_state& state)
{
  if(!settings.global_injectivity) return false;
  int charts = 0;
  const std::vector<char> overlapping = self_overlapping_faces(state.chart, state.x, chart_of_faces(state.chart, charts));
  return std::find(overlapping.begin(), overlapping.end(), 1) != overlapping.end();
}

/// final_solve() of the cut mesh in `state`, or of the same seams rerouted
/// within `settings.rerouting_rings` rings (seam_straightening.h, the ends
/// fixed; the edges flagged in `keep` stay), solved from a Tutte map. Both
/// are solved without box at once (parallel_invoke()), and the rerouted
/// seams are kept if their E_d is at most that of the first plus
/// `settings.rerouting_allowance`; then only the seams kept get the box's
/// solve (final_solve_box()). Where the first map crossed itself (its E_d
/// without box is then that of an invalid map), both are solved through,
/// the box included, and compared after it. Both solves always run and the
/// choice reads both, so the result does not depend on the number of
/// threads; the Newton counts add up.
///
/// Choosing before the box gives the same results as choosing after it on
/// the 20 benchmark meshes (E_d, E_s and coverage), the box's solve of the
/// seams not kept left out: 6188 -> 5978 Newton iterations over the 20.
///
/// Only where the alternation ran on this mesh, from its map (not
/// `from_tutte_map`), and up to two_states_at_once_max_faces faces. The
/// seams carried from a simplified copy (multiresolution.h) are shortest
/// paths already, and at those sizes the final solve is most of the time:
/// two at once on 2 cores share the memory bandwidth (bimba_i_f10000
/// refined to 160k faces: final solve 13.1 -> 25.5 s, the whole run 17.6 ->
/// 30.4 s; CGAL's refined_elephant.off 32.3 -> 58.2 s). Nor where the
/// alternation's map overlaps itself (overlaps_itself()): the first map then
/// starts again from its Tutte map under the barrier (or is cut into
/// pieces), and the rerouted seams' solve from a Tutte map ran beside it, as
/// long, sharing the memory bandwidth. Measured (2 cores) on ArtDemo with
/// holes (wild_corpus.py): 32.9 -> 28.0 s, the same result (its rerouted
/// seams were not kept: E_d 4.5911, E_s 14.876); CGAL's cheese.off: its
/// rerouted seams' solve from Tutte reached the 500-iteration cap.
///
/// The field v opens its cuts along a band, through the mesh's edges: the
/// seams zigzag. Measured on the 20 benchmark meshes (2 cores): rerouted
/// within 1 ring and solved without the comparison, E_s fell on 15, for E_d
/// at most +0.015 on 14 of them; but cow_head's E_d rose by 0.19, and
/// hand1's rerouted map went above low_poly_distortion (then split): why
/// the rerouting is judged, not assumed. With the comparison: kept on 13
/// (venus E_s 2.958 -> 2.815, face_f10000 2.461 -> 2.391, lion_o_f10000
/// 6.877 -> 6.780), E_s at most the same on all 20, E_d at most +0.009, the
/// time within noise. With 2 or 3 rings, kept on 10 only (3 rings without
/// the comparison: hand_1_i_f5000 E_d 4.138 -> 4.451).
template <typename Surface>
Error_code final_solve_with_rerouting(const Surface& surface, const Joint_settings& settings,
                                      const std::vector<char>& keep, bool from_tutte_map, Joint_state& state)
{
  Joint_state rerouted;
  const bool have_rerouted = !from_tutte_map && settings.rerouting_rings > 0
                             && surface.number_of_faces() <= two_states_at_once_max_faces
                             && !overlaps_itself(settings, state)
                             && rerouted_cut_mesh(surface, state, keep, settings.rerouting_rings, false, rerouted);
  if(!have_rerouted) return final_solve(surface, settings, from_tutte_map, state);
  Error_code first = OK, second = OK;
  Unboxed_final_map unboxed, rerouted_unboxed;
  parallel_invoke([&] { first = final_solve_without_box(surface, settings, from_tutte_map, state, unboxed); },
                  [&] { second = final_solve_without_box(surface, settings, true, rerouted, rerouted_unboxed); });
  if(first != OK) return first;
  // where the first map crossed itself, its E_d without box is not yet that
  // of a valid map: both are solved through and compared after the box
  const bool solved_through = unboxed.restart;
  if(solved_through)
  {
    parallel_invoke([&] { first = final_solve_box(settings, unboxed, state); },
                    [&] { if(second == OK) second = final_solve_box(settings, rerouted_unboxed, rerouted); });
    if(first != OK) return first;
  }
  auto distortion = [&](const Joint_state& s, const Unboxed_final_map& u) {
    return solved_through ? mean_distortion(s.chart, s.x) : u.distortion;
  };
  state.add_work(rerouted);
  if(second == OK
     && distortion(rerouted, rerouted_unboxed) <= distortion(state, unboxed) + settings.rerouting_allowance)
  {
    state.is_cut = std::move(rerouted.is_cut);
    state.chart = std::move(rerouted.chart);
    state.corner_uv = std::move(rerouted.corner_uv);
    state.x = std::move(rerouted.x);
    unboxed = rerouted_unboxed;
  }
  return solved_through ? OK : final_solve_box(settings, unboxed, state);
}

/// At most `iterations` Newton iterations on the map of `s` (weights 1, no
/// box, no barrier), which judge a trial cut or zip; `s.distortion` is set
/// to the E_d they leave.
inline Error_code relax_map(int iterations, double tolerance, Inner_solver solver, Joint_state& s)
{
  Distortion_minimizer minimizer(s.chart, std::vector<double>(s.chart.number_of_faces(), 1.), false, 0., 0., solver);
  const Newton_report report = minimizer.minimize(s.x, iterations, tolerance);
  s.count(report);
  s.distortion = mean_distortion(s.chart, s.x);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// Without a bound, splits start on a map with E_d above this: the field v
/// could not place the cuts (low-poly models: CGAL's cube.off 6.53,
/// octahedron.off 6.21, icosahedron.off 5.35, cross.off 7.20, where the 15
/// disk meshes of the benchmark end at 4.62 at most).
constexpr double low_poly_distortion = 5.;
/// Without a bound, a map whose E_d is above this (but not above
/// low_poly_distortion) is split until it is not, each split paying for its
/// seams as below. Models from the wild ended at E_d up to 4.79 (CGAL's
/// femur.off), three benchmark meshes above 4.6. Measured (2 cores), E_d,
/// E_s: planck1 4.635, 2.155 -> 4.589, 2.265 (the reference's E_d now met);
/// face_f10000 4.625, 2.391 -> 4.590, 2.515; camel_simple 4.704, 8.223 ->
/// 4.508, 8.526. Splitting on while splits pay, as below 5 (no target),
/// went much further: planck1 4.224, 3.652. Not on a mesh of more than
/// twice multiresolution_faces faces, where each trial and the final solve
/// after the splits are solves of the whole map (femur.off refined to 125k
/// faces went from 58 s to 110 s for E_d 4.632 -> 4.536): there the copy
/// is split instead (split_on_coarse_copy()).
constexpr double default_distortion_target = 4.6;

/// Newton iterations at most of each solve of the overlap-free pieces in
/// final_solve_after_splits(). Their barrier's solves are slow to converge
/// (pieces apart by piece_gap): on the 8 models of wild_corpus.py cut from
/// CGAL's mpi.off and mpi_triang.off (none, holes, fins, parts; 2 cores,
/// while a fuzzer ran), half of their 23 solves of mpi_triang.none stopped at
/// 500; at most 50 each, all 8 end at E_d 4.02 to 4.59 (at most 500: 4.00
/// to 4.59), 0.1 to 4.4 s (at most 500: 0.2 to 8.7 s; 0.6 to 1.9 s without
/// the pieces).
constexpr int split_pieces_newton_iterations = 50;

/// The final solve of `state`, a map that greedy splits left (judged
/// without the border barrier), with `carried` (the map the splits started
/// from, carried over their cuts); sets `state.distortion`. With global
/// injectivity, on a cut mesh of at most `settings.split_pieces_max_faces`
/// faces, where a chart crossed itself and started again from its carried
/// or Tutte map, and E_d ends above `goal`, the split map is solved again
/// with its crossing charts cut into overlap-free pieces instead
/// (overlap_partition.h, as final_solve_without_box() does for large
/// overlaps), each piece from its part of the split map; the lower E_d is
/// kept. On a low-poly model the splits' maps reach low E_d by borders that
/// cross, and the valid map from which the chart starts again stays far
/// above: the damaged models of wild_corpus.py cut from CGAL's mpi.off (174
/// to 195 faces) ended at E_d 5.12 to 5.80 where the undamaged one ends at
/// 4.59.
///
/// Each solve of the pieces stops after split_pieces_newton_iterations.
template <typename Surface>
Error_code final_solve_after_splits(const Surface& surface, const Joint_settings& settings, double goal,
                                    const Carried_map* carried, Joint_state& state)
{
  const bool may_cut = settings.global_injectivity && goal > 0. && settings.split_pieces_max_faces > 0
                       && state.chart.number_of_faces() <= std::size_t(settings.split_pieces_max_faces);
  Joint_state pieces;
  if(may_cut) pieces = state;
  bool restarted = false;
  Error_code status = final_solve(surface, settings, false, state, carried, &restarted);
  if(status != OK) return status;
  state.distortion = mean_distortion(state.chart, state.x);
  if(!may_cut || !restarted || state.distortion <= goal) return OK;
  Joint_settings cut_up = settings;
  cut_up.overlap_partition_faces = 1; // any chart that overlaps itself
  cut_up.max_newton_iterations = (std::min)(settings.max_newton_iterations, split_pieces_newton_iterations);
  pieces.set_work(state.work());
  if((status = final_solve(surface, cut_up, false, pieces)) != OK) return status;
  pieces.distortion = mean_distortion(pieces.chart, pieces.x);
  if(pieces.distortion < state.distortion) state = std::move(pieces);
  else state.set_work(pieces.work());
  return OK;
}

/// Greedy splits (greedy_splits.h) of the solved cut mesh in `state`: under
/// `settings.distortion_bound`, while E_d is above it and a split lowers it;
/// without a bound, on a map whose E_d is above default_distortion_target
/// (above low_poly_distortion on a large mesh),
/// while a split pays for its seams (Split_settings::gain) and, unless the
/// map started above low_poly_distortion, E_d is above that target; then,
/// where no split pays and E_d is still above the default target (not on a
/// large mesh), while a split lowers it, as under a bound (ArtDemo.obj: E_d
/// 4.695 -> 4.595, E_s 16.77 -> 17.24, 40 -> 43 s; the benchmark's meshes
/// and CGAL's low-poly models end below 4.6 first, unchanged). Never
/// when the seams are the user's alone (no pass).
///
/// A split is judged after a few Newton iterations without box and border
/// barrier (Split_settings::newton_iterations) from the map carried over
/// the cut, against the map without box: with a whole final solve per trial
/// (box, crossing check), ArtDemo.obj of the OptCuts set (15k faces) took
/// tens of seconds per split; now 66 s in all for E_d 6.41 -> 4.99. Once no
/// split is kept, the final solve runs again (box, no crossing border).
/// Under a bound or down to the default target it may end above it (the
/// box's share of E_d, a final solve converged further than the trials):
/// the splits go on from there, three rounds at most (femur.off: 4.60023
/// after the first). Splitting nothing leaves
/// `state` as it was.
///
/// A chart that crosses itself in that final solve starts again from the
/// valid map the splits started from, carried over their cuts
/// (carry_map_over_new_cuts()), not from its Tutte map: with the barrier,
/// most of a Tutte start's iterations grow the map back to where it was.
/// Measured (2 cores) on ArtDemo with holes (wild_corpus.py), whose largest
/// chart (13,370 of 14,182 faces) crosses itself in both rounds' final
/// solves: 2,258 -> 2,108 Newton iterations, 32.5 -> 29.3 s, E_d 4.5874 ->
/// 4.5911, coverage 0.537 -> 0.556; on the benchmark, hand1 384 -> 357 and
/// camel_simple 852 -> 806 iterations (E_d +0.0013), the 19 others the same.
template <typename Surface>
Error_code split_where_distorted(const Surface& surface, const Joint_settings& settings, Joint_state& state)
{
  const bool bounded = settings.distortion_bound > 0.;
  const bool large = settings.multiresolution_faces > 0
                     && state.chart.number_of_faces() > 2 * std::size_t(settings.multiresolution_faces);
  // (the default target only where a split's trial is not a solve of a large map)
  const double target = large ? low_poly_distortion : default_distortion_target;
  if(!settings.greedy_splits || settings.passes == 0 || (!bounded && state.distortion <= target))
    return OK;
  // each trial (a split judged) is reported, and can be canceled
  // (each trial solves the charts its cut runs through: relax_charts())
  auto relax = [&](Joint_state& s, const std::vector<char>& faces) {
    if(settings.progress && !settings.progress({"split", settings.passes, 0, settings.alternations_per_pass(),
                                                settings.epsilon_end, s.distortion}))
      return ERROR_CANCELED;
    return relax_charts(settings.split.newton_iterations, settings.constrained_tolerance, settings.inner_solver, faces, s);
  };
  // a split pays for its seams (Split_settings::gain), or (under a bound, and
  // toward the default target once none pays) lowers E_d
  auto pays = [&](double before, double after, double added) { return before - after >= settings.split.gain * added; };
  auto lowers = [](double before, double after, double) { return after < before; };
  // On a large mesh every trial is a solve of the whole map: the splits go
  // in batches there, one per 10k faces (at most 16; greedy_splits.h).
  Split_settings split_settings = settings.split;
  if(large)
    split_settings.batch = int((std::min)(std::size_t(16), state.chart.number_of_faces() / std::size_t(settings.multiresolution_faces)));
  // the E_d to reach: the bound, else the default target (none on a large mesh)
  const double goal = bounded ? settings.distortion_bound : (large ? 0. : default_distortion_target);
  // without a bound, a map that started between the default target and
  // low_poly_distortion is split down to the target, one above only while splits pay
  const bool to_target = !bounded && state.distortion <= low_poly_distortion;
  for(int round = 0; round < 3; ++round)
  {
    Joint_state split = state;
    Error_code status = relax(split, {}); // the baseline: the map without box
    if(status != OK) return status;
    // the map without box must leave room for the box's share of E_d
    const double box_share = (std::max)(0., state.distortion - split.distortion);
    int kept = 0;
    if(!bounded)
    {
      const double stop_at = to_target ? goal - box_share : 0.;
      status = split_greedily(surface, split_settings, stop_at, relax, pays, split, kept);
      if(status != OK) return status;
    }
    if(goal > 0. && split.distortion > goal - box_share)
    {
      int more = 0;
      status = split_greedily(surface, split_settings, goal - box_share, relax, lowers, split, more);
      if(status != OK) return status;
      kept += more;
    }
    if(kept == 0)
    {
      state.set_work(split.work()); // the trials' work
      return OK;
    }
    Carried_map carried;
    if(settings.global_injectivity) carry_map_over_new_cuts(state.chart, state.x, split.chart, carried);
    state = std::move(split);
    status = final_solve_after_splits(surface, settings, goal, settings.global_injectivity ? &carried : nullptr, state);
    if(status != OK) return status;
    if(!(goal > 0. && state.distortion > goal)) break;
  }
  return OK;
}

/// Completes `state.is_cut` into a cut that leaves every component a disk,
/// builds the chart mesh and its Tutte map.
template <typename Surface>
Error_code initial_map(const Surface& surface, Joint_state& state)
{
  if(!make_disks(surface, state.is_cut, state.rules))
    return state.rules.forbidden.empty() ? ERROR_NO_TOPOLOGICAL_DISC : ERROR_FORBIDDEN_EDGES_BLOCK_CUT;
  state.degenerate_faces = build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  const Embedding_status embedding = disk_charts_embedding(state.chart, state.x);
  if(embedding == Embedding_status::NOT_DISKS) return ERROR_NO_TOPOLOGICAL_DISC;
  if(embedding == Embedding_status::SOLVE_FAILED) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(embedding == Embedding_status::FLIPPED) return ERROR_NO_1_TO_1_MAPPING;
  return OK;
}

/// The initial cut and map of `state` (initial_map()), its E_d, and the
/// progress report "initialize".
template <typename Surface>
Error_code start_cut_mesh(const Surface& surface, const Joint_settings& settings, Joint_state& state)
{
  Scoped_timer initialization(state.timings.initialization);
  const Error_code initial = initial_map(surface, state);
  if(initial != OK) return initial;
  state.initial_distortion = mean_distortion(state.chart, state.x);
  initialization.stop();
  if(settings.progress && !settings.progress({"initialize", 0, 0, settings.alternations_per_pass(),
                                              settings.epsilon_start, state.initial_distortion}))
    return ERROR_CANCELED;
  return OK;
}

/// Where to cut: from `state.is_cut` (seams given by the user), the initial
/// cut and map (unless `state.first_u_step_done`), then the passes of the
/// alternation, each cutting along the paths of v. Leaves the cut mesh and
/// its map (not yet solved) in `state`.
template <typename Surface>
Error_code decide_cuts(const Surface& surface, const std::vector<double>& face_lambda,
                       const Joint_settings& settings, Joint_state& state)
{
  if(!state.first_u_step_done)
  {
    const Error_code initial = start_cut_mesh(surface, settings, state);
    if(initial != OK) return initial;
  }

  for(int pass = 0; pass < settings.passes; ++pass)
  {
    std::vector<Cut_path> paths;
    const Error_code status = alternate(surface, face_lambda, settings, pass, state, paths);
    if(status != OK) return status;
    if(paths.empty()) break;
    Scoped_timer extraction(state.timings.cut_extraction);
    apply_cuts(surface, paths, state);
    extraction.stop();
    if(settings.progress && !settings.progress({"cut", pass, settings.alternations_per_pass(),
                                                settings.alternations_per_pass(), settings.epsilon_end,
                                                mean_distortion(state.chart, state.x)}))
      return ERROR_CANCELED;
  }
  return OK;
}

/// The greedy splits of a large mesh, decided on its simplified copy from
/// the copy's cuts (decide_cuts_on_coarse_copy()): the copy's map is solved
/// (final_solve()) and split where distorted as any mesh of its size
/// (split_where_distorted(), down to default_distortion_target); the seams
/// of the splits join the cuts that go back to the input. At full
/// resolution each trial and the final solve after the splits would be
/// solves of the whole map. The copy's solved map ends above the input's
/// from the same cuts (E_d measured, copy / input, 2 cores: femur.off
/// refined to 125k faces 4.798 / 4.643, CGAL's man.off 4.454 / 4.385,
/// armadillo.off 4.514 / 4.444, feline_half 4.470 / 4.429), so that a copy
/// split down to the target leaves the input below it. Without a bound
/// only (under a bound the input's own splits go to the bound). The copy's
/// cuts stay as they were where no split is kept or a solve fails; a
/// cancel is returned.
template <typename Surface>
Error_code split_on_coarse_copy(const Surface& coarse_surface, const Joint_settings& settings, Joint_state& coarse_state)
{
  if(!settings.greedy_splits || settings.distortion_bound > 0.) return OK;
  const std::vector<char> cuts = coarse_state.is_cut; // where a solve fails
  Error_code status = OK;
  {
    Scoped_timer timer(coarse_state.timings.final_solve);
    status = final_solve(coarse_surface, settings, false, coarse_state);
  }
  if(status == OK)
  {
    coarse_state.distortion = mean_distortion(coarse_state.chart, coarse_state.x);
    status = split_where_distorted(coarse_surface, settings, coarse_state);
  }
  if(status == ERROR_CANCELED) return status;
  if(status != OK) coarse_state.is_cut = cuts;
  return OK;
}

/// decide_cuts() on a copy simplified to about `settings.multiresolution_faces`
/// faces (multiresolution.h) and split there (split_on_coarse_copy()), its
/// cuts carried back to `surface`, then the initial map of `surface` cut
/// there. The Newton counts and the times of
/// the copy are added to `state`; `initial_distortion` is the copy's. Returns
/// false, with `state` untouched, if the copy could not be made.
template <typename Surface>
bool decide_cuts_on_coarse_copy(const Surface& surface, const std::vector<double>& face_lambda,
                                const Joint_settings& settings, Joint_state& state, Error_code& status)
{
  Scoped_timer initialization(state.timings.initialization);
  Coarse_surface coarse;
  if(!simplify_surface(surface, state.is_cut, state.rules.forbidden, face_lambda, std::size_t(settings.multiresolution_faces),
                       coarse))
    return false;
  initialization.stop();
  // The seam cost is λ·ℓ per unit of length (ℓ: the mean edge length, METHOD.md
  // "Scale"), so the copy's longer edges make seams dearer; but the copy also
  // resolves less distortion, which pulls the other way. Its λ is scaled by
  // (ℓ_input / ℓ_copy)^(1/4), measured against full-resolution runs (2 cores;
  // E_d, E_s, with the copy at 10k faces, exponents 0 / 1/4 / 1/2 / 1):
  //   bimba_i_f10000 x4 (40k faces), full 4.294, 3.048: 4.327, 2.729 /
  //     4.321, 3.057 / - / 4.180, 4.049;
  //   CGAL armadillo.off (52k), full 4.395, 6.767: 4.529, 6.085 / 4.447, 6.749 / 4.405, 7.225;
  //   CGAL man.off (35k), full 4.397, 7.925: 4.405, 8.368 / 4.369, 7.880;
  //   CGAL diplodocus.off (48k), full 4.549, 6.138: 4.323, 9.012 / 4.324, 9.007 / 4.380, 8.755.
  Joint_settings coarse_settings = settings;
  coarse_settings.lambda *= std::pow(mean_edge_length(surface) / mean_edge_length(coarse.surface), 0.25);
  Joint_state coarse_state;
  coarse_state.is_cut = coarse.is_cut;
  coarse_state.rules.forbidden = coarse.forbidden;
  coarse_state.rules.edge_factor = edge_lambda_factors(coarse.surface, coarse.face_lambda);
  status = decide_cuts(coarse.surface, coarse.face_lambda, coarse_settings, coarse_state);
  if(status == OK) status = split_on_coarse_copy(coarse.surface, coarse_settings, coarse_state);
  state.add_work(coarse_state);
  state.u_step_work += coarse_state.u_step_work;
  state.v_step_factorizations += coarse_state.v_step_factorizations;
  state.initial_distortion = coarse_state.initial_distortion;
  state.timings.add(coarse_state.timings); // its final solve: that of its splits
  if(status != OK) return true;
  Scoped_timer extraction(state.timings.cut_extraction);
  transfer_cuts(surface, coarse, coarse_state.is_cut, state.rules, state.is_cut);
  if(coarse_state.v.size() > 0) state.v = transfer_face_field(surface, coarse, coarse_state.v);
  extraction.stop();
  Scoped_timer full_resolution(state.timings.initialization);
  status = initial_map(surface, state);
  return true;
}

/// The per-face λ with the forbidden edges' faces made dear
/// (lambda_with_forbidden_faces()); sets the cost of cutting each edge in
/// `state.rules` from it.
template <typename Surface>
std::vector<double> cut_costs(const Surface& surface, const std::vector<double>& input_face_lambda, Joint_state& state)
{
  std::vector<double> face_lambda = lambda_with_forbidden_faces(surface, input_face_lambda, state.rules.forbidden);
  state.rules.edge_factor = edge_lambda_factors(surface, face_lambda);
  return face_lambda;
}

/// True if optimize_cut_mesh() decides the cuts on a simplified copy.
template <typename Surface>
bool cuts_on_coarse_copy(const Surface& surface, const Joint_settings& settings)
{
  return settings.multiresolution_faces > 0 && settings.passes > 0
         && surface.number_of_faces() > 2 * std::size_t(settings.multiresolution_faces);
}

/// What every run of optimize_cut_mesh() from `state` does first whatever
/// its λ: the initial cut and map, and the alternation's first u-step, whose
/// weights are v² + γ with v = 1 (λ enters at the first v-step). Sets
/// `state.first_u_step_done`, so that the runs from `state` start at the
/// first v-step; a λ search (distortion_bound.h) does this once for all its
/// trials. Leaves `state` as it was where the cuts are decided on a
/// simplified copy (cuts_on_coarse_copy()) or there is no pass.
template <typename Surface>
Error_code prepare_first_u_step(const Surface& surface, const std::vector<double>& input_face_lambda,
                                const Joint_settings& settings, Joint_state& state)
{
  if(!settings.valid()) return ERROR_WRONG_PARAMETER;
  if(settings.passes == 0 || cuts_on_coarse_copy(surface, settings)) return OK;
  cut_costs(surface, input_face_lambda, state);
  const Error_code status = start_cut_mesh(surface, settings, state);
  if(status != OK) return status;
  state.v = Eigen::VectorXd::Ones(Eigen::Index(surface.number_of_faces()));
  Scoped_timer setup(state.timings.u_steps);
  Distortion_minimizer minimizer(state.chart, std::vector<double>(surface.number_of_faces(), 1.), false, 0., 0.,
                                 settings.inner_solver);
  setup.stop();
  const Error_code first = u_step(settings, 0, minimizer, state);
  if(first != OK) return first;
  state.first_u_step_done = true;
  return OK;
}

/// The method from `state.is_cut` (seams given by the user) up to the
/// solved cut mesh: where to cut (on a simplified copy for large meshes),
/// the final solve, the greedy splits; `state.distortion` is its E_d. The
/// charts are not packed yet (finish_atlas()).
template <typename Surface>
Error_code optimize_cut_mesh(const Surface& surface, const std::vector<double>& input_face_lambda,
                             const Joint_settings& settings, Joint_state& state)
{
  if(!settings.valid()) return ERROR_WRONG_PARAMETER;
  const std::vector<double> face_lambda = cut_costs(surface, input_face_lambda, state);
  const std::vector<char> user_cut = state.is_cut;
  Error_code status = OK;
  const bool coarse = cuts_on_coarse_copy(surface, settings)
                      && decide_cuts_on_coarse_copy(surface, face_lambda, settings, state, status);
  if(!coarse) status = decide_cuts(surface, face_lambda, settings, state);
  if(status != OK) return status;

  Scoped_timer final_timer(state.timings.final_solve);
  Joint_settings final_settings = settings;
  if(coarse) final_settings.box_tolerance = settings.large_mesh_box_tolerance;
  // the map is still the Tutte map where no alternation ran on this mesh
  const Error_code final_status =
    final_solve_with_rerouting(surface, final_settings, user_cut, coarse || settings.passes == 0, state);
  if(final_status != OK) return final_status;
  state.distortion = mean_distortion(state.chart, state.x);
  return split_where_distorted(surface, final_settings, state);
}

/// Packs the charts of the solved cut mesh in `state` and checks the result
/// (finite, no flipped face, no forbidden edge cut).
inline Error_code finish_atlas(const Joint_settings& settings, Joint_state& state)
{
  Scoped_timer packing_timer(state.timings.packing);
  state.packing = pack_charts(state.chart, state.x, settings.packing);
  packing_timer.stop();
  // never hand out a silently wrong map (checked in every build type)
  if(!state.x.allFinite() || number_of_flipped_faces(state.chart, state.x) > 0) return ERROR_NO_1_TO_1_MAPPING;
  for(std::size_t e = 0; e < state.rules.forbidden.size(); ++e)
    if(state.rules.forbidden[e] && state.is_cut[e]) return ERROR_FORBIDDEN_EDGES_BLOCK_CUT;
  if(settings.progress && !settings.progress({"final", settings.passes, 0, settings.alternations_per_pass(),
                                              settings.epsilon_end, state.distortion}))
    return ERROR_CANCELED;
  return OK;
}

/// The whole method from `state.is_cut` (seams given by the user):
/// optimize_cut_mesh(), then finish_atlas(). Fills the rest of `state`.
template <typename Surface>
Error_code joint_optimization(const Surface& surface, const std::vector<double>& input_face_lambda,
                              const Joint_settings& settings, Joint_state& state)
{
  const Error_code status = optimize_cut_mesh(surface, input_face_lambda, settings, state);
  return status != OK ? status : finish_atlas(settings, state);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
