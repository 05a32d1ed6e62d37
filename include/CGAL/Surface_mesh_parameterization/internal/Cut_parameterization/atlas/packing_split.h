// Charts cut for packing (option split_charts_for_packing): a chart that
// fills less than a given fraction of its minimum-area bounding rectangle
// (its UV area over the rectangle's) is cut, by recursive bisection along
// straight lines across it, into pieces that fill more, before packing.
// Each piece keeps the chart's UVs (a subset of an overlap-free, flip-free
// chart: no flip, no overlap, E_d unchanged); the cuts become seams (E_s
// rises). A cut is the line, along the piece's rectangle axes or its
// principal axis, that lowers the sum of the pieces' rectangle areas most,
// net of a cost for its UV length and for each piece added; the pieces are
// the connected face sets on either side of it.
#ifndef CGAL_SMP_CUT_INTERNAL_PACKING_SPLIT_H
#define CGAL_SMP_CUT_INTERNAL_PACKING_SPLIT_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/atlas_validity.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace packing {

/// Area of the minimum-area bounding rectangle of the UV triangles of
/// `faces` (`corner_uv`: per corner 3f+k), and its angle.
inline double rectangle_area(const std::vector<int>& faces, const std::vector<Vector2>& corner_uv,
                             double* angle = nullptr)
{
  std::vector<Vector2> points;
  points.reserve(3 * faces.size());
  for(int f : faces)
    for(int k = 0; k < 3; ++k) points.push_back(corner_uv[std::size_t(3 * f + k)]);
  const std::vector<Vector2> hull = convex_hull(points);
  if(hull.size() < 3) { if(angle) *angle = 0.; return 0.; }
  const double a = best_angle(hull, false);
  if(angle) *angle = a;
  const Vector2 e = oriented_extents(hull, {a}).front();
  return e.x() * e.y();
}

/// UV area of face f.
inline double uv_face_area(const std::vector<Vector2>& corner_uv, int f)
{
  const Vector2 e1 = corner_uv[std::size_t(3 * f + 1)] - corner_uv[std::size_t(3 * f)];
  const Vector2 e2 = corner_uv[std::size_t(3 * f + 2)] - corner_uv[std::size_t(3 * f)];
  return 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
}

/// The fill of `faces`: UV area over the area of their minimum-area bounding rectangle (1 if it is 0).
inline double rectangle_fill(const std::vector<int>& faces, const std::vector<Vector2>& corner_uv)
{
  double area = 0.;
  for(int f : faces) area += uv_face_area(corner_uv, f);
  const double rect = rectangle_area(faces, corner_uv);
  return rect > 0. ? area / rect : 1.;
}

/// Cuts a chart's faces into pieces for packing (see the file comment).
template <typename Surface>
class Packing_splitter
{
  const Surface& s_;
  const std::vector<char>& seam_;       // per edge: the chart's border
  const std::vector<char>& fixed_;      // per edge (or empty): never cut
  const std::vector<Vector2>& uv_;      // per corner
  double fill_;
  std::vector<int> cluster_;            // per face: the first face of its set joined across fixed edges
  std::vector<Vector2> centroid_;       // per cluster root: area-weighted UV centroid of its faces
  std::vector<int> token_, side_, component_;
  int next_token_ = 0;

  bool joined(int fe) const // face-edge fe joins its two faces within a chart
  { return s_.twin[std::size_t(fe)] >= 0 && !seam_[std::size_t(s_.edge_of[std::size_t(fe)])]; }

