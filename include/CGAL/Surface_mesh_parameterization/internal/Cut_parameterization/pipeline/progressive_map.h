// A map carried from the simplified copy to the input by undoing its
// collapses one by one, in reverse (a progressive mesh): each restored
// vertex is placed inside the kernel of its fan in UV, so that none of its
// faces flips. The copy must have been cut where the input is (its seams
// kept as edges by the simplification, which never removes a seam vertex),
// so that the restored faces' corners take their UV vertices from the faces
// they replace.
#ifndef CGAL_SMP_CUT_INTERNAL_PROGRESSIVE_MAP_H
#define CGAL_SMP_CUT_INTERNAL_PROGRESSIVE_MAP_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/carried_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/multiresolution.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace progressive {

/// A face of the progressive mesh: input vertices and UV vertices, corner by corner.
struct Face
{
  std::array<int, 3> vertex, uv;
};

/// The faces of the current level, found by their vertex set.
class Faces
{
public:
  /// False if the vertex indices do not fit the key (then nothing is carried).
  static bool fits(std::size_t vertices) { return vertices < (std::size_t(1) << 21); }

  void insert(const Face& f)
  {
    index_.emplace(key(f.vertex), int(faces_.size()));
    faces_.push_back(f);
  }
  /// The face on these three vertices, or -1.
  int find(int a, int b, int c) const
  {
    const auto it = index_.find(key({a, b, c}));
    return it == index_.end() ? -1 : it->second;
  }
  Face& operator[](int i) { return faces_[std::size_t(i)]; }
  /// Replaces vertex `from` of face `i` by `to`, with UV vertex `uv`.
  void replace(int i, int from, int to, int uv)
  {
    Face& f = faces_[std::size_t(i)];
    index_.erase(key(f.vertex));
    for(int k = 0; k < 3; ++k)
      if(f.vertex[k] == from)
      {
        f.vertex[k] = to;
        f.uv[k] = uv;
      }
    index_.emplace(key(f.vertex), i);
  }
  std::size_t size() const { return faces_.size(); }

private:
  static std::uint64_t key(std::array<int, 3> v)
  {
    std::sort(v.begin(), v.end());
    return (std::uint64_t(v[0]) << 42) | (std::uint64_t(v[1]) << 21) | std::uint64_t(v[2]);
  }
  std::vector<Face> faces_;
  std::unordered_map<std::uint64_t, int> index_;
};

inline double cross(const Vector2& a, const Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The convex polygon of the points x with cross(q - p, x - p) >= margin |q - p|²
/// for every (p, q) of `sides`, within `box` (its corners, counterclockwise).
inline std::vector<Vector2> kernel(const std::vector<std::pair<Vector2, Vector2>>& sides, double margin,
                                   std::vector<Vector2> polygon)
{
  for(const auto& s : sides)
  {
    const Vector2 d = s.second - s.first;
    auto inside = [&](const Vector2& x) { return cross(d, x - s.first) - margin * d.squaredNorm(); };
    std::vector<Vector2> clipped;
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      const Vector2& a = polygon[i];
      const Vector2& b = polygon[(i + 1) % polygon.size()];
      const double fa = inside(a), fb = inside(b);
      if(fa >= 0.) clipped.push_back(a);
      if((fa >= 0.) != (fb >= 0.)) clipped.push_back(a + (b - a) * (fa / (fa - fb)));
    }
    polygon.swap(clipped);
    if(polygon.size() < 3) return {};
  }
  return polygon;
}

/// The point of the convex `polygon` nearest `t` (t itself if inside).
inline Vector2 nearest_in(const std::vector<Vector2>& polygon, const Vector2& t)
{
  bool inside = true;
  for(std::size_t i = 0; i < polygon.size() && inside; ++i)
    inside = cross(polygon[(i + 1) % polygon.size()] - polygon[i], t - polygon[i]) >= 0.;
  if(inside) return t;
  Vector2 best = polygon[0];
  double best_distance = (t - best).squaredNorm();
  for(std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Vector2 a = polygon[i], d = polygon[(i + 1) % polygon.size()] - a;
    const double s = d.squaredNorm() > 0. ? (std::max)(0., (std::min)(1., (t - a).dot(d) / d.squaredNorm())) : 0.;
    const Vector2 q = a + s * d;
    if((t - q).squaredNorm() < best_distance)
    {
      best = q;
      best_distance = (t - q).squaredNorm();
    }
  }
  return best;
}

