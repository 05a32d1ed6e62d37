// Global injectivity as an energy term: a barrier between the border
// vertices and the border segments of each chart, after Smith and Schaefer
// 2015 ("Bijective parameterization with free boundaries"). A disk chart
// without flipped faces overlaps itself iff its UV border crosses itself,
// and a border can only start crossing itself where one of its vertices
// meets one of its segments. So:
// - the step bound (max_step()) is the first time, along the Newton step,
//   at which a border vertex meets a border segment of its chart
//   (continuous collision detection: a quadratic in the step length per
//   vertex-segment pair, candidates found on a grid of swept boxes);
// - the energy repels a vertex from a segment closer than a distance ε, so
//   that the solver is not stopped by that bound: w (ε/d - 1)^2 for d < ε,
//   zero beyond, with d the distance from the vertex to the segment;
// - as a last guard, a map whose border meets itself is not admissible
//   (value() is +infinity).
// Unlike a scaffold, the term couples only the few vertex-segment pairs
// that come close: the sparsity pattern of the Hessian stays that of the
// chart mesh plus these pairs, and changes only when a new pair comes within
// 2ε (pairs stay declared, so the pattern only grows). The energy itself has
// no state: it is a fixed C^1 function of the UVs.
#ifndef CGAL_SMP_CUT_INTERNAL_BORDER_BARRIER_TERM_H
#define CGAL_SMP_CUT_INTERNAL_BORDER_BARRIER_TERM_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/border_crossings.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Distance from p to the segment ab; `s` is the parameter of the closest
/// point a + s (b - a), `n` the unit vector from it to p (zero if d = 0).
/// The gradient of the distance is n for p, -(1-s) n for a and -s n for b.
inline double point_segment_distance(const Vector2& p, const Vector2& a, const Vector2& b, double& s, Vector2& n)
{
  const Vector2 e = b - a;
  const double length2 = e.squaredNorm();
  s = length2 > 0. ? (std::min)(1., (std::max)(0., (p - a).dot(e) / length2)) : 0.;
  const Vector2 r = p - (a + s * e);
  const double d = r.norm();
  n = d > 0. ? Vector2(r / d) : Vector2(0., 0.);
  return d;
}

/// First t in [0, 1] at which p + t dp lies on the segment from a + t da to
/// b + t db; +infinity if none. Conservative near tangency: a root whose
/// point is within a relative 1e-9 of the segment's ends counts.
inline double first_contact_time(const Vector2& p, const Vector2& dp, const Vector2& a, const Vector2& da,
                                 const Vector2& b, const Vector2& db)
{
  auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const Vector2 e = b - a, de = db - da, q = p - a, dq = dp - da;
  // f(t) = cross(e + t de, q + t dq) = c0 + c1 t + c2 t^2: p on the segment's line
  const double c0 = cross(e, q), c1 = cross(e, dq) + cross(de, q), c2 = cross(de, dq);
  double roots[2];
  int n = 0;
  const double scale = (std::max)({std::abs(c0), std::abs(c1), std::abs(c2)});
  if(!(scale > 0.)) // on the segment's line all along: a contact if on the segment at either end
  {
    auto on_segment = [&](double t) {
      const Vector2 et = e + t * de, qt = q + t * dq;
      const double length2 = et.squaredNorm();
      const double s = length2 > 0. ? qt.dot(et) / length2 : 0.;
      return s >= -1e-9 && s <= 1. + 1e-9;
    };
    return on_segment(0.) || on_segment(1.) ? 0. : std::numeric_limits<double>::infinity();
  }
  if(std::abs(c2) <= 1e-12 * scale)
  {
    if(c1 != 0.) roots[n++] = -c0 / c1;
  }
  else
  {
    const double disc = c1 * c1 - 4. * c2 * c0;
    if(disc >= 0.)
    {
      // stable roots: q = -(c1 + sign(c1) sqrt(disc)) / 2, t = q / c2 and c0 / q
      const double root = std::sqrt(disc);
      const double qq = -0.5 * (c1 + (c1 >= 0. ? root : -root));
      if(c2 != 0.) roots[n++] = qq / c2;
      if(qq != 0.) roots[n++] = c0 / qq;
    }
  }
  std::sort(roots, roots + n);
  for(int k = 0; k < n; ++k)
  {
    const double t = roots[k];
    if(!(t >= 0. && t <= 1.)) continue;
    const Vector2 et = e + t * de, qt = q + t * dq;
    const double length2 = et.squaredNorm();
    const double s = length2 > 0. ? qt.dot(et) / length2 : 0.;
    if(s >= -1e-9 && s <= 1. + 1e-9) return t;
  }
  return std::numeric_limits<double>::infinity();
}

