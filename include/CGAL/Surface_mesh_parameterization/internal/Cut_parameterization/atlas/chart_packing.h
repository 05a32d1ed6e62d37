// Atlas packing of one UV map: lays its charts out in a square without
// overlap, in three stages, the layout of the largest scale kept.
//
// Each chart (connected component of the chart mesh) is moved by a rotation
// and a translation only, then all charts get one common uniform scale (equal
// texel density). A chart is first turned to its minimum-area bounding
// rectangle (convex hull + rotating calipers; a lone chart to the rectangle
// of smallest larger side instead, which fills a square best).
// 1. Rectangles (this file): the rectangles, inflated by the padding, are
//    packed largest first by MaxRects (best short side fit, 90° turns) into
//    the square. The padding is in texels, a fixed fraction of the square
//    whatever the scale, so the largest common scale that packs is searched
//    directly (an area bound, then 5% steps down, then bisection), each trial
//    a full packing in two orders (longer side, area): a scale that always
//    packs, the floor of the next stages.
// 2. Skyline (shape_packing.h): the charts' rasters dropped on a skyline,
//    so that a chart can sit in the notch of another; searched above 1.
// 3. Raster placement (raster_placement.h, driven by shape_packing.h): the
//    rasters placed anywhere on a bit image of the page, holes under
//    overhangs included; searched above 2 (up to
//    tuning::raster_placement_max_charts charts: its cost grows faster),
//    kept only if larger.
// Every stage's guarantee (padding between charts, inside the square) is
// exact, so whichever is kept the layout is valid.
#ifndef CGAL_SMP_CUT_INTERNAL_CHART_PACKING_H
#define CGAL_SMP_CUT_INTERNAL_CHART_PACKING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/shape_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Packing_settings
{
  int texture_size = 1024;  ///< texels per side of the square texture
  double padding = 2.;      ///< gap in texels between two charts, and between a chart and the square's sides
  bool world_units = false; ///< true: keep the 3D scale (scale 1); the layout is the same, in world units
  bool shapes = true;       ///< also try the shape packing (rasters of the charts), kept where it packs larger
  bool raster = true;       ///< in the shape packing, also try the raster placement (holes under overhangs filled)
};

struct Packing_result
{
  double coverage = 0.; ///< total UV area of the charts / area of the packing square
  double scale = 1.;    ///< common factor applied to every chart (UV length per input UV length); 1 in world units
  double side = 1.;     ///< side of the packing square in the output units (1 unless world_units)
  bool by_shape = false; ///< the shape packing was kept (charts' bounding rectangles may overlap)
  bool by_raster = false; ///< ... with the raster placement (not the skyline)
};

