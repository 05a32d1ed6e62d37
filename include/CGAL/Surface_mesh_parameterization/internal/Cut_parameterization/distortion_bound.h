// A distortion bound: the shortest seams whose map has E_d <= bound. Two
// kinds of trials, all from the same start (the initial cut and map, and the
// first u-step where the alternation runs: they do not depend on λ):
// - two split trials without the alternation (split_from_start()): cuts
//   added one at a time where the map is most distorted (greedy_splits.h,
//   OptCuts' split step) until the bound holds;
// - where neither reaches the bound, whole joint_optimization() runs with
//   other seam costs λ (the knob that trades seam length for distortion):
//   E_d falls as λ falls, so the search walks λ down (halving) until the
//   bound holds, or up (doubling) while it holds, then narrows λ once
//   between the largest passing and the smallest failing value above it (in
//   log scale).
// The trials go two at a time, run at once on two cores. The candidates are
// the passing split trials, or else the passing λ trial with the shortest
// seams (E_s is not monotone in λ: on hand1 of the OptCuts set the largest
// passing λ cut more); the seams of each are rerouted and zipped back
// within the bound, and the shortest win. If no trial passes, the splits
// take over from the least distorted λ trial and from the trial at the
// given λ; if still none passes, the trial with the lowest E_d is returned.
#ifndef CGAL_SMP_CUT_INTERNAL_DISTORTION_BOUND_H
#define CGAL_SMP_CUT_INTERNAL_DISTORTION_BOUND_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/joint_optimization.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seam_straightening.h>

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

/// How the search for a bound goes (the defaults are what `distortion_bound`
/// uses).
struct Bound_search_settings
{
  int steps_down = 6;   // halvings of λ at most (λ / 64)
  int steps_up = 3;     // doublings of λ at most (λ · 8)
  // rounds between failing and passing λ, each narrowing the interval 3
  // times. With the split trials, whose seams win on 9 of OptCuts' 11
  // bounds, 2 -> 1 round gave the same E_s on all 11 in 5-10% less time
  // (venus 1.15 -> 1.09 s, face_f10000 19.4 -> 17.9 s); 0 rounds lengthened
  // tooth's seams (E_s 0.242 -> 0.252), where a λ trial wins.
  int refinements = 1;
};

/// The final solve of `candidate` (from a Tutte map or from its own map),
/// with the box only within `settings.distortion_bound`; `state` becomes the
/// result if its E_d is within the bound (`kept`), else takes only its
/// Newton counts. A chart whose border crossed is solved again from its
/// Tutte map, which may end above the bound.
template <typename Surface>
Error_code solve_within_bound(const Surface& surface, const Joint_settings& settings, bool from_tutte_map,
                              Joint_state candidate, Joint_state& state, bool& kept)
{
  Joint_settings bounded = settings;
  bounded.bounding_box_distortion_ceiling = (std::min)(settings.distortion_bound, settings.bounding_box_distortion_ceiling);
  const Error_code status = final_solve(surface, bounded, from_tutte_map, candidate);
  if(status != OK) return status;
  candidate.distortion = mean_distortion(candidate.chart, candidate.x);
  kept = candidate.distortion <= settings.distortion_bound;
  if(kept) state = std::move(candidate);
  else
  {
    state.set_work(candidate.work());
  }
  return OK;
}

/// Seams of the solved cut mesh in `state` (no box), whose E_d is within the
/// bound, zipped back (seam_merging.h) while the map stays within it: each
/// zip is judged after a few Newton iterations without box and border
/// barrier (Merge_settings); then the final solve runs again. If that ends
/// above the bound, the zips are undone from the last, halving their number
/// (at most three final solves); with none left, `state` is left as it was.
/// The edges flagged in `keep` stay cut.
template <typename Surface>
Error_code merge_under_bound(const Surface& surface, const Joint_settings& settings, const std::vector<char>& keep,
                             Joint_state& state)
{
  const double bound = settings.distortion_bound;
  if(!settings.seam_merging || settings.passes == 0 || !(bound > 0.) || state.distortion > bound) return OK;
  auto relax = [&](Joint_state& s) { return relax_map(settings.merge.newton_iterations, settings.constrained_tolerance, settings.inner_solver, s); };
  Joint_state merged = state;
  std::vector<Merge_step> steps;
  Error_code status = merge_greedily(surface, settings.merge, keep, relax,
                                     [&](double, double after) { return after <= bound; }, merged, steps);
  if(status != OK) return status;
  state.set_work(merged.work()); // the trials' work
  bool kept = false;
  for(std::size_t k = steps.size(), tries = 0; k > 0 && tries < 3 && !kept; k /= 2, ++tries)
  {
    Joint_state candidate = state;
    candidate.is_cut = steps[k - 1].is_cut;
    candidate.x = steps[k - 1].x;
    build_chart_mesh(surface, candidate.is_cut, candidate.chart, candidate.corner_uv);
    if((status = solve_within_bound(surface, settings, false, std::move(candidate), state, kept)) != OK) return status;
  }
  return OK;
}

