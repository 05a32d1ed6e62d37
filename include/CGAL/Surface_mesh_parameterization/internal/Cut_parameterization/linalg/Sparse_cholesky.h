// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// Eigen's simplicial Cholesky, ordered by AMD or, from metis_threshold
// unknowns and when CGAL_SMP_CUT_USE_METIS is defined, by METIS's nested
// dissection; from cholmod_threshold unknowns and when CGAL_SMP_CUT_USE_CHOLMOD
// is defined, CHOLMOD's supernodal Cholesky (dense blocks through BLAS), on
// the matrix permuted here with CHOLMOD's ordering. Only the lower triangle
// of the matrix is read; it may be stored whole, compressed or not.
//
// The fill-reducing ordering of the simplicial solvers is computed here, on
// the graph of the UV vertices rather than of the unknowns (order()): a
// scaffold changed the pattern at every Newton iteration, and Eigen's AMD
// on all the unknowns cost more than the factorization itself.
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
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
  // CHOLMOD factorizes the lower triangle of P A P^T, permuted here: its own
  // ordering (with its postorder) is computed once per analysis, and the
  // factorization is then told the matrix is in natural order. Given A
  // itself, every factorization copied it twice (P A P^T, then its
  // transpose: 7% of a 10k-face run).
  Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> cholmod_;
  std::vector<int> cholmod_inverse_order_; // position in P A P^T of each unknown
  std::vector<int> cholmod_value_slot_;    // index in permuted_ of each stored value of A, -1 above the diagonal
  Sparse_matrix compressed_;               // copy of an input not in compressed form

  const Sparse_matrix& compressed(const Sparse_matrix& A)
  {
    if(A.isCompressed()) return A;
    compressed_ = A;
    compressed_.makeCompressed();
    return compressed_;
  }
#endif
  Method method_ = Method::AMD;
  bool analyzed_ = false;
  Permutation permutation_, inverse_permutation_; // P and P^-1 (simplicial solvers only)
  Sparse_matrix permuted_; // P A P^T: upper triangle (simplicial solvers), lower (CHOLMOD)
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

