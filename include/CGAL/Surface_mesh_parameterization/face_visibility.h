// Visibility of each face (ambient occlusion) and the per-face λ it gives,
// so that seams gather where nobody looks (the paper's section 5.3, Fig. 8).
//
//   namespace SMP = CGAL::Surface_mesh_parameterization;
//   auto visibility = mesh.add_property_map<Face_index, double>("f:visibility").first;
//   SMP::face_visibility(mesh, visibility, SMP::parameters::number_of_rays(64));
//   auto lambda = mesh.add_property_map<Face_index, double>("f:lambda").first;
//   SMP::visibility_face_lambda(mesh, visibility, lambda, 3.);
//   SMP::cut_and_parameterize(mesh, seams, uvs, SMP::parameters::face_lambda_map(lambda));
//   double hidden = SMP::seam_visibility(mesh, seams, visibility);
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_FACE_VISIBILITY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_FACE_VISIBILITY_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// `n` unit directions of the upper hemisphere (z > 0), cosine-distributed
/// (Malley's method over a Fibonacci spiral of the unit disk): the same set
/// on every run, so that the visibility is deterministic.
inline std::vector<std::array<double, 3>> hemisphere_directions(int n)
{
  std::vector<std::array<double, 3>> d;
  const double golden = M_PI * (3. - std::sqrt(5.));
  for(int i = 0; i < n; ++i)
  {
    const double r = std::sqrt((i + 0.5) / n), phi = golden * i;
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    d.push_back({x, y, std::sqrt(std::max(0., 1. - x * x - y * y))});
  }
  return d;
}

