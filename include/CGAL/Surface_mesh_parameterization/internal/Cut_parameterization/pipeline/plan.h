// The plan: the one place that decides which stages run, in which order and
// with which arguments. The default run (where to cut, on a simplified copy
// for large meshes; the final solve, with the seams rerouted beside it; the
// greedy splits and the final solve after them, with overlap-free pieces on
// low-poly models; the packing), the default target (the bound search at
// tuning::default_distortion_target where the default run ends above it on
// a small mesh) and the bound search (pipeline/bound_search.h, a peer
// strategy given the default run as its trial). Measurements behind each
// decision: doc/design/pipeline.dox.
#ifndef CGAL_SMP_CUT_INTERNAL_PLAN_H
#define CGAL_SMP_CUT_INTERNAL_PLAN_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/carried_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/greedy_splits.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/alternation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/bound_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/final_solve.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/finish_atlas.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/multiresolution.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progress.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progressive_simplification.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/relax.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/two_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/hard_edges.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_merging.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/seam_straightening.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The explicit inputs of one run of the method (optimize_cut_mesh()),
/// built here only: the default run's from the options, the bound search's
/// trials from it.
struct Run_args
{
  double lambda = 1.;  // the seam cost of the alternation
  double bound = 0.;   // the E_d the splits go to (0: none, the default target)
  bool splits = true;  // greedy splits after the final solve
  int rerouting_rings = tuning::rerouting_rings; // the alternation's seams rerouted beside the final solve (0: never)
  double rerouting_allowance = tuning::rerouting_allowance;
  Final_solve_args final; // barrier, box, pieces, iterations, solver
  Split_settings split;
};

/// True if the options can be run.
inline bool valid_options(const Cut_parameterization_options& o)
{
  const double aspect = o.bounding_box_aspect_ratio_value(), stiffness = o.bounding_box_stiffness_value();
  return o.lambda > 0. && o.epsilon_start > 0. && o.epsilon_end > 0. && o.epsilon_end <= o.epsilon_start
      && o.iterations_per_epsilon >= 1 && o.gamma > 0. && o.number_of_passes >= 0 && o.number_of_iterations >= 1
      && o.minimum_relative_cut_length >= 0. && o.minimum_relative_cut_length <= 1.
      && aspect >= 0. && std::isfinite(aspect) && stiffness >= 0. && std::isfinite(stiffness)
      && o.bounding_box_distortion_budget_value() >= 0. && o.multiresolution_faces >= 0
      && (o.distortion_bound == 0. || (o.distortion_bound >= 4. && std::isfinite(o.distortion_bound)))
      && o.texture_size >= 1 && o.padding >= 0. && std::isfinite(o.padding)
      && (!o.split_charts_for_packing || (*o.split_charts_for_packing > 0. && *o.split_charts_for_packing <= 1.));
}

/// The default run's arguments: the user's λ and box, no bound.
inline Run_args default_run_args(const Cut_parameterization_options& o)
{
  Run_args run;
  run.lambda = o.lambda;
  run.final.global_injectivity = o.global_injectivity;
  run.final.box.aspect_ratio = o.bounding_box_aspect_ratio_value();
  run.final.box.stiffness = o.bounding_box_stiffness_value();
  run.final.box.budget = o.bounding_box_distortion_budget_value();
  run.final.max_iterations = o.number_of_iterations;
  run.final.solver = o.inner_solver;
  if(o.preset == Preset::FAST)
  {
    run.rerouting_rings = 0;
    run.final.tolerance_factor = tuning::fast_tolerance_factor;
  }
  return run;
}

/// True if a mesh is large: its trials are solves of the whole map.
inline bool is_large(std::size_t faces, const Cut_parameterization_options& o)
{
  return o.multiresolution_faces > 0 && faces > 2 * std::size_t(o.multiresolution_faces);
}

/// True if the cuts are decided on a simplified copy (multiresolution.h).
template <typename Surface>
bool cuts_on_coarse_copy(const Surface& surface, const Cut_parameterization_options& o)
{
  return o.number_of_passes > 0 && is_large(surface.number_of_faces(), o);
}

