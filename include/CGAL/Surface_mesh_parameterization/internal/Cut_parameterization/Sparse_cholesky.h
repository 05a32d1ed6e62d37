// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// CHOLMOD (supernodal) when CGAL_SMP_CUT_USE_CHOLMOD is defined, else Eigen's
// simplicial Cholesky, ordered by AMD or, from metis_threshold unknowns and
// when CGAL_SMP_CUT_USE_METIS is defined, by METIS's nested dissection. Only
// the lower triangle of the matrix is read.
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#elif defined(CGAL_SMP_CUT_USE_METIS)
#include <Eigen/MetisSupport>
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
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower> amd_;
#ifdef CGAL_SMP_CUT_USE_METIS
  Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::MetisOrdering<int>> metis_;
  bool use_metis_ = false;
#endif
#endif
  bool analyzed_ = false;

  template <typename F>
  decltype(auto) with_solver(F&& f)
  {
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    return f(solver_);
#elif defined(CGAL_SMP_CUT_USE_METIS)
    return use_metis_ ? f(metis_) : f(amd_);
#else
    return f(amd_);
#endif
  }

public:
  /// Unknowns from which METIS orders the system (if built with it). Factorization
  /// of the distortion Hessian on bimba_i_f10000 and its midpoint subdivisions,
  /// AMD-ordered LDLT vs METIS-ordered LLT (2 cores, one thread): 10k unknowns
  /// 18 vs 18 ms, 20k 54 vs 42 ms, 40k 193 vs 93 ms, 160k 3.5 vs 1.3 s; the
  /// analysis costs METIS 10-70% more, which the scaffold pays per iteration.
  /// Below the threshold the benchmark meshes keep AMD's results bit for bit.
  static constexpr Eigen::Index metis_threshold = 30000;

  /// Symbolic analysis; call again only when the pattern changes.
  void analyze(const Sparse_matrix& A)
  {
#if defined(CGAL_SMP_CUT_USE_METIS) && !defined(CGAL_SMP_CUT_USE_CHOLMOD)
    use_metis_ = A.rows() >= metis_threshold;
#endif
    with_solver([&](auto& s) { s.analyzePattern(A); });
    analyzed_ = true;
  }

  /// Numeric factorization of a matrix with the analyzed pattern.
  bool factorize(const Sparse_matrix& A)
  {
    if(!analyzed_) analyze(A);
    return with_solver([&](auto& s) { s.factorize(A); return s.info() == Eigen::Success; });
  }

  /// Solves A x = b with the last factorization; false if it failed or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    return with_solver([&](auto& s) { x = s.solve(b); return s.info() == Eigen::Success && x.allFinite(); });
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
