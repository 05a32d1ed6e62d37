// Shape packing: charts placed by the texels they cover, not by their
// bounding rectangles, so that a chart can sit in the notch of another.
//
// At a trial scale, each chart (already turned to its minimum-area rectangle)
// is rasterized conservatively at the atlas's resolution: a texel belongs to
// the chart if a triangle comes within tuning::raster_margin_texels of its
// closed square. A raster is kept as its column and row extents, which give
// its lower and upper profiles in the 4 turns by 90°. Charts are placed
// largest first on a skyline (per texel column, the first row above every
// placed chart dilated by the padding): each chart goes where its top ends
// lowest, its lower profile resting on the skyline (a Tetris drop). The
// rasters of two placed charts, one of them dilated by p = ceil(padding)
// texels, are disjoint, so the charts are at least p texels apart (never
// touching, even with padding 0). Turns by 90° about texel corners and
// integer texel offsets map the raster exactly, so the placement is exact.
// The scale is searched between a scale that is known to pack (the
// rectangle packing's) and the area bound. The same search is then run with
// the raster placement (raster_placement.h: charts anywhere on a bit image
// of the page, holes under overhangs included), above the skyline's scale
// (for a scene atlas of few charts, in a few drop orders:
// largest_raster_scale()); the larger scale is kept, so the raster
// placement can only raise the coverage.
#ifndef CGAL_SMP_CUT_INTERNAL_SHAPE_PACKING_H
#define CGAL_SMP_CUT_INTERNAL_SHAPE_PACKING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_raster.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/raster_placement.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace packing {

/// Largest value of `sky` over each window [x, x + w), for x in [first, last]:
/// `out[x]` (van Herk / Gil-Werman: block prefix and suffix maxima, O(n)).
/// Returns the first x of the lowest window.
inline int window_max(const std::vector<int>& sky, int w, int first, int last, std::vector<int>& out,
                       std::vector<int>& prefix, std::vector<int>& suffix)
{
  const int end = last + w; // columns [first, end) are read
  out.resize(sky.size()); prefix.resize(sky.size()); suffix.resize(sky.size());
  for(int k = first; k < end; ++k)
    prefix[k] = (k - first) % w == 0 ? sky[k] : (std::max)(prefix[k - 1], sky[k]);
  for(int k = end; k-- > first;)
    suffix[k] = (k == end - 1 || (k + 1 - first) % w == 0) ? sky[k] : (std::max)(suffix[k + 1], sky[k]);
  int lowest = first;
  for(int x = first; x <= last; ++x)
  {
    out[x] = (std::max)(suffix[x], prefix[x + w - 1]);
    if(out[x] < out[lowest]) lowest = x;
  }
  return lowest;
}

/// Skyline of an `n` × `n` texel square: per column, the first row above
/// every placed raster dilated by `pad` texels. Rasters keep `pad` texels
/// from the sides.
class Skyline
{
  int n_, pad_;
  long free_; // texels above the skyline, inside the padding
  std::vector<int> sky_, lo_, hi_, window_[2], prefix_, suffix_, spread_;

  /// Columns 0 .. w-1 in the order ends, middle, quarters, ...: far apart
  /// first, so that a place that cannot win is ruled out in a few columns.
  void spread_order(int w)
  {
    spread_.clear();
    spread_.push_back(0);
    if(w > 1) spread_.push_back(w - 1);
    std::vector<std::pair<int, int>> ranges{{0, w - 1}}; // open ranges (a, b) still to split
    for(std::size_t k = 0; k < ranges.size(); ++k)
    {
      const int a = ranges[k].first, b = ranges[k].second;
      if(b - a < 2) continue;
      const int m = (a + b) / 2;
      spread_.push_back(m);
      ranges.push_back({a, m});
      ranges.push_back({m, b});
    }
  }

public:
  Skyline(int n, int pad) : n_(n), pad_(pad), free_(long(n - 2 * pad) * (n - 2 * pad)), sky_(n, pad) {}

  /// Texels above the skyline, inside the padding: no more area can be added.
  long free_texels() const { return free_; }

