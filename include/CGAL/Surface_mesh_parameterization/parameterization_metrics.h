#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_METRICS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_METRICS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/border_crossings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/uv_coverage_raster.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// UV of the corner at target(h) in face(h): `uvmap` may be keyed by
/// halfedges (one UV per corner) or by vertices (e.g. a Seam_mesh's vertices,
/// or a plain mesh without seams).
template <typename TriangleMesh, typename UVMap>
Vector2 corner_uv(const TriangleMesh& mesh, const UVMap& uvmap,
                  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  using key_type = typename boost::property_traits<UVMap>::key_type;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  if constexpr(std::is_same<key_type, halfedge_descriptor>::value)
  {
    const auto& p = get(uvmap, h);
    return Vector2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }
  else
  {
    const auto& p = get(uvmap, target(h, mesh));
    return Vector2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }
}

/// The `uv_scale` named parameter (default 1).
template <typename NamedParameters>
double uv_scale(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::Surface_mesh_parameterization::internal_np::uv_scale), 1.);
}

template <typename Point>
Vector3 to_vector3(const Point& p)
{
  return Vector3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

/// 3D corners of triangle f, corner k at the target of h_k (h_0 = halfedge(f)).
template <typename TriangleMesh, typename VertexPointMap>
std::array<Vector3, 3> face_corners(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                                    const TriangleMesh& mesh, const VertexPointMap& vpm)
{
  const auto h = halfedge(f, mesh), h1 = next(h, mesh), h2 = next(h1, mesh);
  CGAL_precondition(next(h2, mesh) == h);
  return {to_vector3(get(vpm, target(h, mesh))), to_vector3(get(vpm, target(h1, mesh))),
          to_vector3(get(vpm, target(h2, mesh)))};
}

/// 3D area and UV Jacobian of face f; the Jacobian is NaN for a degenerate
/// face (see rest_shape()).
template <typename TriangleMesh, typename UVMap, typename VertexPointMap>
std::pair<double, Matrix2> face_area_and_jacobian(
  typename boost::graph_traits<TriangleMesh>::face_descriptor f,
  const TriangleMesh& mesh, const UVMap& uvmap, const VertexPointMap& vpm)
{
  const std::array<Vector3, 3> p = face_corners(f, mesh, vpm);
  Matrix2 rest;
  if(rest_shape(p[0], p[1], p[2], 1., rest))
    return {0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm(), Matrix2::Constant(std::numeric_limits<double>::quiet_NaN())};
  const auto h = halfedge(f, mesh), h1 = next(h, mesh), h2 = next(h1, mesh);
  const Vector2 u0 = corner_uv(mesh, uvmap, h), u1 = corner_uv(mesh, uvmap, h1), u2 = corner_uv(mesh, uvmap, h2);
  Matrix2 D;
  D << u1.x() - u0.x(), u2.x() - u0.x(), u1.y() - u0.y(), u2.y() - u0.y();
  return {0.5 * rest(0, 0) * rest(1, 1), D * rest.inverse()};
}

template <typename TriangleMesh, typename NamedParameters>
auto vertex_points(const TriangleMesh& mesh, const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, mesh));
}

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
///
/// Distortion of one face: σ1² + σ2² + σ1⁻² + σ2⁻² of the map from its 3D
/// triangle to its UV triangle (4 for an isometry, +∞ for a flipped or
/// collapsed UV triangle or a degenerate 3D face: one whose height is
/// below 1e-4 times its longest side).
///
/// `uvmap` is keyed either by halfedges (UV of the corner at `target(h)` in
/// `face(h)`, as written by `cut_and_parameterize()`) or by vertices
/// (e.g. of a `CGAL::Seam_mesh`).
///
/// \param f the face
/// \param mesh the mesh
/// \param uvmap the UV map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{uv_scale}
///     \cgalParamDescription{UV length per 3D length of the map measured, e.g.
///       `Cut_and_parameterize_result::uv_scale` of a packed atlas: the UVs are divided by it}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `f` is a face of `mesh` and a triangle
/// \post the result is ≥ 4, or +∞
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double face_distortion(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                       const TriangleMesh& mesh, const UVMap& uvmap,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto aj = internal::cut::face_area_and_jacobian(f, mesh, uvmap, internal::cut::vertex_points(mesh, np));
  if(!aj.second.allFinite()) return std::numeric_limits<double>::infinity();
  return internal::cut::symmetric_dirichlet_measure(aj.second / internal::cut::uv_scale(np));
}

