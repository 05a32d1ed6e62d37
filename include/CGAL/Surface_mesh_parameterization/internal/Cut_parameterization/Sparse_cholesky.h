// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// CHOLMOD (supernodal) when CGAL_SMP_CUT_USE_CHOLMOD is defined, else Eigen's
// simplicial LDLT. Only the lower triangle of the matrix is read.
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class Sparse_cholesky
{
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> solver_;
#else
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower> solver_;
#endif
  bool analyzed_ = false;

public:
  /// Symbolic analysis; call again only when the pattern changes.
  void analyze(const Sparse_matrix& A)
  {
    solver_.analyzePattern(A);
    analyzed_ = true;
  }

  /// Numeric factorization of a matrix with the analyzed pattern.
  bool factorize(const Sparse_matrix& A)
  {
    if(!analyzed_) analyze(A);
    solver_.factorize(A);
    return solver_.info() == Eigen::Success;
  }

  /// Solves A x = b with the last factorization; false if it failed or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    x = solver_.solve(b);
    return solver_.info() == Eigen::Success && x.allFinite();
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