  /// Connected sets of `faces` (marked by `token`) of one side; small sets flip side once.
  std::vector<std::vector<int>> components(const std::vector<int>& faces, int token)
  {
    std::vector<std::vector<int>> sets;
    for(int pass = 0; pass < 2; ++pass)
    {
      sets.clear();
      for(int f : faces) component_[std::size_t(f)] = -1;
      for(int seed : faces)
      {
        if(component_[std::size_t(seed)] >= 0) continue;
        const int c = int(sets.size());
        sets.emplace_back(1, seed);
        component_[std::size_t(seed)] = c;
        for(std::size_t i = 0; i < sets[std::size_t(c)].size(); ++i)
        {
          const int f = sets[std::size_t(c)][i];
          for(int k = 0; k < 3; ++k)
          {
            const int fe = 3 * f + k;
            if(!joined(fe)) continue;
            const int g = s_.twin[std::size_t(fe)] / 3;
            if(token_[std::size_t(g)] == token && component_[std::size_t(g)] < 0
               && side_[std::size_t(g)] == side_[std::size_t(f)])
            {
              component_[std::size_t(g)] = c;
              sets[std::size_t(c)].push_back(g);
            }
          }
        }
      }
      if(pass == 1) break;
      bool flipped = false;
      for(const std::vector<int>& set : sets)
        if(int(set.size()) < tuning::packing_split_min_faces && sets.size() > 1)
        {
          for(int f : set) side_[std::size_t(f)] ^= 1; // a sliver joins the other side
          flipped = true;
        }
      if(!flipped) break;
    }
    return sets;
  }

  /// UV length of the edges between different components of `faces`.
  double cut_length(const std::vector<int>& faces) const
  {
    double length = 0.;
    for(int f : faces)
      for(int k = 0; k < 3; ++k)
      {
        const int fe = 3 * f + k;
        if(!joined(fe)) continue;
        const int g = s_.twin[std::size_t(fe)] / 3;
        if(token_[std::size_t(g)] == token_[std::size_t(f)] && component_[std::size_t(g)] != component_[std::size_t(f)]
           && fe < s_.twin[std::size_t(fe)])
          length += (uv_[std::size_t(3 * f + (k + 1) % 3)] - uv_[std::size_t(fe)]).norm();
      }
    return length;
  }