  /// Drops raster `r` where its top ends lowest (ties: the first turn, then
  /// the leftmost place), its lower profile resting on the skyline, and
  /// raises the skyline. False (nothing changed) if it fits nowhere.
  bool drop(const Chart_raster& r, Raster_placement& placed)
  {
    // a lower bound of y at each x (the window's highest column less the
    // highest lower profile): the places of the lowest bound are tried
    // first, then only those whose bound can beat the best found
    long best_top = LONG_MAX;
    int lowest[2] = {0, 0};
    for(int pass = 0; pass < 2; ++pass)
      for(int turn = 0; turn < 4; ++turn)
      {
        const int w = turned_profiles(r, turn, lo_, hi_);
        const int h = (turn % 2) ? r.w : r.h;
        const int last = n_ - pad_ - w;
        if(last < pad_ || h > n_ - 2 * pad_) continue;
        std::vector<int>& window = window_[turn % 2];
        if(pass == 0 && turn < 2) lowest[turn] = window_max(sky_, w, pad_, last, window, prefix_, suffix_);
        const int highest_lo = *std::max_element(lo_.begin(), lo_.end());
        spread_order(w);
        // first pass: the first place of the lowest window only
        for(int x = pass == 0 ? lowest[turn % 2] : pad_; x <= (pass == 0 ? lowest[turn % 2] : last); ++x)
        {
          if(long((std::max)(pad_, window[x] - highest_lo)) + h >= best_top) continue;
          long y = pad_;
          for(int k = 0; k < w && y + h < best_top; ++k)
            y = (std::max)(y, long(sky_[x + spread_[k]]) - lo_[spread_[k]]);
          if(y + h < best_top && y + h <= n_ - pad_)
          {
            best_top = y + h;
            placed = {x, int(y), turn};
          }
        }
      }
    if(best_top == LONG_MAX) return false;
    const int w = turned_profiles(r, placed.turn, lo_, hi_);
    for(int i = 0; i < w; ++i)
    {
      const int top = placed.y + hi_[i] + pad_ + 1;
      for(int k = (std::max)(0, placed.x + i - pad_); k <= (std::min)(n_ - 1, placed.x + i + pad_); ++k)
        if(top > sky_[k])
        {
          if(k >= pad_ && k < n_ - pad_)
            free_ -= (std::min)(top, n_ - pad_) - (std::min)(sky_[k], n_ - pad_);
          sky_[k] = top;
        }
    }
    return true;
  }
};

/// Drops each raster, in `order`, on a `Placer` (Skyline or Raster_page) of
/// an `n` × `n` texel square with `pad` texels of padding. Returns 1 if all fit, else the
/// fill ratio reached (area of the charts placed, `area` in texels, over the
/// texels below the skyline; 0 if none was placed). Stops early when the
/// charts left have more area than the texels above the skyline.
template <typename Placer>
double drop_rasters(const std::vector<Chart_raster>& rasters, const std::vector<double>& area,
                    const std::vector<int>& order, int n, int pad, std::vector<Raster_placement>& placement)
{
  Placer skyline(n, pad);
  placement.assign(rasters.size(), Raster_placement());
  double left = 0.;
  for(double a : area) left += a;
  const double total = left, room = double(skyline.free_texels());
  for(int c : order)
  {
    if(left > 1.0001 * double(skyline.free_texels()) || !skyline.drop(rasters[c], placement[c]))
    {
      const double used = room - double(skyline.free_texels());
      return used > 0. ? (std::min)(0.999, (total - left) / used) : 0.;
    }
    left -= area[c];
  }
  return 1.;
}