namespace packing {

/// Convex hull of `p` (Andrew's monotone chain): counterclockwise, no
/// repeated or collinear points; one point if all points are equal, two if
/// they are collinear.
inline std::vector<Vector2> convex_hull(std::vector<Vector2> p)
{
  auto less = [](const Vector2& a, const Vector2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  std::sort(p.begin(), p.end(), less);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if(p.size() < 3) return p;
  auto cross = [](const Vector2& o, const Vector2& a, const Vector2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x()); };
  std::vector<Vector2> h(2 * p.size());
  std::size_t k = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    while(k >= 2 && cross(h[k-2], h[k-1], p[i]) <= 0.) --k;
    h[k++] = p[i];
  }
  for(std::size_t i = p.size() - 1, t = k + 1; i-- > 0;)
  {
    while(k >= t && cross(h[k-2], h[k-1], p[i]) <= 0.) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// Extents (width along u(θ) = (cos θ, sin θ), height along its normal) of
/// the convex polygon `hull` for each of the increasing `angles`, all in
/// [0, π/2): rotating calipers, O(|hull| + |angles|).
inline std::vector<Vector2> oriented_extents(const std::vector<Vector2>& hull, const std::vector<double>& angles)
{
  const std::size_t n = hull.size();
  std::vector<Vector2> extents;
  extents.reserve(angles.size());
  std::size_t contact[4] = {0, 0, 0, 0}; // extreme points along u, normal, -u, -normal
  for(std::size_t a = 0; a < angles.size(); ++a)
  {
    const Vector2 u(std::cos(angles[a]), std::sin(angles[a]));
    const Vector2 dir[4] = {u, Vector2(-u.y(), u.x()), -u, Vector2(u.y(), -u.x())};
    for(int d = 0; d < 4; ++d)
    {
      std::size_t& c = contact[d];
      if(a == 0) // first angle: full scan
      {
        for(std::size_t i = 1; i < n; ++i)
          if(dir[d].dot(hull[i]) > dir[d].dot(hull[c])) c = i;
      }
      else // the contacts turn counterclockwise with the angle
        for(std::size_t step = 0; step < n && dir[d].dot(hull[(c + 1) % n]) > dir[d].dot(hull[c]); ++step)
          c = (c + 1) % n;
    }
    extents.emplace_back(dir[0].dot(hull[contact[0]] - hull[contact[2]]),
                         dir[1].dot(hull[contact[1]] - hull[contact[3]]));
  }
  return extents;
}

/// Angle θ in [0, π/2) whose frame (u(θ), its normal) gives `hull` the
/// bounding rectangle of smallest area (`square_fit` false), or of smallest
/// larger side (`square_fit` true, then smallest area). The minimum-area
/// rectangle lies flush with a hull edge, so the hull edge directions are
/// enough for it. The smallest enclosing square of a lone chart may be
/// oblique (a 10 × 0.5 strip on the diagonal needs a side of 7.4, not 10: 1.8
/// times its texel density), so `square_fit` also tries every degree from
/// the minimum-area frame. Ties go to the smallest angle.
inline double best_angle(const std::vector<Vector2>& hull, bool square_fit)
{
  const double quarter = 0.5 * 3.14159265358979323846;
  auto reduce = [&](double t) { t = std::fmod(t, quarter); if(t < 0.) t += quarter; return t < quarter ? t : 0.; };
  std::vector<double> angles;
  for(std::size_t i = 0; i < hull.size() && hull.size() > 1; ++i)
  {
    const Vector2 e = hull[(i + 1) % hull.size()] - hull[i];
    angles.push_back(reduce(std::atan2(e.y(), e.x())));
  }
  if(angles.empty()) return 0.;
  if(square_fit) // every degree from the minimum-area frame
  {
    const double base = best_angle(hull, false);
    for(int degree = 1; degree < 90; ++degree) angles.push_back(reduce(base + quarter * degree / 90.));
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  const std::vector<Vector2> ext = oriented_extents(hull, angles);
  std::size_t best = 0;
  auto key = [&](std::size_t i) {
    const double area = ext[i].x() * ext[i].y(), larger = ext[i].maxCoeff();
    return square_fit ? std::make_pair(larger, area) : std::make_pair(area, larger); };
  for(std::size_t i = 1; i < ext.size(); ++i)
    if(key(i) < key(best)) best = i;
  return angles[best];
}

/// Axis-aligned rectangle [x0, x1] × [y0, y1].
struct Box { double x0, y0, x1, y1; };

/// MaxRects bin: the maximal free rectangles of a square, split around each
/// placed rectangle. Coordinates are only copied, never recomputed, so
/// placed rectangles never overlap and stay inside the square exactly.
class Max_rects
{
  std::vector<Box> free_, pieces_, kept_;
  std::vector<std::size_t> touching_; // indices in kept_

  static bool contains(const Box& a, const Box& b)
  { return a.x0 <= b.x0 && a.y0 <= b.y0 && b.x1 <= a.x1 && b.y1 <= a.y1; }

public:
  explicit Max_rects(double side) : free_{{0., 0., side, side}} {}

  /// Places a w × h rectangle, turned by 90° if that fits better, in the free
  /// rectangle that leaves the shortest leftover side (ties: the shortest
  /// longer leftover, then the first found). Returns false if it fits nowhere.
  /// Free rectangles narrower than `smallest` (the smallest side of all the
  /// rectangles still to come) are useless and dropped.
  bool insert(double w, double h, double smallest, Box& placed, bool& turned)
  {
    double best_short = std::numeric_limits<double>::infinity(), best_long = best_short;
    std::size_t best = free_.size();
    for(std::size_t i = 0; i < free_.size(); ++i)
      for(int t = 0; t < 2; ++t)
      {
        const Box& f = free_[i];
        const double a = t ? h : w, b = t ? w : h;
        if(!(f.x0 + a <= f.x1 && f.y0 + b <= f.y1)) continue;
        const double dx = f.x1 - f.x0 - a, dy = f.y1 - f.y0 - b;
        const double s = (std::min)(dx, dy), l = (std::max)(dx, dy);
        if(s < best_short || (s == best_short && l < best_long))
        {
          best_short = s; best_long = l; best = i; turned = (t == 1);
        }
      }
    if(best == free_.size()) return false;
    const Box& f = free_[best];
    placed = {f.x0, f.y0, f.x0 + (turned ? h : w), f.y0 + (turned ? w : h)};
    split(placed, smallest);
    return true;
  }

private:
  /// Replaces every free rectangle overlapping `p` by its (up to 4) maximal
  /// parts outside `p`, and drops the new parts contained in another free
  /// rectangle. An old rectangle cannot lie in a new part, and one holding a
  /// new part touches `p` (it reaches p's side and does not overlap p), so
  /// only those are compared: O(free rectangles) per placement.
  void split(const Box& p, double smallest)
  {
    kept_.clear(); pieces_.clear(); touching_.clear();
    auto useful = [&](const Box& b) { return b.x0 + smallest <= b.x1 && b.y0 + smallest <= b.y1; };
    for(const Box& f : free_)
    {
      if(!useful(f)) continue;
      if(!(p.x0 < f.x1 && f.x0 < p.x1 && p.y0 < f.y1 && f.y0 < p.y1))
      {
        if(p.x0 <= f.x1 && f.x0 <= p.x1 && p.y0 <= f.y1 && f.y0 <= p.y1) touching_.push_back(kept_.size());
        kept_.push_back(f);
        continue;
      }
      if(f.x0 < p.x0) pieces_.push_back({f.x0, f.y0, p.x0, f.y1});
      if(p.x1 < f.x1) pieces_.push_back({p.x1, f.y0, f.x1, f.y1});
      if(f.y0 < p.y0) pieces_.push_back({f.x0, f.y0, f.x1, p.y0});
      if(p.y1 < f.y1) pieces_.push_back({f.x0, p.y1, f.x1, f.y1});
    }
    for(std::size_t i = 0; i < pieces_.size(); ++i)
    {
      bool redundant = false;
      for(std::size_t j = 0; j < pieces_.size() && !redundant; ++j)
        redundant = j != i && contains(pieces_[j], pieces_[i]) && (j < i || !contains(pieces_[i], pieces_[j]));
      for(std::size_t j = 0; j < touching_.size() && !redundant; ++j)
        redundant = contains(kept_[touching_[j]], pieces_[i]);
      if(!redundant && useful(pieces_[i])) kept_.push_back(pieces_[i]);
    }
    free_.swap(kept_);
  }
};

/// Where a rectangle went: lower corner of its padded box, and whether it was turned by 90°.
struct Placement { double x = 0., y = 0.; bool turned = false; };

/// Packs the boxes (scale · size[i] + pad) of rectangles `size`, in the
/// given order, into the square [0, side]². Returns false if one does not fit.
inline bool pack_boxes(const std::vector<Vector2>& size, const std::vector<int>& order, double scale, double pad,
                       double side, std::vector<Placement>& placement)
{
  Max_rects bin(side);
  placement.assign(size.size(), Placement());
  std::vector<double> smallest(order.size() + 1, std::numeric_limits<double>::infinity());
  for(std::size_t j = order.size(); j-- > 0;)
    smallest[j] = (std::min)(smallest[j + 1], scale * size[order[j]].minCoeff() + pad);
  Box box;
  for(std::size_t j = 0; j < order.size(); ++j)
  {
    const int i = order[j];
    if(!bin.insert(scale * size[i].x() + pad, scale * size[i].y() + pad, smallest[j + 1], box, placement[i].turned))
      return false;
    placement[i].x = box.x0;
    placement[i].y = box.y0;
  }
  return true;
}

} // namespace packing

namespace packing {

/// Each chart of `mesh` turned to its best rectangle, with its lower corner
/// at the origin: `local` (per vertex) and `size` (per chart); the vertices
/// of chart c are vertices[first[c] .. first[c + 1]), by increasing index.
/// False if a UV is not finite.
inline bool chart_rectangles(const Chart_mesh& mesh, const UV_vector& x, const std::vector<int>& chart_of_face, int n,
                             std::vector<int>& chart_of_vertex, std::vector<int>& first, std::vector<int>& vertices,
                             std::vector<Vector2>& local, std::vector<Vector2>& size)
{
  // vertices of each chart, by increasing index
  chart_of_vertex.assign(mesh.number_of_vertices, -1);
  first.assign(n + 1, 0);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int v : mesh.faces[f])
    {
      if(!x.segment<2>(2 * v).allFinite()) return false; // nothing sensible to pack
      chart_of_vertex[v] = chart_of_face[f];
    }
  for(int c : chart_of_vertex) if(c >= 0) ++first[c + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  vertices.assign(first[n], 0);
  std::vector<int> cursor(first.begin(), first.end() - 1);
  for(int v = 0; v < mesh.number_of_vertices; ++v)
    if(chart_of_vertex[v] >= 0) vertices[cursor[chart_of_vertex[v]]++] = v;

  // turn each chart to its best rectangle, with its lower corner at the origin
  local.assign(mesh.number_of_vertices, Vector2::Zero());
  size.assign(n, Vector2::Zero());
  for(int c = 0; c < n; ++c)
  {
    const Vector2 origin = x.segment<2>(2 * vertices[first[c]]);
    std::vector<Vector2> points;
    for(int i = first[c]; i < first[c + 1]; ++i) points.push_back(x.segment<2>(2 * vertices[i]) - origin);
    const double angle = packing::best_angle(packing::convex_hull(points), n == 1);
    const double co = std::cos(angle), si = std::sin(angle);
    Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for(int i = first[c]; i < first[c + 1]; ++i)
    {
      const Vector2& p = points[i - first[c]];
      Vector2& q = local[vertices[i]];
      q = Vector2(co * p.x() + si * p.y(), -si * p.x() + co * p.y()); // rotation by -angle
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
    }
    for(int i = first[c]; i < first[c + 1]; ++i) local[vertices[i]] -= low;
    size[c] = high - low;
  }
  return true;
}

/// The largest scale at which the rectangles of `size` (made at least a
/// tiny fraction of the largest) pack into the unit square with the padding
/// of `settings` (lowered where even points would not fit): `pad`, `room`
/// and the placements `best` of that scale. Without `rectangles`, only the
/// grid of cells that always fits (the fallback of the shape packing).
inline double largest_packing_scale(std::vector<Vector2>& size, const Packing_settings& settings, double& pad,
                                    double& room, std::vector<Placement>& best, bool rectangles = true)
{
  const int n = int(size.size());
  double largest = 0.;
  for(const Vector2& s : size) largest = (std::max)(largest, s.maxCoeff());
  const double tiny = largest > 0. ? 1e-9 * largest : 1.;
  double max_side = 0., area = 0., perimeter = 0.;
  for(Vector2& s : size)
  {
    s = s.cwiseMax(Vector2::Constant(tiny));
    max_side = (std::max)(max_side, s.maxCoeff());
    area += s.x() * s.y();
    perimeter += s.x() + s.y();
  }

  // In the unit square, box i is (scale * size + pad) and the boxes must fit in
  // [0, 1 - pad]²; the chart sits at pad from its box's lower corner. A k × k
  // grid of cells 'cell' always fits when pad < cell; else lower the padding.
  const int k = int(std::ceil(std::sqrt(double(n))));
  // never 0: with padding 0 two charts still do not touch (their boxes at least
  // min_gap apart, a thousandth of a texel at 1024 texels)
  const double min_gap = 1e-6;
  pad = std::isfinite(settings.padding) && settings.texture_size > 0
                 ? (std::max)(min_gap, settings.padding / settings.texture_size) : min_gap;
  if(pad * (k + 1) >= 1.) pad = 0.5 / (k + 1);
  room = 1. - pad;
  const double cell = room / k;
  double low = (cell - pad) / max_side * (1. - 1e-12);
  // largest scale allowed by the longest side and by the total box area
  const double by_area = (-pad * perimeter + std::sqrt(pad * pad * perimeter * perimeter
                           - 4. * area * (n * pad * pad - room * room))) / (2. * area);
  double high = (std::max)(low, (std::min)((room - pad) / max_side, by_area) * (1. - 1e-12));

  // largest first, by longer side and by area: a scale packs if either order does
  std::vector<int> by_side(n);
  std::iota(by_side.begin(), by_side.end(), 0);
  std::vector<int> by_size = by_side;
  auto larger = [&](double a0, double a1, double b0, double b1, int a, int b) {
    return a0 != b0 ? a0 > b0 : (a1 != b1 ? a1 > b1 : a < b); };
  std::sort(by_side.begin(), by_side.end(), [&](int a, int b) {
    return larger(size[a].maxCoeff(), size[a].minCoeff(), size[b].maxCoeff(), size[b].minCoeff(), a, b); });
  std::sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return larger(size[a].prod(), size[a].maxCoeff(), size[b].prod(), size[b].maxCoeff(), a, b); });
  best.assign(n, Placement());
  std::vector<Placement> trial;
  for(int j = 0; j < n; ++j) // the grid, always valid at scale 'low'
    best[j] = {cell * (j % k), cell * (j / k), false};
  if(!rectangles) return low;
  // largest scale that packs: step down from the bound by 5% until one
  // packs, then bisect (the grid at 'low' is the fallback)
  auto attempt = [&](double scale) {
    if(!pack_boxes(size, by_side, scale, pad, room, trial)
       && !pack_boxes(size, by_size, scale, pad, room, trial)) return false;
    best.swap(trial);
    low = scale;
    return true; };
  for(double s = high; s > low; s *= 0.95)
  {
    if(attempt(s)) break;
    high = s;
  }
  for(int it = 0; it < 60 && high - low > 2e-4 * high; ++it)
  {
    const double mid = high < 2. * low ? 0.5 * (low + high) : std::sqrt(low * high);
    if(!attempt(mid)) high = mid;
  }
  return low;
}

} // namespace packing

