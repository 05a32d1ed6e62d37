// Broad phase of the border barrier (Border_barrier_term.h) and of the
// overlap-free pieces: the pairs of overlapping boxes of two sets, found on a
// uniform grid.
#ifndef CGAL_SMP_CUT_INTERNAL_BOX_PAIRS_H
#define CGAL_SMP_CUT_INTERNAL_BOX_PAIRS_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Box_2 = std::array<double, 4>; // {x0, y0, x1, y1}; x0 > x1: empty, meets nothing

/// The boxes of a set `second` on a uniform grid over the boxes of `first`
/// and `second`, about one cell per box of `second`, for the boxes of
/// `first` to be matched against (query()); a box spanning more than
/// tuning::box_grid_max_cells cells (a long swept box) is tested against
/// every box of the other set instead, so that the cost stays at most
/// quadratic. Queries read the grid only: they may run concurrently.
class Box_grid
{
  const std::vector<Box_2>& second_;
  bool empty_ = true; // no box of either set is non-empty
  int cells_ = 1;
  double low_[2] = {0., 0.}, size_[2] = {1., 1.};
  std::vector<std::array<int, 4>> second_range_;
  std::vector<int> large_second_, count_, bucket_;

  static bool is_empty(const Box_2& b) { return !(b[0] <= b[2] && b[1] <= b[3]); }
  static bool overlap(const Box_2& a, const Box_2& b)
  {
    return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
  }
  int cell_of(double value, int axis) const
  {
    const int c = int((value - low_[axis]) / size_[axis] * cells_);
    return (std::min)((std::max)(c, 0), cells_ - 1);
  }
  /// Cell range {x0, y0, x1, y1}; empty for an empty or a large box.
  std::array<int, 4> range(const Box_2& b, bool& large) const
  {
    large = false;
    if(is_empty(b)) return std::array<int, 4>{1, 1, 0, 0};
    const std::array<int, 4> r{cell_of(b[0], 0), cell_of(b[1], 1), cell_of(b[2], 0), cell_of(b[3], 1)};
    large = long(r[2] - r[0] + 1) * long(r[3] - r[1] + 1) > long(tuning::box_grid_max_cells);
    return large ? std::array<int, 4>{1, 1, 0, 0} : r;
  }

public:
  Box_grid(const std::vector<Box_2>& first, const std::vector<Box_2>& second) : second_(second)
  {
    const double inf = std::numeric_limits<double>::infinity();
    double high[2] = {-inf, -inf};
    low_[0] = low_[1] = inf;
    for(const auto* set : {&first, &second})
      for(const auto& b : *set)
        if(!is_empty(b))
        {
          low_[0] = (std::min)(low_[0], b[0]);
          low_[1] = (std::min)(low_[1], b[1]);
          high[0] = (std::max)(high[0], b[2]);
          high[1] = (std::max)(high[1], b[3]);
        }
    empty_ = !(low_[0] <= high[0] && low_[1] <= high[1]);
    if(empty_) return;
    cells_ = (std::max)(1, int(std::ceil(std::sqrt(double(second.size())))));
    size_[0] = (std::max)(high[0] - low_[0], 1e-300);
    size_[1] = (std::max)(high[1] - low_[1], 1e-300);
    second_range_.resize(second.size());
    count_.assign(std::size_t(cells_) * cells_ + 1, 0);
    for(std::size_t j = 0; j < second.size(); ++j)
    {
      bool large;
      second_range_[j] = range(second[j], large);
      if(large) large_second_.push_back(int(j));
      const auto& r = second_range_[j];
      for(int cy = r[1]; cy <= r[3]; ++cy)
        for(int cx = r[0]; cx <= r[2]; ++cx) ++count_[std::size_t(cy) * cells_ + cx + 1];
    }
    for(std::size_t c = 1; c < count_.size(); ++c) count_[c] += count_[c - 1];
    bucket_.resize(std::size_t(count_.back()));
    std::vector<int> fill(count_.begin(), count_.end() - 1);
    for(std::size_t j = 0; j < second.size(); ++j)
    {
      const auto& r = second_range_[j];
      for(int cy = r[1]; cy <= r[3]; ++cy)
        for(int cx = r[0]; cx <= r[2]; ++cx) bucket_[std::size_t(fill[std::size_t(cy) * cells_ + cx]++)] = int(j);
    }
  }

  /// Calls f(i, j) once for each box j of `second` that overlaps `a` (box
  /// i of `first`), in an order that depends on the boxes only.
  template <typename F>
  void query(int i, const Box_2& a, F&& f) const
  {
    if(empty_) return;
    bool large;
    const std::array<int, 4> r = range(a, large);
    if(large)
    {
      for(std::size_t j = 0; j < second_.size(); ++j)
        if(overlap(a, second_[j])) f(i, int(j));
      return;
    }
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx)
      {
        const std::size_t c = std::size_t(cy) * cells_ + cx;
        for(int k = count_[c]; k < count_[c + 1]; ++k)
        {
          const int j = bucket_[std::size_t(k)];
          const auto& rj = second_range_[std::size_t(j)];
          // each pair once: in the first cell both ranges share
          if((std::max)(r[0], rj[0]) != cx || (std::max)(r[1], rj[1]) != cy) continue;
          if(overlap(a, second_[std::size_t(j)])) f(i, j);
        }
      }
    if(!is_empty(a))
      for(int j : large_second_)
        if(overlap(a, second_[std::size_t(j)])) f(i, j);
  }
};

/// Calls f(i, j) once for each pair of a box of `first` and a box of
/// `second` that overlap (Box_grid), in an order that depends on the boxes only.
template <typename F>
void for_each_overlapping_box_pair(const std::vector<Box_2>& first, const std::vector<Box_2>& second, F&& f)
{
  const Box_grid grid(first, second);
  for(std::size_t i = 0; i < first.size(); ++i) grid.query(int(i), first[i], f);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
