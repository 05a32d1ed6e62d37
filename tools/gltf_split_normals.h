// Split normals of a glTF primitive as seams, for uv_unwrap --hard-edge-angle:
// the primitive's vertices are welded by position (gltf_io::read_triangles),
// so an edge whose two triangles reach a shared position through glTF
// vertices of different NORMAL is where the file splits its normals: a hard
// edge, flagged as a seam beside the library's dihedral rule (as
// split_normals.h does for OBJ's `vn`).
#ifndef CUT_PARAM_TOOLS_GLTF_SPLIT_NORMALS_H
#define CUT_PARAM_TOOLS_GLTF_SPLIT_NORMALS_H

#include "gltf_io.h"
#include "split_normals.h"

#include <array>
#include <cstddef>

namespace split_normals {

/// Flags in `seams` the interior edges of `mesh` (built from `t`: face i is
/// triangle i, vertex i is point i) where the NORMAL of primitive `ref`
/// differs between the two triangles' corners at either end. Returns the
/// number flagged; 0 without NORMAL.
template <typename SeamMap>
std::size_t flag_gltf_split_normal_edges(const gltf_io::Document& doc, gltf_io::Primitive_ref ref,
                                         const gltf_io::Triangles& t, const Mesh& mesh, SeamMap seams)
{
  const auto& prim = doc.model.meshes[std::size_t(ref.mesh)].primitives[std::size_t(ref.primitive)];
  const auto found = prim.attributes.find("NORMAL");
  if(found == prim.attributes.end()) return 0;
  const gltf_io::detail::Accessor_view normals(doc.model, found->second);
  if(normals.components() != 3) return 0;
  // the normal of triangle f's corner at point v
  auto normal_at = [&](std::size_t f, std::size_t v) {
    for(std::size_t k = 0; k < 3; ++k)
      if(t.faces[f][k] == v && t.corners[f][k] < normals.count())
      {
        const std::size_t i = t.corners[f][k];
        return std::array<double, 3>{normals.real(i, 0), normals.real(i, 1), normals.real(i, 2)};
      }
    return std::array<double, 3>{0., 0., 0.}; // none: no split said
  };
  std::size_t flagged = 0;
  for(Mesh::Edge_index e : edges(mesh))
  {
    if(is_border(e, mesh)) continue;
    const Mesh::Halfedge_index h = halfedge(e, mesh);
    const std::size_t f = std::size_t(face(h, mesh)), g = std::size_t(face(opposite(h, mesh), mesh));
    if(f >= t.faces.size() || g >= t.faces.size()) continue;
    bool split = false;
    for(Mesh::Vertex_index v : {source(h, mesh), target(h, mesh)})
      split = split || differ(normal_at(f, std::size_t(v)), normal_at(g, std::size_t(v)));
    if(split && !get(seams, e))
    {
      put(seams, e, true);
      ++flagged;
    }
  }
  return flagged;
}

} // namespace split_normals

#endif