/// Greedy splits of `state` (solved, `state.distortion` its E_d) from
/// `baseline` (its map relaxed without box) under `goal` (0: none): while a
/// split pays for its seams (without a bound; down to `goal` if `to_target`),
/// then while a split lowers E_d down to `goal`. `kept` counts the splits.
template <typename Surface, typename Relax>
Error_code split_toward(const Surface& surface, const Run_args& run, const Split_settings& split, double goal,
                        bool to_target, double box_share, Relax& relax, Map_state& baseline, Work_log& log, int& kept)
{
  // a split pays for its seams (Split_settings::gain), or lowers E_d
  auto pays = [&](double before, double after, double added) { return before - after >= split.gain * added; };
  auto lowers = [](double before, double after, double) { return after < before; };
  Error_code status = OK;
  kept = 0;
  if(!(run.bound > 0.))
  {
    const double stop_at = to_target ? goal - box_share : 0.;
    if((status = split_greedily(surface, split, stop_at, relax, pays, baseline, log, kept)) != OK) return status;
  }
  if(goal > 0. && baseline.distortion > goal - box_share)
  {
    int more = 0;
    if((status = split_greedily(surface, split, goal - box_share, relax, lowers, baseline, log, more)) != OK)
      return status;
    kept += more;
  }
  return OK;
}

/// Greedy splits of the solved cut mesh in `state` where it is distorted:
/// under `run.bound` while E_d is above it; without, above
/// tuning::default_distortion_target (tuning::low_poly_distortion on a
/// large mesh, in batches), while splits pay and down to the target; each
/// trial judged by relax_charts() and reported ("split"); then the final
/// solve after the splits under `final`, from the map carried over their
/// cuts; up to tuning::split_rounds rounds while E_d ends above the goal.
template <typename Surface>
Error_code split_where_distorted(const Surface& surface, const Cut_parameterization_options& o,
                                 const Progress& progress, const Run_args& run, const Final_solve_args& final,
                                 Map_state& state, Work_log& log)
{
  const bool bounded = run.bound > 0.;
  const bool large = is_large(state.chart.number_of_faces(), o);
  const double target = large ? tuning::low_poly_distortion : tuning::default_distortion_target;
  if(!run.splits || o.number_of_passes == 0 || (!bounded && state.distortion <= target)) return OK;
  auto relax = [&](Map_state& s, Work_log& l, const std::vector<char>& faces) {
    if(progress && !progress(progress_report("split", o.number_of_passes, 0, alternations_per_pass(o), o.epsilon_end,
                                             s.distortion)))
      return ERROR_CANCELED;
    return relax_charts(run.split.newton_iterations, tuning::constrained_tolerance, o.inner_solver, faces, s, l);
  };
  Split_settings split = run.split;
  if(large)
    split.batch = int((std::min)(tuning::split_batch_max,
                                 state.chart.number_of_faces() / std::size_t(o.multiresolution_faces)));
  // a CAD part splits once per feature (hundreds of splits, each judged by a relaxation of its
  // charts): splits in batches, and in one round (each round ends in a final solve under the barrier)
  if(is_hard_surface(surface))
  {
    split.batch = (std::max)(split.batch, tuning::hard_surface_split_batch);
    split.max_splits = (std::max)(split.max_splits, tuning::hard_surface_max_splits);
  }
  const double goal = bounded ? run.bound : (large ? 0. : tuning::default_distortion_target);
  const bool to_target = !bounded && state.distortion <= tuning::low_poly_distortion;
  Final_solve_args pieces = final; // the pieces' solve: any chart that overlaps itself, fewer iterations
  pieces.overlap_partition_faces = 1;
  pieces.max_iterations = (std::min)(final.max_iterations, tuning::split_pieces_newton_iterations);
  for(int round = 0; round < tuning::split_rounds; ++round)
  {
    Map_state split_state = state;
    Error_code status = relax(split_state, log, {}); // the baseline: the map without box
    if(status != OK) return status;
    // the map without box must leave room for the box's share of E_d
    const double box_share = (std::max)(0., state.distortion - split_state.distortion);
    int kept = 0;
    status = split_toward(surface, run, split, goal, to_target, box_share, relax, split_state, log, kept);
    if(status != OK) return status;
    if(kept == 0) return OK;
    Carried_map carried;
    if(final.global_injectivity) carry_map_over_new_cuts(state.chart, state.x, split_state.chart, carried);
    state = std::move(split_state);
    status = final_solve_after_splits(surface, final, pieces, goal, final.global_injectivity ? &carried : nullptr,
                                      state, log);
    if(status != OK) return status;
    if(!(goal > 0. && state.distortion > goal)) break;
  }
  return OK;
}

