// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// Eigen's simplicial Cholesky, ordered by AMD or, from metis_threshold
// unknowns and when CGAL_SMP_CUT_USE_METIS is defined, by METIS's nested
// dissection; from cholmod_threshold unknowns and when CGAL_SMP_CUT_USE_CHOLMOD
// is defined, CHOLMOD's supernodal Cholesky (dense blocks through BLAS). Only
// the lower triangle of the matrix is read.
//
// The fill-reducing ordering of the simplicial solvers is computed here, on
// the graph of the UV vertices rather than of the unknowns (order()): a
// scaffold changed the pattern at every Newton iteration, and Eigen's AMD
// on all the unknowns cost more than the factorization itself.
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <vector>
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#if defined(__GNUC__) && defined(__ELF__)
// OpenMP's control of the calling thread, if the process has an OpenMP
// runtime (Debian's CHOLMOD brings libgomp; weak references: null otherwise)
extern "C" int omp_get_max_active_levels(void) __attribute__((weak));
extern "C" void omp_set_max_active_levels(int) __attribute__((weak));
#endif
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

#ifdef CGAL_SMP_CUT_USE_CHOLMOD
/// While alive, OpenMP parallel regions started by the calling thread run on
/// that thread alone (no active level allowed); the setting before is
/// restored after. Debian's CHOLMOD opens a parallel region with a fixed 4
/// threads (CHOLMOD_OMP_NUM_THREADS, whatever OMP_NUM_THREADS says) for small
/// loops inside each supernode: tens of thousands of regions per
/// factorization, whose threads sleep and wake on futexes. On bimba_i_f10000
/// refined to 160k faces (2 cores) that made 2.8 million context switches
/// and a third of the run in the kernel: 95 s, against 63-67 s serial
/// (OMP_THREAD_LIMIT=2: 70 s). The setting is an ICV of the calling thread
/// (OpenMP 5), so other threads keep theirs.
class Serial_openmp_scope
{
  int saved_ = -1;

public:
  Serial_openmp_scope()
  {
#if defined(__GNUC__) && defined(__ELF__)
    if(omp_get_max_active_levels != nullptr && omp_set_max_active_levels != nullptr)
    {
      saved_ = omp_get_max_active_levels();
      omp_set_max_active_levels(0);
    }
#endif
  }
  ~Serial_openmp_scope()
  {
#if defined(__GNUC__) && defined(__ELF__)
    if(saved_ >= 0) omp_set_max_active_levels(saved_);
#endif
  }
  Serial_openmp_scope(const Serial_openmp_scope&) = delete;
  Serial_openmp_scope& operator=(const Serial_openmp_scope&) = delete;
};
#endif

class Sparse_cholesky
{
  enum class Method { AMD, METIS, CHOLMOD };
  using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  // The simplicial solvers factorize the permuted matrix P A P^T, stored as
  // its upper triangle, in its natural order (what they do inside with an
  // ordering of their own); CHOLMOD orders and factorizes A itself.
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt_;
#ifdef CGAL_SMP_CUT_USE_METIS
  Eigen::SimplicialLLT<Sparse_matrix, Eigen::Upper, Eigen::NaturalOrdering<int>> llt_;
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> cholmod_;
#endif
  Method method_ = Method::AMD;
  bool analyzed_ = false;
  Permutation permutation_, inverse_permutation_; // P and P^-1 (simplicial solvers only)
  Sparse_matrix permuted_;                         // upper triangle of P A P^T
  Eigen::VectorXd permuted_b_, permuted_x_;

  /// Calls f with the simplicial solver in use (CHOLMOD is called directly).
  template <typename F>
  decltype(auto) with_simplicial_solver(F&& f)
  {
#ifdef CGAL_SMP_CUT_USE_METIS
    if(method_ == Method::METIS) return f(llt_);
#endif
    return f(ldlt_);
  }

  void permute(const Sparse_matrix& A)
  {
    permuted_.resize(A.rows(), A.cols());
    permuted_.selfadjointView<Eigen::Upper>() = A.selfadjointView<Eigen::Lower>().twistedBy(permutation_);
  }

