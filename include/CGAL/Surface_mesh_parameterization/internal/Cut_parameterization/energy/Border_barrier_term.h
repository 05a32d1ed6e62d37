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
// chart mesh plus these pairs, and changes only when enough new pairs have
// come within 2ε (see update()). ε follows the UV length of the border where
// the map squashes it, and is set by update() at each Newton iteration; in
// between, the energy is a fixed C^1 function of the UVs.
#ifndef CGAL_SMP_CUT_INTERNAL_BORDER_BARRIER_TERM_H
#define CGAL_SMP_CUT_INTERNAL_BORDER_BARRIER_TERM_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/border_crossings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/box_pairs.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/segment_contacts.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Border_barrier_term : public Energy_term
{
  std::vector<std::array<int, 2>> segments_; // UV border, per chart
  std::vector<int> segment_chart_;
  std::vector<int> points_;                  // UV vertices on the border
  std::vector<int> point_chart_;
  // per segment: the third vertex of its face, which reaches the segment
  // only by flipping that face (the distortion term's step bound rules it
  // out): no pair, or a thin border triangle (a fin, a sliver chart) would
  // be held fat by the barrier
  std::vector<int> segment_apex_;
  std::vector<int> point_of_;                // per UV vertex: its index in points_, or -1
  // per chart: its border vertices (indices in points_), its segments (indices in segments_) and
  // those segments; pairs are within a chart only, so each chart gets a grid of its own (one grid
  // over all charts was 90% of the solve of a plate cut into 206 pieces: the boxes of every chart
  // in one grid, a swept box long against the whole atlas's cells tested against every box)
  std::vector<std::vector<int>> chart_points_, chart_segment_ids_;
  std::vector<std::vector<std::array<int, 2>>> chart_segments_;
  int number_of_charts_ = 0;
  double epsilon_ = 0.;                      // barrier distance where the border is not squashed
  double weight_ = 0.;                       // energy of one pair at distance ε/2
  std::vector<double> segment_epsilon_;      // ε of each segment, set by update()
  std::vector<double> point_epsilon_;        // ε of each border vertex, set by update()

  std::vector<std::array<int, 2>> pairs_;          // declared (vertex, segment) pairs
  // per border vertex (index in points_): its declared pairs as (segment, index in pairs_); a few per
  // vertex, scanned (a hash map of the pairs was 7% of a CAD part's solve: looked up per close pair)
  std::vector<std::vector<std::array<int, 2>>> pairs_of_point_;
  std::vector<int> elements_;                      // per declared pair
  std::vector<int> point_elements_;                // per border vertex: its 2x2 diagonal block
  int iterations_since_pattern_ = 0;
  std::size_t epsilon_version_ = 0;                // changes whenever update() changes an ε

  /// A pair closer than its ε (close_pair()).
  struct Close_pair
  {
    int v, j;
    double d, epsilon, s;
    Vector2 n;
  };
  /// The close pairs of the last two maps value() saw (x, the ε version): the gradient and
  /// Hessian are assembled at a map whose energy was just evaluated (after update(), or the
  /// line search's accepted step, a longer trial possibly after it). Not for concurrent calls.
  struct Close_pairs_at
  {
    std::vector<double> border_x; // the UVs of the border vertices (points_), all the pairs read
    std::size_t epsilon_version = 0;
    bool valid = false;
    std::vector<Close_pair> pairs;
  };
  mutable std::array<Close_pairs_at, 2> close_pairs_at_;
  mutable std::size_t next_close_pairs_ = 0;

  /// A segment shorter in UV than this fraction of the mean 3D border
  /// length (squashed by the map) has an ε in proportion to its UV length.
  static constexpr double squashed = tuning::barrier_squashed;
  /// Close pairs not in the pattern (their Hessian is approximated by its
  /// diagonal blocks) are added to it once they are this fraction of the
  /// declared ones, or after this many Newton iterations.
  static constexpr double pattern_growth = tuning::barrier_pattern_growth;
  static constexpr int pattern_delay = tuning::barrier_pattern_delay;

  Vector2 point(const UV_vector& x, int v) const { return Vector2(x[2*v], x[2*v+1]); }

  /// Index in pairs_ of the declared pair (border vertex v, segment j), or -1.
  int declared_pair(int v, int j) const
  {
    for(const auto& p : pairs_of_point_[std::size_t(point_of_[v])])
      if(p[0] == j) return p[1];
    return -1;
  }

  /// Declares the pair (v, j) if it is not; true if it was not.
  bool declare_pair(int v, int j)
  {
    if(declared_pair(v, j) >= 0) return false;
    pairs_of_point_[std::size_t(point_of_[v])].push_back({j, int(pairs_.size())});
    pairs_.push_back({v, j});
    return true;
  }

  /// Barrier distance of the pair (border vertex v, segment j).
  double epsilon(int v, int j) const { return (std::min)(point_epsilon_[point_of_[v]], segment_epsilon_[j]); }

  /// Barrier b(d) at distance ε and its first two derivatives.
  void barrier(double d, double epsilon, double& b, double& db, double& ddb) const
  {
    if(!(d < epsilon)) { b = db = ddb = 0.; return; }
    const double r = epsilon / d;
    b = weight_ * (r - 1.) * (r - 1.);
    db = -2. * weight_ * (r - 1.) * r / d;
    ddb = 2. * weight_ * (r * r + 2. * (r - 1.) * r) / (d * d);
  }

  /// The boxes of chart c's border vertices and segments: each vertex at x
  /// and at x + dx (dx may be null: x only), a vertex's box grown by
  /// `factor` times its ε.
  void chart_boxes(int c, const UV_vector& x, const UV_vector* dx, double factor, std::vector<Box_2>& point_boxes,
                   std::vector<Box_2>& segment_boxes) const
  {
    const double inf = std::numeric_limits<double>::infinity();
    auto box_of = [&](std::initializer_list<int> vertices, double grow) {
      Box_2 box{inf, inf, -inf, -inf};
      for(int v : vertices)
        for(int end = 0; end < (dx ? 2 : 1); ++end)
        {
          const Vector2 p = end == 0 ? point(x, v) : Vector2(point(x, v) + point(*dx, v));
          box = {(std::min)(box[0], p.x() - grow), (std::min)(box[1], p.y() - grow),
                 (std::max)(box[2], p.x() + grow), (std::max)(box[3], p.y() + grow)};
        }
      return box;
    };
    const std::vector<int>& chart_points = chart_points_[std::size_t(c)];
    const std::vector<int>& chart_segments = chart_segment_ids_[std::size_t(c)];
    point_boxes.resize(chart_points.size());
    segment_boxes.resize(chart_segments.size());
    for(std::size_t i = 0; i < chart_points.size(); ++i)
      point_boxes[i] = box_of({points_[std::size_t(chart_points[i])]}, factor * point_epsilon_[std::size_t(chart_points[i])]);
    for(std::size_t j = 0; j < chart_segments.size(); ++j)
    {
      const auto& seg = segments_[std::size_t(chart_segments[j])];
      segment_boxes[j] = box_of({seg[0], seg[1]}, 0.);
    }
  }

  /// Calls f(v, segment) for each candidate pair of chart c whose vertex is
  /// one of its border vertices [first, last) (see map_candidate_pairs()).
  template <typename F>
  void chart_candidate_pairs(int c, const Box_grid& grid, const std::vector<Box_2>& point_boxes, std::size_t first,
                             std::size_t last, F&& f) const
  {
    const std::vector<int>& chart_points = chart_points_[std::size_t(c)];
    const std::vector<int>& chart_segments = chart_segment_ids_[std::size_t(c)];
    for(std::size_t i = first; i < last; ++i)
      grid.query(int(i), point_boxes[i], [&](int, int k) {
        const int v = points_[std::size_t(chart_points[i])], j = chart_segments[std::size_t(k)];
        const auto& seg = segments_[std::size_t(j)];
        if(v != seg[0] && v != seg[1] && v != segment_apex_[std::size_t(j)]) f(v, j);
      });
  }

  /// For each border vertex v and segment of its chart, not incident to v,
  /// whose boxes meet (chart_boxes()): map(v, segment, out), which appends
  /// to `out` what the pair gives. Blocks of border vertices run on all
  /// cores, their outputs joined in order: `out` is the sequence one thread
  /// would give, in an order that depends on the positions only.
  template <typename T, typename Map>
  void map_candidate_pairs(const UV_vector& x, const UV_vector* dx, double factor, const Map& map,
                           std::vector<T>& out) const
  {
    constexpr std::size_t block = tuning::barrier_pair_block;
    out.clear();
    std::vector<Box_2> point_boxes, segment_boxes;
    std::vector<std::vector<T>> block_out;
    for(int c = 0; c < number_of_charts_; ++c)
    {
      chart_boxes(c, x, dx, factor, point_boxes, segment_boxes);
      const Box_grid grid(point_boxes, segment_boxes);
      const std::size_t n = point_boxes.size();
      if(n <= block)
      {
        chart_candidate_pairs(c, grid, point_boxes, 0, n, [&](int v, int j) { map(v, j, out); });
        continue;
      }
      block_out.resize((n + block - 1) / block);
      parallel_tasks(block_out.size(), [&](std::size_t b) {
        std::vector<T>& o = block_out[b];
        o.clear();
        chart_candidate_pairs(c, grid, point_boxes, b * block, (std::min)(n, (b + 1) * block),
                              [&](int v, int j) { map(v, j, o); });
      });
      for(const std::vector<T>& o : block_out) out.insert(out.end(), o.begin(), o.end());
    }
  }

  /// The pair (v, segment j) if it is closer than factor ε at x.
  bool close_pair(const UV_vector& x, int v, int j, double factor, Close_pair& pair) const
  {
    const auto& seg = segments_[std::size_t(j)];
    pair.v = v;
    pair.j = j;
    pair.epsilon = epsilon(v, j);
    pair.d = point_segment_distance(point(x, v), point(x, seg[0]), point(x, seg[1]), pair.s, pair.n);
    return pair.d < factor * pair.epsilon;
  }

  /// The pairs of map_candidate_pairs() closer than factor ε at x, in its order.
  void close_pairs(const UV_vector& x, double factor, std::vector<Close_pair>& out) const
  {
    map_candidate_pairs(x, nullptr, factor, [&](int v, int j, std::vector<Close_pair>& o) {
      Close_pair pair;
      if(close_pair(x, v, j, factor, pair)) o.push_back(pair);
    }, out);
  }

public:
  /// `relative_distance`: ε relative to the mean 3D length of the border
  /// edges (lowered where the map squashes the border, see update());
  /// `relative_weight`: energy of a pair at ε/2 relative to the mean
  /// face area of the chart mesh.
  explicit Border_barrier_term(const Chart_mesh& mesh, double relative_distance = tuning::barrier_relative_distance,
                               double relative_weight = tuning::barrier_relative_weight)
  {
    // border edges with their 3D length
    std::unordered_map<std::uint64_t, int> directed;
    directed.reserve(3 * mesh.faces.size());
    for(const auto& t : mesh.faces)
      for(int k = 0; k < 3; ++k) directed.emplace(directed_edge_key(t[k], t[(k+1)%3]), 0);
    const std::vector<int> chart = chart_of_faces(mesh, number_of_charts_);
    std::vector<int> chart_of_point(mesh.number_of_vertices, -1);
    for(std::size_t f = 0; f < mesh.faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = mesh.faces[f][k], b = mesh.faces[f][(k+1)%3];
        if(directed.count(directed_edge_key(b, a))) continue;
        segments_.push_back({a, b});
        segment_apex_.push_back(mesh.faces[f][(k+2)%3]);
        segment_chart_.push_back(chart[f]);
        epsilon_ += mesh.edge_length(f, k);
        chart_of_point[a] = chart_of_point[b] = chart[f];
      }
    point_of_.assign(mesh.number_of_vertices, -1);
    for(int v = 0; v < mesh.number_of_vertices; ++v)
      if(chart_of_point[v] >= 0)
      {
        point_of_[v] = int(points_.size());
        points_.push_back(v);
        point_chart_.push_back(chart_of_point[v]);
      }
    epsilon_ = segments_.empty() ? 0. : relative_distance * epsilon_ / double(segments_.size());
    segment_epsilon_.assign(segments_.size(), 0.);
    point_epsilon_.assign(points_.size(), 0.);
    pairs_of_point_.resize(points_.size());
    chart_points_.resize(std::size_t(number_of_charts_));
    chart_segment_ids_.resize(std::size_t(number_of_charts_));
    chart_segments_.resize(std::size_t(number_of_charts_));
    for(std::size_t i = 0; i < points_.size(); ++i) chart_points_[std::size_t(point_chart_[i])].push_back(int(i));
    for(std::size_t j = 0; j < segments_.size(); ++j)
    {
      chart_segment_ids_[std::size_t(segment_chart_[j])].push_back(int(j));
      chart_segments_[std::size_t(segment_chart_[j])].push_back(segments_[j]);
    }
    weight_ = relative_weight * mesh.total_area() / double((std::max)(std::size_t(1), mesh.number_of_faces()));
  }

  /// ε where the border is not squashed.
  double epsilon() const { return epsilon_; }

  /// True if two segments of some chart's border that share no vertex meet
  /// at x (cross, touch or overlap).
  bool has_crossing(const UV_vector& x) const
  {
    for(const auto& segments : chart_segments_) // a grid per chart (see chart_segments_)
      if(count_border_crossings(segments, x, nullptr, 1, true) > 0) return true;
    return false;
  }

  /// Per chart (ids of chart_of_faces()): true if its border meets itself
  /// at x (exact predicates), or if one of its border vertices is on one of
  /// its segments as the barrier measures it (distance 0 in floating point:
  /// an infinite energy). The second happens where the predicates see no
  /// contact: the two sides of a slit of zero width whose vertices differ
  /// in their last bits (met on CGAL's boeing.off: the barrier's solve
  /// started at an infinite energy).
  std::vector<char> charts_with_crossing(const UV_vector& x) const
  {
    std::vector<char> crossing(number_of_charts_, 0);
    for(int c = 0; c < number_of_charts_; ++c)
      crossing[c] = count_border_crossings(chart_segments_[std::size_t(c)], x, nullptr, 1, true) > 0;
    std::vector<int> touching; // segments a border vertex is on, as the barrier measures it
    map_candidate_pairs(x, nullptr, 0., [&](int v, int j, std::vector<int>& o) {
      Close_pair pair;
      close_pair(x, v, j, 0., pair);
      if(!(pair.d > 0.)) o.push_back(j);
    }, touching);
    for(int j : touching) crossing[std::size_t(segment_chart_[std::size_t(j)])] = 1;
    return crossing;
  }

  /// Sets ε at x, then the pattern: the pairs closer than 2ε.
  ///
  /// ε is epsilon_ for a segment whose UV length is at least `squashed`
  /// times the mean 3D border length, and in proportion to its UV length
  /// below (a Tutte map squashes the borders of holes almost flat: with one
  /// ε, all their vertices would be pairs with one another); a vertex has
  /// the lesser ε of its segments, a pair the lesser of its vertex's and
  /// segment's. If an ε changed, so did the energy: VALUES (else NONE, and
  /// the solver keeps the energy it has).
  ///
  /// Pairs closer than ε that are not in the pattern count on their own
  /// diagonal blocks only (still a descent direction) until they are many
  /// enough, or have waited long enough, to be worth a new pattern (a
  /// pattern per Newton iteration was most of the time where holes give
  /// thousands of pairs; see the manual, Design and measurements). A new pattern
  /// adds the pairs now closer than 2ε to those declared (MORE_ELEMENTS: the
  /// solver may keep its ordering), or declares only them (ELEMENTS) when
  /// most of the declared ones have gone away.
  Update update(const UV_vector& x) override
  {
    const double squashed_length = squashed * epsilon_;
    bool changed = false;
    std::fill(point_epsilon_.begin(), point_epsilon_.end(), std::numeric_limits<double>::infinity());
    for(std::size_t j = 0; j < segments_.size(); ++j)
    {
      const int a = segments_[j][0], b = segments_[j][1];
      const double length = (point(x, b) - point(x, a)).norm();
      const double epsilon = length < squashed_length ? epsilon_ * length / squashed_length : epsilon_;
      changed = changed || epsilon != segment_epsilon_[j];
      segment_epsilon_[j] = epsilon;
      for(int v : {a, b})
        point_epsilon_[point_of_[v]] = (std::min)(point_epsilon_[point_of_[v]], segment_epsilon_[j]);
    }
    if(changed) ++epsilon_version_;
    ++iterations_since_pattern_;
    std::vector<std::array<int, 3>> found; // (v, segment, fresh: closer than ε and not declared)
    map_candidate_pairs(x, nullptr, 2., [&](int v, int j, std::vector<std::array<int, 3>>& o) {
      Close_pair pair;
      if(close_pair(x, v, j, 2., pair)) o.push_back({v, j, int(pair.d < pair.epsilon && declared_pair(v, j) < 0)});
    }, found);
    std::size_t fresh = 0;
    for(const auto& pair : found) fresh += std::size_t(pair[2]);
    if(fresh == 0 || (double(fresh) < pattern_growth * double(pairs_.size())
                      && iterations_since_pattern_ < pattern_delay))
      return changed ? Update::VALUES : Update::NONE;
    iterations_since_pattern_ = 0;
    std::size_t kept = 0;
    for(const auto& pair : found) kept += declared_pair(pair[0], pair[1]) >= 0;
    const bool renew = 2 * kept < pairs_.size();
    if(renew)
    {
      pairs_.clear();
      for(auto& p : pairs_of_point_) p.clear();
    }
    for(const auto& pair : found) declare_pair(pair[0], pair[1]);
    return renew ? Update::ELEMENTS : Update::MORE_ELEMENTS;
  }

  std::size_t number_of_declared_pairs() const { return pairs_.size(); }

  /// Pairs closer than their ε at x that are not in the pattern.
  std::size_t number_of_undeclared_close_pairs(const UV_vector& x) const
  {
    std::vector<Close_pair> found;
    close_pairs(x, 1., found);
    std::size_t n = 0;
    for(const Close_pair& p : found) n += declared_pair(p.v, p.j) < 0;
    return n;
  }

  void declare_elements(Hessian_assembler& hessian) override
  {
    point_elements_.clear();
    for(int v : points_) point_elements_.push_back(hessian.add_element({2*v, 2*v+1}));
    elements_.clear();
    for(const auto& pair : pairs_)
    {
      const int v = pair[0], a = segments_[pair[1]][0], b = segments_[pair[1]][1];
      elements_.push_back(hessian.add_element({2*v, 2*v+1, 2*a, 2*a+1, 2*b, 2*b+1}));
    }
  }

  double value(const UV_vector& x) const override
  {
    // the crossing test and the close pairs at once: neither reads what the other writes
    bool crossing = false;
    Close_pairs_at& at = close_pairs_at_[next_close_pairs_];
    at.valid = false;
    at.pairs.clear();
    parallel_invoke([&] { crossing = has_crossing(x); }, [&] { close_pairs(x, 1., at.pairs); });
    if(crossing) return std::numeric_limits<double>::infinity();
    at.border_x.resize(2 * points_.size());
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      at.border_x[2 * i] = x[2 * points_[i]];
      at.border_x[2 * i + 1] = x[2 * points_[i] + 1];
    }
    at.epsilon_version = epsilon_version_;
    at.valid = true;
    next_close_pairs_ = 1 - next_close_pairs_;
    double energy = 0.;
    for(const Close_pair& p : at.pairs)
    {
      double b, db, ddb;
      barrier(p.d, p.epsilon, b, db, ddb);
      energy += b;
    }
    return energy;
  }

  void add_gradient(const UV_vector& x, Eigen::VectorXd& gradient) const override
  {
    accumulate(x, gradient, nullptr);
  }

  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    accumulate(x, gradient, &hessian);
  }

  double max_step(const UV_vector& x, const UV_vector& dx) const override
  {
    // boxes swept over the step t in [0, 1]
    std::vector<double> contacts;
    map_candidate_pairs(x, &dx, 0., [&](int v, int j, std::vector<double>& o) {
      const auto& s = segments_[std::size_t(j)];
      const double t = first_contact_time(point(x, v), point(dx, v), point(x, s[0]), point(dx, s[0]),
                                          point(x, s[1]), point(dx, s[1]));
      if(t < std::numeric_limits<double>::infinity()) o.push_back(t);
    }, contacts);
    double t = std::numeric_limits<double>::infinity();
    for(double c : contacts) t = (std::min)(t, c);
    return t;
  }