/// `final` on `surface`: on a hard-surface part (is_hard_surface()) the
/// barrier's solve of charts cut into overlap-free pieces is capped.
template <typename Surface>
Final_solve_args final_args_on(const Surface& surface, Final_solve_args final)
{
  if(is_hard_surface(surface)) final.pieces_max_iterations = tuning::hard_surface_pieces_newton_iterations;
  return final;
}

/// The copy's cuts split as any mesh of its size (without a bound only): its
/// map solved, then split_where_distorted(); the copy's cuts stay as they
/// were where no split is kept or a solve fails; a cancel is returned.
template <typename Surface>
Error_code split_on_coarse_copy(const Surface& coarse_surface, const Cut_parameterization_options& o,
                                const Progress& progress, const Run_args& run, Map_state& coarse_state, Work_log& log)
{
  if(!run.splits || run.bound > 0.) return OK;
  const std::vector<char> cuts = coarse_state.is_cut; // where a solve fails
  const Final_solve_args final = final_args_on(coarse_surface, run.final);
  Error_code status = OK;
  {
    Scoped_timer timer(log.timings.final_solve);
    status = final_solve(coarse_surface, final, false, coarse_state, log);
  }
  if(status == OK)
  {
    coarse_state.distortion = mean_distortion(coarse_state.chart, coarse_state.x);
    status = split_where_distorted(coarse_surface, o, progress, run, final, coarse_state, log);
  }
  if(status == ERROR_CANCELED) return status;
  if(status != OK) coarse_state.is_cut = cuts;
  return OK;
}

/// True if the copy that decides the cuts of `surface` is made on the index
/// arrays (simplify_for_carrying(), about three times faster) rather than by
/// CGAL's edge collapse (simplify_surface()): under Preset::FAST, but for a
/// hard-surface part (is_hard_surface()). Another copy moves the cuts
/// (doc/design/pipeline.dox): the default keeps CGAL's, and so does a CAD
/// part, whose cuts from the other copy were slower to solve.
template <typename Surface>
bool cuts_copy_on_index_arrays(const Surface& surface, const Cut_parameterization_options& o)
{
  return o.preset == Preset::FAST && !is_hard_surface(surface);
}

/// True if the copy that decides the cuts of `surface` is made in two
/// stages (simplify_surface_in_two_stages(), first to
/// tuning::staged_cut_copy_ratio times the copy's faces): above
/// tuning::staged_cut_copy_min_ratio times them, but for a hard-surface part.
/// CGAL's collapse of the whole input took a third of a 640k-face run; the
/// first stage moves the cuts a little (doc/design/pipeline.dox).
template <typename Surface>
bool cuts_copy_in_two_stages(const Surface& surface, const Cut_parameterization_options& o)
{
  return surface.number_of_faces() > tuning::staged_cut_copy_min_ratio * std::size_t(o.multiresolution_faces)
         && !is_hard_surface(surface);
}