/// Where the restored vertex at `center` (3D) would sit in its fan if the
/// fan kept its 3D shape: the fan unfolded around it (its angles scaled to
/// 2π if closed, to at most tuning::progressive_open_fan_angle if open),
/// mapped onto the UV ring by the least-squares similarity. `ring3` and
/// `ring2`: the ring in 3D and UV, counterclockwise; `closed`: whether it
/// goes all around.
inline Vector2 similar_position(const Vector3& center, const std::vector<Vector3>& ring3,
                                const std::vector<Vector2>& ring2, bool closed)
{
  using Complex = std::complex<double>;
  const std::size_t n = ring3.size(), sectors = closed ? n : n - 1;
  std::vector<double> angle(sectors);
  double total = 0.;
  for(std::size_t i = 0; i < sectors; ++i)
  {
    const Vector3 a = ring3[i] - center, b = ring3[(i + 1) % n] - center;
    angle[i] = std::atan2(a.cross(b).norm(), a.dot(b));
    total += angle[i];
  }
  const double two_pi = 8. * std::atan(1.);
  const double scale = closed ? two_pi / total : (std::min)(1., tuning::progressive_open_fan_angle * two_pi / total);
  std::vector<Complex> z(n), w(n);
  Complex mz(0., 0.), mw(0., 0.);
  double phi = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    z[i] = std::polar((ring3[i] - center).norm(), phi);
    if(i < sectors) phi += scale * angle[i];
    w[i] = Complex(ring2[i].x(), ring2[i].y());
    mz += z[i];
    mw += w[i];
  }
  mz /= double(n);
  mw /= double(n);
  Complex num(0., 0.);
  double den = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    num += (w[i] - mw) * std::conj(z[i] - mz);
    den += std::norm(z[i] - mz);
  }
  const Complex a = den > 0. ? num / den : Complex(0., 0.);
  const Complex t = mw - a * mz;
  return Vector2(t.real(), t.imag());
}

/// The position of a restored vertex whose fan has the counterclockwise
/// sides `sides` (each face's two other corners, in UV): the kernel point
/// (tuning::progressive_kernel_margin inside it, or halved until it is not
/// empty) nearest `target`; false if it stays empty.
inline bool place_in_kernel(const std::vector<std::pair<Vector2, Vector2>>& sides, const Vector2& target,
                            Vector2& placed)
{
  Vector2 lo = sides[0].first, hi = lo;
  for(const auto& s : sides)
    for(const Vector2& p : {s.first, s.second})
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const Vector2 pad = (hi - lo) + Vector2(1e-12, 1e-12);
  lo -= pad;
  hi += pad;
  const std::vector<Vector2> box{lo, Vector2(hi.x(), lo.y()), hi, Vector2(lo.x(), hi.y())};
  // a narrow kernel takes a thinner margin (the kept vertex was strictly inside its own fan)
  double margin = tuning::progressive_kernel_margin;
  for(int i = 0; i < tuning::progressive_margin_halvings; ++i, margin *= 0.5)
  {
    const std::vector<Vector2> k = kernel(sides, margin, box);
    if(k.empty()) continue;
    placed = nearest_in(k, target);
    return true;
  }
  return false;
}

} // namespace progressive

