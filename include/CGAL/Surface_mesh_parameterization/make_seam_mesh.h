#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MAKE_SEAM_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MAKE_SEAM_MESH_H

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
///
/// Makes a seam edge map and a seam vertex map consistent with what
/// `CGAL::Seam_mesh` expects: edges on the mesh's boundary are unflagged
/// (CGAL ignores them as seams), and exactly the vertices of the remaining
/// seam edges are flagged. Returns the number of seam edges.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam SeamEdgeMap a `ReadWritePropertyMap`, edge → `bool`
/// \tparam SeamVertexMap a `WritablePropertyMap`, vertex → `bool`
/// \pre `seam_edge_map` is defined on every edge of `mesh`
/// \post no border edge is flagged in `seam_edge_map`; a vertex is flagged in
///   `seam_vertex_map` if and only if it is an end of a flagged edge
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
std::size_t normalize_seam_maps(const TriangleMesh& mesh, SeamEdgeMap seam_edge_map,
                                SeamVertexMap seam_vertex_map)
{
  for(auto v : vertices(mesh)) put(seam_vertex_map, v, false);
  std::size_t n = 0;
  for(auto e : edges(mesh))
  {
    if(!get(seam_edge_map, e)) continue;
    if(is_border(e, mesh)) { put(seam_edge_map, e, false); continue; }
    ++n;
    put(seam_vertex_map, source(e, mesh), true);
    put(seam_vertex_map, target(e, mesh), true);
  }
  return n;
}

/// \ingroup PkgCutParameterizationRef
///
/// Builds the `CGAL::Seam_mesh` of `mesh` opened along the seams of
/// `seam_edge_map` (such as the seams found by `cut_and_parameterize()`), filling
/// `seam_vertex_map` and setting the seam mesh's seam counter, which CGAL
/// only updates through `add_seam()`. The UV map written by
/// `cut_and_parameterize()` (keyed by halfedges of `mesh`) is then a valid
/// vertex UV map of the seam mesh, for CGAL's parameterizers and I/O
/// (e.g. `Symmetric_dirichlet_parameterizer_3` through
/// `CGAL::Surface_mesh_parameterization::parameterize()`).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam SeamEdgeMap a `ReadWritePropertyMap`, edge → `bool`
/// \tparam SeamVertexMap a `ReadWritePropertyMap`, vertex → `bool`
/// \pre `mesh` is a triangle mesh; the maps outlive the seam mesh, which refers to them
/// \post the maps are normalized as by `normalize_seam_maps()`, and the seam
///   mesh's number of seam edges is that of `seam_edge_map`
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>
make_seam_mesh(const TriangleMesh& mesh, SeamEdgeMap seam_edge_map, SeamVertexMap seam_vertex_map)
{
  const std::size_t n = normalize_seam_maps(mesh, seam_edge_map, seam_vertex_map);
  CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> seam_mesh(mesh, seam_edge_map, seam_vertex_map);
  seam_mesh.set_seam_edges_number(n);
  return seam_mesh;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