/// The order in which the charts of `shapes` are dropped, largest first by
/// `key`: 0, the longer side of the frame, then the shorter; 1, the area of
/// the frame's rectangle, then the longer side; 2, the shorter side, then
/// the longer (ties: the index). The raster placement fills its holes
/// differently in each order.
/// \post a permutation of the indices of `shapes`
inline std::vector<int> drop_order(const std::vector<Chart_shape>& shapes, int key)
{
  std::vector<int> order(shapes.size());
  for(std::size_t c = 0; c < order.size(); ++c) order[c] = int(c);
  auto value = [&](int c) {
    const Vector2& s = shapes[c].size;
    if(key == 1) return std::make_pair(s.x() * s.y(), s.maxCoeff());
    if(key == 2) return std::make_pair(s.minCoeff(), s.maxCoeff());
    return std::make_pair(s.maxCoeff(), s.minCoeff());
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return value(a) > value(b); });
  return order;
}

/// Shape packing of `shapes` into an `n` × `n` texel square with `pad`
/// texels of padding: the largest scale (texels per unit of the charts'
/// frames) found in (`low`, `high`] at which all charts drop in the order
/// of `key` (drop_order(); down from `high` by tuning::shape_packing_step or
/// more, then bisected `refinements` times), with their rasters and
/// placements; 0 if none was found above `low`.
template <typename Placer = Skyline>
double largest_shape_scale(const std::vector<Chart_shape>& shapes, int n, int pad, double low, double high,
                           std::vector<Chart_raster>& rasters, std::vector<Raster_placement>& placement, int key = 0,
                           int refinements = tuning::shape_packing_refinements)
{
  const std::vector<int> order = drop_order(shapes, key);
  double found = 0.;
  std::vector<Chart_raster> trial_rasters(shapes.size());
  std::vector<Raster_placement> trial;
  std::vector<double> area(shapes.size());
  double placed = 0.; // fill ratio reached by the last trial
  auto attempt = [&](double texels) {
    for(std::size_t c = 0; c < shapes.size(); ++c)
    {
      trial_rasters[c] = rasterize(shapes[c], texels);
      area[c] = shapes[c].area * texels * texels;
    }
    placed = drop_rasters<Placer>(trial_rasters, area, order, n, pad, trial);
    if(placed < 1.) return false;
    found = texels;
    rasters.swap(trial_rasters);
    trial_rasters.resize(shapes.size());
    placement.swap(trial);
    return true; };
  // down from the area bound in steps until one packs (a step at least as
  // large as the area the last trial could not place), then bisect
  double fail = high, texels = high;
  bool above_low_tried = false;
  for(int step = 0; step < tuning::shape_packing_steps && found == 0.; ++step)
  {
    if(texels <= low * tuning::shape_packing_margin) // the last chance to beat the rectangles
    {
      if(above_low_tried || fail <= low * tuning::shape_packing_margin) return 0.;
      texels = low * tuning::shape_packing_margin;
      above_low_tried = true;
    }
    if(!attempt(texels))
    {
      // the fill ratio reached, at the scale that fills the square at that ratio
      fail = texels;
      const double fill = placed > 0. ? std::sqrt(placed) * high / texels : 0.;
      texels *= (std::max)(0.5, (std::min)(tuning::shape_packing_step, fill));
    }
  }
  for(int it = 0; it < refinements && found > 0. && fail > found; ++it)
  {
    const double mid = 0.5 * (found + fail);
    if(!attempt(mid)) fail = mid;
  }
  return found;
}

/// The raster placement's scale search: largest_shape_scale() with a
/// Raster_page, in the first drop_order() only, or, up to
/// tuning::raster_orders_max_charts charts and
/// tuning::raster_orders_max_padding texels of padding (each order is a search),
/// in each of the tuning::raster_placement_orders orders with
/// tuning::raster_placement_refinements bisections, each order searched
/// above the best scale so far. Returns the largest scale found in (`low`,
/// `high`], with its rasters and placements; 0 if none.
inline double largest_raster_scale(const std::vector<Chart_shape>& shapes, int n, int pad, double low, double high,
                                   std::vector<Chart_raster>& rasters, std::vector<Raster_placement>& placement)
{
  const bool few = int(shapes.size()) <= tuning::raster_orders_max_charts && pad <= tuning::raster_orders_max_padding;
  const int orders = few ? tuning::raster_placement_orders : 1;
  const int refinements = few ? tuning::raster_placement_refinements : tuning::shape_packing_refinements;
  double best = 0.;
  std::vector<Chart_raster> trial_rasters;
  std::vector<Raster_placement> trial;
  for(int key = 0; key < orders; ++key)
  {
    const double found = largest_shape_scale<Raster_page>(shapes, n, pad, (std::max)(low, best), high, trial_rasters,
                                                          trial, key, refinements);
    if(found > best) // only above the best so far: an order never lowers it
    {
      best = found;
      rasters.swap(trial_rasters);
      placement.swap(trial);
    }
  }
  return best;
}

