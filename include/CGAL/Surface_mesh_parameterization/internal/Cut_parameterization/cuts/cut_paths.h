// A cut path, the boundary vertices of a cut and the 3D length of its seams:
// what the stages that cut share.
#ifndef CGAL_SMP_CUT_INTERNAL_CUT_PATHS_H
#define CGAL_SMP_CUT_INTERNAL_CUT_PATHS_H

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Cut_path
{
  std::vector<int> edges; // indices into surface.edges
  double length = 0.;     // 3D length of the edges not already on the boundary
};

/// Boundary vertices of the cut mesh (on a border or cut edge).
template <typename Surface>
std::vector<char> cut_boundary_vertices(const Surface& surface, const std::vector<char>& is_cut)
{
  std::vector<char> on_boundary(surface.number_of_vertices(), 0);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < 0 || is_cut[surface.edge_of[fe]])
      on_boundary[surface.edge_source(fe)] = on_boundary[surface.edge_target(fe)] = 1;
  return on_boundary;
}

/// 3D length of the cut edges that are not on the mesh's border.
template <typename Surface>
double seam_length_3d(const Surface& surface, const std::vector<char>& is_cut)
{
  double length = 0.;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] > fe && is_cut[surface.edge_of[fe]]) length += surface.edge_length(fe);
  return length;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
