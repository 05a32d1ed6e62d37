// Stacked parts of a scene atlas: meshes that are copies of one mesh (the
// same faces over the same vertex numbering, placed by a rigid motion, as
// the instances of a glTF scene or a level's repeated props) share the
// texels of the first one instead of being packed again. A copy is told
// (instance_of) or found: same connectivity, and the best rotation and
// translation (Kabsch: the SVD of the cross-covariance, its determinant kept
// at +1 so that a mirror image is not a copy) moves its vertices onto the
// original's within a tolerance relative to the original's size.
#ifndef CGAL_SMP_CUT_INTERNAL_STACKED_MESHES_H
#define CGAL_SMP_CUT_INTERNAL_STACKED_MESHES_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Same faces over the same vertex numbering (corner k of face f at the same vertex index).
template <typename Surface>
bool same_connectivity(const Surface& a, const Surface& b)
{
  return a.number_of_vertices() == b.number_of_vertices() && a.corner_vertex == b.corner_vertex;
}

/// The largest distance from a vertex of `original` to its counterpart of
/// `copy` moved by the rotation (no reflection) and translation that fit
/// them best in the least-squares sense.
/// \pre same_connectivity(copy, original)
template <typename Surface>
double rigid_fit_error(const Surface& copy, const Surface& original)
{
  const std::size_t n = original.number_of_vertices();
  Vector3 ca = Vector3::Zero(), cb = Vector3::Zero();
  for(std::size_t v = 0; v < n; ++v) { ca += copy.points[v]; cb += original.points[v]; }
  ca /= double(n);
  cb /= double(n);
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero(); // cross-covariance of the centred points
  for(std::size_t v = 0; v < n; ++v) h += (copy.points[v] - ca) * (original.points[v] - cb).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0. ? -1. : 1.; // a rotation, never a mirror
  const Eigen::Matrix3d rotation = svd.matrixV() * d * svd.matrixU().transpose();
  double error = 0.;
  for(std::size_t v = 0; v < n; ++v)
    error = (std::max)(error, (rotation * (copy.points[v] - ca) + cb - original.points[v]).norm());
  return error;
}

/// Length of the bounding box diagonal of `surface`.
template <typename Surface>
double bounding_box_diagonal(const Surface& surface)
{
  Vector3 lo = surface.points.front(), hi = lo;
  for(const Vector3& p : surface.points) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  return (hi - lo).norm();
}

/// Per surface, the surface whose texels it shares (itself if none):
/// `instance_of[m]` where given (>= 0 and not m; followed to the first mesh
/// of the chain), else, with a `tolerance`, the first earlier mesh that is
/// not a copy itself, has the same connectivity, and fits within
/// `tolerance` times its bounding box diagonal. False if `instance_of` has
/// another size than `surfaces` (and is not empty), an index out of range,
/// a cycle, or an instance whose connectivity differs from its original's.
template <typename Surface>
bool stacked_originals(const std::vector<Surface>& surfaces, const std::vector<int>& instance_of,
                       std::optional<double> tolerance, std::vector<int>& original)
{
  const int n = int(surfaces.size());
  if(!instance_of.empty() && int(instance_of.size()) != n) return false;
  original.assign(std::size_t(n), -1);
  for(int m = 0; m < n; ++m)
  {
    int root = m;
    for(int steps = 0; steps <= n; ++steps) // a chain longer than n is a cycle
    {
      const int next = instance_of.empty() ? -1 : instance_of[std::size_t(root)];
      if(next < 0 || next == root) break;
      if(next >= n || steps == n) return false;
      root = next;
    }
    if(root != m && !same_connectivity(surfaces[std::size_t(m)], surfaces[std::size_t(root)])) return false;
    original[std::size_t(m)] = root;
  }
  if(!tolerance) return true;
  // the candidates of a mesh: the originals with a face array of the same hash
  std::unordered_map<std::uint64_t, std::vector<int>> originals_of_hash;
  for(int m = 0; m < n; ++m)
  {
    const Surface& s = surfaces[std::size_t(m)];
    std::uint64_t hash = 1469598103934665603ull ^ std::uint64_t(s.number_of_vertices());
    for(const auto& c : s.corner_vertex)
      for(int v : c) hash = (hash ^ std::uint64_t(v)) * 1099511628211ull; // FNV-1a over the indices
    if(original[std::size_t(m)] != m) continue; // told already
    std::vector<int>& candidates = originals_of_hash[hash];
    for(int o : candidates)
      if(same_connectivity(s, surfaces[std::size_t(o)]) &&
         rigid_fit_error(s, surfaces[std::size_t(o)]) <= *tolerance * bounding_box_diagonal(surfaces[std::size_t(o)]))
      {
        original[std::size_t(m)] = o;
        break;
      }
    if(original[std::size_t(m)] == m) candidates.push_back(m);
  }
  for(int& o : original) o = original[std::size_t(o)]; // an instance of a mesh found to be a copy
  return true;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