/// The shape packing of the charts of `mesh` (turned to their frames:
/// `local`, extents `size`) at a scale above `scale` (UV per frame unit, the
/// rectangles'), `padding` in texels of a `texture_size` square: writes the UVs of the charts' vertices into `x` and returns
/// the scale, or returns 0 (nothing written) if it found none. With
/// `raster`, the raster placement is also tried (up to
/// tuning::raster_placement_max_charts charts), kept where its scale is larger.
inline double pack_shapes(const Chart_mesh& mesh, const std::vector<int>& chart_of_face,
                          const std::vector<int>& chart_of_vertex, const std::vector<Vector2>& local,
                          const std::vector<Vector2>& size, int texture_size, double padding,
                          double scale, UV_vector& x, bool raster = true, bool* by_raster = nullptr)
{
  if(by_raster) *by_raster = false;
  const int n = texture_size;
  const int pad = std::isfinite(padding) ? int(std::ceil((std::max)(0., padding))) : 0;
  if(n <= 0 || size.size() < 2 || 2 * pad + 2 >= n) return 0.;
  std::vector<Chart_shape> shapes(size.size());
  double area = 0.;
  for(std::size_t c = 0; c < size.size(); ++c) shapes[c].size = size[c];
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const auto& t = mesh.faces[f];
    Chart_shape& shape = shapes[chart_of_face[f]];
    shape.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
    const Vector2 e1 = local[t[1]] - local[t[0]], e2 = local[t[2]] - local[t[0]];
    const double a = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
    shape.area += a;
    area += a;
  }
  if(!(area > 0.)) return 0.;
  const double high = (n - 2. * pad) / std::sqrt(area); // texels per unit filling the square
  std::vector<Chart_raster> rasters;
  std::vector<Raster_placement> at;
  double texels = largest_shape_scale(shapes, n, pad, scale * n, high, rasters, at);
  if(raster && int(shapes.size()) <= tuning::raster_placement_max_charts)
  {
    std::vector<Chart_raster> raster_rasters;
    std::vector<Raster_placement> raster_at;
    // one order (the scene atlas tries more): a mesh's own atlas keeps its time
    const double by_bits = largest_shape_scale<Raster_page>(shapes, n, pad, (std::max)(scale * n, texels), high,
                                                            raster_rasters, raster_at);
    if(by_bits > texels) // found only above the skyline's scale
    {
      texels = by_bits;
      rasters.swap(raster_rasters);
      at.swap(raster_at);
      if(by_raster) *by_raster = true;
    }
  }
  if(!(texels > 0.)) return 0.;
  // center the layout by whole texels (the rasters stay on the grid)
  int used_x = 0, used_y = 0;
  for(std::size_t c = 0; c < at.size(); ++c)
  {
    const bool turned = at[c].turn % 2 != 0;
    used_x = (std::max)(used_x, at[c].x + (turned ? rasters[c].h : rasters[c].w));
    used_y = (std::max)(used_y, at[c].y + (turned ? rasters[c].w : rasters[c].h));
  }
  for(Raster_placement& p : at)
  {
    p.x += (n - pad - used_x) / 2;
    p.y += (n - pad - used_y) / 2;
  }
  for(int v = 0; v < mesh.number_of_vertices; ++v)
  {
    const int c = chart_of_vertex[v];
    if(c >= 0) x.segment<2>(2 * v) = place_point(local[v], texels, rasters[c], at[c]) / double(n);
  }
  return texels / n;
}

} // namespace packing
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
