// What both inner solvers (Projected_newton_solver, Proxy_quasi_newton_solver)
// share: the energy terms, the sparsity pattern of their Hessian and its
// symbolic factorization, the assembly and factorization of the projected
// Hessian, the flip-free step bound and the backtracking line search; and
// their settings and report. The sparse solver is a template parameter
// (Sparse_cholesky for both), so that this header stays below it.
#ifndef CGAL_SMP_CUT_INTERNAL_ENERGY_TERMS_CORE_H
#define CGAL_SMP_CUT_INTERNAL_ENERGY_TERMS_CORE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

// Inner_solver (cut_parameterization_named_parameters.h) chooses between
// Projected_newton_solver (NEWTON) and Proxy_quasi_newton_solver.
using Surface_mesh_parameterization::Inner_solver;

/// The slow-tail rule: a minimization that has taken `after` steps stops
/// once its energy fell by less than `ratio` of itself over its last
/// `window` steps (after = 0: never): on charts that no flat map fits,
/// projected Newton ends crawling like gradient descent (see the manual,
/// Design and measurements).
struct Slow_tail
{
  int after = 0;
  int window = tuning::slow_tail_window;
  double ratio = tuning::slow_tail_ratio;
};

struct Newton_settings
{
  int max_iterations = tuning::newton_max_iterations;
  /// Stop when the Newton decrement (predicted decrease) falls below
  /// tolerance * energy_scale. With energy_scale = sum_f w_f A_f this is a
  /// bound on the decrease of the area-weighted mean distortion, which does
  /// not depend on the mesh's scale.
  double tolerance = tuning::newton_tolerance;
  double energy_scale = 1.;
  Slow_tail slow_tail;
  /// The reweighted start (Energy_terms_core::reweighted_start()): while
  /// the mean energy (energy / energy_scale) is above
  /// `reweighted_start_energy`, steps on the terms' reweighted proxies come
  /// first, as long as each leaves at most `reweighted_start_ratio` of the
  /// energy before it (0: no such step). The default mean energy is far
  /// above the minimum of any chart, so that a map near its minimum takes
  /// no such step.
  double reweighted_start_ratio = 0.;
  double reweighted_start_energy = tuning::reweighted_start_energy;
  /// The longest step the line search tries, in whole steps (1: none
  /// longer; Energy_terms_core::line_search()).
  double step_growth = 1.;
};

/// The reweighted start's ratio of Distortion_minimizer (minimize_distortion.h).
constexpr double default_reweighted_start_ratio = tuning::reweighted_start_ratio;

/// Newton_settings::step_growth of Distortion_minimizer (minimize_distortion.h):
/// in a slow tail of projected Newton the clamped twist curvature makes the
/// model stiffer than the energy, and longer steps gain more.
constexpr double default_step_growth = tuning::step_growth;

/// SLOW_TAIL: stopped by Newton_settings::slow_tail.
enum class Newton_status { CONVERGED, MAX_ITERATIONS, STALLED, SLOW_TAIL, LINEAR_SOLVE_FAILED, NOT_FINITE };

struct Newton_report
{
  Newton_status status = Newton_status::CONVERGED;
  int iterations = 0;
  /// numeric Cholesky factorizations of the Hessian (retries with a larger
  /// diagonal shift included)
  int factorizations = 0;
  /// solves with a factorization (forward and back substitutions)
  int solves = 0;
  double initial_energy = 0.;
  double energy = 0.;
  bool ok() const { return status != Newton_status::LINEAR_SOLVE_FAILED && status != Newton_status::NOT_FINITE; }
};

/// Watches the energies after the steps of one minimization (a ring of the
/// last window + 1, allocated once) for Slow_tail's rule.
class Tail_watch
{
  Slow_tail rule_;
  std::vector<double> ring_;
  int steps_ = 0;

public:
  explicit Tail_watch(const Slow_tail& rule)
    : rule_(rule), ring_(std::size_t((std::max)(rule.window, 0)) + 1, 0.)
  {}

  /// Records the energy after a step; true if the minimization crawls.
  bool crawls(double energy)
  {
    const std::size_t size = ring_.size();
    ring_[std::size_t(steps_) % size] = energy;
    ++steps_;
    if(rule_.after <= 0 || rule_.window <= 0 || steps_ < rule_.after || steps_ <= rule_.window) return false;
    return ring_[std::size_t(steps_ - 1 - rule_.window) % size] - energy < rule_.ratio * energy;
  }