/// decide_cuts() on a copy simplified to about `o.multiresolution_faces`
/// faces (cuts_copy_on_index_arrays() and cuts_copy_in_two_stages() tell how),
/// at λ scaled by (ℓ_input / ℓ_copy)^tuning::coarse_lambda_exponent,
/// split there (split_on_coarse_copy()), its cuts carried back to `surface`,
/// then the cut mesh of `surface` cut there, without a map (the plan
/// chooses its start); `initial_distortion` is the copy's. Returns false,
/// with `state` untouched, if the copy could not be made.
template <typename Surface>
bool decide_cuts_on_coarse_copy(const Surface& surface, const std::vector<double>& face_lambda,
                                const Cut_parameterization_options& o, const Progress& progress, const Run_args& run,
                                Map_state& state, Work_log& log, Error_code& status)
{
  Scoped_timer initialization(log.timings.initialization);
  Coarse_surface coarse;
  const std::size_t faces = std::size_t(o.multiresolution_faces);
  const bool made
    = cuts_copy_on_index_arrays(surface, o)
        ? simplify_for_carrying(surface, state.is_cut, state.rules.forbidden, face_lambda, faces, coarse)
      : cuts_copy_in_two_stages(surface, o)
        ? simplify_surface_in_two_stages(surface, state.is_cut, state.rules.forbidden, face_lambda,
                                         tuning::staged_cut_copy_ratio * faces, faces, coarse)
        : simplify_surface(surface, state.is_cut, state.rules.forbidden, face_lambda, faces, coarse);
  if(!made) return false;
  initialization.stop();
  Run_args coarse_run = run; // the copy's longer edges make seams dearer, its coarser map pulls the other way
  coarse_run.lambda *= std::pow(mean_edge_length(surface) / mean_edge_length(coarse.surface),
                                tuning::coarse_lambda_exponent);
  Map_state coarse_state;
  coarse_state.is_cut = coarse.is_cut;
  coarse_state.rules.forbidden = coarse.forbidden;
  coarse_state.rules.edge_factor = edge_lambda_factors(coarse.surface, coarse.face_lambda);
  status = decide_cuts(coarse.surface, coarse.face_lambda, coarse_run.lambda, o, progress, coarse_state, log);
  if(status == OK) status = split_on_coarse_copy(coarse.surface, o, progress, coarse_run, coarse_state, log);
  state.initial_distortion = coarse_state.initial_distortion;
  if(status != OK) return true;
  Scoped_timer extraction(log.timings.cut_extraction);
  transfer_cuts(surface, coarse, coarse_state.is_cut, state.rules, state.is_cut);
  if(coarse_state.v.size() > 0) state.v = transfer_face_field(surface, coarse, coarse_state.v);
  extraction.stop();
  Scoped_timer full_resolution(log.timings.initialization);
  status = initial_cut_mesh(surface, state);
  return true;
}

/// The final solve of the cut mesh in `state` under `final`, with its seams
/// rerouted within `run.rerouting_rings` rings beside it
/// (final_solve_with_rerouting(); the edges flagged in `keep` stay) only
/// where the alternation ran on this mesh, from its map (not
/// `from_tutte_map`: seams from a simplified copy are shortest paths
/// already), up to two states at once, and where that map does not overlap
/// itself (it then starts again, as long as the rerouted seams' solve).
template <typename Surface>
Error_code final_solve_rerouted(const Surface& surface, const Final_solve_args& final, const Run_args& run,
                                const std::vector<char>& keep, bool from_tutte_map, Map_state& state, Work_log& log)
{
  Map_state rerouted;
  const bool have_rerouted = !from_tutte_map && run.rerouting_rings > 0
                             && surface.number_of_faces() <= tuning::two_states_at_once_max_faces
                             && !overlaps_itself(final.global_injectivity, state)
                             && rerouted_cut_mesh(surface, state, keep, run.rerouting_rings, false, rerouted);
  return final_solve_with_rerouting(surface, final, run.rerouting_allowance, from_tutte_map,
                                    have_rerouted ? &rerouted : nullptr, state, log);
}

