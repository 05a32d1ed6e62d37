// Tutte embedding of a disk: uniform weights, boundary on a circle whose area
// equals the mesh's area, boundary vertices spaced by 3D arc length. The
// result has no flipped face (Tutte's theorem) up to round-off.
#ifndef CGAL_SMP_CUT_INTERNAL_TUTTE_EMBEDDING_H
#define CGAL_SMP_CUT_INTERNAL_TUTTE_EMBEDDING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Edge_length_map = std::unordered_map<std::uint64_t, double>;

/// 3D length of every directed face edge (a, b) of the chart mesh.
inline Edge_length_map directed_edge_lengths(const Chart_mesh& mesh)
{
  Edge_length_map length;
  length.reserve(3 * mesh.number_of_faces());
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      length[directed_edge_key(mesh.faces[f][k], mesh.faces[f][(k+1)%3])] = mesh.edge_length(f, k);
  return length;
}

/// A boundary loop pinned on a circle.
struct Pinned_loop
{
  std::vector<int> vertices;
  Vector2 center = Vector2::Zero();
  double radius = 1.;
};

/// Where the boundary vertices go on their circle: spaced like their 3D arc
/// length, or evenly (the fallback when zero-length boundary edges make
/// arc-length spacing put two vertices on one point).
enum class Boundary_spacing { ARC_LENGTH, UNIFORM };

/// Writes the Tutte embedding into x: each loop on its circle, every other
/// vertex at the mean of its neighbours. Precondition: each connected
/// component has exactly one of the loops as its only boundary. Components
/// do not interact, so one solve embeds them all. False if the solve fails.
inline bool tutte_embedding(const Chart_mesh& mesh, const std::vector<Pinned_loop>& loops, Boundary_spacing spacing,
                            UV_vector& x)
{
  const int n = mesh.number_of_vertices;
  x.setZero(2 * n);
  std::vector<char> on_boundary(n, 0);
  const Edge_length_map length = directed_edge_lengths(mesh);
  for(const Pinned_loop& loop : loops)
  {
    const std::size_t m = loop.vertices.size();
    std::vector<double> lengths(m);
    double perimeter = 0.;
    for(std::size_t i = 0; i < m; ++i)
      perimeter += lengths[i] = spacing == Boundary_spacing::UNIFORM
                                  ? 1. : length.at(directed_edge_key(loop.vertices[i], loop.vertices[(i+1) % m]));
    double arc = 0.;
    for(std::size_t i = 0; i < m; ++i)
    {
      const double angle = 2. * M_PI * arc / perimeter;
      const int v = loop.vertices[i];
      x[2*v] = loop.center.x() + loop.radius * std::cos(angle);
      x[2*v+1] = loop.center.y() + loop.radius * std::sin(angle);
      on_boundary[v] = 1;
      arc += lengths[i];
    }
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

enum class Embedding_status { OK, NOT_DISKS, SOLVE_FAILED, FLIPPED };

/// Tutte embedding of a chart mesh whose components are all topological
/// disks, each on its own circle (of its own area), circles side by side.
/// Exact Tutte maps are flip-free, but boundary vertices that arc-length
/// spacing puts on one point (zero-length boundary edges) give zero-area
/// triangles: then the boundary is spaced evenly. FLIPPED if round-off still
/// leaves a face without positive area.
inline Embedding_status disk_charts_embedding(const Chart_mesh& mesh, UV_vector& x)
{
  int number_of_charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(mesh, number_of_charts);
  std::vector<int> chart_of_vertex(mesh.number_of_vertices, -1);
  std::vector<double> chart_area(number_of_charts, 0.);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    for(int v : mesh.faces[f]) chart_of_vertex[v] = chart_of_face[f];
    chart_area[chart_of_face[f]] += mesh.area[f];
  }
  std::vector<Pinned_loop> pinned(number_of_charts);
  std::vector<int> loops_per_chart(number_of_charts, 0);
  for(std::vector<int>& loop : boundary_loops(mesh))
  {
    const int c = chart_of_vertex[loop.front()];
    if(++loops_per_chart[c] > 1) return Embedding_status::NOT_DISKS;
    pinned[c].vertices = std::move(loop);
  }
  double left = 0.;
  for(int c = 0; c < number_of_charts; ++c)
  {
    if(loops_per_chart[c] != 1 || pinned[c].vertices.size() < 3) return Embedding_status::NOT_DISKS;
    pinned[c].radius = std::sqrt(chart_area[c] / M_PI);
    pinned[c].center = Vector2(left + pinned[c].radius, 0.);
    left += tuning::tutte_circle_spacing * pinned[c].radius;
  }
  for(Boundary_spacing spacing : {Boundary_spacing::ARC_LENGTH, Boundary_spacing::UNIFORM})
  {
    if(!tutte_embedding(mesh, pinned, spacing, x)) return Embedding_status::SOLVE_FAILED;
    if(number_of_flipped_faces(mesh, x) == 0) return Embedding_status::OK;
  }
  return Embedding_status::FLIPPED;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
