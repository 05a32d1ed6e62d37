// Interface of an energy term minimized by the projected Newton solver. New
// terms (box penalty, boundary barrier, ...) implement it and are added to the
// solver without touching its loop.
#ifndef CGAL_SMP_CUT_INTERNAL_ENERGY_TERM_H
#define CGAL_SMP_CUT_INTERNAL_ENERGY_TERM_H

#include <Eigen/Core>

#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using UV_vector = Eigen::VectorXd; // (u0, v0, u1, v1, ...), as in mesh/Chart_mesh.h

class Hessian_assembler; // linalg/Hessian_assembler.h, which the terms include

class Energy_term
{
public:
  /// What update() changed: nothing, the energy, the Hessian blocks too
  /// (ELEMENTS), or only new blocks added to those before (MORE_ELEMENTS: the
  /// solver may keep its fill-reducing ordering).
  enum class Update { NONE, VALUES, ELEMENTS, MORE_ELEMENTS };

  virtual ~Energy_term() = default;

  /// Called at the current x before each Newton iteration. A term that
  /// changes itself there (a barrier's close pairs) returns VALUES if its energy changed
  /// and ELEMENTS or MORE_ELEMENTS if its Hessian blocks changed too
  /// (declare_elements() is then called again).
  virtual Update update(const UV_vector&) { return Update::NONE; }

  /// Declares the Hessian blocks the term writes (called once per sparsity pattern).
  virtual void declare_elements(Hessian_assembler& hessian) = 0;

  /// Energy at x; +infinity where x is not admissible (e.g. a flipped face).
  virtual double value(const UV_vector& x) const = 0;

  /// Adds the gradient to `gradient` and a positive semi-definite Hessian approximation to `hessian`.
  virtual void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                        Hessian_assembler& hessian) const = 0;

  /// Adds the gradient and the Hessian of the term's reweighted proxy
  /// (Energy_terms_core::reweighted_start()): a positive definite model
  /// whose step reaches far from the minimum at once. A term without one
  /// (barrier, box: their projected Hessians already model them) gives
  /// add_gradient_and_hessian()'s.
  virtual void add_gradient_and_reweighted_proxy(const UV_vector& x, Eigen::VectorXd& gradient,
                                                 Hessian_assembler& hessian) const
  {
    add_gradient_and_hessian(x, gradient, hessian);
  }
  /// Adds the gradient at x to `gradient`: add_gradient_and_hessian()'s,
  /// without the Hessian (what a quasi-Newton iteration asks for).
  virtual void add_gradient(const UV_vector& x, Eigen::VectorXd& gradient) const = 0;

  /// Largest step t along dx such that x + s dx stays admissible for all s < t.
  virtual double max_step(const UV_vector&, const UV_vector&) const
  {
    return std::numeric_limits<double>::infinity();
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
