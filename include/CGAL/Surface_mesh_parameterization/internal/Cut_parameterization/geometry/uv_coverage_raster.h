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

/// Area covered more than once by the UV triangles `triangles` (corners in
/// any orientation), a point covered k times counting k - 1 times, measured
/// on `resolution` × `resolution` cells over the square around the UVs'
/// bounding box: a sample at each cell's center, a covered sample counting
/// the cell's area. Degenerate (collinear) triangles cover nothing. NaN if a
/// UV is not finite.
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
      for(std::size_t i = i0; i <= i1; ++i)
        if(sample_in_ccw_triangle(Point(lo[0] + (double(i) + 0.5) * h, lo[1] + (double(j) + 0.5) * h), a, b, c))
        {
          std::uint16_t& k = count[j * n + i];
          if(k > 0) ++excess;
          if(k < std::numeric_limits<std::uint16_t>::max()) ++k;
        }
  }
  return double(excess) * h * h;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