/// Seams of the solved cut mesh in `state` rerouted along shorter paths
/// (seam_straightening.h), the map solved again from a Tutte map; kept if
/// its E_d is within the bound. Then once more with the ends of the seams
/// from the mesh border free to slide along it (to the border vertex
/// nearest their other end in their corridor), kept the same way: under
/// OptCuts' 11 bounds, tooth 0.2416 -> 0.2371, planck1 1.858 -> 1.624,
/// venus 1.659 -> 1.639, the other 8 unchanged. The slides are a second
/// step, so that a slide that breaks the bound cannot undo the reroutes.
template <typename Surface>
Error_code straighten_under_bound(const Surface& surface, const Joint_settings& settings, const std::vector<char>& keep,
                                  Joint_state& state)
{
  const double bound = settings.distortion_bound;
  const int rings = settings.seam_straightening_rings;
  if(rings <= 0 || settings.passes == 0 || !(bound > 0.) || state.distortion > bound) return OK;
  for(bool slide : {false, true})
  {
    Joint_state candidate = state;
    if(!rerouted_cut_mesh(surface, state, keep, rings, slide, candidate)) continue;
    bool kept = false;
    const Error_code status = solve_within_bound(surface, settings, true, std::move(candidate), state, kept);
    if(status != OK) return status;
  }
  return OK;
}

/// Meshes up to this many faces get the split trials of the bound search
/// (split_from_start()): each split is judged by Newton iterations on the
/// whole mesh, and a bound far below the initial map's E_d asks for tens of
/// splits (circular_box_o_f20000 of the OptCuts set: 21 s for the trial alone).
constexpr std::size_t split_trial_max_faces = 25000;

/// Most distorted vertices judged per split by the split trial that keeps
/// the best of them (Split_settings::best_candidate). Under OptCuts' 11
/// bounds, 3 -> 6: the seams at most OptCuts' on 6 meshes instead of 5
/// (venus E_s 1.737 -> 1.659), geometric mean of E_s / OptCuts' 0.99 ->
/// 0.96 (face_f10000 1.353 -> 1.228, armadillo_i_f10000 2.386 -> 2.161;
/// circular_box_o_f20000 1.387 -> 1.423).
constexpr int best_split_candidates = 6;

/// A trial of the bound search without the alternation: from the initial
/// cut and map of `state` (with its first u-step where the search prepared
/// one), the final solve without box, then cuts added one at a time where
/// the map is most distorted (greedy_splits.h) until E_d is within the
/// bound; `best_candidate`: see Split_settings (with best_split_candidates
/// vertices judged per split). Such seams grow from the most distorted
/// places only, and are often shorter than those of the field v at the same
/// E_d (OptCuts' 11 bounds, see bounded_joint_optimization()).
template <typename Surface>
Error_code split_from_start(const Surface& surface, const std::vector<double>& face_lambda,
                            const Joint_settings& settings, bool best_candidate, Joint_state& state)
{
  Joint_settings split_settings = settings;
  split_settings.split.best_candidate = best_candidate;
  if(best_candidate) split_settings.split.candidates = best_split_candidates;
  const bool from_tutte_map = !state.first_u_step_done;
  if(from_tutte_map)
  {
    cut_costs(surface, face_lambda, state);
    const Error_code status = start_cut_mesh(surface, settings, state);
    if(status != OK) return status;
  }
  Scoped_timer final_timer(state.timings.final_solve);
  const Error_code status = final_solve(surface, split_settings, from_tutte_map, state);
  if(status != OK) return status;
  state.distortion = mean_distortion(state.chart, state.x);
  return split_where_distorted(surface, split_settings, state);
}

