// Quasi-Newton minimization of a sum of energy terms over UV coordinates,
// on a proxy of the Hessian factorized at a few iterates only: the projected
// Hessian of the energy (Projected_newton_solver's) is factorized at the
// first iterate, and the iterations after it cost a gradient and one solve
// with that factorization, improved by L-BFGS updates (Nocedal 1980) with
// the factorization as their initial inverse Hessian. The proxy is
// factorized again where the steps stop paying (each step's decrease falls
// below a fraction of the first one's after the last factorization), and at
// the end: convergence is decided on the exact projected Newton direction.
// Every step is capped so that no term becomes inadmissible (no face flips,
// no border crossing), then backtracks (Armijo), as in projected Newton.
//
// The idea of a fixed proxy of the Hessian, factorized once, for the
// symmetric Dirichlet energy is that of Kovalsky et al. 2016 ("Accelerated
// Quadratic Proxy") and of the Sobolev-preconditioned quasi-Newton of Zhu et
// al. 2018 ("Blended Cured Quasi-Newton"), whose proxy is the Laplacian;
// here it is the projected Hessian at an iterate, which already holds the
// anisotropy of the distorted faces and the weights of the alternation
// (v² + γ, fixed during a u-step).
#ifndef CGAL_SMP_CUT_INTERNAL_PROXY_QUASI_NEWTON_SOLVER_H
#define CGAL_SMP_CUT_INTERNAL_PROXY_QUASI_NEWTON_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/Energy_terms_core.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Proxy_quasi_newton_solver : public Energy_terms_core<Sparse_cholesky>
{
  // L-BFGS pairs since the last factorization: a ring of `memory` slots
  // whose vectors keep their storage from one pair to the next (no
  // allocation inside the iterations); pair k (0: the oldest) is in slot
  // (first_ + k) % memory
  std::vector<Eigen::VectorXd> s_, y_;
  std::vector<double> rho_;
  int first_ = 0, pairs_ = 0;
  Eigen::VectorXd alpha_, q_, ds_, dy_; // two-loop and new-pair scratch

public:
  /// Curvature pairs kept.
  static constexpr int memory = tuning::lbfgs_memory;
  /// The proxy is factorized again once a step decreases the energy by less
  /// than this fraction of the first step after the last factorization
  /// (measured in the manual, "Inner solvers").
  static constexpr double refactorization_ratio = tuning::refactorization_ratio;

  Proxy_quasi_newton_solver(const std::vector<Energy_term*>& terms, int dimension)
    : Energy_terms_core<Sparse_cholesky>(terms, dimension)
  {}

  /// Minimizes from an admissible x (finite energy); x stays admissible.
  /// `iterations` counts the steps, `factorizations` the proxies factorized.
  Newton_report minimize(UV_vector& x, const Newton_settings& settings)
  {
    Newton_report report;
    const int solves_before = solves_;
    bool pattern_changed = false;
    update_terms(x, &pattern_changed);
    report.initial_energy = report.energy = energy(x);
    if(!std::isfinite(report.energy)) { report.status = Newton_status::NOT_FINITE; return report; }
    if(!reweighted_start(x, settings, report)) return failed(report, solves_before);

    // the weights or the map changed since the last call: a new proxy
    have_factor_ = false;
    Eigen::VectorXd gradient(x.size()), direction, previous_gradient;
    UV_vector previous_x;
    bool fresh = false;          // the factorization is of the Hessian at x
    double first_decrease = 0.;  // of the first step after the last factorization
    Tail_watch tail(settings.slow_tail);
    report.status = Newton_status::MAX_ITERATIONS;
    for(; report.iterations < settings.max_iterations; ++report.iterations)
    {
      if(report.iterations > 0)
      {
        if(update_terms(x, &pattern_changed)) report.energy = energy(x);
        if(pattern_changed) have_factor_ = false;
      }
      if(!have_factor_)
      {
        double shift = 0.;
        if(!assemble(x, gradient, shift) || !factorize_and_solve(shift, -gradient, direction, report.factorizations))
          return failed(report, solves_before);
        clear_pairs();
        fresh = true;
      }
      else
      {
        if(!gradient_at(x, gradient)) return failed(report, solves_before);
        add_pair(x, previous_x, gradient, previous_gradient);
        if(!quasi_newton_direction(gradient, direction)) return failed(report, solves_before);
        fresh = false;
      }
      const double slope = gradient.dot(direction);
      if(!(-slope > settings.tolerance * settings.energy_scale))
      {
        if(fresh)
        {
          report.status = Newton_status::CONVERGED;
          break;
        }
        have_factor_ = false; // decide on the exact projected Newton direction
        continue;
      }
      previous_x = x;
      previous_gradient = gradient;
      const double before = report.energy;
      if(!line_search(x, direction, slope, report.energy, settings.step_growth))
      {
        if(fresh)
        {
          report.status = Newton_status::STALLED;
          break;
        }
        have_factor_ = false;
        continue;
      }
      if(tail.stops(report)) break;
      const double decrease = before - report.energy;
      if(fresh) first_decrease = decrease;
      else if(decrease < refactorization_ratio * first_decrease) have_factor_ = false;
    }
    report.solves = solves_ - solves_before;
    return report;
  }

private:
  Newton_report& failed(Newton_report& report, int solves_before)
  {
    report.status = Newton_status::LINEAR_SOLVE_FAILED;
    report.solves = solves_ - solves_before;
    return report;
  }

  void clear_pairs()
  {
    first_ = pairs_ = 0;
  }

  int slot(int k) const { return (first_ + k) % memory; }

  /// Keeps s = x - x', y = g - g' where the curvature along s is positive
  /// enough (the energy is not convex: other pairs would break the update's
  /// positive definiteness); the oldest pair goes when the ring is full.
  void add_pair(const UV_vector& x, const UV_vector& previous_x, const Eigen::VectorXd& g,
                const Eigen::VectorXd& previous_g)
  {
    if(s_.empty())
    {
      s_.resize(memory);
      y_.resize(memory);
      rho_.resize(memory);
    }
    ds_ = x - previous_x;
    dy_ = g - previous_g;
    const double sy = ds_.dot(dy_);
    if(!(sy > tuning::lbfgs_curvature * ds_.norm() * dy_.norm())) return;
    const int k = pairs_ < memory ? slot(pairs_) : first_;
    s_[k].swap(ds_); // the scratch takes the slot's old storage
    y_[k].swap(dy_);
    rho_[k] = 1. / sy;
    if(pairs_ < memory) ++pairs_;
    else first_ = (first_ + 1) % memory;
  }

  /// L-BFGS two-loop recursion with the factorized proxy as the initial
  /// inverse Hessian: direction = -H g.
  bool quasi_newton_direction(const Eigen::VectorXd& gradient, Eigen::VectorXd& direction)
  {
    alpha_.resize(pairs_);
    q_ = gradient;
    for(int i = pairs_ - 1; i >= 0; --i)
    {
      const int k = slot(i);
      alpha_[i] = rho_[k] * s_[k].dot(q_);
      q_ -= alpha_[i] * y_[k];
    }
    if(!solve(q_, direction)) return false;
    for(int i = 0; i < pairs_; ++i)
    {
      const int k = slot(i);
      direction += (alpha_[i] - rho_[k] * y_[k].dot(direction)) * s_[k];
    }
    direction = -direction;
    return true;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
