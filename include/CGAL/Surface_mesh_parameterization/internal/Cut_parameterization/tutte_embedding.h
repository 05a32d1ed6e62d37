// Tutte embedding of a disk: uniform weights, boundary on a circle whose area
// equals the mesh's area, boundary vertices spaced by 3D arc length. The
// result has no flipped face (Tutte's theorem) up to round-off.
#ifndef CGAL_SMP_CUT_INTERNAL_TUTTE_EMBEDDING_H
#define CGAL_SMP_CUT_INTERNAL_TUTTE_EMBEDDING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Sparse_cholesky.h>

#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// 3D lengths of the boundary edges leaving each vertex of `loop`.
inline std::vector<double> boundary_edge_lengths(const Chart_mesh& mesh, const std::vector<int>& loop)
{
  std::unordered_map<std::uint64_t, double> length;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      length[directed_edge_key(mesh.faces[f][k], mesh.faces[f][(k+1)%3])] = mesh.edge_length(f, k);
  std::vector<double> lengths(loop.size());
  for(std::size_t i = 0; i < loop.size(); ++i)
    lengths[i] = length[directed_edge_key(loop[i], loop[(i+1) % loop.size()])];
  return lengths;
}

/// Writes the Tutte embedding into x. Precondition: `loop` is the only
/// boundary loop of a connected mesh. Returns false if the linear solve fails.
inline bool tutte_embedding(const Chart_mesh& mesh, const std::vector<int>& loop, UV_vector& x)
{
  const int n = mesh.number_of_vertices;
  x.setZero(2 * n);
  const std::vector<double> lengths = boundary_edge_lengths(mesh, loop);
  double perimeter = 0.;
  for(double l : lengths) perimeter += l;
  const double radius = std::sqrt(mesh.total_area() / M_PI);
  std::vector<char> on_boundary(n, 0);
  double arc = 0.;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const double angle = 2. * M_PI * arc / perimeter;
    x[2*loop[i]] = radius * std::cos(angle);
    x[2*loop[i]+1] = radius * std::sin(angle);
    on_boundary[loop[i]] = 1;
    arc += lengths[i];
  }

  std::vector<int> interior_index(n, -1);
  int m = 0;
  for(int v = 0; v < n; ++v) if(!on_boundary[v]) interior_index[v] = m++;
  if(m == 0) return true;

  std::unordered_set<std::uint64_t> edges; // each undirected edge once
  for(const auto& t : mesh.faces)
    for(int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k+1)%3];
      edges.insert(directed_edge_key((std::min)(a, b), (std::max)(a, b)));
    }
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 2);
  for(std::uint64_t key : edges)
  {
    const int a = int(key >> 32), b = int(key & 0xffffffffu);
    for(int side = 0; side < 2; ++side)
    {
      const int i = side ? b : a, j = side ? a : b;
      if(interior_index[i] < 0) continue;
      entries.emplace_back(interior_index[i], interior_index[i], 1.);
      if(interior_index[j] >= 0)
      {
        if(interior_index[j] < interior_index[i])
          entries.emplace_back(interior_index[i], interior_index[j], -1.);
      }
      else
      {
        rhs(interior_index[i], 0) += x[2*j];
        rhs(interior_index[i], 1) += x[2*j+1];
      }
    }
  }
  Sparse_matrix laplacian(m, m);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Sparse_cholesky solver;
  if(!solver.factorize(laplacian)) return false;
  for(int c = 0; c < 2; ++c)
  {
    Eigen::VectorXd solution;
    if(!solver.solve(rhs.col(c), solution)) return false;
    for(int v = 0; v < n; ++v)
      if(interior_index[v] >= 0) x[2*v+c] = solution[interior_index[v]];
  }
  return true;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