/// \ingroup PkgCutParameterizationRef
///
/// The distortion E_d = Σ_f A_f (σ1²+σ2²+σ1⁻²+σ2⁻²) / Σ_f A_f of a UV map
/// (A_f: 3D area), as in the paper's Table 1. Minimum 4; +∞ if any face is
/// flipped or collapsed in UV. Degenerate 3D faces (zero area, or height
/// below 1e-4 times the longest side) have no weight.
/// `uvmap` as in `face_distortion()`.
///
/// \param mesh the mesh
/// \param uvmap the UV map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{uv_scale}
///     \cgalParamDescription{UV length per 3D length of the map measured, e.g.
///       `Cut_and_parameterize_result::uv_scale` of a packed atlas: the UVs are divided by it}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `mesh` is a non-empty triangle mesh
/// \post the result is ≥ 4, +∞ if a face is flipped or collapsed, or NaN if
///   every face is degenerate
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double distortion_energy(const TriangleMesh& mesh, const UVMap& uvmap,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::cut::vertex_points(mesh, np);
  const double scale = internal::cut::uv_scale(np);
  double sum = 0., area = 0.;
  for(auto f : faces(mesh))
  {
    const auto aj = internal::cut::face_area_and_jacobian(f, mesh, uvmap, vpm);
    if(!aj.second.allFinite()) continue; // degenerate 3D face
    if(!(aj.second.determinant() > 0.))
      return std::numeric_limits<double>::infinity();
    sum += aj.first * internal::cut::symmetric_dirichlet_measure(aj.second / scale);
    area += aj.first;
  }
  return area > 0. ? sum / area : std::numeric_limits<double>::quiet_NaN();
}

/// \ingroup PkgCutParameterizationRef
///
/// Number of faces whose UV triangle has a non-positive signed area.
/// `uvmap` as in `face_distortion()`.
/// \pre `mesh` is a triangle mesh
/// \post the result is at most `num_faces(mesh)`; a face with a non-finite UV counts
template <typename TriangleMesh, typename UVMap>
std::size_t number_of_flipped_faces(const TriangleMesh& mesh, const UVMap& uvmap)
{
  std::size_t flipped = 0;
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    const auto u0 = internal::cut::corner_uv(mesh, uvmap, h);
    const auto u1 = internal::cut::corner_uv(mesh, uvmap, next(h, mesh));
    const auto u2 = internal::cut::corner_uv(mesh, uvmap, next(next(h, mesh), mesh));
    const double signed_area2 = (u1 - u0).x() * (u2 - u0).y() - (u1 - u0).y() * (u2 - u0).x();
    if(!(signed_area2 > 0.)) ++flipped;
  }
  return flipped;
}

