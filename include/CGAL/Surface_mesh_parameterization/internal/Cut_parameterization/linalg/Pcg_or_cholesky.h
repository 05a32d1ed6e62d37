// SPD solve of a sequence of systems with one sparsity pattern, each from a
// guess close to its solution (the last one): Eigen's conjugate gradient
// preconditioned by the diagonal, warm-started from the guess, and where it
// does not reach its tolerance within its iterations, Sparse_cholesky (whose
// symbolic analysis is done at its first use only). Made for nearly
// diagonal systems (the v-step's, cuts/discontinuity_field.h), where a few
// matrix-vector products replace a factorization. Serial: the same result
// for any thread count. Only the lower triangle of the matrix is read.
#ifndef CGAL_SMP_CUT_INTERNAL_PCG_OR_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_PCG_OR_CHOLESKY_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <Eigen/IterativeLinearSolvers>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Pcg_or_cholesky
{
  Eigen::ConjugateGradient<Sparse_matrix, Eigen::Lower, Eigen::DiagonalPreconditioner<double>> cg_;
  Sparse_cholesky cholesky_;
  bool analyzed_ = false;
  int max_iterations_;
  double tolerance_;
  std::size_t factorizations_ = 0, iterations_ = 0;

public:
  /// `max_iterations` of the conjugate gradient before the Cholesky
  /// fallback (0: always Cholesky); `tolerance`: its target residual
  /// relative to the right-hand side.
  /// \pre max_iterations >= 0, tolerance > 0
  explicit Pcg_or_cholesky(int max_iterations = tuning::v_step_cg_iterations,
                           double tolerance = tuning::v_step_cg_tolerance)
    : max_iterations_(max_iterations), tolerance_(tolerance)
  {}

  /// Solves A x = b, `x` on entry the guess (any size other than b's: 0).
  /// A must keep its pattern from one call to the next.
  /// \pre A symmetric positive definite, its lower triangle stored
  /// \post true and x finite with A x = b to the tolerance (or to the
  ///   factorization's precision), or false
  bool solve(const Sparse_matrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    if(x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
    if(max_iterations_ > 0)
    {
      cg_.setMaxIterations(max_iterations_);
      cg_.setTolerance(tolerance_);
      cg_.compute(A);
      Eigen::VectorXd y = cg_.solveWithGuess(b, x);
      iterations_ += std::size_t(cg_.iterations());
      if(cg_.info() == Eigen::Success && y.allFinite())
      {
        x = std::move(y);
        return true;
      }
    }
    if(!analyzed_) cholesky_.analyze(A);
    analyzed_ = true;
    ++factorizations_;
    return cholesky_.factorize(A) && cholesky_.solve(b, x);
  }

  /// Systems solved by the fallback (each a factorization).
  std::size_t factorizations() const { return factorizations_; }
  /// Conjugate-gradient iterations done (converged or not).
  std::size_t iterations() const { return iterations_; }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
