#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CUT_PARAMETERIZATION_UV_COVERAGE_RASTER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CUT_PARAMETERIZATION_UV_COVERAGE_RASTER_H

// The coverage count behind uv_overlap_area() (parameterization_metrics.h):
// UV triangles rasterized on a grid of sample points, each sample counting
// the triangles that contain it.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// True if the sample `p` lies in the triangle (a, b, c), given
/// counterclockwise, under a half-open rule: a point on an edge or a vertex
/// belongs to the triangle if the point moved by an infinitesimal ε(1, η)
/// (0 < ε ≪ η ≪ 1) is inside. Exact orientation predicates; so the
/// triangles of a map without overlap (no flipped face, charts disjoint)
/// hold each sample at most once, shared edges and vertices included.
inline bool sample_in_ccw_triangle(const CGAL::Epick::Point_2& p, const CGAL::Epick::Point_2& a,
                                   const CGAL::Epick::Point_2& b, const CGAL::Epick::Point_2& c)
{
  const std::array<const CGAL::Epick::Point_2*, 3> corner{&a, &b, &c};
  for(std::size_t k = 0; k < 3; ++k)
  {
    const CGAL::Epick::Point_2& s = *corner[k];
    const CGAL::Epick::Point_2& t = *corner[(k + 1) % 3];
    const CGAL::Orientation o = CGAL::orientation(s, t, p);
    if(o == CGAL::RIGHT_TURN) return false;
    // on the edge's line: orientation(s, t, p + ε(1, η)) has the sign of
    // η d.x - d.y, d = t - s (the signs of differences of doubles are exact)
    if(o == CGAL::COLLINEAR && !(t.y() < s.y() || (t.y() == s.y() && t.x() > s.x()))) return false;
  }
  return true;
}

/// The samples of row `j` (ordinate `y`) in columns [i0, i1] that the
/// triangle (a, b, c), counterclockwise, holds, as `visit(i)`: by
/// sample_in_ccw_triangle(), but where `y` is at least `margin` from every
/// corner's ordinate, the samples clearly between the row's two crossings
/// of the triangle's border (computed in floating point, off by far less
/// than `margin` relative to the magnitudes) are taken without a predicate,
/// and a row clear of the corners' ordinates, below or above them all, holds none.
template <typename Visit>
void row_samples_in_triangle(const CGAL::Epick::Point_2& a, const CGAL::Epick::Point_2& b,
                             const CGAL::Epick::Point_2& c, double y, double x0, double h, std::size_t i0,
                             std::size_t i1, double margin, const Visit& visit)
{
  using Point = CGAL::Epick::Point_2;
  const auto x_of = [&](std::size_t i) { return x0 + (double(i) + 0.5) * h; };
  const std::array<const Point*, 3> corner{&a, &b, &c};
  bool exact = false;
  for(const Point* p : corner) exact = exact || std::abs(y - p->y()) < margin * (1. + std::abs(p->y()));
  // clear of every corner's ordinate and below or above all of them: outside
  if(!exact && ((y < a.y() && y < b.y() && y < c.y()) || (y > a.y() && y > b.y() && y > c.y()))) return;
  double left = -std::numeric_limits<double>::infinity(), right = -left;
  double left_slack = 0., right_slack = 0.;
  for(std::size_t k = 0; k < 3 && !exact; ++k)
  {
    const Point& s = *corner[k];
    const Point& t = *corner[(k + 1) % 3];
    const double dy = t.y() - s.y();
    if(dy == 0.) continue; // a horizontal side: the row is strictly on its inner side (not at a corner)
    const double x = s.x() + (t.x() - s.x()) * ((y - s.y()) / dy); // left of the side: x < this if dy > 0
    const double slack = margin * (1. + std::abs(x) + std::abs(s.x()) + std::abs(t.x()));
    if(!std::isfinite(x)) exact = true;
    else if(dy > 0. && x < right) { right = x; right_slack = slack; }
    else if(dy < 0. && x > left) { left = x; left_slack = slack; }
  }
  if(exact)
  {
    for(std::size_t i = i0; i <= i1; ++i)
      if(sample_in_ccw_triangle(Point(x_of(i), y), a, b, c)) visit(i);
    return;
  }
  // the columns whose sample may lie in [left - slack, right + slack], one more each side
  const double first = std::floor((left - left_slack - x0) / h - 0.5) - 1.;
  const double last = std::ceil((right + right_slack - x0) / h - 0.5) + 1.;
  if(!(first <= double(i1)) || !(last >= double(i0))) return;
  const std::size_t from = first > double(i0) ? std::size_t(first) : i0;
  const std::size_t to = last < double(i1) ? std::size_t(last) : i1;
  for(std::size_t i = from; i <= to; ++i)
  {
    const double x = x_of(i);
    if(x < left - left_slack || x > right + right_slack) continue;
    if((x > left + left_slack && x < right - right_slack) || sample_in_ccw_triangle(Point(x, y), a, b, c)) visit(i);
  }
}