/// joint_optimization() under `settings.distortion_bound` (> 0): fills
/// `state` with the chosen trial; `bound_met` tells whether its E_d is
/// within the bound. The Newton counts and times add up over the trials.
template <typename Surface>
Error_code bounded_joint_optimization(const Surface& surface, const std::vector<double>& face_lambda,
                                      const Joint_settings& settings, Joint_state& state, bool& bound_met,
                                      const Bound_search_settings& search = Bound_search_settings())
{
  if(!settings.valid()) return ERROR_WRONG_PARAMETER; // the trials run with other bounds
  const std::vector<char> user_cut = state.is_cut;
  const double bound = settings.distortion_bound;
  Joint_state best_pass, best_any;
  double best_pass_length = 0.; // 3D length of the seams of best_pass
  double best_pass_lambda = 0.; // the largest λ that passed (the bisection's lower end)
  bool have_pass = false, have_any = false;
  std::vector<double> failed; // λ of the trials above the bound
  double lowest_tried = std::numeric_limits<double>::infinity();

  double best_any_lambda = 0.;
  // The trials, the rerouting and the merges run without the bounding box:
  // the bound's room goes to shorter seams first; the box comes last, within
  // what the bound leaves (bounding_box_distortion_ceiling).
  Joint_settings unboxed = settings;
  unboxed.bounding_box_stiffness = 0.;
  // the candidates' seams are rerouted below, within the bound: not in each trial
  unboxed.rerouting_rings = 0;
  // Every trial starts from the same initial map and first u-step, which
  // do not depend on λ: done once here. Under OptCuts' 11 bounds (2 cores,
  // trials one at a time) the same results, 3-11% faster (venus 1.00 ->
  // 0.94 s, armadillo_i_f10000 31.3 -> 27.9 s).
  Joint_state prepared = state;
  Error_code status = prepare_first_u_step(surface, face_lambda, unboxed, prepared);
  if(status != OK) return status;
  const Joint_state start = std::move(prepared);
  Joint_state totals; // the work of all runs: what came before (indexing, the prepared start), then each run's
  totals.set_work_records(start);
  // A trial runs as without bound, or with the splits that go on until the
  // bound holds (`split_to_bound`). Without bound, the low-poly splits only
  // run at or below the given λ: above it, the search asks for fewer seams,
  // and splits on the more distorted maps of a large λ cost time for little
  // (circular_box_o_f20000 under 4.537: 9.9 -> 37.9 s, E_s 1.78 -> 1.71;
  // armadillo_i_f10000 under 5.222: 23.7 -> 60.4 s, E_s 3.26 -> 3.42).
  //
  // The trials go by rounds of two, run at once (parallel_invoke()): each
  // is a deterministic function of its λ, and the search reads the pair's
  // results in order once both are done, so the result does not depend on
  // the number of threads. A progress callback is called by one trial at a
  // time. Each trial is mostly serial (its factorizations), so two of them
  // fill the two cores of the machine measured: under OptCuts' 11 bounds,
  // against one trial at a time with three bisections, 1.05-1.5x faster
  // (venus 0.94 -> 0.66 s, face_f10000 15.1 -> 11.6 s), E_s the same on 7,
  // shorter on hand1 (6.41 -> 5.91) and bunnyhead, longer on planck1
  // (2.273 -> 2.289) and armadillo_i_f10000 (2.609 -> 2.724).
  // Two runs at once hold two states: on meshes above
  // two_states_at_once_max_faces they go one after the other (the same result).
  const bool at_once = surface.number_of_faces() <= two_states_at_once_max_faces;
  std::mutex progress_mutex;
  Joint_settings trial_base = unboxed;
  if(settings.progress)
    trial_base.progress = [&](const Joint_progress& p) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      return settings.progress(p);
    };
  auto run = [&](double lambda, bool split_to_bound, Joint_state& s) {
    Joint_settings trial_settings = trial_base;
    trial_settings.lambda = lambda;
    if(!split_to_bound)
    {
      trial_settings.distortion_bound = 0.;
      trial_settings.greedy_splits = settings.greedy_splits && lambda <= settings.lambda;
    }
    s = start;
    return optimize_cut_mesh(surface, face_lambda, trial_settings, s);
  };
  // the work of a trial from `start`
  auto add_work = [&](const Joint_state& s) { totals.add_work_since(s, start); };
  auto record = [&](double lambda, Joint_state& s) {
    add_work(s);
    const bool passed = s.distortion <= bound;
    lowest_tried = (std::min)(lowest_tried, lambda);
    if(!passed) failed.push_back(lambda);
    if(passed)
    {
      const double length = seam_length_3d(surface, s.is_cut);
      if(!have_pass || length < best_pass_length)
      {
        best_pass = s;
        best_pass_length = length;
      }
      best_pass_lambda = (std::max)(best_pass_lambda, lambda);
      have_pass = true;
    }
    if(!have_any || s.distortion < best_any.distortion)
    {
      best_any = std::move(s);
      best_any_lambda = lambda;
      have_any = true;
    }
  };
  // n trials, `trial(i, s)` filling trials[i], two at once (in_pairs());
  // the first error in their order
  std::vector<Joint_state> trials;
  auto run_trials = [&](std::size_t n, const auto& trial) {
    trials.assign(n, Joint_state());
    std::vector<Error_code> statuses(n, OK);
    in_pairs(n, [&](std::size_t i) { statuses[i] = trial(i, trials[i]); }, at_once);
    for(Error_code s : statuses)
      if(s != OK) return s;
    return OK;
  };
  // one or two λ trials, recorded in the order given
  auto run_round = [&](const std::vector<double>& lambdas, bool split_to_bound) {
    const Error_code round_status = run_trials(lambdas.size(), [&](std::size_t i, Joint_state& s) {
      return run(lambdas[i], split_to_bound, s);
    });
    if(round_status != OK) return round_status;
    for(std::size_t i = 0; i < lambdas.size(); ++i) record(lambdas[i], trials[i]);
    return OK;
  };

  // The split trials (split_from_start()), two at once: keeping the first
  // split accepted among the three most distorted vertices, and keeping the
  // best of the six most distorted. Under OptCuts' 11 bounds (2 cores; both
  // trials judging three vertices, with the λ search too) the seams kept
  // came from the first kind on 4 meshes, from the second on 5, from a λ
  // trial on 2 (tooth, cat); E_s / OptCuts' E_s went from a geometric mean
  // of 1.27 to 0.99 (bimba_i_f10000 2.37 -> 1.72, bunnyhead 3.87 -> 2.43,
  // hand1 5.91 -> 3.88), at 1.5-4x the time (venus 0.61 -> 1.04 s,
  // armadillo_i_f10000 23 -> 46 s, circular_box_o_f20000 11.6 -> 44.6 s);
  // best_split_candidates for six.
  //
  // Those within the bound are the candidates, and the λ search runs only
  // where neither is: once the seams are shortened (below), a split trial's
  // were the shortest on all 11 of OptCuts' bounds (the λ trial's were
  // 1-73% longer in 3D length: tooth 0.980 against 0.969, cat 0.173
  // against 0.171, venus 7.79 against 5.04, bunnyhead 3.55 against 2.05).
  // Without the λ search, the same E_d and E_s on all 11 in 0.44-0.82x the
  // time (2 cores: venus 2.31 -> 1.16 s, bimba_i_f10000 44.0 -> 26.9 s,
  // armadillo_i_f10000 67.0 -> 45.2 s); with the candidates of the second
  // trial judged at once too (split_greedily()), 0.38-0.69x (0.95 s,
  // 22.6 s, 38.9 s).
  //
  // The run at the given λ goes with them (a task each, all at once; read in
  // order), so that a bound the default run meets never gets longer seams
  // than it (where the bound is below the default's E_d, it is the λ
  // search's first trial): under OptCuts' bounds the same seams, for up to
  // 13% more time (venus 0.95 -> 1.02 s, duck1 2.10 -> 2.34 s).
  std::vector<Joint_state> candidates;
  bool given_lambda_tried = false;
  if(settings.greedy_splits && settings.passes > 0 && surface.number_of_faces() <= split_trial_max_faces)
  {
    // (at most split_trial_max_faces faces: three states at once fit)
    std::vector<Joint_state> opening(3);
    std::vector<Error_code> statuses(3, OK);
    parallel_tasks(3, [&](std::size_t i) {
      if(i == 2) { statuses[i] = run(settings.lambda, false, opening[i]); return; }
      opening[i] = start;
      statuses[i] = split_from_start(surface, face_lambda, trial_base, i == 1, opening[i]);
    });
    for(Error_code s : statuses)
      if(s != OK) return s;
    for(std::size_t i = 0; i < 2; ++i)
    {
      add_work(opening[i]);
      if(opening[i].distortion <= bound) candidates.push_back(std::move(opening[i]));
    }
    record(settings.lambda, opening[2]);
    given_lambda_tried = true;
  }

  // The λ search only where no split trial reached the bound (see above).
  if(candidates.empty())
  {
    // The walk: the given λ and half of it first (a bound is most often asked
    // for less distortion than the default gives), then down by two halvings
    // per round while nothing passed, or up by two doublings per round from a
    // passing λ while nothing above it failed, within the search's limits.
    const double lowest = settings.lambda * std::ldexp(1., -search.steps_down);
    const double highest = settings.lambda * std::ldexp(1., search.steps_up);
    auto failing_above = [&](double lambda) {
      double above = 0.;
      for(double f : failed)
        if(f > lambda && (above == 0. || f < above)) above = f;
      return above;
    };
    std::vector<double> lambdas{settings.lambda, 0.5 * settings.lambda};
    if(given_lambda_tried) lambdas.erase(lambdas.begin()); // the same walk, its first trial done
    while(!lambdas.empty())
    {
      if((status = run_round(lambdas, false)) != OK) return status;
      lambdas.clear();
      const double from = have_pass ? best_pass_lambda : lowest_tried;
      const double factor = have_pass ? 2. : 0.5;
      if(have_pass && failing_above(best_pass_lambda) > 0.) break;
      for(double next = from * factor; lambdas.size() < 2 && next >= lowest * 0.999 && next <= highest * 1.001;
          next *= factor)
        lambdas.push_back(next);
    }
    // Between the largest passing λ and the smallest failing one above it:
    // each round tries the two points that cut that interval in three (log
    // scale), so two rounds narrow it 9 times (three bisections: 8 times).
    for(int k = 0; k < search.refinements && have_pass; ++k)
    {
      const double above = failing_above(best_pass_lambda);
      if(above == 0.) break;
      const double ratio = std::cbrt(above / best_pass_lambda);
      if((status = run_round({best_pass_lambda * ratio, best_pass_lambda * ratio * ratio}, false)) != OK) return status;
    }
  }

  // No trial reached the bound: the least distorted λ trial again, split
  // greedily (greedy_splits.h), and the trial at the given λ, whose seams are
  // shorter to start with; the shorter seams within the bound win. hand1 of
  // the OptCuts set under 4.1: no λ down to λ/64 reaches it (4.1027 at best,
  // at λ/16); split from λ/16: E_d 4.0879, seams 5.42 long; from λ: 4.0914, 4.77.
  if(!have_pass && candidates.empty() && settings.greedy_splits)
  {
    const double least_distorted = best_any_lambda;
    std::vector<double> split_lambdas{least_distorted};
    if(settings.lambda != least_distorted) split_lambdas.push_back(settings.lambda);
    if((status = run_round(split_lambdas, true)) != OK) return status;
  }
  // the λ candidate (first, if any) next to split trials' is shortened only
  // where it can win (below)
  const bool lambda_beside_splits = have_pass && !candidates.empty();
  if(have_pass) candidates.insert(candidates.begin(), std::move(best_pass));
  bound_met = !candidates.empty();
  if(!bound_met)
  {
    state = std::move(best_any);
    state.set_work_records(totals);
    return finish_atlas(settings, state);
  }

  // Each candidate's seams rerouted, zipped back, then rerouted again within
  // the bound, two candidates at once; the shortest seams win (the first of
  // equals). The split trials' seams shorten the most: splits overshoot, each
  // cutting a whole path to the border (OptCuts' 11 bounds, venus: 3.26 ->
  // 2.33 for the first split accepted, 2.44 -> 1.74 for the best; planck1
  // 3.14 -> 1.86 and 2.30 -> 2.19). The zips leave shorter branches in new
  // corridors: rerouting them again took the seams kept under OptCuts' bounds
  // from 7 to 8 meshes at most OptCuts' (cat 1.298 -> 1.263, duck1 1.093 ->
  // 1.065, hand1 3.998 -> 3.938, bimba_i_f10000 1.707 -> 1.681,
  // face_f10000 1.223 -> 1.214; the other 6 unchanged), for 0-8% more time.
  {
    Scoped_timer merging(totals.timings.final_solve);
    // the trials' work is counted already: from here each state counts its own
    auto collect_work = [&](Joint_state& s) {
      totals.add_work(s);
      s.set_work({});
    };
    for(Joint_state& c : candidates) c.set_work({});
    std::vector<Error_code> statuses(candidates.size(), OK);
    auto shorten = [&](std::size_t i) {
      if((statuses[i] = straighten_under_bound(surface, unboxed, user_cut, candidates[i])) == OK
         && (statuses[i] = merge_under_bound(surface, unboxed, user_cut, candidates[i])) == OK)
        statuses[i] = straighten_under_bound(surface, unboxed, user_cut, candidates[i]);
    };
    const std::size_t first = lambda_beside_splits ? 1 : 0;
    in_pairs(candidates.size() - first, [&](std::size_t i) { shorten(first + i); }, at_once);
    if(lambda_beside_splits)
    {
      // The seam steps shorten a λ trial's seams by a third at most (by
      // 1-34% under OptCuts' bounds): one 1.5 times as long as the shortest
      // split trial's, shortened, cannot win, and is left as it is. Under
      // OptCuts' bounds the run at the given λ passes on hand1, bunnyhead
      // and armadillo_i_f10000 and is left so (shortened, its seams were
      // 1.2-1.7x the winner's; shortening them cost up to 23% more time).
      double split_shortest = std::numeric_limits<double>::infinity();
      for(std::size_t i = 1; i < candidates.size(); ++i)
        if(statuses[i] == OK) split_shortest = (std::min)(split_shortest, seam_length_3d(surface, candidates[i].is_cut));
      if(seam_length_3d(surface, candidates[0].is_cut) < 1.5 * split_shortest) shorten(0);
    }
    std::size_t chosen = 0;
    double shortest = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < candidates.size(); ++i)
    {
      if(statuses[i] != OK) return statuses[i];
      collect_work(candidates[i]);
      const double length = seam_length_3d(surface, candidates[i].is_cut);
      if(length < shortest)
      {
        shortest = length;
        chosen = i;
      }
    }
    state = std::move(candidates[chosen]);
    if(settings.bounding_box_stiffness > 0.)
    {
      bool kept = false;
      if((status = solve_within_bound(surface, settings, false, state, state, kept)) != OK) return status;
      collect_work(state);
    }
  }
  state.set_work_records(totals);
  return finish_atlas(settings, state);
}