/// Calls f(i, j) once for each pair of a box of `first` and a box of
/// `second` that overlap (boxes as {x0, y0, x1, y1}; an empty box, with
/// x0 > x1, meets nothing), in an order that depends on the boxes only.
/// Small boxes are matched on a uniform grid, about one cell per box of
/// `second`; a box spanning more than 64 cells (a long swept box) is tested
/// against every box of the other set instead, so that the cost stays at
/// most quadratic.
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
  constexpr long max_cells = 64;
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

class Border_barrier_term : public Energy_term
{
  std::vector<std::array<int, 2>> segments_; // UV border, per chart
  std::vector<int> segment_chart_;
  std::vector<int> points_;                  // UV vertices on the border
  std::vector<int> point_chart_;
  int number_of_charts_ = 0;
  double epsilon_ = 0.; // barrier distance
  double weight_ = 0.;  // energy of one pair at distance ε/2

  std::vector<std::array<int, 2>> pairs_;          // declared (vertex, segment) pairs
  std::unordered_map<std::uint64_t, int> pair_of_; // key (vertex, segment) -> index in pairs_
  std::vector<int> elements_;                      // per declared pair

  Vector2 point(const UV_vector& x, int v) const { return Vector2(x[2*v], x[2*v+1]); }

  /// Barrier b(d) and its first two derivatives.
  void barrier(double d, double& b, double& db, double& ddb) const
  {
    if(!(d < epsilon_)) { b = db = ddb = 0.; return; }
    const double r = epsilon_ / d;
    b = weight_ * (r - 1.) * (r - 1.);
    db = -2. * weight_ * (r - 1.) * r / d;
    ddb = 2. * weight_ * (r * r + 2. * (r - 1.) * r) / (d * d);
  }

  /// Calls f(v, segment, d, s, n) for each border vertex v and segment of
  /// its chart, not incident to v, closer than ε at x (point_segment_distance()
  /// gives d, s, n), in an order that depends on x only.
  template <typename F>
  void for_each_close_pair(const UV_vector& x, F&& f, double factor = 1.) const
  {
    if(!(epsilon_ > 0.)) return;
    const double reach = factor * epsilon_;
    std::vector<std::array<double, 4>> point_boxes(points_.size()), segment_boxes(segments_.size());
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      const Vector2 p = point(x, points_[i]);
      point_boxes[i] = {p.x() - reach, p.y() - reach, p.x() + reach, p.y() + reach};
    }
    for(std::size_t j = 0; j < segments_.size(); ++j)
    {
      const Vector2 a = point(x, segments_[j][0]), b = point(x, segments_[j][1]);
      segment_boxes[j] = {(std::min)(a.x(), b.x()), (std::min)(a.y(), b.y()), (std::max)(a.x(), b.x()),
                          (std::max)(a.y(), b.y())};
    }
    for_each_overlapping_box_pair(point_boxes, segment_boxes, [&](int i, int j) {
      const int v = points_[i];
      const auto& seg = segments_[j];
      if(point_chart_[i] != segment_chart_[j] || v == seg[0] || v == seg[1]) return;
      double s;
      Vector2 n;
      const double d = point_segment_distance(point(x, v), point(x, seg[0]), point(x, seg[1]), s, n);
      if(d < reach) f(v, j, d, s, n);
    });
  }