/// Packs the charts of `mesh` (its connected components) into a square.
///
/// Guarantees, for the UV vertices of the faces (other entries of `x` are
/// left as they are): each chart is moved by a rotation and a translation,
/// then scaled by `result.scale`, common to all charts, so shapes and face
/// orientations (signed UV areas) are kept. The charts lie in the square
/// [0, result.side]² (the unit square, or in world units the same layout
/// with scale 1), at least `padding * side / texture_size` (and never less
/// than 1e-6 side, so that charts never touch) from each other and from the
/// square's sides. With the rectangle packing (`result.by_shape` false) this
/// holds for their bounding rectangles; with the shape packing, for the
/// charts themselves (their rasters, dilated by the padding rounded up to
/// whole texels, are disjoint). If even charts shrunk to
/// points could not be that far apart (the padding times about sqrt(number of
/// charts) exceeds the texture size), the padding is lowered to half of the
/// largest feasible value, so the layout is always valid and finite.
/// Charts of zero extent get a tiny rectangle. If a UV of a face is not
/// finite, nothing is done (`x` unchanged, coverage 0). The result depends on the
/// input only (no threads, no hashing order): same input, same bits.
inline Packing_result pack_charts(const Chart_mesh& mesh, UV_vector& x,
                                  const Packing_settings& settings = Packing_settings())
{
  Packing_result result;
  int n = 0;
  const std::vector<int> chart_of_face = chart_of_faces(mesh, n);
  if(n == 0) return result;
  std::vector<int> chart_of_vertex, first, vertices;
  std::vector<Vector2> local, size;
  if(!packing::chart_rectangles(mesh, x, chart_of_face, n, chart_of_vertex, first, vertices, local, size))
    return result;
  double pad = 0., room = 0.;
  std::vector<packing::Placement> best;
  const bool rectangles = !settings.shapes || n <= tuning::rectangle_packing_max_charts;
  double scale = packing::largest_packing_scale(size, settings, pad, room, best, rectangles);
  const double by_shape = settings.shapes
                              ? packing::pack_shapes(mesh, chart_of_face, chart_of_vertex, local, size, settings.texture_size,
                                                     settings.padding, scale, x, settings.raster, &result.by_raster)
                              : 0.;
  result.by_shape = by_shape > 0.;
  if(result.by_shape) scale = by_shape;
  else
  {
    // center the layout, then place each chart at pad inside its box
    Vector2 used = Vector2::Zero();
    for(int c = 0; c < n; ++c)
    {
      const Vector2 s = scale * size[c] + Vector2::Constant(pad);
      used = used.cwiseMax(Vector2(best[c].x, best[c].y) + (best[c].turned ? Vector2(s.y(), s.x()) : s));
    }
    const Vector2 shift = 0.5 * (Vector2::Constant(room) - used).cwiseMax(Vector2::Zero()) + Vector2::Constant(pad);
    for(int v = 0; v < mesh.number_of_vertices; ++v)
    {
      const int c = chart_of_vertex[v];
      if(c < 0) continue;
      const Vector2& q = local[v];
      const Vector2 p = best[c].turned ? Vector2(size[c].y() - q.y(), q.x()) : q; // turned: rotation by +90°
      x.segment<2>(2 * v) = Vector2(best[c].x, best[c].y) + shift + scale * p;
    }
  }
  const double unit = settings.world_units ? 1. / scale : 1.; // length of the square's side
  result.scale = settings.world_units ? 1. : scale;
  result.side = unit;
  for(int v = 0; v < mesh.number_of_vertices; ++v)
  {
    if(chart_of_vertex[v] < 0) continue;
    Vector2 uv = x.segment<2>(2 * v);
    uv = uv.cwiseMax(Vector2::Zero()).cwiseMin(Vector2::Ones()); // rounding only
    x.segment<2>(2 * v) = uv * unit;
  }
  double uv_area = 0.;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    uv_area += 0.5 * std::abs(mesh.uv_edges(x, f).determinant());
  result.coverage = uv_area / (unit * unit);
  return result;
}
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