/// \ingroup PkgCutParameterizationRef
///
/// Number of pairs of UV border segments that cross properly: 0 for an atlas
/// without overlap (given no flipped face), positive where charts overlap
/// each other or themselves.
///
/// A UV border segment is the UV image of a face edge whose other side is
/// the mesh border or a face whose corner UVs along that edge differ from
/// this face's (a seam). Corners of one vertex with exactly equal UVs are
/// the same UV point; two segments cross properly when they meet at a single
/// point interior to both. Segments that share a UV point, touch, or overlap
/// along a line are not counted. The predicates are exact (on the UVs
/// converted to `double`); a UV that is not finite makes its segments cross
/// nothing. Near-linear time (a uniform grid over the segments).
///
/// `uvmap` as in `face_distortion()` (a vertex-keyed map has no seams: its
/// border segments are the mesh's border edges).
/// \pre `mesh` is a triangle mesh
/// \post the result is 0 if `mesh` has no face
template <typename TriangleMesh, typename UVMap>
std::size_t number_of_border_crossings(const TriangleMesh& mesh, const UVMap& uvmap)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

  // Number the distinct UV points of each vertex: its corners with exactly
  // equal UVs share an index. The points of one vertex form a linked list
  // (first_point of the vertex, then next_point).
  auto first_point = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  auto corner_point = get(CGAL::dynamic_halfedge_property_t<int>(), mesh);
  for(vertex_descriptor v : vertices(mesh)) put(first_point, v, -1);
  std::vector<internal::cut::Vector2> points;
  std::vector<int> next_point;
  for(auto f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const internal::cut::Vector2 uv = internal::cut::corner_uv(mesh, uvmap, h);
      const vertex_descriptor v = target(h, mesh);
      int i = get(first_point, v);
      while(i >= 0 && !(points[std::size_t(i)] == uv)) i = next_point[std::size_t(i)];
      if(i < 0)
      {
        i = int(points.size());
        points.push_back(uv);
        next_point.push_back(get(first_point, v));
        put(first_point, v, i);
      }
      put(corner_point, h, i);
    }

  // Border segments, oriented like their face: an edge is inner (no
  // segment) when the face on its other side has the same two UV points.
  std::vector<std::array<int, 2>> segments;
  for(auto f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const int a = get(corner_point, prev(h, mesh)), b = get(corner_point, h); // source(h), target(h)
      const halfedge_descriptor o = opposite(h, mesh);
      if(!is_border(o, mesh) && get(corner_point, o) == a && get(corner_point, prev(o, mesh)) == b) continue;
      segments.push_back({a, b});
    }

  internal::cut::UV_vector x(2 * points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    x[2 * i] = points[i].x();
    x[2 * i + 1] = points[i].y();
  }
  return internal::cut::count_border_crossings(segments, x);
}

/// \ingroup PkgCutParameterizationRef
///
/// Total UV area: the sum of the unsigned areas of the faces' UV triangles
/// (overlapping and flipped triangles count in full). For an atlas inside
/// the unit square this is its coverage, the fraction of the texture used.
/// `uvmap` as in `face_distortion()`.
/// \pre `mesh` is a triangle mesh
/// \post the result is >= 0, or NaN if a UV is not finite
template <typename TriangleMesh, typename UVMap>
double uv_area(const TriangleMesh& mesh, const UVMap& uvmap)
{
  double area = 0.;
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    const auto u0 = internal::cut::corner_uv(mesh, uvmap, h);
    const auto u1 = internal::cut::corner_uv(mesh, uvmap, next(h, mesh));
    const auto u2 = internal::cut::corner_uv(mesh, uvmap, next(next(h, mesh), mesh));
    area += 0.5 * std::abs((u1 - u0).x() * (u2 - u0).y() - (u1 - u0).y() * (u2 - u0).x());
  }
  return area;
}

