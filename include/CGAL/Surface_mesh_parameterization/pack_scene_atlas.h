#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PACK_SCENE_ATLAS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PACK_SCENE_ATLAS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/packing_split.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/scene_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/stacked_meshes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
/// One mesh of a scene atlas: the mesh, its seams and its UVs (at its
/// halfedges, as `cut_and_parameterize()` writes them). The maps are copied;
/// the UV map is written through its copy (a property map is a handle).
template <typename TriangleMesh, typename SeamEdgeMap, typename HalfedgeUVMap>
struct Scene_atlas_mesh
{
  const TriangleMesh* mesh;   ///< the mesh (not owned)
  SeamEdgeMap seam_edge_map;  ///< its seams: the charts are its faces cut along them
  HalfedgeUVMap uvmap;        ///< its UVs, read, then replaced by those of the atlas
};

/// \ingroup PkgCutParameterizationRef
/// Makes a `Scene_atlas_mesh`; `mesh` must outlive it.
template <typename TriangleMesh, typename SeamEdgeMap, typename HalfedgeUVMap>
Scene_atlas_mesh<TriangleMesh, SeamEdgeMap, HalfedgeUVMap>
make_scene_atlas_mesh(const TriangleMesh& mesh, SeamEdgeMap seam_edge_map, HalfedgeUVMap uvmap)
{
  return {&mesh, seam_edge_map, uvmap};
}

/// \ingroup PkgCutParameterizationRef
/// What `pack_scene_atlas()` did.
struct Scene_atlas_result
{
  Error_code error = OK;       ///< `OK` or the reason nothing was written
  int number_of_pages = 0;     ///< pages used
  double texels_per_unit = 0.; ///< texels per unit of 3D length, the same for every mesh
  std::vector<int> page;       ///< page of each mesh, in the order given
  /// per mesh, the mesh whose texels it shares (`instance_of`, `stacking_tolerance`); itself if none
  std::vector<int> stacked_on;
  std::size_t number_of_charts = 0; ///< charts packed (those of the stacked copies not counted)
  /// per mesh, the charts added by `split_charts_for_packing` (0 without it; a stacked copy's: its original's)
  std::vector<std::size_t> added_charts;
  /// per mesh, the length of the seams added by `split_charts_for_packing` (0 without it), in the unit of
  /// `Cut_and_parameterize_result::seam_length` (3D length over the radius of the disk of the mesh's area)
  std::vector<double> added_seam_length;
};