#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  /// CHOLMOD's fill-reducing ordering of A (its default choice, AMD or
  /// nested dissection, followed by its postorder) unless `keep_order` (the
  /// last one is used again), the lower triangle of P A P^T in permuted_
  /// with the slot of each value of A, then CHOLMOD's supernodal analysis of
  /// P A P^T in natural order.
  void cholmod_analyze_permuted(const Sparse_matrix& input, bool keep_order)
  {
    const Sparse_matrix& A = compressed(input);
    const int n = int(A.rows());
    cholmod_common& common = cholmod_.cholmod();
    if(!keep_order)
    {
      common.nmethods = 0; // CHOLMOD's default: AMD, nested dissection if AMD fills in a lot
      common.postorder = 1;
      common.supernodal = CHOLMOD_SIMPLICIAL; // the ordering only: no supernodal analysis here
      cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
      cholmod_factor* ordering = cholmod_analyze(&view, &common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      cholmod_inverse_order_.assign(std::size_t(n), 0);
      if(ordering == nullptr || ordering->Perm == nullptr)
        for(int i = 0; i < n; ++i) cholmod_inverse_order_[i] = i;
      else
      {
        const int* order = static_cast<const int*>(ordering->Perm);
        for(int k = 0; k < n; ++k) cholmod_inverse_order_[order[k]] = k;
      }
      cholmod_free_factor(&ordering, &common);
    }

    // lower triangle of P A P^T, rows sorted in each column: a counting sort
    // by row, then a stable one by column
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    const std::size_t stored = std::size_t(outer[n]);
    std::vector<int> row_start(std::size_t(n) + 1, 0), column_start(std::size_t(n) + 1, 0);
    for(int j = 0; j < n; ++j)
      for(int k = outer[j]; k < outer[j + 1]; ++k)
      {
        if(inner[k] < j) continue; // only the lower triangle is read
        const int r = cholmod_inverse_order_[inner[k]], c = cholmod_inverse_order_[j];
        ++row_start[std::size_t((std::max)(r, c)) + 1];
        ++column_start[std::size_t((std::min)(r, c)) + 1];
      }
    for(int i = 0; i < n; ++i)
    {
      row_start[i + 1] += row_start[i];
      column_start[i + 1] += column_start[i];
    }
    const std::size_t nnz = std::size_t(row_start[n]);
    std::vector<int> by_row(nnz), by_row_column(nnz); // values of A by their row in P A P^T, and their column
    {
      std::vector<int> next(row_start.begin(), row_start.end() - 1);
      for(int j = 0; j < n; ++j)
        for(int k = outer[j]; k < outer[j + 1]; ++k)
        {
          if(inner[k] < j) continue;
          const int r = cholmod_inverse_order_[inner[k]], c = cholmod_inverse_order_[j];
          const int position = next[(std::max)(r, c)]++;
          by_row[position] = k;
          by_row_column[position] = (std::min)(r, c);
        }
    }
    permuted_.resize(n, n);
    permuted_.resizeNonZeros(Eigen::Index(nnz));
    std::copy(column_start.begin(), column_start.end(), permuted_.outerIndexPtr());
    cholmod_value_slot_.assign(stored, -1);
    std::vector<int> next(column_start.begin(), column_start.end() - 1);
    int* rows = permuted_.innerIndexPtr();
    for(int r = 0; r < n; ++r)
      for(int position = row_start[r]; position < row_start[r + 1]; ++position)
      {
        const int slot = next[by_row_column[position]]++;
        rows[slot] = r;
        cholmod_value_slot_[std::size_t(by_row[position])] = slot;
      }
    std::fill_n(permuted_.valuePtr(), nnz, 0.);

    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_NATURAL;
    common.postorder = 0; // P is postordered already
    // Supernodes merged more eagerly than CHOLMOD's defaults (4, 16, 48 columns;
    // 0.8, 0.1, 0.05 zeros): CHOLMOD's per-supernode work around BLAS (an
    // OpenMP region per small loop, even serial, is a futex call; timers;
    // workspace clears) outweighs the extra zeros. bimba_i_f10000 (10k
    // unknowns): 1441 -> about 800 supernodes. Whole runs (2 cores):
    // bimba_i_f10000 2.81 -> 2.39 s, lion_o_f10000 5.47 -> 4.67 s, refined
    // to 40k faces 6.86 -> 6.32 s, to 160k 18.7 -> 18.1 s; same Newton
    // iterations, E_d and E_s. 16, 64, 256 or 32, 128, 512 columns were slower.
    const std::size_t nrelax[3] = {12, 32, 96};
    const double zrelax[3] = {0.8, 0.2, 0.1};
    std::copy(nrelax, nrelax + 3, common.nrelax);
    std::copy(zrelax, zrelax + 3, common.zrelax);
    cholmod_.analyzePattern(permuted_);
  }
#endif

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
  ///
  /// Measured and left out: one level of nested dissection on two cores
  /// (METIS vertex separator; each half its own CHOLMOD factor with the
  /// separator last, c I in its block; the separator's Schur complement
  /// from the halves' last blocks, dense). bimba_i_f10000, 10k unknowns, 118
  /// in the separator: 4.7 ms per factorization against 5.6 ms (the halves
  /// 3.3 and 3.1 ms one after the other, 3.9 and 3.7 ms at once; their work
  /// 24 and 10 MFlop until the separator was moved by weights), but the
  /// analyses (separator, two orderings) at every new pattern ate the gain:
  /// on the 8 benchmark meshes of 8k-20k faces, end to end -5% to +8%.
  static constexpr Eigen::Index cholmod_threshold = 8000;

  /// Symbolic analysis; call again only when the pattern changes.
  /// `block_size`: see order(). Ordering the 2 unknowns of each UV vertex
  /// together (block size 2) gives the same fill for a fraction of the time;
  /// ordering + symbolic analysis of the distortion Hessian on bimba_i_f10000
  /// and its midpoint subdivisions (2 cores, one thread), all unknowns vs
  /// vertices: 10k unknowns 20 vs 8 ms (AMD), 20k 57 vs 16 ms, 40k 162 vs
  /// 116 ms (METIS); factorizations within 1%.
  ///
  /// With `keep_ordering`, the fill-reducing ordering of the last analysis
  /// (same size) is used again: only the symbolic analysis is redone. For
  /// CHOLMOD too: on bimba_i_f10000 refined to 640k faces its ordering
  /// (nested dissection at that size) took 2.7 s, a factorization 3.7 s, and
  /// the border barrier's new patterns (a few pairs more or fewer) asked for
  /// 13 orderings in the final solve, 35 s of a 110 s run; keeping them: 8
  /// orderings fewer, 79 s, the same Newton iterations and E_d. (Giving
  /// CHOLMOD a matrix ordered by METIS on the vertices instead, measured at
  /// 160k faces before, gained nothing.)
  void analyze(const Sparse_matrix& A, int block_size = 1, bool keep_ordering = false)
  {
    const bool keep = keep_ordering && analyzed_ && permuted_.rows() == A.rows();
    if(!keep)
    {
      method_ = Method::AMD;
#ifdef CGAL_SMP_CUT_USE_METIS
      if(A.rows() >= metis_threshold) method_ = Method::METIS;
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
      if(A.rows() >= cholmod_threshold) method_ = Method::CHOLMOD;
#endif
    }
    analyzed_ = true;
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(method_ == Method::CHOLMOD)
    {
      Serial_openmp_scope serial;
      cholmod_analyze_permuted(A, keep);
      return;
    }
#endif
    if(!keep) order(A, block_size);
    permute(A);
    with_simplicial_solver([&](auto& s) { s.analyzePattern(permuted_); });
  }

  /// True where a solve costs a small fraction of a factorization (the
  /// simplicial solvers), so that an old factorization pays as a
  /// preconditioner; CHOLMOD's supernodal factorization is fast and its
  /// solves are not (Projected_newton_solver::reuse_factor()). Measured
  /// again with OpenBLAS's AVX-512 kernels (a CHOLMOD solve about 1/8 of a
  /// factorization on bimba_i_f10000): with the reuse in CHOLMOD's range too,
  /// more Newton iterations and longer seams (bimba_i_f10000 284 -> 365, E_s
  /// 2.673 -> 3.007; max_planck_i_f8000 253 -> 292), time x1.03 over the 21
  /// benchmark meshes.
  bool solves_are_cheap() const { return method_ != Method::CHOLMOD; }

  /// Numeric factorization of a matrix with the analyzed pattern.
  bool factorize(const Sparse_matrix& A)
  {
    if(!analyzed_) analyze(A);
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(method_ == Method::CHOLMOD)
    {
      Serial_openmp_scope serial;
      const Sparse_matrix& source = compressed(A);
      // another pattern than the analyzed one (a caller's error) must not write out of bounds
      if(std::size_t(source.nonZeros()) != cholmod_value_slot_.size() || source.rows() != permuted_.rows()) return false;
      double* values = permuted_.valuePtr();
      const double* a = source.valuePtr();
      for(std::size_t k = 0; k < cholmod_value_slot_.size(); ++k)
        if(cholmod_value_slot_[k] >= 0) values[cholmod_value_slot_[k]] = a[k];
      cholmod_.factorize(permuted_);
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
      permuted_b_.resize(b.size());
      for(Eigen::Index i = 0; i < b.size(); ++i) permuted_b_[cholmod_inverse_order_[i]] = b[i];
      permuted_x_ = cholmod_.solve(permuted_b_);
      x.resize(b.size());
      for(Eigen::Index i = 0; i < b.size(); ++i) x[i] = permuted_x_[cholmod_inverse_order_[i]];
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
