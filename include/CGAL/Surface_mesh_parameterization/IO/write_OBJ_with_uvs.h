// Writes a mesh and a per-corner UV map as a Wavefront OBJ with `vt` lines.
// CGAL's own OBJ writer has no texture coordinates, hence this file.
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_IO_WRITE_OBJ_WITH_UVS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_IO_WRITE_OBJ_WITH_UVS_H

#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
///
/// Writes `mesh` with its UV map to `os` in the OBJ format:
/// - one `v x y z` line per vertex, in the order of `vertices(mesh)`;
/// - one `vt u v` line per distinct (vertex, UV) pair, so corners that share
///   a UV across a non-seam edge share one texture vertex and seams split it;
/// - one `f v/vt ...` line per face, in the order of `faces(mesh)`, starting
///   at the target of `halfedge(f, mesh)` (the order CGAL's own writers use).
///
/// Indices are 1-based. Coordinates are written with enough digits to be
/// read back exactly, unless `stream_precision` is given.
///
/// \tparam TriangleMesh a model of `FaceGraph` (faces may have any degree)
/// \tparam HalfedgeUVMap a `ReadablePropertyMap` whose value type is a 2D point and
///   whose key is either a halfedge (the UV of the corner at `target(h)` in
///   `face(h)`, as written by `cut_and_parameterize()`) or a vertex (one UV
///   per vertex: a mesh without seams)
///
/// \param os the output stream
/// \param mesh the mesh
/// \param uvmap the UV map
/// \tparam NamedParameters a sequence of named parameters
/// \param np an optional sequence of %CGAL's named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions written in the `v` lines}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{only used to find a vertex's texture vertices; OBJ indices follow
///       the order of `vertices(mesh)`}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or a dynamic one}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{digits written for coordinates}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`std::numeric_limits<double>::max_digits10`, which reads back exactly}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `true` if the stream is still good after writing
///
/// \pre `uvmap` gives a UV to every corner of every face of `mesh` (to every vertex if keyed by vertices)
/// \post the precision of `os` is restored; `mesh` and `uvmap` are unchanged
template <typename TriangleMesh, typename HalfedgeUVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_OBJ_with_uvs(std::ostream& os, const TriangleMesh& mesh, HalfedgeUVMap uvmap,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  const auto vpm = internal::cut::vertex_points(mesh, np);
  const auto vimap = CGAL::get_initialized_vertex_index_map(mesh, np);

  const auto old_precision = os.precision();
  if(is_default_parameter<NamedParameters, CGAL::internal_np::stream_precision_t>::value)
    os.precision(std::numeric_limits<double>::max_digits10);
  else
    CGAL::set_stream_precision_from_NP(os, np);

  // The index map may have holes (a Surface_mesh with removed elements):
  // number vertices in the order they are written instead.
  std::size_t index_bound = 0;
  for(auto v : vertices(mesh))
    index_bound = (std::max)(index_bound, std::size_t(get(vimap, v)) + 1);
  std::vector<std::size_t> obj_index(index_bound, 0);
  std::size_t number_of_vertices = 0;
  for(auto v : vertices(mesh))
  {
    obj_index[get(vimap, v)] = ++number_of_vertices;
    const auto& p = get(vpm, v);
    os << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' '
       << CGAL::to_double(p.z()) << '\n';
  }

  // Texture vertices already written, per mesh vertex: few per vertex (one
  // per chart the vertex belongs to), so a linear scan is enough. Exact
  // comparison is right: the UV map gives bitwise-equal values to corners
  // that share a UV.
  using UV = std::pair<double, double>;
  std::vector<std::vector<std::pair<UV, std::size_t>>> written(index_bound);
  std::size_t number_of_texture_vertices = 0;
  std::vector<std::pair<std::size_t, std::size_t>> face_corners; // (v, vt), 1-based
  std::vector<std::size_t> face_sizes;
  face_sizes.reserve(num_faces(mesh));

  for(auto f : faces(mesh))
  {
    std::size_t degree = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const auto uv = internal::cut::corner_uv(mesh, uvmap, h);
      const UV key(uv.x(), uv.y());
      const std::size_t vi = get(vimap, target(h, mesh));
      std::size_t vt = 0;
      for(const auto& entry : written[vi])
        if(entry.first == key) { vt = entry.second; break; }
      if(vt == 0)
      {
        vt = ++number_of_texture_vertices;
        written[vi].emplace_back(key, vt);
        os << "vt " << key.first << ' ' << key.second << '\n';
      }
      face_corners.emplace_back(obj_index[vi], vt);
      ++degree;
    }
    face_sizes.push_back(degree);
  }

  std::size_t c = 0;
  for(std::size_t degree : face_sizes)
  {
    os << 'f';
    for(std::size_t i = 0; i < degree; ++i, ++c)
      os << ' ' << face_corners[c].first << '/' << face_corners[c].second;
    os << '\n';
  }

  os.precision(old_precision);
  return os.good();
}

/// \ingroup PkgCutParameterizationRef
///
/// Same as above, writing to the file `filename` (created or overwritten).
///
/// \tparam TriangleMesh a model of `FaceGraph` (faces may have any degree)
/// \tparam HalfedgeUVMap as above
/// \tparam NamedParameters a sequence of named parameters
/// \param filename the file written
/// \param mesh the mesh
/// \param uvmap the UV map
/// \param np an optional sequence of %CGAL's named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions written in the `v` lines}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{only used to find a vertex's texture vertices; OBJ indices follow
///       the order of `vertices(mesh)`}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or a dynamic one}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{digits written for coordinates}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`std::numeric_limits<double>::max_digits10`, which reads back exactly}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `false` if the file cannot be opened or written
///
/// \pre as above
/// \post on `true`, the file holds the whole mesh
template <typename TriangleMesh, typename HalfedgeUVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_OBJ_with_uvs(const std::string& filename, const TriangleMesh& mesh, HalfedgeUVMap uvmap,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  std::ofstream os(filename);
  if(!os) return false;
  if(!write_OBJ_with_uvs(os, mesh, uvmap, np)) return false;
  os.close();
  return !os.fail();
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