/// Area covered more than once by the UV triangles `triangles` (corners in
/// any orientation), a point covered k times counting k - 1 times, measured
/// on `resolution` × `resolution` cells over the square around the UVs'
/// bounding box: a sample at each cell's center, a covered sample counting
/// the cell's area. Degenerate (collinear) triangles cover nothing. NaN if a
/// UV is not finite. Each triangle's rows are scanned between their
/// crossings of its sides; the exact predicate decides the samples near a
/// side (row_samples_in_triangle()).
inline double overlap_area_of_triangles(const std::vector<std::array<std::array<double, 2>, 3>>& triangles,
                                        std::size_t resolution)
{
  using Point = CGAL::Epick::Point_2;
  if(triangles.empty() || resolution == 0) return 0.;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(const auto& t : triangles)
    for(const auto& c : t)
      for(int d = 0; d < 2; ++d)
      {
        if(!std::isfinite(c[d])) return std::numeric_limits<double>::quiet_NaN();
        lo[d] = std::min(lo[d], c[d]);
        hi[d] = std::max(hi[d], c[d]);
      }
  const double side = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(side > 0.)) return 0.;
  const double h = side / double(resolution);
  const std::size_t n = resolution;
  // far above the few ulps of error of a crossing, relative to the magnitudes
  const double margin = 1e-9;
  std::vector<std::uint16_t> count(n * n, 0);
  std::size_t excess = 0; // samples covered beyond the first time
  const auto cell_range = [&](double a, double b, int d, std::size_t& first, std::size_t& last) {
    // cells whose center (lo + (i + 1/2) h) may lie in [a, b]; one cell of margin
    const double i0 = std::floor((a - lo[d]) / h - 0.5) - 1., i1 = std::ceil((b - lo[d]) / h - 0.5) + 1.;
    first = std::size_t(std::max(0., i0));
    last = std::size_t(std::min(double(n) - 1., std::max(0., i1)));
  };
  for(const auto& t : triangles)
  {
    Point a(t[0][0], t[0][1]), b(t[1][0], t[1][1]), c(t[2][0], t[2][1]);
    const CGAL::Orientation o = CGAL::orientation(a, b, c);
    if(o == CGAL::COLLINEAR) continue;
    if(o == CGAL::RIGHT_TURN) std::swap(b, c);
    std::size_t i0, i1, j0, j1;
    cell_range(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}), 0, i0, i1);
    cell_range(std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}), 1, j0, j1);
    for(std::size_t j = j0; j <= j1; ++j)
    {
      std::uint16_t* row = count.data() + j * n;
      row_samples_in_triangle(a, b, c, lo[1] + (double(j) + 0.5) * h, lo[0], h, i0, i1, margin, [&](std::size_t i) {
        std::uint16_t& k = row[i];
        if(k > 0) ++excess;
        if(k < std::numeric_limits<std::uint16_t>::max()) ++k;
      });
    }
  }
  return double(excess) * h * h;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