/// Rays cast between two reports of face_visibility()'s progress callback
/// (a block of faces: 1,024 at the default 64 rays per face), so that a
/// cancellation waits for about as much work whatever the number of rays.
constexpr std::size_t visibility_rays_per_report = 65536;

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
/// Computes the visibility of each face of `mesh`: the fraction of the
/// hemisphere above the face, cosine-weighted (ambient occlusion), from
/// which the face is seen, i.e. that no other face of `mesh` blocks within
/// `maximum_distance`. A face inside a closed surface gets 0, a lone face 1.
///
/// Rays leave the face's centroid (moved off the face by 10⁻⁶ of the
/// bounding box's diagonal, so that the face does not block itself) in a
/// fixed set of directions, and are tested against an `AABB_tree` of the
/// faces; faces are processed in parallel with TBB when linked. The result
/// does not depend on the number of threads.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VisibilityMap a `WritablePropertyMap` with
///   `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param mesh the mesh
/// \param visibility output: the visibility of each face
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_rays}
///     \cgalParamDescription{rays cast per face}
///     \cgalParamType{`int`, ≥ 1}
///     \cgalParamDefault{`64`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_distance}
///     \cgalParamDescription{faces farther than this from a face's centroid do not block its rays}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called with the fraction of the faces done, in [0, 1]: 0 before the
///       work starts, then after each block of faces (65,536 rays: 1,024 faces at 64 rays),
///       the last time with 1; one call at a time, from the calling thread. Returning `false`
///       stops the computation with `ERROR_CANCELED`, `visibility` unchanged (the convention
///       of `cut_and_parameterize()`'s `progress_callback`)}
///     \cgalParamType{a callable as `bool(double)`, e.g. `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`; `ERROR_EMPTY_MESH` with no face;
///         `ERROR_NON_TRIANGULAR_MESH` if a face is not a triangle;
///         `ERROR_WRONG_PARAMETER` for fewer than 1 ray or a maximum
///         distance that is not positive; `ERROR_CANCELED` if the
///         `progress_callback` returned false.
///
/// \pre every face of `mesh` is a triangle (else `ERROR_NON_TRIANGULAR_MESH`)
/// \post on `OK`, every face gets a value in [0, 1]; a degenerate face (no
///       normal) gets 1
/// \post on error, `visibility` is left unchanged
template <typename TriangleMesh, typename VisibilityMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code face_visibility(const TriangleMesh& mesh, VisibilityMap visibility,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  using Point = typename boost::property_traits<VPM>::value_type;
  using K = typename Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VPM>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const int rays = choose_parameter(get_parameter(np, internal_np::number_of_rays), 64);
  const double max_distance = choose_parameter(get_parameter(np, internal_np::maximum_distance),
                                               std::numeric_limits<double>::infinity());
  const std::function<bool(double)> progress =
    choose_parameter(get_parameter(np, internal_np::progress_callback), std::function<bool(double)>());
  if(rays < 1 || !(max_distance > 0.)) return ERROR_WRONG_PARAMETER;
  std::vector<face_descriptor> face_list(faces(mesh).begin(), faces(mesh).end());
  if(face_list.empty()) return ERROR_EMPTY_MESH;
  for(face_descriptor f : face_list)
    if(CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size() != 3) return ERROR_NON_TRIANGULAR_MESH;
  if(progress && !progress(0.)) return ERROR_CANCELED;

  Tree tree(faces(mesh).first, faces(mesh).second, mesh, vpm);
  tree.build();
  const auto box = tree.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double offset = 1e-6 * diagonal;
  const auto directions = internal::cut::hemisphere_directions(rays);

  std::vector<double> result(face_list.size(), 1.);
  auto face_work = [&](std::size_t i) {
    const face_descriptor f = face_list[i];
    const auto h = halfedge(f, mesh);
    const Point& p0 = get(vpm, source(h, mesh));
    const Point& p1 = get(vpm, target(h, mesh));
    const Point& p2 = get(vpm, target(next(h, mesh), mesh));
    const double a[3] = {CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(p0.z())};
    const double b[3] = {CGAL::to_double(p1.x()), CGAL::to_double(p1.y()), CGAL::to_double(p1.z())};
    const double c[3] = {CGAL::to_double(p2.x()), CGAL::to_double(p2.y()), CGAL::to_double(p2.z())};
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(!(length > 0.) || !std::isfinite(length)) return; // degenerate: 1
    for(double& x : n) x /= length;
    // a frame (t, s, n) of the face
    double t[3] = {u[0], u[1], u[2]};
    const double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for(double& x : t) x /= tl;
    const double s[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
    const double o[3] = {(a[0] + b[0] + c[0]) / 3. + offset * n[0], (a[1] + b[1] + c[1]) / 3. + offset * n[1],
                         (a[2] + b[2] + c[2]) / 3. + offset * n[2]};
    const typename K::Point_3 origin(o[0], o[1], o[2]);
    int seen = 0;
    for(const auto& d : directions)
    {
      const double dir[3] = {d[0] * t[0] + d[1] * s[0] + d[2] * n[0], d[0] * t[1] + d[1] * s[1] + d[2] * n[1],
                             d[0] * t[2] + d[1] * s[2] + d[2] * n[2]};
      bool blocked;
      if(std::isfinite(max_distance))
        blocked = tree.do_intersect(typename K::Segment_3(
          origin, typename K::Point_3(o[0] + max_distance * dir[0], o[1] + max_distance * dir[1],
                                      o[2] + max_distance * dir[2])));
      else
        blocked = tree.do_intersect(typename K::Ray_3(origin, typename K::Vector_3(dir[0], dir[1], dir[2])));
      if(!blocked) ++seen;
    }
    result[i] = double(seen) / double(rays);
  };
  // by blocks, a report after each (without callback: one block)
  const std::size_t n = face_list.size();
  const std::size_t block =
    progress ? (std::max)(std::size_t(1), internal::cut::visibility_rays_per_report / std::size_t(rays)) : n;
  for(std::size_t first = 0; first < n; first += block)
  {
    const std::size_t last = (std::min)(n, first + block);
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for(std::size_t i = r.begin(); i != r.end(); ++i) face_work(i);
                      });
#else
    for(std::size_t i = first; i < last; ++i) face_work(i);
#endif
    if(progress && !progress(double(last) / double(n))) return ERROR_CANCELED;
  }
  for(std::size_t i = 0; i < face_list.size(); ++i) put(visibility, face_list[i], result[i]);
  return OK;
}