/// The method from `state.is_cut` (seams given by the user) up to the
/// solved cut mesh under `run`: where to cut (on a simplified copy for large
/// meshes), the final solve (from a copy of the cut mesh solved and carried
/// back, start_from_solved_copy(), where the cuts came from a copy and the
/// mesh is not a hard-surface part, is_hard_surface(); the
/// alternation's seams rerouted beside it where it ran on this mesh, up to
/// two states at once), the greedy splits;
/// `state.distortion` is its E_d. The charts are not packed yet.
template <typename Surface>
Error_code optimize_cut_mesh(const Surface& surface, const std::vector<double>& input_face_lambda,
                             const Cut_parameterization_options& o, const Progress& progress, const Run_args& run,
                             Map_state& state, Work_log& log)
{
  const std::vector<double> face_lambda = cut_costs(surface, input_face_lambda, state);
  const std::vector<char> user_cut = state.is_cut;
  Error_code status = OK;
  const bool coarse = cuts_on_coarse_copy(surface, o)
                      && decide_cuts_on_coarse_copy(surface, face_lambda, o, progress, run, state, log, status);
  if(!coarse) status = decide_cuts(surface, face_lambda, run.lambda, o, progress, state, log);
  if(status != OK) return status;

  Scoped_timer final_timer(log.timings.final_solve);
  Final_solve_args final = final_args_on(surface, run.final);
  if(coarse) final.box.tolerance = tuning::large_mesh_box_tolerance;
  // cut on a copy, the input starts from a copy of its cut mesh solved and carried back; not a CAD
  // part: from its Tutte map, holes on one circle, the copy's solve under the barrier crawls
  Carried_map copy_start;
  if(coarse)
  {
    const std::size_t copy_faces = std::size_t(o.multiresolution_faces);
    status = is_hard_surface(surface) ? tutte_map(state)
                                      : start_from_solved_copy(surface, face_lambda,
                                                               solved_copy_faces(surface.number_of_faces(), copy_faces),
                                                               copy_faces, final, state, log, &copy_start);
    if(status != OK) return status;
  }
  // no alternation ran on this mesh: the map is its Tutte map or one carried (a start for the barrier)
  const bool from_tutte_map = coarse || o.number_of_passes == 0;
  // a chart started from the solved copy that crosses itself starts again from there, not from Tutte;
  // the box's budget was judged on the copy: above the ceiling or the default target here, the whole
  // final solve (without box, then the box within its budget) from the fitted map
  status = copy_start.valid.empty()
             ? final_solve_rerouted(surface, final, run, user_cut, from_tutte_map, state, log)
             : final_solve_from_carried(surface, final, from_tutte_map, copy_start,
                                        (std::min)(final.box.ceiling, tuning::default_distortion_target), state, log);
  if(status != OK) return status;
  state.distortion = mean_distortion(state.chart, state.x);
  return split_where_distorted(surface, o, progress, run, final, state, log);
}

/// A trial of the bound search without the alternation: from the initial
/// cut and map of `state` (with its first u-step where the search prepared
/// one), the final solve without box, then splits until E_d is within
/// `run.bound` (`best_candidate`: see Split_settings, judging
/// tuning::best_split_candidates vertices per split).
template <typename Surface>
Error_code split_from_start(const Surface& surface, const std::vector<double>& face_lambda,
                            const Cut_parameterization_options& o, const Progress& progress, const Run_args& run,
                            bool best_candidate, Map_state& state, Work_log& log)
{
  Run_args split_run = run;
  split_run.split.best_candidate = best_candidate;
  if(best_candidate) split_run.split.candidates = tuning::best_split_candidates;
  const bool from_tutte_map = !state.first_u_step_done;
  if(from_tutte_map)
  {
    cut_costs(surface, face_lambda, state);
    const Error_code status = start_cut_mesh(surface, o, progress, state, log);
    if(status != OK) return status;
  }
  Scoped_timer final_timer(log.timings.final_solve);
  const Error_code status = final_solve(surface, run.final, from_tutte_map, state, log);
  if(status != OK) return status;
  state.distortion = mean_distortion(state.chart, state.x);
  return split_where_distorted(surface, o, progress, split_run, run.final, state, log);
}

