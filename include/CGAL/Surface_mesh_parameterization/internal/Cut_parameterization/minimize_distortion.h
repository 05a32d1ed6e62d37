// Weighted symmetric Dirichlet minimization on a chart mesh, and the checks
// shared by the public entry points.
#ifndef CGAL_SMP_CUT_INTERNAL_MINIMIZE_DISTORTION_H
#define CGAL_SMP_CUT_INTERNAL_MINIMIZE_DISTORTION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Distortion_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Projected_newton_solver.h>

#include <memory>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// A distortion solver bound to one chart mesh connectivity: the symbolic
/// factorization is reused by every call to minimize(); weights may change.
class Distortion_minimizer
{
  std::vector<double> weights_;
  Distortion_term term_;
  Projected_newton_solver solver_;

public:
  Distortion_minimizer(const Chart_mesh& mesh, std::vector<double> weights)
    : weights_(std::move(weights)), term_(mesh, weights_),
      solver_({&term_}, 2 * mesh.number_of_vertices)
  {}

  std::vector<double>& weights() { return weights_; }

  Newton_report minimize(UV_vector& x, int max_iterations, double tolerance)
  {
    Newton_settings settings;
    settings.max_iterations = max_iterations;
    settings.tolerance = tolerance;
    settings.energy_scale = term_.weighted_area();
    return solver_.minimize(x, settings);
  }
};

/// E_d of METHOD.md on the chart mesh: area-weighted mean of s1²+s2²+s1⁻²+s2⁻².
inline double mean_distortion(const Chart_mesh& mesh, const UV_vector& x)
{
  double sum = 0., area = 0.;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    sum += mesh.area[f] * symmetric_dirichlet_measure(mesh.jacobian(x, f));
    area += mesh.area[f];
  }
  return sum / area;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
