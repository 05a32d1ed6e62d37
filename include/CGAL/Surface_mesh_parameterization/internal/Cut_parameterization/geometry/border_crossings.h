// Crossings of UV border segments: the test of global injectivity. A disk
// chart without flipped faces is injective iff its border is a simple curve,
// so counting the pairs of border segments that cross properly tells whether
// an atlas overlaps itself. A uniform grid over the segments' bounding box
// keeps the count near-linear in the number of segments.
#ifndef CGAL_SMP_CUT_INTERNAL_BORDER_CROSSINGS_H
#define CGAL_SMP_CUT_INTERNAL_BORDER_CROSSINGS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Vector2 = Eigen::Vector2d;   // as in mesh/Chart_mesh.h
using UV_vector = Eigen::VectorXd; // (u0, v0, u1, v1, ...)

/// True if the open segments pq and rs cross at a single interior point
/// (exact orientation predicates; touching and collinear overlap do not count).
inline bool segments_cross_properly(const Vector2& p, const Vector2& q, const Vector2& r, const Vector2& s)
{
  using Point = CGAL::Epick::Point_2;
  const Point P(p.x(), p.y()), Q(q.x(), q.y()), R(r.x(), r.y()), S(s.x(), s.y());
  const CGAL::Orientation o1 = CGAL::orientation(P, Q, R), o2 = CGAL::orientation(P, Q, S);
  if(o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o1 == o2) return false;
  const CGAL::Orientation o3 = CGAL::orientation(R, S, P), o4 = CGAL::orientation(R, S, Q);
  return o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR && o3 != o4;
}

/// True if the closed segments pq and rs have a point in common (crossing,
/// touching or overlapping), by exact predicates.
inline bool segments_meet(const Vector2& p, const Vector2& q, const Vector2& r, const Vector2& s)
{
  using Point = CGAL::Epick::Point_2;
  return CGAL::do_intersect(CGAL::Epick::Segment_2(Point(p.x(), p.y()), Point(q.x(), q.y())),
                            CGAL::Epick::Segment_2(Point(r.x(), r.y()), Point(s.x(), s.y())));
}

/// Number of pairs of segments (UV-vertex index pairs into x) that cross
/// properly (with `touching`, that meet at all); segments sharing a vertex
/// index are not tested. If `group` is not null, only pairs in the same
/// group (e.g. the same chart) count.
/// Counting stops once `limit` crossings are found. Non-finite coordinates
/// make every segment through them count as crossing nothing.
inline std::size_t count_border_crossings(const std::vector<std::array<int, 2>>& segments, const UV_vector& x,
                                          const std::vector<int>* group = nullptr,
                                          std::size_t limit = std::numeric_limits<std::size_t>::max(),
                                          bool touching = false)
{
  const std::size_t n = segments.size();
  if(n < 2) return 0;
  auto point = [&](int v) { return Vector2(x[2*v], x[2*v+1]); };
  const double inf = std::numeric_limits<double>::infinity();
  Vector2 low(inf, inf), high(-inf, -inf);
  for(const auto& s : segments)
    for(int v : s)
      if(point(v).allFinite())
      {
        low = low.cwiseMin(point(v));
        high = high.cwiseMax(point(v));
      }
  if(!(low.x() <= high.x() && low.y() <= high.y())) return 0;

  // about one segment per cell; cells may be non-square
  const int cells = (std::max)(1, int(std::ceil(std::sqrt(double(n)))));
  const Vector2 size = (high - low).cwiseMax(Vector2::Constant(1e-300));
  auto cell_of = [&](double value, int axis) {
    const int c = int((value - low[axis]) / size[axis] * cells);
    return (std::min)((std::max)(c, 0), cells - 1);
  };
  std::vector<std::array<int, 4>> box(n); // cell range x0, y0, x1, y1
  std::vector<int> count(std::size_t(cells) * cells + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vector2 a = point(segments[i][0]), b = point(segments[i][1]);
    if(!a.allFinite() || !b.allFinite()) { box[i] = {1, 1, 0, 0}; continue; } // empty range
    box[i] = {cell_of((std::min)(a.x(), b.x()), 0), cell_of((std::min)(a.y(), b.y()), 1),
              cell_of((std::max)(a.x(), b.x()), 0), cell_of((std::max)(a.y(), b.y()), 1)};
    for(int cy = box[i][1]; cy <= box[i][3]; ++cy)
      for(int cx = box[i][0]; cx <= box[i][2]; ++cx) ++count[std::size_t(cy) * cells + cx + 1];
  }
  for(std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  std::vector<int> bucket(count.back()), fill(count.begin(), count.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
    for(int cy = box[i][1]; cy <= box[i][3]; ++cy)
      for(int cx = box[i][0]; cx <= box[i][2]; ++cx) bucket[fill[std::size_t(cy) * cells + cx]++] = int(i);

  std::size_t crossings = 0;
  for(int cy = 0; cy < cells; ++cy)
    for(int cx = 0; cx < cells; ++cx)
    {
      const std::size_t c = std::size_t(cy) * cells + cx;
      for(int a = count[c]; a < count[c + 1]; ++a)
        for(int b = a + 1; b < count[c + 1]; ++b)
        {
          const int i = bucket[a], j = bucket[b];
          // a pair is tested in one cell only: the first cell both ranges share
          if((std::max)(box[i][0], box[j][0]) != cx || (std::max)(box[i][1], box[j][1]) != cy) continue;
          if(group && (*group)[i] != (*group)[j]) continue;
          const auto& s = segments[i];
          const auto& t = segments[j];
          if(s[0] == t[0] || s[0] == t[1] || s[1] == t[0] || s[1] == t[1]) continue;
          const bool meet = touching ? segments_meet(point(s[0]), point(s[1]), point(t[0]), point(t[1]))
                                     : segments_cross_properly(point(s[0]), point(s[1]), point(t[0]), point(t[1]));
          if(meet && ++crossings >= limit) return crossings;
        }
    }
  return crossings;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