/// The final solve of `candidate` under `final` with the box only within
/// `bound` (its ceiling); `state` becomes the result if its E_d is within
/// the bound (`kept`).
template <typename Surface>
Error_code solve_within_bound(const Surface& surface, const Final_solve_args& final, double bound,
                              bool from_tutte_map, Map_state candidate, Map_state& state, Work_log& log, bool& kept)
{
  Final_solve_args bounded = final;
  bounded.box.ceiling = (std::min)(bound, final.box.ceiling);
  const Error_code status = final_solve(surface, bounded, from_tutte_map, candidate, log);
  if(status != OK) return status;
  candidate.distortion = mean_distortion(candidate.chart, candidate.x);
  kept = candidate.distortion <= bound;
  if(kept) state = std::move(candidate);
  return OK;
}

/// The bound search for `bound` (pipeline/bound_search.h) from `state`,
/// with this plan's steps: the trials are runs of optimize_cut_mesh() and
/// split_from_start() without the box and the rerouting (the bound's room
/// goes to shorter seams first), all from one start (the first u-step done
/// once); a candidate's seams are rerouted, zipped back and rerouted again
/// within the bound (seams/); the box comes last, within the bound.
template <typename Surface>
Error_code bounded_run(const Surface& surface, const std::vector<double>& face_lambda,
                       const Cut_parameterization_options& o, const Progress& progress, const Run_args& run,
                       double bound, Map_state& state, Work_log& log, bool& bound_met)
{
  const std::vector<char> user_cut = state.is_cut;
  Run_args unboxed = run;
  unboxed.bound = bound;
  unboxed.final.box.stiffness = 0.;
  unboxed.rerouting_rings = 0; // the candidates' seams are rerouted below, within the bound
  Map_state start = state;
  if(o.number_of_passes > 0 && !cuts_on_coarse_copy(surface, o))
  {
    const Error_code status = prepare_first_u_step(surface, face_lambda, o, progress, start, log);
    if(status != OK) return status;
  }
  std::mutex progress_mutex; // the trials report one at a time
  Progress locked;
  if(progress)
    locked = [&](const Cut_and_parameterize_progress& p) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      return progress(p);
    };
  auto trial = [&](double lambda, bool split_to_bound, Map_state& s, Work_log& l) {
    Run_args t = unboxed;
    t.lambda = lambda;
    if(!split_to_bound)
    {
      t.bound = 0.;
      t.splits = run.splits && lambda <= run.lambda; // above the given λ, splits cost time for little
    }
    s = start;
    return optimize_cut_mesh(surface, face_lambda, o, locked, t, s, l);
  };
  auto split_trial = [&](bool best_candidate, Map_state& s, Work_log& l) {
    s = start;
    return split_from_start(surface, face_lambda, o, locked, unboxed, best_candidate, s, l);
  };
  auto within = [&](bool from_tutte_map, Map_state candidate, Map_state& s, Work_log& l, bool& kept) {
    return solve_within_bound(surface, unboxed.final, bound, from_tutte_map, std::move(candidate), s, l, kept);
  };
  auto relax = [&](Map_state& s, Work_log& l) {
    return relax_map(tuning::merge_newton_iterations, tuning::constrained_tolerance, o.inner_solver, s, l);
  };
  auto shorten = [&](Map_state& s, Work_log& l) {
    if(o.number_of_passes == 0) return OK; // the seams are the user's alone
    const int rings = tuning::seam_straightening_rings;
    Error_code status = straighten_under_bound(surface, bound, rings, user_cut, within, s, l);
    if(status == OK) status = merge_under_bound(surface, bound, user_cut, relax, within, s, l);
    if(status == OK) status = straighten_under_bound(surface, bound, rings, user_cut, within, s, l);
    return status;
  };
  auto box = [&](Map_state& s, Work_log& l) {
    bool kept = false;
    return run.final.box.stiffness > 0. ? solve_within_bound(surface, run.final, bound, false, s, s, l, kept) : OK;
  };
  const auto steps = bound_search_steps(trial, split_trial, shorten, box);
  const bool split_trials = run.splits && o.number_of_passes > 0
                            && surface.number_of_faces() <= tuning::split_trial_max_faces;
  Bound_search<Surface, decltype(steps)> search(surface, bound, run.lambda, run.splits, split_trials, steps, log);
  return search.search(state, bound_met);
}

