// A distortion bound: the shortest seams whose map has E_d <= bound, a
// search over trials that all start from the same state (the initial cut
// and map, and the first u-step where the alternation runs: they do not
// depend on λ). The trials are steps the plan gives (pipeline/plan.h):
// - two split trials (cuts added where the map is most distorted until the
//   bound holds), and the run at the given λ beside them;
// - where neither split trial reaches the bound, runs at other seam costs
//   λ: E_d falls as λ falls, so λ walks down (halving) until the bound
//   holds, or up (doubling) while it holds, then narrows once between the
//   largest passing and the smallest failing λ above it (log scale).
// The trials go two at a time, at once, read in order (the result does not
// depend on the number of threads). The candidates (passing split trials,
// else the passing λ trial with the shortest seams) get their seams
// shortened within the bound, and the shortest win; if none passes, split
// trials from the least distorted λ and from the given λ, else the trial
// with the lowest E_d. Measurements: doc/design/pipeline.dox.
#ifndef CGAL_SMP_CUT_INTERNAL_BOUND_SEARCH_H
#define CGAL_SMP_CUT_INTERNAL_BOUND_SEARCH_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_paths.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The steps of a bound search, given by the plan; each fills a state from
/// the search's start and logs its work:
/// - `trial(λ, split_to_bound, state, log)`: a run at seam cost λ, without
///   the bound's splits or (`split_to_bound`) with splits until it holds;
/// - `split_trial(best_candidate, state, log)`: the split trial;
/// - `shorten(state, log)`: a candidate's seams shortened within the bound;
/// - `box(state, log)`: the box's solve of the chosen one, within the bound.
template <typename Trial, typename Split_trial, typename Shorten, typename Box_solve>
struct Bound_search_steps
{
  Trial trial;
  Split_trial split_trial;
  Shorten shorten;
  Box_solve box;
};

template <typename Trial, typename Split_trial, typename Shorten, typename Box_solve>
Bound_search_steps<Trial, Split_trial, Shorten, Box_solve>
bound_search_steps(Trial trial, Split_trial split_trial, Shorten shorten, Box_solve box)
{
  return {trial, split_trial, shorten, box};
}

/// The search for `bound` from the given seam cost `lambda`; `splits`: greedy
/// splits are allowed (fallback split trials), `split_trials`: the opening
/// split trials run.
template <typename Surface, typename Steps>
class Bound_search
{
public:
  Bound_search(const Surface& surface, double bound, double lambda, bool splits, bool split_trials,
               const Steps& steps, Work_log& log)
    : surface_(surface), bound_(bound), lambda_(lambda), splits_(splits), split_trials_(split_trials),
      steps_(steps), log_(log), at_once_(surface.number_of_faces() <= tuning::two_states_at_once_max_faces)
  {}

  /// Fills `state` with the chosen trial; `bound_met` tells whether its E_d
  /// is within the bound. The work of every trial goes to the log.
  Error_code search(Map_state& state, bool& bound_met)
  {
    Error_code status = OK;
    if(split_trials_ && (status = open_with_split_trials()) != OK) return status;
    // the λ search only where no split trial reached the bound
    if(candidates_.empty())
    {
      if((status = walk()) != OK) return status;
      if((status = narrow()) != OK) return status;
    }
    // no trial reached the bound: split trials from the least distorted λ and from the given λ
    if(!have_pass_ && candidates_.empty() && splits_)
    {
      std::vector<double> split_lambdas{best_any_lambda_};
      if(lambda_ != best_any_lambda_) split_lambdas.push_back(lambda_);
      if((status = run_round(split_lambdas, true)) != OK) return status;
    }
    // the λ candidate (first, if any) next to split trials' is shortened only where it can win
    const bool lambda_beside_splits = have_pass_ && !candidates_.empty();
    if(have_pass_) candidates_.insert(candidates_.begin(), std::move(best_pass_));
    bound_met = !candidates_.empty();
    if(!bound_met)
    {
      state = std::move(best_any_);
      return OK;
    }
    return choose_shortest(lambda_beside_splits, state);
  }

private:
  double seam_length(const Map_state& s) const { return seam_length_3d(surface_, s.is_cut); }

  /// A trial's result: its work logged, the best passing (shortest seams)
  /// and the least distorted kept.
  void record(double lambda, Map_state& s, const Work_log& log)
  {
    log_.add(log);
    const bool passed = s.distortion <= bound_;
    lowest_tried_ = (std::min)(lowest_tried_, lambda);
    if(!passed) failed_.push_back(lambda);
    if(passed)
    {
      const double length = seam_length(s);
      if(!have_pass_ || length < best_pass_length_)
      {
        best_pass_ = s;
        best_pass_length_ = length;
      }
      best_pass_lambda_ = (std::max)(best_pass_lambda_, lambda);
      have_pass_ = true;
    }
    if(!have_any_ || s.distortion < best_any_.distortion)
    {
      best_any_ = std::move(s);
      best_any_lambda_ = lambda;
      have_any_ = true;
    }
  }

  /// One or two λ trials at once, recorded in the order given.
  Error_code run_round(const std::vector<double>& lambdas, bool split_to_bound)
  {
    const std::size_t n = lambdas.size();
    std::vector<Map_state> trials(n);
    std::vector<Work_log> logs(n);
    std::vector<Error_code> statuses(n, OK);
    in_pairs(n, [&](std::size_t i) { statuses[i] = steps_.trial(lambdas[i], split_to_bound, trials[i], logs[i]); },
             at_once_);
    for(Error_code s : statuses)
      if(s != OK) return s;
    for(std::size_t i = 0; i < n; ++i) record(lambdas[i], trials[i], logs[i]);
    return OK;
  }