namespace internal {
namespace cut {

/// UV of every corner 3f+k of `surface`; false if one is not finite.
template <typename Surface, typename HalfedgeUVMap>
bool read_corner_uvs(const Surface& surface, const HalfedgeUVMap& uvmap, std::vector<Vector2>& uv)
{
  uv.resize(3 * surface.number_of_faces());
  for(std::size_t c = 0; c < uv.size(); ++c)
  {
    const auto p = get(uvmap, surface.corner_halfedge[c / 3][c % 3]);
    uv[c] = Vector2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    if(!uv[c].allFinite()) return false;
  }
  return true;
}

/// Charts (faces joined across edges that are neither seams, flagged in
/// `seams` per edge, nor borders: packing::face_charts()) of one mesh, with
/// the UV `corner_uv` of every corner 3f+k (read_corner_uvs()), as scene
/// charts at 3D scale; `face_chart` and the frame corners of each face are
/// kept to write the UVs back. False if the UV area is zero.
template <typename Surface>
bool read_scene_charts(const Surface& surface, const std::vector<char>& seams, const std::vector<Vector2>& corner_uv,
                       int mesh, std::vector<Scene_chart>& charts, std::vector<int>& face_chart)
{
  const std::size_t nf = surface.number_of_faces();
  std::vector<int> label(nf, -1);
  const std::vector<std::vector<int>> components = packing::face_charts(surface, seams);
  for(std::size_t c = 0; c < components.size(); ++c)
    for(int f : components[c]) label[std::size_t(f)] = int(c);
  std::vector<std::array<Vector2, 3>> uv(nf);
  double area_3d = 0., area_uv = 0.;
  for(std::size_t f = 0; f < nf; ++f)
  {
    for(int k = 0; k < 3; ++k) uv[f][k] = corner_uv[3 * f + std::size_t(k)];
    const Vector3 &a = surface.points[surface.corner_vertex[f][0]], &b = surface.points[surface.corner_vertex[f][1]],
                  &c = surface.points[surface.corner_vertex[f][2]];
    area_3d += 0.5 * (b - a).cross(c - a).norm();
    area_uv += packing::uv_face_area(corner_uv, int(f));
  }
  if(!(area_uv > 0.) || !(area_3d > 0.)) return false;
  const double scale = std::sqrt(area_3d / area_uv); // the mesh's UV at 3D scale
  std::vector<std::vector<std::array<Vector2, 3>>> corners(components.size());
  std::vector<std::vector<int>> faces(components.size());
  face_chart.assign(nf, -1);
  for(std::size_t f = 0; f < nf; ++f) // in face order, as the charts' shapes were always read
  {
    corners[std::size_t(label[f])].push_back(uv[f]);
    faces[std::size_t(label[f])].push_back(int(f));
  }
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    for(int f : faces[c]) face_chart[f] = int(charts.size());
    charts.push_back({chart_shape(corners[c], scale), mesh});
  }
  return true;
}

/// Writes into the copy `to` (a scene mesh stacked on `from`, of the same
/// connectivity, so that face f, corner k and edge e are the same in both
/// indexings) the UVs and seam flags of `from`.
template <typename Surface, typename SceneAtlasMesh>
void copy_stacked_outputs(const Surface& from_surface, const SceneAtlasMesh& from, const Surface& to_surface,
                          const SceneAtlasMesh& to)
{
  for(std::size_t fe = 0; fe < 3 * to_surface.number_of_faces(); ++fe)
  {
    const auto uv = get(from.uvmap, from_surface.corner_halfedge[fe / 3][fe % 3]);
    put(to.uvmap, to_surface.corner_halfedge[fe / 3][fe % 3], uv);
    if(to_surface.twin[fe] < 0) put(to.uvmap, opposite(to_surface.face_edge_halfedge(int(fe)), *to.mesh), uv);
  }
  for(std::size_t e = 0; e < to_surface.edges.size(); ++e)
    put(to.seam_edge_map, to_surface.edges[e], bool(get(from.seam_edge_map, from_surface.edges[e])));
}

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
///
/// Finds the meshes of a scene that are copies of an earlier one (stacked
/// parts): the same faces over the same vertex numbering (the order of
/// `vertices(mesh)` and `faces(mesh)`, vertices in no face left out), and
/// vertices that a rotation and a translation (the least-squares fit,
/// Kabsch; no reflection) move onto the original's within
/// `stacking_tolerance` times the original's bounding box diagonal. A caller
/// may unwrap only the originals, then give `stacked_on` to
/// `pack_scene_atlas()` as its `instance_of`: every copy gets its original's
/// UVs and seams.
///
/// \tparam TriangleMesh a model of `FaceGraph` made of triangles
/// \param meshes the meshes (not owned)
/// \param stacked_on output: per mesh, the index of the first earlier mesh it is a copy of, itself if none
///   (an original is never a copy)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{stacking_tolerance}
///     \cgalParamDescription{the largest distance between a vertex of the original and its
///       counterpart of the copy moved onto it, relative to the original's bounding box diagonal}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`1e-4`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`, `ERROR_EMPTY_MESH` (no mesh, a null pointer or a mesh without face),
///   `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATE`, `ERROR_NON_MANIFOLD`,
///   `ERROR_WRONG_PARAMETER` (the tolerance out of range)
/// \pre none (the meshes are checked)
/// \post on success, `stacked_on[m] <= m` and `stacked_on[stacked_on[m]] == stacked_on[m]`;
///   on error, `stacked_on` is left unchanged
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code find_stacked_meshes(const std::vector<const TriangleMesh*>& meshes, std::vector<int>& stacked_on,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ic = internal::cut;
  const double tolerance = choose_parameter(get_parameter(np, internal_np::stacking_tolerance), 1e-4);
  if(!(tolerance >= 0.) || !std::isfinite(tolerance)) return ERROR_WRONG_PARAMETER;
  if(meshes.empty()) return ERROR_EMPTY_MESH;
  std::vector<ic::Indexed_surface<TriangleMesh>> surfaces(meshes.size());
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    if(meshes[m] == nullptr) return ERROR_EMPTY_MESH;
    const Error_code indexing = ic::to_error_code(
      ic::index_surface(*meshes[m], ic::vertex_points(*meshes[m], CGAL::parameters::default_values()), surfaces[m]));
    if(indexing != OK) return indexing;
  }
  std::vector<int> found;
  if(!ic::stacked_originals(surfaces, {}, tolerance, found)) return ERROR_WRONG_PARAMETER;
  stacked_on.swap(found);
  return OK;
}

