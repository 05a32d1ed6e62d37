// Assembles element blocks into a sparse symmetric matrix whose pattern is
// fixed: the position of every block entry in the value array is computed
// once, so each Newton step only zeroes and scatters values. Where the
// pattern is built again with the same leading elements (the border
// barrier's pairs change, the faces stay), the pattern of those elements is
// kept and only the others are merged into it.
#ifndef CGAL_SMP_CUT_INTERNAL_HESSIAN_ASSEMBLER_H
#define CGAL_SMP_CUT_INTERNAL_HESSIAN_ASSEMBLER_H

#include <Eigen/Sparse>

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>; // as in Sparse_cholesky.h

class Hessian_assembler
{
  // the elements, flat: element e couples dofs_[dof_start_[e] .. dof_start_[e + 1])
  std::vector<int> dofs_;
  std::vector<int> dof_start_{0};
  std::vector<int> slots_;      // per element, n x n: lower-triangle value index of (i, j), -1 above
  std::vector<int> slot_start_; // element e's slots from slot_start_[e]
  std::vector<int> diagonal_slots_;
  Sparse_matrix matrix_;
  int dimension_ = 0;

  // A kept pattern: the full diagonal and the first `elements` elements of an earlier build.
  struct Kept_pattern
  {
    std::vector<int> dofs, dof_start{0};
    std::size_t elements = 0;
    int dimension = -1;
    std::vector<int> outer, inner;    // compressed columns, lower triangle
    std::vector<int> slots, diagonal; // slots of its elements and diagonal within it

    /// Its leading elements that are those of (dofs, dof_start) for a matrix of `of_dimension`.
    std::size_t leading(const std::vector<int>& other_dofs, const std::vector<int>& other_start,
                        int of_dimension) const
    {
      if(dimension != of_dimension) return 0;
      std::size_t same = 0;
      const std::size_t others = other_start.size() - 1;
      while(same < (std::min)(others, elements))
      {
        const int b = dof_start[same], n = dof_start[same + 1] - b;
        if(other_start[same] != b || other_start[same + 1] - b != n
           || !std::equal(other_dofs.begin() + b, other_dofs.begin() + b + n, dofs.begin() + b))
          break;
        ++same;
      }
      return same;
    }
  };
  // base_: the pattern merged into (the last build whole, so that the next merges only the
  // elements added since: the border barrier's pairs grow a few at a time); root_: the pattern
  // last built from scratch, taken again where the elements after its own changed
  Kept_pattern base_, root_;
  std::vector<int> base_to_new_;             // index of each of its entries in matrix_
  std::vector<int> extra_start_, extra_rows_, fill_; // entries merged in, by column
  std::vector<int> last_column_of_row_;              // merge(): the last column a row was met in
  std::vector<int> outer_, inner_;                   // the merged pattern

public:
  /// Forgets every element (the pattern is built again by finalize()).
  void clear()
  {
    dofs_.clear();
    dof_start_.assign(1, 0);
  }

  /// Declares an element coupling the given degrees of freedom; returns its id.
  int add_element(std::initializer_list<int> dofs) { return push_element(dofs.begin(), dofs.end()); }
  int add_element(const std::vector<int>& dofs) { return push_element(dofs.data(), dofs.data() + dofs.size()); }

  /// Builds the pattern (lower triangle plus full diagonal) of a dimension x
  /// dimension matrix. The same pattern, entries in the same order, whether
  /// built whole or merged into the kept one.
  void finalize(int dimension)
  {
    dimension_ = dimension;
    const std::size_t elements = dof_start_.size() - 1;
    const std::size_t same = base_.leading(dofs_, dof_start_, dimension); // 0 for a new dimension
    if(base_.dimension != dimension || same < base_.elements)
    {
      if(root_.dimension == dimension && root_.leading(dofs_, dof_start_, dimension) == root_.elements)
        base_ = root_;
      else
      {
        build_base(base_.dimension == dimension ? same : elements); // all, for a new dimension
        root_ = base_;
      }
    }
    merge_others();

    slot_start_.resize(elements);
    std::size_t count = 0;
    for(std::size_t e = 0; e < elements; ++e)
    {
      slot_start_[e] = int(count);
      const std::size_t n = std::size_t(dof_start_[e + 1] - dof_start_[e]);
      count += n * n;
    }
    slots_.resize(count);
    const std::size_t base_slots = base_.slots.size();
    for(std::size_t s = 0; s < base_slots; ++s)
      slots_[s] = base_.slots[s] < 0 ? -1 : base_to_new_[std::size_t(base_.slots[s])];
    for(std::size_t e = base_.elements; e < elements; ++e)
      element_slots(e, matrix_.outerIndexPtr(), matrix_.innerIndexPtr(), slots_.data() + slot_start_[e]);
    diagonal_slots_.resize(std::size_t(dimension));
    for(std::size_t d = 0; d < std::size_t(dimension); ++d) diagonal_slots_[d] = base_to_new_[std::size_t(base_.diagonal[d])];
    if(elements > base_.elements) // this build becomes the pattern the next one merges into
    {
      base_.dofs = dofs_;
      base_.dof_start = dof_start_;
      base_.elements = elements;
      base_.outer = outer_;
      base_.inner = inner_;
      base_.slots = slots_;
      base_.diagonal = diagonal_slots_;
    }
  }

  int dimension() const { return dimension_; }
  const Sparse_matrix& matrix() const { return matrix_; }

