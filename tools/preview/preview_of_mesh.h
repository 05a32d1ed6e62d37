// A CGAL mesh and its UV map copied into the preview's plain arrays.
#ifndef UV_PREVIEW_PREVIEW_OF_MESH_H
#define UV_PREVIEW_PREVIEW_OF_MESH_H

#include "preview.h"

#include <CGAL/boost/graph/iterator.h>

#include <array>

/// Appends `mesh` (triangles, indices contiguous as in a freshly read
/// `Surface_mesh`) to `preview`: its points, faces, corner UVs (`uvmap`,
/// shifted by `u_offset` along u: a page drawn beside the others) and seam
/// edges (`seams`). Faces keep the mesh's order, so per-face data can
/// follow in the same order.
template <typename Mesh, typename UVMap, typename SeamMap>
void append_to_preview(Preview_mesh& preview, const Mesh& mesh, const UVMap& uvmap, const SeamMap& seams,
                       double u_offset = 0.)
{
  const int first = int(preview.points.size());
  for(auto vd : vertices(mesh))
  {
    const auto& p = mesh.point(vd);
    preview.points.push_back({p.x(), p.y(), p.z()});
  }
  for(auto f : faces(mesh))
  {
    std::array<int, 3> corners;
    std::array<std::array<double, 2>, 3> uvs;
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      corners[k] = first + int(target(h, mesh).idx());
      uvs[k] = {get(uvmap, h).x() + u_offset, get(uvmap, h).y()};
      ++k;
    }
    preview.faces.push_back(corners);
    preview.corner_uv.push_back(uvs);
  }
  for(auto e : edges(mesh))
    if(get(seams, e))
      preview.seam_edges.emplace_back(first + int(source(e, mesh).idx()), first + int(target(e, mesh).idx()));
}

#endif