/// `carried.x` on `fine` (the chart mesh of `surface` cut as the copy is)
/// from the map `coarse_x` of `coarse_chart` (the copy's chart mesh), by
/// undoing `coarse.collapses` in reverse: each restored vertex goes into
/// the kernel of its fan (progressive::place_in_kernel()), at the point
/// nearest where the fan's 3D shape would put it
/// (progressive::similar_position()). `carried.valid` per chart of `fine`:
/// no flipped face, a border that does not meet itself, every corner
/// found. Returns false (nothing carried) where the copy's faces do not
/// refine back to the input's.
///
/// Precondition: `coarse` made by simplify_for_carrying() from `surface`,
/// with the seams of `fine` kept; `coarse_x` without flipped face.
template <typename Surface>
bool undo_collapses(const Surface& surface, const Coarse_surface& coarse, const Chart_mesh& coarse_chart,
                    const UV_vector& coarse_x, const Chart_mesh& fine, Carried_map& carried)
{
  using namespace progressive;
  if(!Faces::fits(surface.number_of_vertices())) return false;
  Faces faces;
  std::vector<Vector2> position(std::size_t(coarse_chart.number_of_vertices));
  for(std::size_t i = 0; i < position.size(); ++i) position[i] = coarse_x.segment<2>(2 * Eigen::Index(i));
  for(std::size_t f = 0; f < coarse_chart.number_of_faces(); ++f)
  {
    Face face;
    for(int k = 0; k < 3; ++k) face.vertex[k] = coarse.fine_vertex[std::size_t(coarse.surface.corner_vertex[f][k])];
    face.uv = coarse_chart.faces[f];
    faces.insert(face);
  }
  std::vector<std::pair<int, int>> uv_of; // (input vertex, UV vertex) around the restored vertex
  auto uv_at = [&](int v) {
    for(const auto& p : uv_of)
      if(p.first == v) return p.second;
    return -1;
  };
  std::vector<std::pair<Vector2, Vector2>> sides;
  std::vector<int> ring;
  for(auto c = coarse.collapses.rbegin(); c != coarse.collapses.rend(); ++c)
  {
    const int r = c->removed, k = c->kept, ur = int(position.size());
    position.emplace_back(0., 0.);
    uv_of.clear();
    // star faces are (a, r, b): the face (r, b, a) counterclockwise from r
    for(const auto& s : c->star)
    {
      if(s[0] == k || s[2] == k) continue; // gone with the collapse: restored below
      const int t = faces.find(s[0], k, s[2]);
      if(t < 0) return false;
      for(int i = 0; i < 3; ++i) uv_of.emplace_back(faces[t].vertex[i], faces[t].uv[i]);
      faces.replace(t, k, r, ur);
    }
    for(const auto& s : c->star)
    {
      if(s[0] != k && s[2] != k) continue;
      const int ua = uv_at(s[0]), ub = uv_at(s[2]);
      if(ua < 0 || ub < 0) return false;
      faces.insert(Face{{s[0], r, s[2]}, {ua, ur, ub}});
    }
    // the ring, counterclockwise: the sides (b, a) chained b -> a
    sides.clear();
    for(const auto& s : c->star)
    {
      const int ub = uv_at(s[2]), ua = uv_at(s[0]);
      if(ua < 0 || ub < 0) return false;
      sides.emplace_back(position[std::size_t(ub)], position[std::size_t(ua)]);
    }
    ring.clear();
    std::size_t start = 0; // an open fan starts where no side ends
    for(std::size_t i = 0; i < c->star.size(); ++i)
    {
      bool ends_here = false;
      for(const auto& s : c->star) ends_here = ends_here || s[0] == c->star[i][2];
      if(!ends_here) start = i;
    }
    bool chained = true;
    int at = c->star[start][2];
    ring.push_back(at);
    for(std::size_t step = 0; step < c->star.size() && chained; ++step)
    {
      chained = false;
      for(const auto& s : c->star)
        if(s[2] == at)
        {
          at = s[0];
          chained = true;
          break;
        }
      if(chained) ring.push_back(at);
    }
    const bool closed = chained && ring.size() == c->star.size() + 1 && ring.front() == ring.back();
    if(closed) ring.pop_back();
    Vector2 target = Vector2::Zero();
    for(const auto& sd : sides) target += 0.5 * (sd.first + sd.second) / double(sides.size());
    if(ring.size() == c->star.size() + (closed ? 0 : 1) && ring.size() >= 2)
    {
      std::vector<Vector3> ring3;
      std::vector<Vector2> ring2;
      for(int v : ring)
      {
        ring3.push_back(surface.points[std::size_t(v)]);
        ring2.push_back(position[std::size_t(uv_at(v))]);
      }
      target = similar_position(surface.points[std::size_t(r)], ring3, ring2, closed);
    }
    Vector2 placed = target; // an empty kernel: the chart's faces flip, it is not carried
    place_in_kernel(sides, target, placed);
    position[std::size_t(ur)] = placed;
  }

  // the restored faces are the input's, their UV vertices those of `fine`
  const std::size_t nf = fine.number_of_faces();
  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(fine, charts);
  carried.valid.assign(std::size_t(charts), 1);
  carried.x.setZero(2 * Eigen::Index(fine.number_of_vertices));
  if(faces.size() != nf) return false;
  std::vector<int> from(std::size_t(fine.number_of_vertices), -1);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& cv = surface.corner_vertex[f];
    const int t = faces.find(cv[0], cv[1], cv[2]);
    if(t < 0) return false;
    const Face& face = faces[t];
    int shift = 0;
    while(shift < 3 && face.vertex[std::size_t(shift)] != cv[0]) ++shift;
    for(int j = 0; j < 3; ++j)
    {
      const int u = face.uv[std::size_t((j + shift) % 3)], fv = fine.faces[f][std::size_t(j)];
      if(shift == 3 || face.vertex[std::size_t((j + shift) % 3)] != cv[std::size_t(j)]
         || (from[std::size_t(fv)] >= 0 && from[std::size_t(fv)] != u))
      {
        carried.valid[std::size_t(chart_of_face[f])] = 0; // cut otherwise than the copy
        continue;
      }
      from[std::size_t(fv)] = u;
      carried.x.segment<2>(2 * Eigen::Index(fv)) = position[std::size_t(u)];
    }
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(!(fine.uv_edges(carried.x, f).determinant() > 0.)) carried.valid[std::size_t(chart_of_face[f])] = 0;
  const std::vector<char> crossing = Border_barrier_term(fine).charts_with_crossing(carried.x);
  for(int c = 0; c < charts; ++c)
    if(crossing[std::size_t(c)]) carried.valid[std::size_t(c)] = 0;
  return true;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