  void set_zero() { std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.); }

  /// Adds a dense symmetric block (row-major indexable as block(i,j)) of element e.
  template <typename Block>
  void add(int element, const Block& block)
  {
    const int* slots = slots_.data() + slot_start_[std::size_t(element)];
    const std::size_t n = std::size_t(dof_start_[std::size_t(element) + 1] - dof_start_[std::size_t(element)]);
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
  int push_element(const int* begin, const int* end)
  {
    dofs_.insert(dofs_.end(), begin, end);
    dof_start_.push_back(int(dofs_.size()));
    return int(dof_start_.size()) - 2;
  }

  /// base_: the pattern of the diagonal and the first `elements` elements.
  void build_base(std::size_t elements)
  {
    base_.dimension = dimension_;
    base_.elements = elements;
    base_.dof_start.assign(dof_start_.begin(), dof_start_.begin() + std::ptrdiff_t(elements) + 1);
    base_.dofs.assign(dofs_.begin(), dofs_.begin() + base_.dof_start.back());
    const std::size_t columns = std::size_t(dimension_);
    std::vector<int> diagonal_outer(columns + 1), diagonal_inner(columns);
    for(int d = 0; d <= dimension_; ++d) diagonal_outer[std::size_t(d)] = d;
    for(int d = 0; d < dimension_; ++d) diagonal_inner[std::size_t(d)] = d;
    merge(0, elements, diagonal_outer, diagonal_inner, base_.outer, base_.inner, base_.diagonal);
    base_.slots.clear();
    for(std::size_t e = 0; e < elements; ++e)
    {
      const std::size_t n = std::size_t(base_.dof_start[e + 1] - base_.dof_start[e]);
      base_.slots.resize(base_.slots.size() + n * n);
      element_slots(e, base_.outer.data(), base_.inner.data(), base_.slots.data() + base_.slots.size() - n * n);
    }
  }

  /// matrix_: the kept pattern with the entries of the elements after it.
  void merge_others()
  {
    merge(base_.elements, dof_start_.size() - 1, base_.outer, base_.inner, outer_, inner_, base_to_new_);
    matrix_.resize(dimension_, dimension_);
    matrix_.resizeNonZeros(Eigen::Index(inner_.size()));
    std::copy(outer_.begin(), outer_.end(), matrix_.outerIndexPtr());
    std::copy(inner_.begin(), inner_.end(), matrix_.innerIndexPtr());
    set_zero();
  }

  /// The compressed lower-triangle pattern (`outer`, `inner`) with the
  /// entries of elements [first, end) merged in (bucketed by column, each
  /// column's rows sorted), into (`merged_outer`, `merged_inner`); `map`:
  /// the index in it of each entry of the pattern given.
  void merge(std::size_t first, std::size_t end, const std::vector<int>& outer, const std::vector<int>& inner,
             std::vector<int>& merged_outer, std::vector<int>& merged_inner, std::vector<int>& map)
  {
    const std::size_t columns = std::size_t(dimension_);
    extra_start_.assign(columns + 1, 0);
    auto for_each_entry = [&](auto&& f) {
      for(std::size_t e = first; e < end; ++e)
        for(int i = dof_start_[e]; i < dof_start_[e + 1]; ++i)
          for(int j = dof_start_[e]; j < dof_start_[e + 1]; ++j)
            if(dofs_[std::size_t(i)] >= dofs_[std::size_t(j)]) f(dofs_[std::size_t(j)], dofs_[std::size_t(i)]);
    };
    for_each_entry([&](int col, int) { ++extra_start_[std::size_t(col) + 1]; });
    for(std::size_t c = 0; c < columns; ++c) extra_start_[c + 1] += extra_start_[c];
    extra_rows_.resize(std::size_t(extra_start_[columns]));
    fill_.assign(extra_start_.begin(), extra_start_.end() - 1);
    for_each_entry([&](int col, int row) { extra_rows_[std::size_t(fill_[std::size_t(col)]++)] = row; });

    map.resize(inner.size());
    merged_outer.assign(columns + 1, 0);
    merged_inner.clear();
    merged_inner.reserve(inner.size() + extra_rows_.size());
    last_column_of_row_.assign(columns, -1);
    for(std::size_t col = 0; col < columns; ++col)
    {
      int* x = extra_rows_.data() + extra_start_[col];
      int* x_end = extra_rows_.data() + extra_start_[col + 1];
      // each row once before the sort: neighbouring elements repeat most entries
      int* unique_end = x;
      for(int* r = x; r != x_end; ++r)
        if(last_column_of_row_[std::size_t(*r)] != int(col))
        {
          last_column_of_row_[std::size_t(*r)] = int(col);
          *unique_end++ = *r;
        }
      x_end = unique_end;
      std::sort(x, x_end);
      int b = outer[col];
      const int b_end = outer[col + 1];
      while(b < b_end || x != x_end)
      {
        const bool from_pattern = x == x_end || (b < b_end && inner[std::size_t(b)] <= *x);
        const int row = from_pattern ? inner[std::size_t(b)] : *x;
        while(x != x_end && *x == row) ++x;
        if(from_pattern) map[std::size_t(b++)] = int(merged_inner.size());
        merged_inner.push_back(row);
      }
      merged_outer[col + 1] = int(merged_inner.size());
    }
  }

  /// The slots of element e of the current elements in the pattern (`outer`, `inner`).
  void element_slots(std::size_t e, const int* outer, const int* inner, int* out) const
  {
    const int* dofs = dofs_.data() + dof_start_[e];
    const std::size_t n = std::size_t(dof_start_[e + 1] - dof_start_[e]);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j)
        out[i * n + j] = dofs[i] >= dofs[j]
                           ? int(std::lower_bound(inner + outer[dofs[j]], inner + outer[dofs[j] + 1], dofs[i]) - inner)
                           : -1;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
