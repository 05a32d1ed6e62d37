// Chart rasters: the texels a chart covers at one scale (conservative: every
// texel a triangle comes near), as row and column extents and as bit rows,
// and the map from a chart's frame to a placed, turned raster.
#ifndef CGAL_SMP_CUT_INTERNAL_CHART_RASTER_H
#define CGAL_SMP_CUT_INTERNAL_CHART_RASTER_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace packing {
/// Triangles of one chart, in its turned frame (lower corner at the origin).
struct Chart_shape
{
  std::vector<std::array<Vector2, 3>> triangles;
  Vector2 size = Vector2::Zero(); ///< extent of the chart in its frame
  double area = 0.;               ///< area of its triangles
};

/// A chart's conservative raster at one scale: `w` × `h` texels; the chart,
/// scaled, lies in [0, w] × [0, h] after adding `shift` (texel units).
/// Extents: texels of column i span rows [col_lo[i], col_hi[i]], those of
/// row j columns [row_lo[j], row_hi[j]]. `bits`: the texels themselves, row
/// j's in words [j * words, (j + 1) * words), bit i % 64 of word i / 64.
struct Chart_raster
{
  int w = 0, h = 0, words = 0;
  Vector2 shift = Vector2::Zero();
  std::vector<int> col_lo, col_hi, row_lo, row_hi;
  std::vector<std::uint64_t> bits;
};

/// Sets bits [a, b] (a <= b) of the bit row starting at `row`.
inline void set_bits(std::uint64_t* row, int a, int b)
{
  for(int k = a / 64; k <= b / 64; ++k)
  {
    const int lo = (std::max)(a, 64 * k) - 64 * k, hi = (std::min)(b, 64 * k + 63) - 64 * k;
    row[k] |= (hi == 63 ? ~std::uint64_t(0) : (std::uint64_t(1) << (hi + 1)) - 1) & (~std::uint64_t(0) << lo);
  }
}

/// Adds the texels touched by triangle `t` (texel units, inside [0, w] × [0, h]) to `r`.
inline void rasterize_triangle(const std::array<Vector2, 3>& t, Chart_raster& r)
{
  const double m = tuning::raster_margin_texels;
  auto cell = [](double v, int n) { return (std::min)(n - 1, (std::max)(0, int(std::floor(v)))); };
  const double y0 = (std::min)({t[0].y(), t[1].y(), t[2].y()}), y1 = (std::max)({t[0].y(), t[1].y(), t[2].y()});
  for(int j = cell(y0 - m, r.h), j1 = cell(y1 + m, r.h); j <= j1; ++j)
  {
    // x extent of the triangle within the band [j - m, j + 1 + m]
    const double b0 = j - m, b1 = j + 1 + m;
    double a = std::numeric_limits<double>::infinity(), b = -a;
    for(int k = 0; k < 3; ++k)
    {
      const Vector2& p = t[k];
      const Vector2& q = t[(k + 1) % 3];
      if(p.y() >= b0 && p.y() <= b1) { a = (std::min)(a, p.x()); b = (std::max)(b, p.x()); }
      for(double yb : {b0, b1})
        if((p.y() - yb) * (q.y() - yb) < 0.)
        {
          const double x = p.x() + (q.x() - p.x()) * (yb - p.y()) / (q.y() - p.y());
          a = (std::min)(a, x);
          b = (std::max)(b, x);
        }
    }
    if(!(a <= b)) continue;
    const int i0 = cell(a - m, r.w), i1 = cell(b + m, r.w);
    r.row_lo[j] = (std::min)(r.row_lo[j], i0);
    r.row_hi[j] = (std::max)(r.row_hi[j], i1);
    set_bits(&r.bits[std::size_t(j) * r.words], i0, i1);
    for(int i = i0; i <= i1; ++i)
    {
      r.col_lo[i] = (std::min)(r.col_lo[i], j);
      r.col_hi[i] = (std::max)(r.col_hi[i], j);
    }
  }
}

/// The raster of `shape` scaled by `texels` (texels per unit of its frame),
/// centered in the fewest texels that hold it with the margin.
inline Chart_raster rasterize(const Chart_shape& shape, double texels)
{
  Chart_raster r;
  const double m = tuning::raster_margin_texels;
  const Vector2 ext = texels * shape.size;
  r.w = int(std::floor(ext.x() + 2. * m)) + 1;
  r.h = int(std::floor(ext.y() + 2. * m)) + 1;
  r.shift = 0.5 * (Vector2(r.w, r.h) - ext);
  r.col_lo.assign(r.w, INT_MAX); r.col_hi.assign(r.w, INT_MIN);
  r.row_lo.assign(r.h, INT_MAX); r.row_hi.assign(r.h, INT_MIN);
  r.words = (r.w + 63) / 64;
  r.bits.assign(std::size_t(r.h) * r.words, 0);
  for(const auto& t : shape.triangles)
    rasterize_triangle({texels * t[0] + r.shift, texels * t[1] + r.shift, texels * t[2] + r.shift}, r);
  // a column or row no triangle reached (degenerate triangles): treat as full
  for(int i = 0; i < r.w; ++i) if(r.col_lo[i] > r.col_hi[i]) { r.col_lo[i] = 0; r.col_hi[i] = r.h - 1; }
  for(int j = 0; j < r.h; ++j) if(r.row_lo[j] > r.row_hi[j]) { r.row_lo[j] = 0; r.row_hi[j] = r.w - 1; }
  return r;
}

/// Lower and upper profiles of raster `r` turned by `turn` quarter turns
/// counterclockwise (cell (i, j) goes to (h-1-j, i) by one turn): width, and
/// per column the lowest and highest texel rows.
inline int turned_profiles(const Chart_raster& r, int turn, std::vector<int>& lo, std::vector<int>& hi)
{
  const int w = (turn % 2) ? r.h : r.w;
  lo.resize(w); hi.resize(w);
  for(int i = 0; i < w; ++i)
    switch(turn)
    {
      case 0: lo[i] = r.col_lo[i]; hi[i] = r.col_hi[i]; break;
      case 1: lo[i] = r.row_lo[r.h - 1 - i]; hi[i] = r.row_hi[r.h - 1 - i]; break;
      case 2: lo[i] = r.h - 1 - r.col_hi[r.w - 1 - i]; hi[i] = r.h - 1 - r.col_lo[r.w - 1 - i]; break;
      default: lo[i] = r.w - 1 - r.row_hi[i]; hi[i] = r.w - 1 - r.row_lo[i]; break;
    }
  return w;
}

/// Where a chart's raster went: texel offset of its (turned) raster, and the turn.
struct Raster_placement { int x = 0, y = 0, turn = 0; };

/// Maps point `p` of a chart's frame to texel coordinates of the square:
/// scaled, shifted into its raster, turned, moved to its placement.
inline Vector2 place_point(const Vector2& p, double texels, const Chart_raster& r, const Raster_placement& at)
{
  const Vector2 g = texels * p + r.shift;
  Vector2 t;
  switch(at.turn)
  {
    case 0: t = g; break;
    case 1: t = Vector2(r.h - g.y(), g.x()); break;
    case 2: t = Vector2(r.w - g.x(), r.h - g.y()); break;
    default: t = Vector2(g.y(), r.w - g.x()); break;
  }
  return t + Vector2(at.x, at.y);
}

} // namespace packing
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