  /// The best cut of `faces` into pieces (empty: none worth it).
  std::vector<std::vector<int>> best_cut(const std::vector<int>& faces, double rect0, double angle)
  {
    const int token = ++next_token_;
    for(int f : faces) token_[std::size_t(f)] = token;
    // directions: the rectangle's two axes and the principal axis of the cluster centroids
    double total = 0.;
    Vector2 mean = Vector2::Zero();
    for(int f : faces)
    {
      const double a = uv_face_area(uv_, f);
      total += a;
      mean += a * centroid_[std::size_t(cluster_[std::size_t(f)])];
    }
    if(!(total > 0.)) return {};
    mean /= total;
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for(int f : faces)
    {
      const Vector2 d = centroid_[std::size_t(cluster_[std::size_t(f)])] - mean;
      cov += uv_face_area(uv_, f) * d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(cov);
    const Vector2 axes[3] = {Vector2(std::cos(angle), std::sin(angle)), Vector2(-std::sin(angle), std::cos(angle)),
                             eigen.eigenvectors().col(1)};
    std::vector<std::vector<int>> best;
    double best_value = tuning::packing_split_min_gain;
    std::vector<std::pair<double, int>> order(faces.size());
    for(const Vector2& axis : axes)
    {
      for(std::size_t i = 0; i < faces.size(); ++i)
        order[i] = {axis.dot(centroid_[std::size_t(cluster_[std::size_t(faces[i])])]), faces[i]};
      std::sort(order.begin(), order.end());
      std::vector<double> thresholds;
      double sum = 0.;
      int next = 1;
      for(const auto& [t, f] : order)
      {
        sum += uv_face_area(uv_, f);
        while(next <= tuning::packing_split_positions && sum >= total * next / (tuning::packing_split_positions + 1.))
        { thresholds.push_back(t); ++next; }
      }
      thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
      for(double t : thresholds)
      {
        for(const auto& [p, f] : order) side_[std::size_t(f)] = p > t;
        std::vector<std::vector<int>> sets = components(faces, token);
        if(sets.size() < 2) continue;
        double rects = 0.;
        for(const std::vector<int>& set : sets) rects += rectangle_area(set, uv_);
        const double value = (1. - rects / rect0)
                             - tuning::packing_split_seam_weight * cut_length(faces) / std::sqrt(rect0)
                             - tuning::packing_split_piece_cost * double(sets.size() - 1);
        if(value > best_value) { best_value = value; best.swap(sets); }
      }
    }
    return best;
  }

public:
  Packing_splitter(const Surface& s, const std::vector<char>& seam, const std::vector<char>& fixed,
                   const std::vector<Vector2>& corner_uv, double fill)
    : s_(s), seam_(seam), fixed_(fixed), uv_(corner_uv), fill_(fill)
  {
    const std::size_t nf = s.number_of_faces();
    cluster_.resize(nf);
    std::iota(cluster_.begin(), cluster_.end(), 0);
    auto find = [&](int f) {
      while(cluster_[std::size_t(f)] != f) f = cluster_[std::size_t(f)] = cluster_[std::size_t(cluster_[std::size_t(f)])];
      return f; };
    for(std::size_t fe = 0; fe < 3 * nf; ++fe)
      if(!fixed_.empty() && joined(int(fe)) && fixed_[std::size_t(s.edge_of[fe])])
      {
        const int a = find(int(fe / 3)), b = find(s.twin[fe] / 3);
        cluster_[std::size_t((std::max)(a, b))] = (std::min)(a, b);
      }
    std::vector<double> area(nf, 0.);
    centroid_.assign(nf, Vector2::Zero());
    for(std::size_t f = 0; f < nf; ++f)
    {
      const int r = find(int(f));
      cluster_[f] = r;
      const double a = (std::max)(uv_face_area(uv_, int(f)), 1e-300);
      area[std::size_t(r)] += a;
      centroid_[std::size_t(r)] += a * (uv_[3 * f] + uv_[3 * f + 1] + uv_[3 * f + 2]) / 3.;
    }
    for(std::size_t f = 0; f < nf; ++f)
      if(cluster_[f] == int(f)) centroid_[f] /= area[f];
    token_.assign(nf, 0);
    side_.assign(nf, 0);
    component_.assign(nf, -1);
  }

  /// The pieces of the chart `faces`: cut while a piece fills less than the
  /// threshold, has at least twice tuning::packing_split_min_faces faces and
  /// a cut worth its cost exists, up to tuning::packing_split_max_pieces pieces.
  std::vector<std::vector<int>> pieces(const std::vector<int>& faces)
  {
    std::vector<std::vector<int>> done, todo(1, faces);
    while(!todo.empty())
    {
      std::vector<int> piece = std::move(todo.back());
      todo.pop_back();
      double area = 0., angle = 0.;
      for(int f : piece) area += uv_face_area(uv_, f);
      const double rect = rectangle_area(piece, uv_, &angle);
      std::vector<std::vector<int>> cut;
      if(rect > 0. && area < fill_ * rect && int(piece.size()) >= 2 * tuning::packing_split_min_faces
         && int(done.size() + todo.size()) + 2 <= tuning::packing_split_max_pieces)
        cut = best_cut(piece, rect, angle);
      if(cut.empty()) done.push_back(std::move(piece));
      else
        for(std::vector<int>& c : cut) todo.push_back(std::move(c));
    }
    for(std::vector<int>& p : done) std::sort(p.begin(), p.end());
    std::sort(done.begin(), done.end()); // the same order whatever the cuts' order
    return done;
  }
};

/// The charts of `s`: its faces joined across edges neither border nor
/// flagged in `seam` (per edge), each listed from its lowest face outwards,
/// in the order of their lowest faces.
template <typename Surface>
std::vector<std::vector<int>> face_charts(const Surface& s, const std::vector<char>& seam)
{
  const std::size_t nf = s.number_of_faces();
  std::vector<int> chart(nf, -1);
  std::vector<std::vector<int>> charts;
  for(std::size_t f0 = 0; f0 < nf; ++f0)
  {
    if(chart[f0] >= 0) continue;
    charts.emplace_back(1, int(f0));
    chart[f0] = int(charts.size() - 1);
    for(std::size_t i = 0; i < charts.back().size(); ++i)
    {
      const int f = charts.back()[i];
      for(int k = 0; k < 3; ++k)
      {
        const int tw = s.twin[std::size_t(3 * f + k)];
        if(tw < 0 || seam[std::size_t(s.edge_of[std::size_t(3 * f + k)])] || chart[std::size_t(tw / 3)] >= 0) continue;
        chart[std::size_t(tw / 3)] = chart[f0];
        charts.back().push_back(tw / 3);
      }
    }
  }
  return charts;
}

/// The edges to cut so that every chart of `s` (its faces joined across
/// edges neither border nor flagged in `seam`) that fills less than `fill`
/// of its minimum-area bounding rectangle (UVs `corner_uv`, per corner 3f+k)
/// is cut into pieces that fill more (Packing_splitter); edges flagged in
/// `fixed` (per edge, or empty) are never cut. `pieces` gets the number of
/// charts added.
/// \pre the UVs of each chart form an overlap-free, flip-free map; 0 < fill <= 1
/// \post every flagged edge is an interior edge, not in `seam` nor in `fixed`
template <typename Surface>
std::vector<char> packing_cuts(const Surface& s, const std::vector<char>& seam, const std::vector<char>& fixed,
                               const std::vector<Vector2>& corner_uv, double fill, std::size_t& pieces)
{
  const std::size_t nf = s.number_of_faces();
  const std::vector<std::vector<int>> charts = face_charts(s, seam);
  Packing_splitter<Surface> splitter(s, seam, fixed, corner_uv, fill);
  std::vector<int> piece(nf, -1);
  int next = 0;
  pieces = 0;
  for(const std::vector<int>& faces : charts)
  {
    const std::vector<std::vector<int>> split = splitter.pieces(faces);
    pieces += split.size() - 1;
    for(const std::vector<int>& p : split)
    {
      for(int f : p) piece[std::size_t(f)] = next;
      ++next;
    }
  }
  std::vector<char> cut(s.edges.size(), 0);
  for(std::size_t fe = 0; fe < 3 * nf; ++fe)
  {
    const int tw = s.twin[fe];
    if(tw >= 0 && !seam[std::size_t(s.edge_of[fe])] && piece[fe / 3] != piece[std::size_t(tw / 3)])
      cut[std::size_t(s.edge_of[fe])] = 1;
  }
  return cut;
}

/// 3D length of the edges flagged in `flags`.
template <typename Surface>
double flagged_length(const Surface& s, const std::vector<char>& flags)
{
  double length = 0.;
  for(std::size_t fe = 0; fe < s.twin.size(); ++fe)
    if(flags[std::size_t(s.edge_of[fe])] && (s.twin[fe] < 0 || s.twin[fe] > int(fe))) length += s.edge_length(int(fe));
  return length;
}

/// Cuts the charts of the solved cut mesh in `state` (a Map_state: its
/// `is_cut`, `rules.forbidden`, `chart`, `corner_uv`, `x`) that fill less than
/// `fill` (packing_cuts(); forbidden edges never cut), rebuilding its chart
/// mesh with the same UV at every corner. Returns the charts added (0, and
/// `state` unchanged, if a piece would not be a topological disk).
/// \post every face keeps its UV triangle; `state.is_cut` only gains edges
template <typename Surface, typename State>
std::size_t cut_charts_for_packing(const Surface& s, double fill, State& state)
{
  std::vector<Vector2> uv(3 * s.number_of_faces());
  for(std::size_t c = 0; c < uv.size(); ++c) uv[c] = state.x.template segment<2>(2 * state.corner_uv[c]);
  std::size_t added = 0;
  const std::vector<char> cut = packing_cuts(s, state.is_cut, state.rules.forbidden, uv, fill, added);
  if(added == 0) return 0;
  std::vector<char> is_cut = state.is_cut;
  for(std::size_t e = 0; e < cut.size(); ++e)
    if(cut[e]) is_cut[e] = 1;
  Chart_mesh chart;
  std::vector<int> corner_uv;
  build_chart_mesh(s, is_cut, chart, corner_uv);
  if(!charts_are_disks(chart)) return 0; // a piece around a hole: keep the charts as they are
  UV_vector x(2 * chart.number_of_vertices);
  for(std::size_t c = 0; c < uv.size(); ++c) x.template segment<2>(2 * corner_uv[c]) = uv[c];
  state.is_cut.swap(is_cut);
  state.chart = std::move(chart);
  state.corner_uv.swap(corner_uv);
  state.x = std::move(x);
  return added;
}

} // namespace packing
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