  /// The two split trials (first accepted, best of best_split_candidates)
  /// and the run at the given λ, at once (three states: small meshes only).
  Error_code open_with_split_trials()
  {
    std::vector<Map_state> opening(3);
    std::vector<Work_log> logs(3);
    std::vector<Error_code> statuses(3, OK);
    parallel_tasks(3, [&](std::size_t i) {
      if(i == 2) { statuses[i] = steps_.trial(lambda_, false, opening[i], logs[i]); return; }
      statuses[i] = steps_.split_trial(i == 1, opening[i], logs[i]);
    });
    for(Error_code s : statuses)
      if(s != OK) return s;
    for(std::size_t i = 0; i < 2; ++i)
    {
      log_.add(logs[i]);
      if(opening[i].distortion <= bound_) candidates_.push_back(std::move(opening[i]));
    }
    record(lambda_, opening[2], logs[2]);
    given_lambda_tried_ = true;
    return OK;
  }

  /// The smallest failing λ above `lambda` (0: none).
  double failing_above(double lambda) const
  {
    double above = 0.;
    for(double f : failed_)
      if(f > lambda && (above == 0. || f < above)) above = f;
    return above;
  }

  /// The walk: the given λ and half of it first, then down by two halvings
  /// per round while nothing passed, or up by two doublings from a passing
  /// λ while nothing above it failed, within the search's limits.
  Error_code walk()
  {
    const double lowest = lambda_ * std::ldexp(1., -tuning::bound_steps_down);
    const double highest = lambda_ * std::ldexp(1., tuning::bound_steps_up);
    std::vector<double> lambdas{lambda_, 0.5 * lambda_};
    if(given_lambda_tried_) lambdas.erase(lambdas.begin()); // the same walk, its first trial done
    while(!lambdas.empty())
    {
      const Error_code status = run_round(lambdas, false);
      if(status != OK) return status;
      lambdas.clear();
      const double from = have_pass_ ? best_pass_lambda_ : lowest_tried_;
      const double factor = have_pass_ ? 2. : 0.5;
      if(have_pass_ && failing_above(best_pass_lambda_) > 0.) break;
      for(double next = from * factor; lambdas.size() < 2 && next >= lowest * 0.999 && next <= highest * 1.001;
          next *= factor)
        lambdas.push_back(next);
    }
    return OK;
  }

  /// Between the largest passing λ and the smallest failing one above it:
  /// each round tries the two points that cut the interval in three (log scale).
  Error_code narrow()
  {
    for(int k = 0; k < tuning::bound_refinements && have_pass_; ++k)
    {
      const double above = failing_above(best_pass_lambda_);
      if(above == 0.) break;
      const double ratio = std::cbrt(above / best_pass_lambda_);
      const Error_code status = run_round({best_pass_lambda_ * ratio, best_pass_lambda_ * ratio * ratio}, false);
      if(status != OK) return status;
    }
    return OK;
  }

  /// Each candidate's seams shortened (two at once), the shortest win (the
  /// first of equals); then the box's solve. A λ candidate beside split
  /// trials is shortened only where its seams can still win.
  Error_code choose_shortest(bool lambda_beside_splits, Map_state& state)
  {
    Scoped_timer merging(log_.timings.final_solve);
    std::vector<Work_log> logs(candidates_.size());
    std::vector<Error_code> statuses(candidates_.size(), OK);
    auto shorten = [&](std::size_t i) { statuses[i] = steps_.shorten(candidates_[i], logs[i]); };
    const std::size_t first = lambda_beside_splits ? 1 : 0;
    in_pairs(candidates_.size() - first, [&](std::size_t i) { shorten(first + i); }, at_once_);
    if(lambda_beside_splits)
    {
      double split_shortest = std::numeric_limits<double>::infinity();
      for(std::size_t i = 1; i < candidates_.size(); ++i)
        if(statuses[i] == OK) split_shortest = (std::min)(split_shortest, seam_length(candidates_[i]));
      if(seam_length(candidates_[0]) < tuning::lambda_candidate_length_ratio * split_shortest) shorten(0);
    }
    std::size_t chosen = 0;
    double shortest = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < candidates_.size(); ++i)
    {
      if(statuses[i] != OK) return statuses[i];
      log_.add(logs[i]);
      const double length = seam_length(candidates_[i]);
      if(length < shortest)
      {
        shortest = length;
        chosen = i;
      }
    }
    state = std::move(candidates_[chosen]);
    return steps_.box(state, log_);
  }

  const Surface& surface_;
  const double bound_, lambda_;
  const bool splits_, split_trials_;
  const Steps& steps_;
  Work_log& log_;
  const bool at_once_;
  Map_state best_pass_, best_any_;
  double best_pass_length_ = 0.; // 3D length of the seams of best_pass_
  double best_pass_lambda_ = 0.; // the largest λ that passed
  double best_any_lambda_ = 0.;
  bool have_pass_ = false, have_any_ = false;
  std::vector<double> failed_; // λ of the trials above the bound
  double lowest_tried_ = std::numeric_limits<double>::infinity();
  bool given_lambda_tried_ = false;
  std::vector<Map_state> candidates_;
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