/// The run without a bound, and where it ends above the default target on
/// a small mesh (with splits and passes, and no box kept whatever it costs),
/// the bound search at that target from the same input, kept if it meets
/// it; the work of both runs adds up.
template <typename Surface>
Error_code default_target_run(const Surface& surface, const std::vector<double>& face_lambda,
                              const Cut_parameterization_options& o, const Progress& progress, const Run_args& run,
                              Map_state& state, Work_log& log, Packing_result& packing)
{
  const bool may_search = run.splits && o.number_of_passes > 0 && o.preset != Preset::FAST
                          && surface.number_of_faces() <= tuning::default_target_search_max_faces
                          && !(run.final.box.final_stiffness() > 0. && !std::isfinite(run.final.box.budget));
  Map_state input;
  if(may_search) input = state; // the search starts where the first run did
  Error_code status = optimize_cut_mesh(surface, face_lambda, o, progress, run, state, log);
  if(status == OK) status = finish_atlas(surface, o, progress, state, log, packing);
  if(!may_search || status != OK || !(state.distortion > tuning::default_distortion_target)) return status;
  Map_state search = std::move(input);
  Work_log search_log;
  Packing_result search_packing;
  bool met = false;
  status = bounded_run(surface, face_lambda, o, progress, run, tuning::default_distortion_target, search, search_log,
                       met);
  if(status == OK) status = finish_atlas(surface, o, progress, search, search_log, search_packing);
  if(status == ERROR_CANCELED) return status;
  log.add(search_log);
  if(status == OK && met)
  {
    state = std::move(search);
    packing = search_packing;
  }
  return OK;
}

/// The options of the run on `surface` (those of with_preset()): under the
/// fast preset, a hard-surface part (is_hard_surface()) gets the default's
/// copy (`multiresolution_faces` not below its default value): a copy of
/// fast_multiresolution_faces faces cannot hold its holes and creases.
template <typename Surface>
Cut_parameterization_options options_on(const Surface& surface, Cut_parameterization_options o)
{
  const int default_faces = Cut_parameterization_options().multiresolution_faces;
  if(o.preset == Preset::FAST && o.multiresolution_faces > 0 && o.multiresolution_faces < default_faces
     && 2 * std::size_t(o.multiresolution_faces) < surface.number_of_faces() && is_hard_surface(surface))
    o.multiresolution_faces = default_faces;
  return o;
}

/// The plan of cut_and_parameterize(): from `state.is_cut` (the user's
/// seams) and `state.rules`, the bound search where the options ask for a
/// bound, else the default target run; then the packing. `log` gets the
/// work of every stage.
template <typename Surface>
Error_code run_plan(const Surface& surface, const std::vector<double>& face_lambda,
                    const Cut_parameterization_options& preset_options, Map_state& state, Work_log& log,
                    Packing_result& packing, bool& bound_met)
{
  if(!valid_options(preset_options)) return ERROR_WRONG_PARAMETER;
  const Cut_parameterization_options o = options_on(surface, preset_options);
  const Progress& progress = o.progress_callback;
  const Run_args run = default_run_args(o);
  if(!(o.distortion_bound > 0.)) return default_target_run(surface, face_lambda, o, progress, run, state, log, packing);
  const Error_code status = bounded_run(surface, face_lambda, o, progress, run, o.distortion_bound, state, log,
                                        bound_met);
  return status != OK ? status : finish_atlas(surface, o, progress, state, log, packing);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