public:
  /// `relative_distance`: ε relative to the mean 3D length of the border
  /// edges; `relative_weight`: energy of a pair at ε/2 relative to the mean
  /// face area of the chart mesh.
  explicit Border_barrier_term(const Chart_mesh& mesh, double relative_distance = 0.25, double relative_weight = 1.)
  {
    // border edges with their 3D length
    std::unordered_map<std::uint64_t, int> directed;
    directed.reserve(3 * mesh.faces.size());
    for(const auto& t : mesh.faces)
      for(int k = 0; k < 3; ++k) directed.emplace(directed_edge_key(t[k], t[(k+1)%3]), 0);
    const std::vector<int> chart = chart_of_faces(mesh, number_of_charts_);
    double length = 0.;
    std::vector<int> chart_of_point(mesh.number_of_vertices, -1);
    for(std::size_t f = 0; f < mesh.faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = mesh.faces[f][k], b = mesh.faces[f][(k+1)%3];
        if(directed.count(directed_edge_key(b, a))) continue;
        segments_.push_back({a, b});
        segment_chart_.push_back(chart[f]);
        length += mesh.edge_length(f, k);
        chart_of_point[a] = chart_of_point[b] = chart[f];
      }
    for(int v = 0; v < mesh.number_of_vertices; ++v)
      if(chart_of_point[v] >= 0)
      {
        points_.push_back(v);
        point_chart_.push_back(chart_of_point[v]);
      }
    epsilon_ = segments_.empty() ? 0. : relative_distance * length / double(segments_.size());
    weight_ = relative_weight * mesh.total_area() / double((std::max)(std::size_t(1), mesh.number_of_faces()));
  }

  double epsilon() const { return epsilon_; }

  /// True if two segments of some chart's border that share no vertex meet
  /// at x (cross, touch or overlap).
  bool has_crossing(const UV_vector& x) const
  {
    return count_border_crossings(segments_, x, &segment_chart_, 1, true) > 0;
  }

  /// Per chart (ids of chart_of_faces()): true if its border meets itself at x.
  std::vector<char> charts_with_crossing(const UV_vector& x) const
  {
    std::vector<char> crossing(number_of_charts_, 0);
    std::vector<std::vector<std::array<int, 2>>> segments(number_of_charts_);
    for(std::size_t i = 0; i < segments_.size(); ++i) segments[segment_chart_[i]].push_back(segments_[i]);
    for(int c = 0; c < number_of_charts_; ++c)
      crossing[c] = count_border_crossings(segments[c], x, nullptr, 1, true) > 0;
    return crossing;
  }

  /// Declares the pairs closer than 2ε at x that are not yet (they stay
  /// declared, so the pattern only grows).
  Update update(const UV_vector& x) override
  {
    std::vector<std::array<int, 2>> found;
    for_each_close_pair(x, [&](int v, int j, double, double, const Vector2&) { found.push_back({v, j}); }, 2.);
    bool grown = false;
    for(const auto& pair : found)
      if(pair_of_.emplace(directed_edge_key(pair[0], pair[1]), int(pairs_.size())).second)
      {
        pairs_.push_back(pair);
        grown = true;
      }
    return grown ? Update::MORE_ELEMENTS : Update::NONE;
  }

  std::size_t number_of_declared_pairs() const { return pairs_.size(); }

  void declare_elements(Hessian_assembler& hessian) override
  {
    elements_.clear();
    for(const auto& pair : pairs_)
    {
      const int v = pair[0], a = segments_[pair[1]][0], b = segments_[pair[1]][1];
      elements_.push_back(hessian.add_element({2*v, 2*v+1, 2*a, 2*a+1, 2*b, 2*b+1}));
    }
  }

  double value(const UV_vector& x) const override
  {
    if(has_crossing(x)) return std::numeric_limits<double>::infinity();
    double energy = 0.;
    for_each_close_pair(x, [&](int, int, double d, double, const Vector2&) {
      double b, db, ddb;
      barrier(d, b, db, ddb);
      energy += b;
    });
    return energy;
  }

  /// Per pair closer than ε: the gradient b'(d) g and the Hessian
  /// approximation b''(d) g g^T (positive semi-definite), g being the
  /// gradient of d over the pair's three vertices. Every such pair was
  /// declared by update() at this x.
  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    for_each_close_pair(x, [&](int v, int j, double d, double s, const Vector2& n) {
      double b, db, ddb;
      barrier(d, b, db, ddb);
      Eigen::Matrix<double, 6, 1> g;
      g << n, -(1. - s) * n, -s * n;
      const int ids[3] = {v, segments_[j][0], segments_[j][1]};
      for(int c = 0; c < 3; ++c)
      {
        gradient[2*ids[c]] += db * g[2*c];
        gradient[2*ids[c]+1] += db * g[2*c+1];
      }
      const auto it = pair_of_.find(directed_edge_key(v, j));
      if(it != pair_of_.end()) hessian.add(elements_[it->second], Eigen::Matrix<double, 6, 6>(ddb * g * g.transpose()));
    });
  }

  double max_step(const UV_vector& x, const UV_vector& dx) const override
  {
    // swept boxes over the step t in [0, 1]
    std::vector<std::array<double, 4>> point_boxes(points_.size()), segment_boxes(segments_.size());
    auto sweep = [&](std::array<double, 4>& box, int v) {
      const Vector2 p = point(x, v), q = p + point(dx, v);
      box[0] = (std::min)({box[0], p.x(), q.x()});
      box[1] = (std::min)({box[1], p.y(), q.y()});
      box[2] = (std::max)({box[2], p.x(), q.x()});
      box[3] = (std::max)({box[3], p.y(), q.y()});
    };
    const double inf = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      point_boxes[i] = {inf, inf, -inf, -inf};
      sweep(point_boxes[i], points_[i]);
    }
    for(std::size_t j = 0; j < segments_.size(); ++j)
    {
      segment_boxes[j] = {inf, inf, -inf, -inf};
      sweep(segment_boxes[j], segments_[j][0]);
      sweep(segment_boxes[j], segments_[j][1]);
    }
    double t = inf;
    for_each_overlapping_box_pair(point_boxes, segment_boxes, [&](int i, int j) {
      const int v = points_[i];
      const auto& s = segments_[j];
      if(point_chart_[i] != segment_chart_[j] || v == s[0] || v == s[1]) return;
      t = (std::min)(t, first_contact_time(point(x, v), point(dx, v), point(x, s[0]), point(dx, s[0]),
                                           point(x, s[1]), point(dx, s[1])));
    });
    return t;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