/// \ingroup PkgCutParameterizationRef
///
/// Overlap area: the UV area covered by more than one face, a point covered
/// k times counting k - 1 times. Independent of the border crossings
/// (`number_of_border_crossings()`): it sees charts lying exactly on top of
/// each other and a chart nested inside another, whose borders never cross.
/// 0 for a map without overlap; of the order of `uv_area()` times the
/// fraction of the charts laid over others.
///
/// Measured by a coverage count: the UV triangles are rasterized on
/// `resolution` × `resolution` square cells over their bounding box (its
/// longer side), a sample at each cell's center; each sample covered k > 1
/// times adds k - 1 times the cell's area. The predicates are exact (on the
/// UVs converted to `double`), with a half-open rule on the triangles'
/// edges and vertices, so that the faces of a map without flipped face and
/// with disjoint charts cover each sample at most once (result exactly 0).
/// An overlap narrower than the cell side (the bounding box's longer side
/// divided by `resolution`) may be missed. Flipped faces count like the
/// others (a fold overlaps its neighbours); faces with collinear UVs cover
/// nothing. Time: the number of faces plus the number of samples their UV
/// bounding boxes hold; memory: 2 bytes per cell.
///
/// `uvmap` as in `face_distortion()`.
/// \pre `mesh` is a triangle mesh
/// \post the result is >= 0, or NaN if a UV is not finite
template <typename TriangleMesh, typename UVMap>
double uv_overlap_area(const TriangleMesh& mesh, const UVMap& uvmap, std::size_t resolution = 1024)
{
  std::vector<std::array<std::array<double, 2>, 3>> triangles;
  triangles.reserve(std::size_t(num_faces(mesh)));
  for(auto f : faces(mesh))
  {
    std::array<std::array<double, 2>, 3> t;
    std::size_t k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      if(k == 3) break;
      const internal::cut::Vector2 uv = internal::cut::corner_uv(mesh, uvmap, h);
      t[k++] = {uv.x(), uv.y()};
    }
    triangles.push_back(t);
  }
  return internal::cut::overlap_area_of_triangles(triangles, resolution);
}

/// \ingroup PkgCutParameterizationRef
///
/// True if face `f` is degenerate: zero area, a needle or coincident corners,
/// i.e. its height is below 1e-4 times its longest side. Such faces are
/// clamped by `cut_and_parameterize()` (or refused with its
/// `reject_degenerate_faces` option) and have no weight in
/// `distortion_energy()`.
///
/// \param f the face
/// \param mesh the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `f` is a face of `mesh` and a triangle
/// \post the result does not depend on any UV
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_degenerate_face(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& mesh,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto p = internal::cut::face_corners(f, mesh, internal::cut::vertex_points(mesh, np));
  return internal::cut::is_degenerate_triangle(p[0], p[1], p[2]);
}

/// \ingroup PkgCutParameterizationRef
///
/// Total 3D area of the mesh's faces.
///
/// \param mesh the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `mesh` is a triangle mesh
/// \post the result is ≥ 0 (0 without faces), or NaN if a point is not finite
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
double surface_area(const TriangleMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::cut::vertex_points(mesh, np);
  double area = 0.;
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    const auto p0 = internal::cut::to_vector3(get(vpm, source(h, mesh)));
    const auto p1 = internal::cut::to_vector3(get(vpm, target(h, mesh)));
    const auto p2 = internal::cut::to_vector3(get(vpm, target(next(h, mesh), mesh)));
    area += 0.5 * (p1 - p0).cross(p2 - p0).norm();
  }
  return area;
}

/// \ingroup PkgCutParameterizationRef
///
/// The seam length E_s = L / sqrt(A / π): L the total 3D length of the edges
/// flagged in `seam_edge_map` (each once; edges on the mesh's own boundary
/// excluded), A the total 3D area. 0 for no seam.
///
/// \param mesh the mesh
/// \param seam_edge_map the seams: a `ReadablePropertyMap`, edge → `bool`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `mesh` is a triangle mesh
/// \post the result is ≥ 0, and 0 when no edge off the boundary is flagged
template <typename TriangleMesh, typename SeamEdgeMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double seam_length(const TriangleMesh& mesh, const SeamEdgeMap& seam_edge_map,
                   const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto vpm = internal::cut::vertex_points(mesh, np);
  double length = 0.;
  for(auto e : edges(mesh))
  {
    if(!get(seam_edge_map, e) || is_border(e, mesh)) continue;
    const auto h = halfedge(e, mesh);
    length += (internal::cut::to_vector3(get(vpm, target(h, mesh)))
               - internal::cut::to_vector3(get(vpm, source(h, mesh)))).norm();
  }
  const double area = surface_area(mesh, np);
  return area > 0. ? length / std::sqrt(area / M_PI) : 0.;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
