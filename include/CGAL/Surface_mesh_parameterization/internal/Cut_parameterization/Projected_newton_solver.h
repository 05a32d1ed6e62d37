// Projected Newton minimization of a sum of energy terms over UV coordinates.
// The sparsity pattern and its symbolic factorization are set up at the
// first minimization and again only when a term changes its elements; each
// iteration assembles, factorizes, solves, caps the step so that no term
// becomes inadmissible (no face flips), then backtracks (Armijo).
#ifndef CGAL_SMP_CUT_INTERNAL_PROJECTED_NEWTON_SOLVER_H
#define CGAL_SMP_CUT_INTERNAL_PROJECTED_NEWTON_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Sparse_cholesky.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Newton_settings
{
  int max_iterations = 500;
  /// Stop when the Newton decrement (predicted decrease) falls below
  /// tolerance * energy_scale. With energy_scale = sum_f w_f A_f this is a
  /// bound on the decrease of the area-weighted mean distortion, which does
  /// not depend on the mesh's scale.
  double tolerance = 1e-9;
  double energy_scale = 1.;
};

enum class Newton_status { CONVERGED, MAX_ITERATIONS, STALLED, LINEAR_SOLVE_FAILED, NOT_FINITE };

struct Newton_report
{
  Newton_status status = Newton_status::CONVERGED;
  int iterations = 0;
  /// numeric Cholesky factorizations of the Hessian, never fewer than
  /// `iterations`: one per iteration, one for the direction found converged
  /// (or not followed, STALLED), and the retries with a larger diagonal shift
  int factorizations = 0;
  double initial_energy = 0.;
  double energy = 0.;
  bool ok() const { return status != Newton_status::LINEAR_SOLVE_FAILED && status != Newton_status::NOT_FINITE; }
};

class Projected_newton_solver
{
  std::vector<Energy_term*> terms_;
  Hessian_assembler hessian_;
  Sparse_cholesky cholesky_;
  int dimension_;
  bool pattern_built_ = false;

  Eigen::Index ordered_entries_ = 0; // entries of the pattern last ordered

  /// With `added` (elements were only added since the last pattern), the
  /// fill-reducing ordering is kept unless the pattern grew by more than 2%
  /// since it was computed: a few couplings more (border barrier pairs)
  /// barely change the fill, and the ordering is most of the analysis
  /// (40k unknowns: 85 ms of METIS, for a 90 ms factorization).
  void build_pattern(bool added = false)
  {
    hessian_.clear();
    for(Energy_term* term : terms_) term->declare_elements(hessian_);
    hessian_.finalize(dimension_);
    const Eigen::Index entries = hessian_.matrix().nonZeros();
    const bool keep = added && pattern_built_ && entries <= ordered_entries_ + ordered_entries_ / 50;
    if(!keep) ordered_entries_ = entries;
    cholesky_.analyze(hessian_.matrix(), 2, keep); // unknowns (u, v) of each UV vertex ordered together
    pattern_built_ = true;
  }

  /// Lets every term update itself at x; true if an energy value changed.
  bool update_terms(const UV_vector& x)
  {
    bool values = false, elements = false, added = false;
    for(Energy_term* term : terms_)
    {
      const Energy_term::Update u = term->update(x);
      values = values || u != Energy_term::Update::NONE;
      elements = elements || u == Energy_term::Update::ELEMENTS;
      added = added || u == Energy_term::Update::MORE_ELEMENTS;
    }
    if(elements || added || !pattern_built_) build_pattern(added && !elements);
    return values;
  }

public:
  /// Registers the terms for `dimension` unknowns; the pattern is built by
  /// the first minimize(), once the terms have seen x.
  Projected_newton_solver(const std::vector<Energy_term*>& terms, int dimension)
    : terms_(terms), dimension_(dimension)
  {}

  double energy(const UV_vector& x) const
  {
    double e = 0.;
    for(const Energy_term* term : terms_) e += term->value(x);
    return e;
  }

  /// Minimizes from an admissible x (finite energy); x stays admissible.
  Newton_report minimize(UV_vector& x, const Newton_settings& settings)
  {
    Newton_report report;
    update_terms(x);
    report.initial_energy = report.energy = energy(x);
    if(!std::isfinite(report.energy)) { report.status = Newton_status::NOT_FINITE; return report; }

    Eigen::VectorXd gradient(x.size()), direction;
    report.status = Newton_status::MAX_ITERATIONS;
    for(; report.iterations < settings.max_iterations; ++report.iterations)
    {
      if(report.iterations > 0 && update_terms(x)) report.energy = energy(x);
      if(!newton_direction(x, gradient, direction, report.factorizations))
      {
        report.status = Newton_status::LINEAR_SOLVE_FAILED;
        return report;
      }
      const double slope = gradient.dot(direction);
      if(!(-slope > settings.tolerance * settings.energy_scale))
      {
        report.status = Newton_status::CONVERGED;
        break;
      }
      if(!line_search(x, direction, slope, report.energy))
      {
        report.status = Newton_status::STALLED;
        break;
      }
    }
    return report;
  }

private:
  /// Adds the factorizations it does to `factorizations`.
  bool newton_direction(const UV_vector& x, Eigen::VectorXd& gradient, Eigen::VectorXd& direction,
                        int& factorizations)
  {
    gradient.setZero();
    hessian_.set_zero();
    for(const Energy_term* term : terms_) term->add_gradient_and_hessian(x, gradient, hessian_);
    if(!gradient.allFinite()) return false;
    // A small diagonal shift removes the rigid-motion null space; it grows if
    // the factorization still fails.
    double shift = 1e-9 * (std::max)(hessian_.mean_diagonal(), 1e-300);
    hessian_.add_to_diagonal(shift);
    for(int attempt = 0; attempt < 6; ++attempt)
    {
      ++factorizations;
      if(cholesky_.factorize(hessian_.matrix()) && cholesky_.solve(-gradient, direction))
        return true;
      hessian_.add_to_diagonal(99. * shift);
      shift *= 100.;
    }
    return false;
  }

  double max_step(const UV_vector& x, const UV_vector& direction) const
  {
    double t = std::numeric_limits<double>::infinity();
    for(const Energy_term* term : terms_) t = (std::min)(t, term->max_step(x, direction));
    return t;
  }

  /// Flip-free backtracking; updates x and energy. False if no decrease was found.
  bool line_search(UV_vector& x, const Eigen::VectorXd& direction, double slope, double& current)
  {
    double t = (std::min)(1., 0.9 * max_step(x, direction));
    const double armijo = 1e-4;
    UV_vector trial(x.size());
    for(int k = 0; k < 60 && t > 0.; ++k, t *= 0.5)
    {
      trial = x + t * direction;
      const double e = energy(trial);
      if(e <= current + armijo * t * slope)
      {
        if(!(e < current)) return false;
        x.swap(trial);
        current = e;
        return true;
      }
    }
    return false;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
