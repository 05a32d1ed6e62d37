// Distortion per face and its excess per vertex: where the map is most
// distorted (greedy splits cut there, seam merges zip where it is least).
#ifndef CGAL_SMP_CUT_INTERNAL_VERTEX_DISTORTION_H
#define CGAL_SMP_CUT_INTERNAL_VERTEX_DISTORTION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The symmetric Dirichlet energy of each face of `chart` under `x`.
inline std::vector<double> face_distortions(const Chart_mesh& chart, const UV_vector& x)
{
  std::vector<double> psi(chart.number_of_faces());
  for(std::size_t f = 0; f < psi.size(); ++f) psi[f] = symmetric_dirichlet(chart.jacobian(x, f));
  return psi;
}

/// Per surface vertex: Σ A_f (e_f − 4) / 3 over its faces, e_f the E_d
/// integrand of face f in the map `x` of the chart mesh.
template <typename Surface>
std::vector<double> vertex_distortion_excess(const Surface& surface, const Chart_mesh& chart, const UV_vector& x)
{
  std::vector<double> excess(surface.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
  {
    const double e = chart.area[f] * (symmetric_dirichlet_measure(chart.jacobian(x, f)) - 4.) / 3.;
    for(int v : surface.corner_vertex[f]) excess[v] += e;
  }
  return excess;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