/// \ingroup PkgCutParameterizationRef
///
/// Packs the charts of several already unwrapped meshes (for instance by
/// `cut_and_parameterize()`) into one atlas, or into pages of one size when
/// one page is not enough, all at one texel density: each mesh's UVs are
/// scaled so that their total area equals its 3D area, then every chart is
/// moved by a rotation and a translation and all by one common scale, the
/// texels per unit of 3D length. Charts are packed by their shape (their
/// rasters at the page's resolution, turned by multiples of 90°; at the
/// largest density of a few hundred charts at most, also turned by free
/// angles, kept where the density is larger). All the charts of a mesh go
/// to one page.
///
/// Stacked parts: a mesh that is an instance of another (`instance_of`) or
/// found to be a copy of an earlier one (`stacking_tolerance`, see
/// `find_stacked_meshes()`) is not packed: it gets the UVs and seams of its
/// original, corner by corner, so that the copies share the original's
/// texels (the packed area is that of the originals; its own UVs and seams
/// are not read). A mirror image is never found to be a copy: a texture would
/// appear mirrored on it (and a normal map's tangent frame would flip).
///
/// \tparam SceneAtlasMesh `Scene_atlas_mesh<TriangleMesh, SeamEdgeMap, HalfedgeUVMap>`
///   (`make_scene_atlas_mesh()`), with `SeamEdgeMap` a `ReadablePropertyMap` from edges to
///   `bool` and `HalfedgeUVMap` a `ReadWritePropertyMap` from halfedges to a 2D point
///
/// \param meshes the meshes, their seams and UVs; the UVs are replaced by
///   those of the atlas (in [0,1]² of the mesh's page)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{texture_size}
///     \cgalParamDescription{texels per side of a page}
///     \cgalParamType{`int`, ≥ 1}
///     \cgalParamDefault{`1024`}
///   \cgalParamNEnd
///   \cgalParamNBegin{padding}
///     \cgalParamDescription{gap in texels between charts (of any meshes of a page) and to the
///       page's sides, rounded up to whole texels}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texels_per_unit}
///     \cgalParamDescription{texels per unit of 3D length; meshes go on as many pages as
///       needed; 0: the largest density at which every chart fits one page}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{instance_of}
///     \cgalParamDescription{per mesh, the index of the mesh it is an instance of (the same
///       faces over the same vertex numbering, e.g. two nodes of a glTF scene that use one mesh),
///       whose texels it shares whatever its vertices' positions; -1 (or its own index): none.
///       Chains are followed to their first mesh}
///     \cgalParamType{`std::vector<int>`, empty or of the size of `meshes`}
///     \cgalParamDefault{no instance}
///   \cgalParamNEnd
///   \cgalParamNBegin{stacking_tolerance}
///     \cgalParamDescription{given, every mesh that is not an instance is compared with the
///       earlier originals: one of the same connectivity whose vertices a rotation and a
///       translation move onto its own within this distance, relative to its bounding box
///       diagonal, is stacked on it (`find_stacked_meshes()`)}
///     \cgalParamType{`double`, ≥ 0 and finite (e.g. `1e-4`)}
///     \cgalParamDefault{no detection}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_charts_for_packing}
///     \cgalParamDescription{given, every chart whose UV area is less than this fraction of the area
///       of its minimum-area bounding rectangle is cut, before packing, by straight lines across it
///       (recursive bisection along its rectangle's or principal axes, the cut that lowers the
///       pieces' rectangle area most net of a cost for its length and for each piece) into pieces
///       that fill more: each piece keeps the chart's UVs (no flip, no overlap, E_d unchanged), the
///       cuts are written as seams (interior edges; `SeamEdgeMap` must then be writable to get
///       them); the result's `added_charts` and `added_seam_length` (E_s added) report them}
///     \cgalParamType{`double`, in (0, 1] (e.g. `0.5`)}
///     \cgalParamDefault{charts never cut}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `error` `OK`, or `ERROR_EMPTY_MESH` (no mesh or a mesh without
///   face), `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATE`,
///   `ERROR_NON_MANIFOLD`, `ERROR_WRONG_PARAMETER` (a parameter out of range,
///   a UV that is not finite or a mesh of zero UV area, the charts of a mesh
///   that do not fit one page at the given density, or an `instance_of` of the
///   wrong size, with an index out of range, a cycle, or an instance whose
///   connectivity differs from its original's)
///
/// \pre every mesh is a model of `FaceGraph` made of triangles, and the UV map
///   of every mesh that is not stacked on another
///   holds one UV map of it whose charts are the connected components of its
///   faces cut along the seams (as `cut_and_parameterize()` leaves them)
/// \pre with stacked copies, `SeamEdgeMap` is also a `WritablePropertyMap` (the
///   copies' seams are written)
/// \post on error, every UV map is left unchanged
/// \post on success: every UV lies in [0,1]²; the charts of the meshes of one
///   page are at least `padding` texels apart (never touching); each chart
///   is moved by a similarity (no mirror), all at `texels_per_unit`; the result
///   depends on the input only; every stacked copy has, at each corner and
///   edge, the UV and seam flag of its original's, and its original's page
template <typename SceneAtlasMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Scene_atlas_result pack_scene_atlas(const std::vector<SceneAtlasMesh>& meshes,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ic = internal::cut;
  using TriangleMesh = std::remove_cv_t<std::remove_pointer_t<decltype(SceneAtlasMesh::mesh)>>;
  using Surface = ic::Indexed_surface<TriangleMesh>;
  Scene_atlas_result result;
  const int texture_size = choose_parameter(get_parameter(np, internal_np::texture_size), 1024);
  const double padding = choose_parameter(get_parameter(np, internal_np::padding), 2.);
  const double texels_per_unit = choose_parameter(get_parameter(np, internal_np::texels_per_unit), 0.);
  if(!(texture_size >= 1) || !(padding >= 0.) || !std::isfinite(padding) || !(texels_per_unit >= 0.) ||
     !std::isfinite(texels_per_unit))
  { result.error = ERROR_WRONG_PARAMETER; return result; }
  if(meshes.empty()) { result.error = ERROR_EMPTY_MESH; return result; }
  std::optional<double> stacking_tolerance;
  ic::read_named_parameter(np, internal_np::stacking_tolerance, stacking_tolerance);
  if(stacking_tolerance && (!(*stacking_tolerance >= 0.) || !std::isfinite(*stacking_tolerance)))
  { result.error = ERROR_WRONG_PARAMETER; return result; }
  const std::vector<int> instance_of = choose_parameter(get_parameter(np, internal_np::instance_of), std::vector<int>());
  std::optional<double> split_fill;
  ic::read_named_parameter(np, internal_np::split_charts_for_packing, split_fill);
  if(split_fill && !(*split_fill > 0. && *split_fill <= 1.)) { result.error = ERROR_WRONG_PARAMETER; return result; }

  std::vector<Surface> surfaces(meshes.size());
  std::vector<std::vector<int>> face_chart(meshes.size());
  std::vector<ic::Scene_chart> charts;
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const TriangleMesh& mesh = *meshes[m].mesh;
    const Error_code indexing = ic::to_error_code(
      ic::index_surface(mesh, ic::vertex_points(mesh, CGAL::parameters::default_values()), surfaces[m]));
    if(indexing != OK) { result.error = indexing; return result; }
  }
  std::vector<int> original; // per mesh, the mesh whose texels it shares
  if(!ic::stacked_originals(surfaces, instance_of, stacking_tolerance, original))
  { result.error = ERROR_WRONG_PARAMETER; return result; }
  std::vector<std::vector<char>> added_seams(meshes.size());
  result.added_charts.assign(meshes.size(), 0);
  result.added_seam_length.assign(meshes.size(), 0.);
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    if(original[m] != int(m)) continue; // a copy: its charts are its original's
    const Surface& s = surfaces[m];
    std::vector<char> seams(s.edges.size());
    for(std::size_t e = 0; e < s.edges.size(); ++e) seams[e] = get(meshes[m].seam_edge_map, s.edges[e]) ? 1 : 0;
    std::vector<ic::Vector2> uv;
    if(!ic::read_corner_uvs(s, meshes[m].uvmap, uv)) { result.error = ERROR_WRONG_PARAMETER; return result; }
    if(split_fill)
    {
      added_seams[m] = ic::packing::packing_cuts(s, seams, {}, uv, *split_fill, result.added_charts[m]);
      double area = 0.; // E_s's unit: the radius of the disk of the mesh's area
      for(const auto& cv : s.corner_vertex)
        area += 0.5 * (s.points[cv[1]] - s.points[cv[0]]).cross(s.points[cv[2]] - s.points[cv[0]]).norm();
      result.added_seam_length[m] =
        area > 0. ? ic::packing::flagged_length(s, added_seams[m]) / std::sqrt(area / M_PI) : 0.;
      for(std::size_t e = 0; e < s.edges.size(); ++e) seams[e] |= added_seams[m][e];
    }
    if(!ic::read_scene_charts(s, seams, uv, int(m), charts, face_chart[m]))
    { result.error = ERROR_WRONG_PARAMETER; return result; }
  }
  ic::Scene_layout layout;
  if(!ic::layout_scene(charts, int(meshes.size()), texture_size, padding, texels_per_unit, layout))
  { result.error = ERROR_WRONG_PARAMETER; return result; }

  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    if(original[m] != int(m)) continue; // written from its original below
    const Surface& s = surfaces[m];
    using Point_2 = typename boost::property_traits<decltype(meshes[m].uvmap)>::value_type;
    std::vector<std::size_t> next(charts.size(), 0); // next triangle of each chart, in face order
    std::vector<Point_2> uv(3 * s.number_of_faces());
    for(std::size_t f = 0; f < s.number_of_faces(); ++f)
    {
      const int c = face_chart[m][f];
      const auto& t = charts[c].shape.triangles[next[c]++];
      for(int k = 0; k < 3; ++k)
      {
        const ic::Vector2 p = ic::scene_uv(layout, texture_size, c, t[k]);
        uv[3 * f + k] = Point_2(p.x(), p.y());
      }
    }
    for(std::size_t fe = 0; fe < uv.size(); ++fe)
    {
      put(meshes[m].uvmap, s.corner_halfedge[fe / 3][fe % 3], uv[fe]);
      if(s.twin[fe] < 0) put(meshes[m].uvmap, opposite(s.face_edge_halfedge(int(fe)), *meshes[m].mesh), uv[fe]);
    }
    if constexpr(!std::is_same_v<typename boost::property_traits<decltype(meshes[m].seam_edge_map)>::category,
                                 boost::readable_property_map_tag>)
      for(std::size_t e = 0; e < added_seams[m].size(); ++e)
        if(added_seams[m][e]) put(meshes[m].seam_edge_map, s.edges[e], true);
  }
  for(std::size_t m = 0; m < meshes.size(); ++m)
    if(original[m] != int(m))
    {
      ic::copy_stacked_outputs(surfaces[std::size_t(original[m])], meshes[std::size_t(original[m])], surfaces[m],
                               meshes[m]);
      layout.page_of_mesh[m] = layout.page_of_mesh[std::size_t(original[m])];
      result.added_charts[m] = result.added_charts[std::size_t(original[m])];
      result.added_seam_length[m] = result.added_seam_length[std::size_t(original[m])];
    }
  result.number_of_pages = layout.pages;
  result.texels_per_unit = layout.texels_per_unit;
  result.page = layout.page_of_mesh;
  result.stacked_on = original;
  result.number_of_charts = charts.size();
  return result;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
