// Indexed triangle mesh of the cut surface, the working representation of all
// solvers: UV vertices (corner classes) per face, and the rest shape of each
// face in a local 2D frame.
#ifndef CGAL_SMP_CUT_INTERNAL_CHART_MESH_H
#define CGAL_SMP_CUT_INTERNAL_CHART_MESH_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

// (the same aliases as in energy/, geometry/: each header stays on the lowest floor)
using Vector3 = Eigen::Vector3d;
using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;
using UV_vector = Eigen::VectorXd; // (u0, v0, u1, v1, ...)

/// Rest shape of a triangle as the 2D edge matrix [[l01, x], [0, y]],
/// rebuilt from its 3D corners. A degenerate triangle (zero area, a needle,
/// coincident corners) gets its height and first side clamped to
/// `tuning::degenerate_ratio` times its longest side (or `fallback_length` if all
/// corners coincide), so no NaN or infinity can come out of it. Returns true
/// iff the triangle was clamped.
inline bool rest_shape(const Vector3& p0, const Vector3& p1, const Vector3& p2, double fallback_length,
                       Matrix2& rest)
{
  double l01 = (p1 - p0).norm(), l02 = (p2 - p0).norm(), l12 = (p2 - p1).norm();
  const double lmax = (std::max)({l01, l02, l12});
  const double scale = (lmax > 0. && std::isfinite(lmax)) ? lmax : fallback_length;
  const double floor = tuning::degenerate_ratio * scale;
  bool clamped = !(lmax > 0.) || !std::isfinite(lmax);
  if(clamped) l01 = l02 = l12 = scale;
  if(l01 < floor) { l01 = floor; clamped = true; }
  const double x = (l01 * l01 + l02 * l02 - l12 * l12) / (2. * l01);
  double y = std::sqrt((std::max)(0., l02 * l02 - x * x));
  // the height from the 3D cross product is more accurate than from lengths
  const double twice_area = (p1 - p0).cross(p2 - p0).norm();
  if(!clamped && std::isfinite(twice_area)) y = twice_area / l01;
  if(y < floor) { y = floor; clamped = true; }
  rest << l01, x, 0., y;
  return clamped;
}

/// True if rest_shape() clamps the triangle.
inline bool is_degenerate_triangle(const Vector3& p0, const Vector3& p1, const Vector3& p2)
{
  Matrix2 rest;
  return rest_shape(p0, p1, p2, 1., rest);
}

struct Chart_mesh
{
  std::vector<std::array<int, 3>> faces; // UV-vertex index of each corner
  std::vector<Matrix2> rest_inverse;     // inverse of the rest edge matrix
  std::vector<double> area;              // 3D area
  int number_of_vertices = 0;

  std::size_t number_of_faces() const { return faces.size(); }

  /// Sets the rest shape of face f from its 3D corners (rest_shape());
  /// returns true iff the face was clamped as degenerate.
  bool set_rest_shape(std::size_t f, const Vector3& p0, const Vector3& p1, const Vector3& p2,
                      double fallback_length = 1.)
  {
    Matrix2 rest;
    const bool clamped = rest_shape(p0, p1, p2, fallback_length, rest);
    rest_inverse[f] = rest.inverse();
    area[f] = 0.5 * rest(0, 0) * rest(1, 1);
    return clamped;
  }

  void resize_faces(std::size_t n)
  {
    faces.resize(n);
    rest_inverse.resize(n);
    area.resize(n);
  }

  /// Edge matrix [x1-x0, x2-x0] of face f in UV.
  Matrix2 uv_edges(const UV_vector& x, std::size_t f) const
  {
    const auto& t = faces[f];
    Matrix2 D;
    D << x[2*t[1]] - x[2*t[0]], x[2*t[2]] - x[2*t[0]],
         x[2*t[1]+1] - x[2*t[0]+1], x[2*t[2]+1] - x[2*t[0]+1];
    return D;
  }

  Matrix2 jacobian(const UV_vector& x, std::size_t f) const
  {
    return uv_edges(x, f) * rest_inverse[f];
  }

  /// 3D length of the edge of face f from corner k to corner k+1.
  double edge_length(std::size_t f, int k) const
  {
    const Matrix2 rest = rest_inverse[f].inverse();
    const Vector2 e1 = rest.col(0), e2 = rest.col(1);
    return k == 0 ? e1.norm() : (k == 1 ? (e2 - e1).norm() : e2.norm());
  }

  double total_area() const
  {
    double a = 0.;
    for(double fa : area) a += fa;
    return a;
  }
};

inline std::uint64_t directed_edge_key(int a, int b)
{
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

/// Faces whose UV triangle does not have a positive signed area (a NaN counts).
inline int number_of_flipped_faces(const Chart_mesh& mesh, const UV_vector& x)
{
  int flipped = 0;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    if(!(mesh.uv_edges(x, f).determinant() > 0.)) ++flipped;
  return flipped;
}

/// Border edges of the chart mesh as (a, b) UV-vertex pairs, oriented like
/// their face (interior on the left), in face order.
inline std::vector<std::array<int, 2>> border_segments(const Chart_mesh& mesh)
{
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(3 * mesh.faces.size());
  for(const auto& t : mesh.faces)
    for(int k = 0; k < 3; ++k)
      directed.emplace(directed_edge_key(t[k], t[(k+1)%3]), 0);
  std::vector<std::array<int, 2>> segments;
  for(const auto& t : mesh.faces)
    for(int k = 0; k < 3; ++k)
      if(!directed.count(directed_edge_key(t[(k+1)%3], t[k])))
        segments.push_back({t[k], t[(k+1)%3]});
  return segments;
}

/// Boundary loops of the chart mesh, each a cycle of UV vertices oriented
/// like the faces (interior on the left). Empty for a closed mesh.
inline std::vector<std::vector<int>> boundary_loops(const Chart_mesh& mesh)
{
  std::unordered_map<int, int> next; // boundary successor
  for(const auto& s : border_segments(mesh)) next.emplace(s[0], s[1]);

  std::vector<std::vector<int>> loops;
  std::unordered_map<int, bool> visited;
  for(const auto& entry : next)
  {
    if(visited[entry.first]) continue;
    std::vector<int> loop;
    int v = entry.first;
    while(!visited[v])
    {
      visited[v] = true;
      loop.push_back(v);
      auto it = next.find(v);
      if(it == next.end()) break;
      v = it->second;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

/// Number of connected components of the chart mesh (through shared UV vertices).
inline std::vector<int> chart_of_faces(const Chart_mesh& mesh, int& number_of_charts)
{
  std::vector<int> parent(mesh.number_of_vertices);
  for(int i = 0; i < mesh.number_of_vertices; ++i) parent[i] = i;
  auto find = [&](int i) { while(parent[i] != i) i = parent[i] = parent[parent[i]]; return i; };
  for(const auto& t : mesh.faces)
  {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::unordered_map<int, int> chart_id;
  std::vector<int> chart(mesh.faces.size());
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    chart[f] = chart_id.emplace(find(mesh.faces[f][0]), int(chart_id.size())).first->second;
  number_of_charts = int(chart_id.size());
  return chart;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