/// \ingroup PkgCutParameterizationRef
/// Turns a visibility (e.g. from `face_visibility()`) into a per-face λ
/// factor for the `face_lambda_map` named parameter: seams get cheaper where
/// the surface is hidden and dearer where it is seen. The factor of face f is
/// exp(`strength` · (vis_f − vis̄)), vis̄ the area-weighted mean visibility,
/// so that the factors' area-weighted geometric mean is 1 and the overall
/// amount of seams stays about the same.
///
/// \pre `mesh` is a triangle mesh; every visibility is in [0, 1] (else
///      `ERROR_WRONG_PARAMETER`).
/// \post on `OK`, every factor is positive and finite, and their
///       area-weighted geometric mean is 1 (up to rounding)
/// \param mesh a model of `FaceListGraph`
/// \param visibility a `ReadablePropertyMap`, face → `double` in [0, 1]
/// \param lambda a `WritablePropertyMap`, face → `double`: the factors (left
///        unchanged on error)
/// \param strength ≥ 0; 0 gives 1 everywhere. At 3, a face seen from every
///        direction costs e³ ≈ 20 times more to cut than a face in a crack.
/// \return `OK`, or `ERROR_WRONG_PARAMETER` for a negative or non-finite
///         strength or a visibility outside [0, 1].
template <typename TriangleMesh, typename VisibilityMap, typename LambdaMap>
Error_code visibility_face_lambda(const TriangleMesh& mesh, const VisibilityMap& visibility, LambdaMap lambda,
                                  double strength)
{
  if(!(strength >= 0.) || !std::isfinite(strength)) return ERROR_WRONG_PARAMETER;
  const auto vpm = get_const_property_map(vertex_point, mesh);
  double area = 0., weighted = 0.;
  for(auto f : faces(mesh))
  {
    const double vis = get(visibility, f);
    if(!(vis >= 0. && vis <= 1.)) return ERROR_WRONG_PARAMETER;
    const auto h = halfedge(f, mesh);
    const double a = std::sqrt(CGAL::to_double(CGAL::squared_area(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                                                                  get(vpm, target(next(h, mesh), mesh)))));
    if(std::isfinite(a)) { area += a; weighted += a * vis; }
  }
  // A contrast on the visibility, not on its rank: seams go to the faces
  // really hidden (measured in the manual, Cut_parameterization_visibility).
  const double mean = area > 0. ? weighted / area : 1.;
  for(auto f : faces(mesh)) put(lambda, f, std::exp(strength * (get(visibility, f) - mean)));
  return OK;
}

/// \ingroup PkgCutParameterizationRef
/// The mean visibility along the seams, weighted by edge length: each seam
/// edge counts with the mean visibility of its faces. 0 when there is no
/// seam. Lower is better hidden.
///
/// \pre `mesh` is a model of `FaceListGraph`; `seams` is defined on its
///      edges, `visibility` on its faces
/// \post the result is in [0, 1] when every visibility is
template <typename TriangleMesh, typename SeamMap, typename VisibilityMap>
double seam_visibility(const TriangleMesh& mesh, const SeamMap& seams, const VisibilityMap& visibility)
{
  const auto vpm = get_const_property_map(vertex_point, mesh);
  double length = 0., weighted = 0.;
  for(auto e : edges(mesh))
  {
    if(!get(seams, e)) continue;
    const auto h = halfedge(e, mesh);
    double vis = 0.;
    int n = 0;
    for(auto g : {h, opposite(h, mesh)})
      if(!is_border(g, mesh)) { vis += get(visibility, face(g, mesh)); ++n; }
    if(n == 0) continue;
    const auto& p = get(vpm, source(h, mesh));
    const auto& q = get(vpm, target(h, mesh));
    const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    length += l;
    weighted += l * vis / n;
  }
  return length > 0. ? weighted / length : 0.;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