  /// After a step of a solver's loop: true (the loop stops) if the
  /// minimization crawls, `report` then counting that step, SLOW_TAIL.
  bool stops(Newton_report& report)
  {
    if(!crawls(report.energy)) return false;
    ++report.iterations;
    report.status = Newton_status::SLOW_TAIL;
    return true;
  }
};

/// `Linear_solver`: analyze(matrix, block_size, keep_ordering),
/// factorize(matrix), solve(rhs, result), as Sparse_cholesky.
template <typename Linear_solver>
class Energy_terms_core
{
protected:
  std::vector<Energy_term*> terms_;
  Hessian_assembler hessian_;
  Linear_solver cholesky_;
  int dimension_;
  bool pattern_built_ = false;
  Eigen::Index ordered_entries_ = 0; // entries of the pattern last ordered
  bool have_factor_ = false;         // cholesky_ holds a factorization of a Hessian of this pattern

  Energy_terms_core(const std::vector<Energy_term*>& terms, int dimension) : terms_(terms), dimension_(dimension) {}

  /// The fill-reducing ordering is kept while the number of entries stays
  /// within tuning::ordering_kept_within of the pattern it was computed for:
  /// a few border barrier pairs more or fewer barely change the fill, and
  /// the ordering is most of the analysis.
  void build_pattern()
  {
    hessian_.clear();
    for(Energy_term* term : terms_) term->declare_elements(hessian_);
    hessian_.finalize(dimension_);
    const Eigen::Index entries = hessian_.matrix().nonZeros();
    const Eigen::Index slack = ordered_entries_ / tuning::ordering_kept_within;
    const bool keep = pattern_built_ && entries <= ordered_entries_ + slack && entries >= ordered_entries_ - slack;
    if(!keep) ordered_entries_ = entries;
    cholesky_.analyze(hessian_.matrix(), 2, keep); // unknowns (u, v) of each UV vertex ordered together
    pattern_built_ = true;
    have_factor_ = false;
  }

  /// Lets every term update itself at x; true if an energy value changed.
  /// `pattern_changed` is set where the Hessian's pattern was built again
  /// (the factorization is then gone).
  bool update_terms(const UV_vector& x, bool* pattern_changed = nullptr)
  {
    bool values = false, pattern = false;
    for(Energy_term* term : terms_)
    {
      const Energy_term::Update u = term->update(x);
      values = values || u != Energy_term::Update::NONE;
      pattern = pattern || u == Energy_term::Update::ELEMENTS || u == Energy_term::Update::MORE_ELEMENTS;
    }
    pattern = pattern || !pattern_built_;
    if(pattern) build_pattern();
    if(pattern_changed != nullptr) *pattern_changed = pattern;
    return values;
  }

  /// The gradient at x and the projected Hessian, with a small diagonal
  /// shift that removes the rigid-motion null space (returned); false if the
  /// gradient is not finite.
  bool assemble(const UV_vector& x, Eigen::VectorXd& gradient, double& shift, bool reweighted = false)
  {
    gradient.setZero(x.size());
    hessian_.set_zero();
    for(const Energy_term* term : terms_)
    {
      if(reweighted) term->add_gradient_and_reweighted_proxy(x, gradient, hessian_);
      else term->add_gradient_and_hessian(x, gradient, hessian_);
    }
    if(!gradient.allFinite()) return false;
    shift = tuning::hessian_shift * (std::max)(hessian_.mean_diagonal(), 1e-300);
    hessian_.add_to_diagonal(shift);
    return true;
  }

  /// The gradient alone at x; false if it is not finite.
  bool gradient_at(const UV_vector& x, Eigen::VectorXd& gradient) const
  {
    gradient.setZero(x.size());
    for(const Energy_term* term : terms_) term->add_gradient(x, gradient);
    return gradient.allFinite();
  }

  /// Factorizes the assembled Hessian and solves H d = rhs; the shift
  /// grows (tuning::hessian_shift_growth, up to tuning::factorization_attempts
  /// tries) while the factorization fails. Adds the factorizations to
  /// `factorizations`.
  bool factorize_and_solve(double shift, const Eigen::VectorXd& rhs, Eigen::VectorXd& direction, int& factorizations)
  {
    have_factor_ = false;
    for(int attempt = 0; attempt < tuning::factorization_attempts; ++attempt)
    {
      ++factorizations;
      if(cholesky_.factorize(hessian_.matrix()) && solve(rhs, direction))
        return have_factor_ = true;
      hessian_.add_to_diagonal((tuning::hessian_shift_growth - 1.) * shift);
      shift *= tuning::hessian_shift_growth;
    }
    return false;
  }