private:
  /// Per pair closer than ε: the gradient b'(d) g and, where `hessian` is
  /// not null, the Hessian approximation b''(d) g g^T (positive
  /// semi-definite), g being the gradient of d over the pair's three
  /// vertices; for a pair not in the pattern, the 2x2 diagonal blocks of
  /// that matrix.
  /// The close pairs value() found at x with the ε of now, if it saw x (its border vertices) last
  /// or the time before.
  const std::vector<Close_pair>* saved_close_pairs(const UV_vector& x) const
  {
    auto same_border = [&](const Close_pairs_at& at) {
      for(std::size_t i = 0; i < points_.size(); ++i)
        if(std::memcmp(&at.border_x[2 * i], x.data() + 2 * points_[i], 2 * sizeof(double)) != 0) return false;
      return true;
    };
    for(const Close_pairs_at& at : close_pairs_at_)
      if(at.valid && at.epsilon_version == epsilon_version_ && same_border(at)) return &at.pairs;
    return nullptr;
  }

  void accumulate(const UV_vector& x, Eigen::VectorXd& gradient, Hessian_assembler* hessian) const
  {
    const std::vector<Close_pair>* saved = saved_close_pairs(x);
    std::vector<Close_pair> found;
    if(saved == nullptr) close_pairs(x, 1., found);
    for(const Close_pair& p : saved != nullptr ? *saved : found)
    {
      double b, db, ddb;
      barrier(p.d, p.epsilon, b, db, ddb);
      Eigen::Matrix<double, 6, 1> g;
      g << p.n, -(1. - p.s) * p.n, -p.s * p.n;
      const int ids[3] = {p.v, segments_[p.j][0], segments_[p.j][1]};
      for(int c = 0; c < 3; ++c)
      {
        gradient[2*ids[c]] += db * g[2*c];
        gradient[2*ids[c]+1] += db * g[2*c+1];
      }
      if(hessian == nullptr) continue;
      const Eigen::Matrix<double, 6, 6> block = ddb * g * g.transpose();
      const int pair = declared_pair(p.v, p.j);
      if(pair >= 0)
        hessian->add(elements_[std::size_t(pair)], block);
      else // not in the pattern (yet): the diagonal blocks of a PSD matrix are PSD
        for(int c = 0; c < 3; ++c)
          hessian->add(point_elements_[point_of_[ids[c]]], block.block<2, 2>(2 * c, 2 * c));
    }
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
