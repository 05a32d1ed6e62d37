// Projected Newton minimization of a sum of energy terms over UV coordinates.
// The sparsity pattern and its symbolic factorization are set up at the
// first minimization and again only when a term changes its elements; each
// iteration assembles, factorizes (or solves by conjugate gradients
// preconditioned by the last factorization, reuse_factor()), caps the step so
// that no term becomes inadmissible (no face flips), then backtracks (Armijo);
// it stops at convergence, or in a slow tail where the settings ask (Slow_tail).
#ifndef CGAL_SMP_CUT_INTERNAL_PROJECTED_NEWTON_SOLVER_H
#define CGAL_SMP_CUT_INTERNAL_PROJECTED_NEWTON_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/Energy_terms_core.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Projected_newton_solver : public Energy_terms_core<Sparse_cholesky>
{
  bool inexact_ = false;             // the last direction came from reuse_factor()
  Eigen::VectorXd cg_r_, cg_z_, cg_p_, cg_q_;

public:
  /// Registers the terms for `dimension` unknowns; the pattern is built by
  /// the first minimize(), once the terms have seen x.
  Projected_newton_solver(const std::vector<Energy_term*>& terms, int dimension)
    : Energy_terms_core<Sparse_cholesky>(terms, dimension)
  {}

  /// Minimizes from an admissible x (finite energy); x stays admissible.
  Newton_report minimize(UV_vector& x, const Newton_settings& settings)
  {
    Newton_report report;
    const int solves_before = solves_;
    update_terms(x);
    report.initial_energy = report.energy = energy(x);
    if(!std::isfinite(report.energy)) { report.status = Newton_status::NOT_FINITE; return report; }
    if(!reweighted_start(x, settings, report))
    {
      report.status = Newton_status::LINEAR_SOLVE_FAILED;
      return report;
    }

    Eigen::VectorXd gradient(x.size()), direction;
    Tail_watch tail(settings.slow_tail);
    report.status = Newton_status::MAX_ITERATIONS;
    for(; report.iterations < settings.max_iterations; ++report.iterations)
    {
      if(report.iterations > 0 && update_terms(x)) report.energy = energy(x);
      if(!newton_direction(x, gradient, direction, report.factorizations))
      {
        report.status = Newton_status::LINEAR_SOLVE_FAILED;
        return report;
      }
      double slope = gradient.dot(direction);
      if(!(-slope > settings.tolerance * settings.energy_scale) && inexact_)
      {
        // an inexact direction underestimates the decrease: decide on the exact one
        have_factor_ = false;
        if(!newton_direction(x, gradient, direction, report.factorizations))
        {
          report.status = Newton_status::LINEAR_SOLVE_FAILED;
          return report;
        }
        slope = gradient.dot(direction);
      }
      if(!(-slope > settings.tolerance * settings.energy_scale))
      {
        report.status = Newton_status::CONVERGED;
        break;
      }
      if(!line_search(x, direction, slope, report.energy, settings.step_growth))
      {
        report.status = Newton_status::STALLED;
        break;
      }
      if(tail.stops(report)) break;
    }
    report.solves = solves_ - solves_before;
    return report;
  }

private:
  /// Adds the factorizations it does to `factorizations`.
  bool newton_direction(const UV_vector& x, Eigen::VectorXd& gradient, Eigen::VectorXd& direction,
                        int& factorizations)
  {
    double shift = 0.;
    if(!assemble(x, gradient, shift)) return false;
    inexact_ = have_factor_ && cholesky_.solves_are_cheap() && reuse_factor(gradient, direction);
    if(inexact_) return true;
    return factorize_and_solve(shift, -gradient, direction, factorizations);
  }

  /// Conjugate gradients on H d = -g preconditioned by the factorization of
  /// an earlier Hessian of the same pattern (the last one factorized); false
  /// if they do not reach a residual of reuse_tolerance |g| within
  /// reuse_iterations (the caller then factorizes H).
  ///
  /// An inexact Newton step: within one minimization the Hessian changes
  /// little from one iteration to the next, and with the simplicial solvers
  /// a solve costs a fraction of a factorization (see the manual, Design and
  /// measurements). Convergence is never decided on an inexact direction
  /// (minimize()).
  static constexpr int reuse_iterations = tuning::reuse_iterations;
  static constexpr double reuse_tolerance = tuning::reuse_tolerance;
  bool reuse_factor(const Eigen::VectorXd& gradient, Eigen::VectorXd& direction)
  {
    const auto H = hessian_.matrix().template selfadjointView<Eigen::Lower>();
    const double target = reuse_tolerance * gradient.norm();
    direction.setZero(gradient.size());
    cg_r_ = -gradient;
    if(!solve(cg_r_, cg_z_)) return false;
    cg_p_ = cg_z_;
    double rz = cg_r_.dot(cg_z_);
    for(int k = 0; k < reuse_iterations; ++k)
    {
      cg_q_ = H * cg_p_;
      const double pq = cg_p_.dot(cg_q_);
      if(!(pq > 0.)) return false;
      const double alpha = rz / pq;
      direction += alpha * cg_p_;
      cg_r_ -= alpha * cg_q_;
      if(cg_r_.norm() <= target) return true;
      if(!solve(cg_r_, cg_z_)) return false;
      const double rz_next = cg_r_.dot(cg_z_);
      cg_p_ = cg_z_ + (rz_next / rz) * cg_p_;
      rz = rz_next;
    }
    return false;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
