// Sparse SPD solver with a symbolic analysis done once per sparsity pattern:
// Eigen's simplicial Cholesky, ordered by AMD or, from metis_threshold
// unknowns and when CGAL_SMP_CUT_USE_METIS is defined, by METIS's nested
// dissection; from cholmod_threshold unknowns and when CGAL_SMP_CUT_USE_CHOLMOD
// is defined, CHOLMOD's supernodal Cholesky (dense blocks through BLAS), on
// the matrix permuted here with CHOLMOD's ordering. Only the lower triangle
// of the matrix is read; it may be stored whole, compressed or not.
//
// The fill-reducing ordering of the simplicial solvers is computed here, on
// the graph of the UV vertices rather than of the unknowns (order()): Eigen's
// AMD on all the unknowns cost more than the factorization itself (see the
// manual, Design and measurements).
#ifndef CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_SMP_CUT_INTERNAL_SPARSE_CHOLESKY_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

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
#include <dlfcn.h>
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

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>; // as in Hessian_assembler.h

#ifdef CGAL_SMP_CUT_USE_CHOLMOD
/// While alive, OpenMP parallel regions started by the calling thread run on
/// that thread alone (no active level allowed); the setting before is
/// restored after. Debian's CHOLMOD opens a parallel region of a fixed 4
/// threads for small loops inside each supernode, whose threads sleep and
/// wake on futexes: slower than serial (see the manual, Design and
/// measurements). The setting is an ICV of the calling thread (OpenMP 5), so
/// other threads keep theirs.
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

#ifdef CGAL_SMP_CUT_USE_CHOLMOD
/// True if the process runs OpenMP regions of one thread on the calling
/// thread without a team: a program that links the project's
/// tools/serial_openmp_regions.cpp says so through the function
/// `cut_param_openmp_regions_without_team()` (looked up once, by name).
/// CHOLMOD's regions then cost no system call each.
inline bool openmp_regions_without_team()
{
#if defined(__GNUC__) && defined(__ELF__)
  static const bool answer = [] {
    using Query = int (*)();
    const Query query = reinterpret_cast<Query>(dlsym(RTLD_DEFAULT, "cut_param_openmp_regions_without_team"));
    return query != nullptr && query() != 0;
  }();
  return answer;
#else
  return false;
#endif
}
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
  // factorization is then told the matrix is in natural order (given A
  // itself, every factorization copied it twice).
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
    // supernodes merged more eagerly than CHOLMOD's defaults (tuning.h)
    std::copy(tuning::cholmod_nrelax, tuning::cholmod_nrelax + 3, common.nrelax);
    std::copy(tuning::cholmod_zrelax, tuning::cholmod_zrelax + 3, common.zrelax);
    cholmod_.analyzePattern(permuted_);
  }
#endif

public:
  /// Unknowns from which METIS orders the system (if built with it; built
  /// with CHOLMOD too, these systems go to CHOLMOD).
  static constexpr Eigen::Index metis_threshold = tuning::metis_threshold;

  /// Unknowns from which CHOLMOD's supernodal factorization takes over (if
  /// built with it): tuning::cholmod_threshold, or
  /// tuning::cholmod_threshold_without_team where the process runs OpenMP
  /// regions of one thread without a team (openmp_regions_without_team()).
  static Eigen::Index cholmod_threshold()
  {
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
    if(openmp_regions_without_team()) return tuning::cholmod_threshold_without_team;
#endif
    return tuning::cholmod_threshold;
  }

  /// Symbolic analysis; call again only when the pattern changes.
  /// `block_size`: see order(); 2 orders the (u, v) of each UV vertex
  /// together, the same fill for a fraction of the time.
  /// With `keep_ordering`, the fill-reducing ordering of the last analysis
  /// (same size) is used again: only the symbolic analysis is redone (for
  /// CHOLMOD too, whose ordering at 640k faces costs most of a factorization).
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
      if(A.rows() >= cholmod_threshold()) method_ = Method::CHOLMOD;
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
  /// preconditioner (Projected_newton_solver::reuse_factor()); not CHOLMOD's
  /// supernodal solves of tuning::cholmod_threshold unknowns or more
  /// (measured: see the manual, Design and measurements). Below, CHOLMOD
  /// runs only where its regions cost no system call, and its solves are as
  /// cheap as the simplicial ones.
  bool solves_are_cheap() const
  {
    return method_ != Method::CHOLMOD || permuted_.rows() < tuning::cholmod_threshold;
  }

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
