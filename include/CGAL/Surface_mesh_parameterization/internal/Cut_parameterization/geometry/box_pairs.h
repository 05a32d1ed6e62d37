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

/// Calls f(i, j) once for each pair of a box of `first` and a box of
/// `second` that overlap (boxes as {x0, y0, x1, y1}; an empty box, with
/// x0 > x1, meets nothing), in an order that depends on the boxes only.
/// Small boxes are matched on a uniform grid, about one cell per box of
/// `second`; a box spanning more than tuning::box_grid_max_cells cells (a
/// long swept box) is tested against every box of the other set instead, so
/// that the cost stays at most quadratic.
template <typename F>
void for_each_overlapping_box_pair(const std::vector<std::array<double, 4>>& first,
                                   const std::vector<std::array<double, 4>>& second, F&& f)
{
  auto empty = [](const std::array<double, 4>& b) { return !(b[0] <= b[2] && b[1] <= b[3]); };
  auto overlap = [](const std::array<double, 4>& a, const std::array<double, 4>& b) {
    return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
  };
  const double inf = std::numeric_limits<double>::infinity();
  double low[2] = {inf, inf}, high[2] = {-inf, -inf};
  for(const auto* set : {&first, &second})
    for(const auto& b : *set)
      if(!empty(b))
      {
        low[0] = (std::min)(low[0], b[0]);
        low[1] = (std::min)(low[1], b[1]);
        high[0] = (std::max)(high[0], b[2]);
        high[1] = (std::max)(high[1], b[3]);
      }
  if(!(low[0] <= high[0] && low[1] <= high[1])) return;
  const int cells = (std::max)(1, int(std::ceil(std::sqrt(double(second.size())))));
  const double size[2] = {(std::max)(high[0] - low[0], 1e-300), (std::max)(high[1] - low[1], 1e-300)};
  auto cell_of = [&](double value, int axis) {
    const int c = int((value - low[axis]) / size[axis] * cells);
    return (std::min)((std::max)(c, 0), cells - 1);
  };
  constexpr long max_cells = tuning::box_grid_max_cells;
  // cell range {x0, y0, x1, y1}; empty for an empty or a large box
  auto range = [&](const std::array<double, 4>& b, bool& large) {
    large = false;
    if(empty(b)) return std::array<int, 4>{1, 1, 0, 0};
    const std::array<int, 4> r{cell_of(b[0], 0), cell_of(b[1], 1), cell_of(b[2], 0), cell_of(b[3], 1)};
    large = long(r[2] - r[0] + 1) * long(r[3] - r[1] + 1) > max_cells;
    return large ? std::array<int, 4>{1, 1, 0, 0} : r;
  };
  std::vector<std::array<int, 4>> second_range(second.size());
  std::vector<int> large_second;
  std::vector<int> count(std::size_t(cells) * cells + 1, 0);
  for(std::size_t j = 0; j < second.size(); ++j)
  {
    bool large;
    second_range[j] = range(second[j], large);
    if(large) large_second.push_back(int(j));
    const auto& r = second_range[j];
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx) ++count[std::size_t(cy) * cells + cx + 1];
  }
  for(std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  std::vector<int> bucket(count.back()), fill(count.begin(), count.end() - 1);
  for(std::size_t j = 0; j < second.size(); ++j)
  {
    const auto& r = second_range[j];
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx) bucket[fill[std::size_t(cy) * cells + cx]++] = int(j);
  }
  for(std::size_t i = 0; i < first.size(); ++i)
  {
    const auto& a = first[i];
    bool large;
    const std::array<int, 4> r = range(a, large);
    if(large)
    {
      for(std::size_t j = 0; j < second.size(); ++j)
        if(overlap(a, second[j])) f(int(i), int(j));
      continue;
    }
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx)
      {
        const std::size_t c = std::size_t(cy) * cells + cx;
        for(int k = count[c]; k < count[c + 1]; ++k)
        {
          const int j = bucket[k];
          const auto& rj = second_range[j];
          // each pair once: in the first cell both ranges share
          if((std::max)(r[0], rj[0]) != cx || (std::max)(r[1], rj[1]) != cy) continue;
          if(overlap(a, second[j])) f(int(i), j);
        }
      }
    if(!empty(a))
      for(int j : large_second)
        if(overlap(a, second[j])) f(int(i), j);
  }
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