  /// A fill-reducing ordering of A. With block_size b > 1, the unknowns come
  /// in groups of b consecutive ones (the u and v of a UV vertex) coupled
  /// together: the graph of the groups is ordered, b times smaller, and
  /// each group stays together; the fill is the same.
  void order(const Sparse_matrix& A, int block_size)
  {
    const int b = (block_size > 1 && A.rows() % block_size == 0) ? block_size : 1;
    const int n = int(A.rows()) / b;
    Sparse_matrix symmetric(n, n);
    if(b == 1) symmetric = A.selfadjointView<Eigen::Lower>();
    else
    {
      std::vector<Eigen::Triplet<double>> entries;
      entries.reserve(2 * A.nonZeros() / (b * b) + n);
      for(int col = 0; col < A.outerSize(); ++col)
        for(Sparse_matrix::InnerIterator it(A, col); it; ++it)
        {
          const int i = int(it.row()) / b, j = col / b;
          entries.emplace_back(i, j, 1.);
          if(i != j) entries.emplace_back(j, i, 1.);
        }
      symmetric.setFromTriplets(entries.begin(), entries.end());
    }
    Permutation groups;
#ifdef CGAL_SMP_CUT_USE_METIS
    if(method_ != Method::AMD) Eigen::MetisOrdering<int>()(symmetric, groups);
    else
#endif
      Eigen::AMDOrdering<int>()(symmetric, groups);
    inverse_permutation_.resize(int(A.rows()));
    for(int g = 0; g < n; ++g)
      for(int k = 0; k < b; ++k) inverse_permutation_.indices()[b * g + k] = b * groups.indices()[g] + k;
    permutation_ = inverse_permutation_.inverse();
  }

public:
  /// Unknowns from which METIS orders the system (if built with it). Factorization
  /// of the distortion Hessian on bimba_i_f10000 and its midpoint subdivisions,
  /// AMD-ordered LDLT vs METIS-ordered LLT (2 cores, one thread): 10k unknowns
  /// 18 vs 18 ms, 20k 54 vs 42 ms, 40k 193 vs 93 ms, 160k 3.5 vs 1.3 s; the
  /// ordering costs METIS 10-70% more. Built with CHOLMOD too, these
  /// systems go to CHOLMOD (cholmod_threshold is lower).
  static constexpr Eigen::Index metis_threshold = 30000;

  /// Unknowns from which CHOLMOD's supernodal factorization takes over (if
  /// built with it). A matrix of the Hessian's pattern on benchmark meshes and
  /// on bimba_i_f10000 refined to 40k faces, one factorization, Eigen's
  /// AMD-ordered simplicial LDLT vs CHOLMOD supernodal with OpenBLAS (one
  /// thread, OpenMP regions kept serial, 2 cores): 700 unknowns 0.17 vs
  /// 0.45 ms, 3.9k 2.5 vs 2.7 ms, 5k 3.9 vs 3.8 ms, 10k 14 vs 9.1 ms, 20k 40
  /// vs 19 ms, 40k 166 vs 58 ms (METIS-ordered simplicial LLT: 93 ms); at
  /// 160k 1.3 s (METIS) vs 0.88 s, at 640k 11.1 vs 3.7 s. The 15 benchmark
  /// meshes: same E_d and E_s, geometric-mean speedup 2.20x -> 2.57x.
  static constexpr Eigen::Index cholmod_threshold = 8000;

  /// Symbolic analysis; call again only when the pattern changes.
  /// `block_size`: see order(). Ordering the 2 unknowns of each UV vertex
  /// together (block size 2) gives the same fill for a fraction of the time;
  /// ordering + symbolic analysis of the distortion Hessian on bimba_i_f10000
  /// and its midpoint subdivisions (2 cores, one thread), all unknowns vs
  /// vertices: 10k unknowns 20 vs 8 ms (AMD), 20k 57 vs 16 ms, 40k 162 vs
  /// 116 ms (METIS); factorizations within 1%.
  ///
  /// With `keep_ordering`, the simplicial solvers use the ordering of the
  /// last analysis again (same size): only the symbolic analysis is redone.
  /// CHOLMOD orders by itself in any case: giving it the matrix ordered by
  /// METIS on the vertices (natural ordering inside), so that its ordering
  /// could be kept too, was measured on bimba_i_f10000 x 16 (160k faces)
  /// and gained nothing: its final solve took 120 s either way.
  void analyze(const Sparse_matrix& A, int block_size = 1, bool keep_ordering = false)
  {
    if(!(keep_ordering && analyzed_ && method_ != Method::CHOLMOD && permutation_.size() == A.rows()))
    {
      method_ = Method::AMD;
#ifdef CGAL_SMP_CUT_USE_METIS
      if(A.rows() >= metis_threshold) method_ = Method::METIS;
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
      if(A.rows() >= cholmod_threshold) method_ = Method::CHOLMOD;
#endif
      analyzed_ = true;
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
      if(method_ == Method::CHOLMOD)
      {
        Serial_openmp_scope serial;
        cholmod_.analyzePattern(A);
        return;
      }
#endif
      order(A, block_size);
    }
    permute(A);
    with_simplicial_solver([&](auto& s) { s.analyzePattern(permuted_); });
  }

  /// Numeric factorization of a matrix with the analyzed pattern.
  bool factorize(const Sparse_matrix& A)
  {
    if(!analyzed_) analyze(A);
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(method_ == Method::CHOLMOD)
    {
      Serial_openmp_scope serial;
      cholmod_.factorize(A);
      return cholmod_.info() == Eigen::Success;
    }
#endif
    permute(A);
    return with_simplicial_solver([&](auto& s) { s.factorize(permuted_); return s.info() == Eigen::Success; });
  }

  /// Solves A x = b with the last factorization; false if it failed or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(method_ == Method::CHOLMOD)
    {
      Serial_openmp_scope serial;
      x = cholmod_.solve(b);
      return cholmod_.info() == Eigen::Success && x.allFinite();
    }
#endif
    permuted_b_ = permutation_ * b;
    return with_simplicial_solver([&](auto& s) {
      permuted_x_ = s.solve(permuted_b_);
      x = inverse_permutation_ * permuted_x_;
      return s.info() == Eigen::Success && x.allFinite();
    });
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