  /// Solves with the last factorization (counted in solves_).
  bool solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& result)
  {
    ++solves_;
    return cholesky_.solve(rhs, result);
  }
  int solves_ = 0; // solves with a factorization since construction

  double max_step(const UV_vector& x, const UV_vector& direction) const
  {
    double t = std::numeric_limits<double>::infinity();
    for(const Energy_term* term : terms_) t = (std::min)(t, term->max_step(x, direction));
    return t;
  }

  /// The first steps of a minimization from a map far from the minimum
  /// (Newton_settings::reweighted_start_ratio): directions from the terms'
  /// reweighted proxies (SLIM's for the distortion), with the same flip-free
  /// line search, while they pay (see Newton_settings). Called after
  /// update_terms() at x, with `report` holding the energy at x; counts its
  /// steps and factorizations there. False if the gradient is not finite or
  /// no factorization succeeded.
  ///
  /// From a Tutte map, projected Newton grows a crushed face by 4/3 per
  /// iteration (the Newton step on s^-2); the proxy's step aims every face at
  /// its closest rotation at once (see the manual, Design and measurements).
  bool reweighted_start(UV_vector& x, const Newton_settings& settings, Newton_report& report)
  {
    if(!(settings.reweighted_start_ratio > 0.)) return true;
    Eigen::VectorXd gradient(x.size()), direction;
    for(int step = 0; report.iterations < settings.max_iterations
                      && report.energy > settings.reweighted_start_energy * settings.energy_scale; ++step)
    {
      if(step > 0 && update_terms(x)) report.energy = energy(x);
      double shift = 0.;
      if(!assemble(x, gradient, shift, true)
         || !factorize_and_solve(shift, -gradient, direction, report.factorizations))
        return false;
      const double slope = gradient.dot(direction), before = report.energy;
      if(!(slope < 0.) || !line_search(x, direction, slope, report.energy, settings.step_growth)) break;
      ++report.iterations;
      if(report.energy > settings.reweighted_start_ratio * before) break;
    }
    return true;
  }

  /// Flip-free backtracking (Armijo) from the whole step, or
  /// tuning::step_bound_fraction of the step bound where that is shorter;
  /// updates x and energy. False if no decrease was found. Where that first
  /// trial passes, steps 2, 4, ... times as long follow, at most `growth`
  /// whole steps and that fraction of the step bound, while each lowers the
  /// energy further; the last of them is kept (Newton_settings::step_growth).
  bool line_search(UV_vector& x, const Eigen::VectorXd& direction, double slope, double& current,
                   double growth = 1.)
  {
    const double bound = tuning::step_bound_fraction * max_step(x, direction);
    double t = (std::min)(1., bound);
    const double armijo = tuning::armijo;
    for(int k = 0; k < tuning::line_search_halvings && t > 0.; ++k, t *= 0.5)
    {
      trial_ = x + t * direction; // (trial_ keeps its size: allocated once per solver)
      double e = energy(trial_);
      if(e <= current + armijo * t * slope)
      {
        if(!(e < current)) return false;
        if(k == 0) grow_step(x, direction, t, (std::min)(growth, bound), trial_, e);
        x.swap(trial_);
        current = e;
        return true;
      }
    }
    return false;
  }

  /// `step` is x + t `direction`, of energy `e`: it becomes x + 2t direction,
  /// then 4t, ... up to `longest`, while each lowers e further.
  void grow_step(const UV_vector& x, const Eigen::VectorXd& direction, double t, double longest, UV_vector& step,
                 double& e)
  {
    for(double longer = 2. * t; longer <= longest; longer *= 2.)
    {
      longer_step_ = x + longer * direction;
      const double longer_e = energy(longer_step_);
      if(!(longer_e < e)) return;
      step.swap(longer_step_);
      e = longer_e;
    }
  }

  UV_vector trial_, longer_step_; // the line search's trials

public:
  double energy(const UV_vector& x) const
  {
    double e = 0.;
    for(const Energy_term* term : terms_) e += term->value(x);
    return e;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