/// Meshes of at most this many faces whose run without a bound ends above
/// default_distortion_target get the bound search at that target
/// (default_target_joint_optimization()). The search costs up to 11 runs:
/// CGAL's mpi.off (180 faces) 0.43 s -> 2.4 s in all.
constexpr std::size_t default_target_search_max_faces = 2000;

/// The run without a bound: joint_optimization(); where it ends above
/// default_distortion_target on a mesh of at most
/// default_target_search_max_faces faces (with greedy splits and at least
/// one pass), the bound search at that target
/// (bounded_joint_optimization()) runs from the same input, and its result
/// replaces the first one if it meets the target. A peer of the splits, not
/// a step of them: the splits are judged on maps without the border barrier,
/// and on some low-poly models (CGAL's mpi.off, 180 faces) their trials
/// reach E_d 4.0 with a chart whose border crosses itself, which the final
/// solve, from Tutte under the barrier, leaves at 5.11 in one chart (E_s
/// 13.28); the bound search judges its candidates on valid atlases: 4.59 in
/// three charts, E_s 12.84 (mpi_triang.off: 5.13, E_s 12.44 -> 4.35, E_s
/// 10.06). Not where a box is kept whatever it costs (an explicit
/// `bounding_box_aspect_ratio` or stiffness: its share of E_d is the user's
/// price, as in the splits). The work and the times of both runs add up.
template <typename Surface>
Error_code default_target_joint_optimization(const Surface& surface, const std::vector<double>& face_lambda,
                                             const Joint_settings& settings, Joint_state& state)
{
  const bool may_search = settings.distortion_bound <= 0. && settings.greedy_splits && settings.passes > 0
                          && surface.number_of_faces() <= default_target_search_max_faces
                          && !(final_box_stiffness(settings) > 0. && !std::isfinite(settings.bounding_box_distortion_budget));
  Joint_state input;
  if(may_search) input = state; // the search starts where the first run did
  Error_code status = joint_optimization(surface, face_lambda, settings, state);
  if(!may_search || status != OK || !(state.distortion > default_distortion_target)) return status;
  Joint_settings bounded = settings;
  bounded.distortion_bound = default_distortion_target;
  Joint_state search = input;
  bool met = false;
  status = bounded_joint_optimization(surface, face_lambda, bounded, search, met);
  if(status == ERROR_CANCELED) return status;
  const bool replace = status == OK && met;
  Joint_state& kept = replace ? search : state;
  const Joint_state& other = replace ? state : search;
  // the other run's work since the input
  kept.add_work_since(other, input);
  if(replace) state = std::move(search);
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
