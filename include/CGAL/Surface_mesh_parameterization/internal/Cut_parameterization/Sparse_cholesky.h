// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// Eigen's simplicial Cholesky, ordered by AMD or, from metis_threshold
// unknowns and when CGAL_SMP_CUT_USE_METIS is defined, by METIS's nested
// dissection; from cholmod_threshold unknowns and when CGAL_SMP_CUT_USE_CHOLMOD
// is defined, CHOLMOD's supernodal Cholesky (dense blocks through BLAS). Only
// the lower triangle of the matrix is read.
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif
#ifdef CGAL_SMP_CUT_USE_METIS
#include <iostream> // Eigen's MetisSupport uses std::cerr without including it
#include <Eigen/MetisSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class Sparse_cholesky
{
  enum class Method { AMD, METIS, CHOLMOD };
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower> amd_;
#ifdef CGAL_SMP_CUT_USE_METIS
  Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::MetisOrdering<int>> metis_;
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> cholmod_;
#endif
  Method method_ = Method::AMD;
  bool analyzed_ = false;

  template <typename F>
  decltype(auto) with_solver(F&& f)
  {
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(method_ == Method::CHOLMOD) return f(cholmod_);
#endif
#ifdef CGAL_SMP_CUT_USE_METIS
    if(method_ == Method::METIS) return f(metis_);
#endif
    return f(amd_);
  }

public:
  /// Unknowns from which METIS orders the system (if built with it). Factorization
  /// of the distortion Hessian on bimba_i_f10000 and its midpoint subdivisions,
  /// AMD-ordered LDLT vs METIS-ordered LLT (2 cores, one thread): 10k unknowns
  /// 18 vs 18 ms, 20k 54 vs 42 ms, 40k 193 vs 93 ms, 160k 3.5 vs 1.3 s; the
  /// analysis costs METIS 10-70% more, which the scaffold pays per iteration.
  /// Below the threshold the benchmark meshes keep AMD's results bit for bit.
  static constexpr Eigen::Index metis_threshold = 30000;

  /// Unknowns from which CHOLMOD's supernodal factorization takes over (if
  /// built with it). A matrix of the Hessian's pattern on the same meshes,
  /// METIS-ordered simplicial LLT vs CHOLMOD with OpenBLAS (2 cores), analysis
  /// + factorization: 40k unknowns 0.14 + 0.11 vs 0.02 + 0.18 s, 160k
  /// 0.84 + 0.86 vs 0.11 + 0.88 s, 640k 4.3 + 11.1 vs 3.9 + 3.7 s.
  static constexpr Eigen::Index cholmod_threshold = 100000;

  /// Symbolic analysis; call again only when the pattern changes.
  void analyze(const Sparse_matrix& A)
  {
    method_ = Method::AMD;
#ifdef CGAL_SMP_CUT_USE_METIS
    if(A.rows() >= metis_threshold) method_ = Method::METIS;
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(A.rows() >= cholmod_threshold) method_ = Method::CHOLMOD;
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
