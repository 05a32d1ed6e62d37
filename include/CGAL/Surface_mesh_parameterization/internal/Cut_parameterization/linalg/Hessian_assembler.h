// Assembles element blocks into a sparse symmetric matrix whose pattern is
// fixed: the position of every block entry in the value array is computed
// once, so each Newton step only zeroes and scatters values.
#ifndef CGAL_SMP_CUT_INTERNAL_HESSIAN_ASSEMBLER_H
#define CGAL_SMP_CUT_INTERNAL_HESSIAN_ASSEMBLER_H

#include <Eigen/Sparse>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>; // as in Sparse_cholesky.h

class Hessian_assembler
{
  std::vector<std::vector<int>> element_dofs_;
  std::vector<std::vector<int>> element_slots_; // lower-triangle value index per (i,j), -1 above
  std::vector<int> diagonal_slots_;
  Sparse_matrix matrix_;
  int dimension_ = 0;

public:
  /// Forgets every element (the pattern is built again by finalize()).
  void clear()
  {
    element_dofs_.clear();
    element_slots_.clear();
  }

  /// Declares an element coupling the given degrees of freedom; returns its id.
  int add_element(const std::vector<int>& dofs)
  {
    element_dofs_.push_back(dofs);
    return int(element_dofs_.size()) - 1;
  }

  /// Builds the pattern (lower triangle plus full diagonal) of a dimension x dimension matrix.
  void finalize(int dimension)
  {
    dimension_ = dimension;
    std::size_t count = std::size_t(dimension);
    for(const auto& dofs : element_dofs_) count += dofs.size() * (dofs.size() + 1) / 2;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(count); // grown by doubling, a large part of a new pattern's time at 160k faces
    for(int d = 0; d < dimension; ++d) entries.emplace_back(d, d, 0.);
    for(const auto& dofs : element_dofs_)
      for(int a : dofs)
        for(int b : dofs)
          if(a >= b) entries.emplace_back(a, b, 0.);
    matrix_.resize(dimension, dimension);
    matrix_.setFromTriplets(entries.begin(), entries.end());
    matrix_.makeCompressed();

    diagonal_slots_.resize(dimension);
    for(int d = 0; d < dimension; ++d) diagonal_slots_[d] = slot(d, d);
    element_slots_.resize(element_dofs_.size());
    for(std::size_t e = 0; e < element_dofs_.size(); ++e)
    {
      const auto& dofs = element_dofs_[e];
      const std::size_t n = dofs.size();
      element_slots_[e].assign(n * n, -1);
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < n; ++j)
          if(dofs[i] >= dofs[j]) element_slots_[e][i * n + j] = slot(dofs[i], dofs[j]);
    }
  }

  int dimension() const { return dimension_; }
  const Sparse_matrix& matrix() const { return matrix_; }
  const std::vector<int>& dofs(int element) const { return element_dofs_[element]; }

  void set_zero() { std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.); }

  /// Adds a dense symmetric block (row-major indexable as block(i,j)) of element e.
  template <typename Block>
  void add(int element, const Block& block)
  {
    const auto& slots = element_slots_[element];
    const std::size_t n = element_dofs_[element].size();
    double* values = matrix_.valuePtr();
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j)
      {
        const int s = slots[i * n + j];
        if(s >= 0) values[s] += block(i, j);
      }
  }

  void add_to_diagonal(double value)
  {
    double* values = matrix_.valuePtr();
    for(int s : diagonal_slots_) values[s] += value;
  }

  double mean_diagonal() const
  {
    double sum = 0.;
    for(int s : diagonal_slots_) sum += matrix_.valuePtr()[s];
    return dimension_ > 0 ? sum / dimension_ : 0.;
  }

private:
  int slot(int row, int col) const
  {
    const int* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col];
    const int* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col + 1];
    return int(std::lower_bound(begin, end, row) - matrix_.innerIndexPtr());
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
