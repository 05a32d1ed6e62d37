// Weighted symmetric Dirichlet minimization on a chart mesh, and the checks
// shared by the public entry points.
#ifndef CGAL_SMP_CUT_INTERNAL_MINIMIZE_DISTORTION_H
#define CGAL_SMP_CUT_INTERNAL_MINIMIZE_DISTORTION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Bounding_box_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Distortion_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/Projected_newton_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/Proxy_quasi_newton_solver.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// A distortion solver bound to one chart mesh connectivity: the symbolic
/// factorization is reused by every call to minimize(); weights may change.
/// With `injective`, a border barrier keeps every chart free of self-overlap: x
/// must then have no crossing border when minimize() is called. With a
/// positive `box_aspect_ratio` and `box_stiffness`, a bounding-box term pulls
/// each chart into a rectangle of that width / height.
class Distortion_minimizer
{
  std::vector<double> weights_;
  Distortion_term term_;
  std::unique_ptr<Border_barrier_term> barrier_;
  std::unique_ptr<Bounding_box_term> box_;
  std::unique_ptr<Projected_newton_solver> newton_;
  std::unique_ptr<Proxy_quasi_newton_solver> proxy_;
  double reweighted_start_ratio_ = default_reweighted_start_ratio;
  double step_growth_ = default_step_growth;

  std::vector<Energy_term*> terms()
  {
    std::vector<Energy_term*> t{&term_};
    if(barrier_) t.push_back(barrier_.get());
    if(box_) t.push_back(box_.get());
    return t;
  }

public:
  Distortion_minimizer(const Chart_mesh& mesh, std::vector<double> weights, bool injective = false,
                       double box_aspect_ratio = 0., double box_stiffness = 0.,
                       Inner_solver solver = Inner_solver::NEWTON)
    : weights_(std::move(weights)), term_(mesh, weights_),
      barrier_(injective ? std::make_unique<Border_barrier_term>(mesh) : nullptr),
      box_(box_aspect_ratio > 0. && box_stiffness > 0.
             ? std::make_unique<Bounding_box_term>(mesh, box_aspect_ratio, box_stiffness) : nullptr)
  {
    if(solver == Inner_solver::PROXY_QUASI_NEWTON)
      proxy_ = std::make_unique<Proxy_quasi_newton_solver>(terms(), 2 * int(mesh.number_of_vertices));
    else
      newton_ = std::make_unique<Projected_newton_solver>(terms(), 2 * int(mesh.number_of_vertices));
  }

  std::vector<double>& weights() { return weights_; }

  /// The reweighted start of the minimizations (Newton_settings::reweighted_start_ratio;
  /// 0: none). On by default (default_reweighted_start_ratio).
  void set_reweighted_start(double ratio) { reweighted_start_ratio_ = ratio; }

  /// The longest step of the line search, in whole steps (Newton_settings::step_growth;
  /// 1: none longer). default_step_growth by default.
  void set_step_growth(double growth) { step_growth_ = growth; }

  /// At most `max_iterations` iterations from x, to `tolerance` (Newton_settings), or
  /// until the slow-tail rule `slow_tail` stops them (never by default).
  Newton_report minimize(UV_vector& x, int max_iterations, double tolerance, const Slow_tail& slow_tail = {})
  {
    Newton_settings settings;
    settings.max_iterations = max_iterations;
    settings.tolerance = tolerance;
    settings.slow_tail = slow_tail;
    settings.energy_scale = term_.weighted_area();
    settings.reweighted_start_ratio = reweighted_start_ratio_;
    settings.step_growth = step_growth_;
    return proxy_ ? proxy_->minimize(x, settings) : newton_->minimize(x, settings);
  }
};

/// E_d (the manual, "The Ambrosio–Tortorelli energy") on the chart mesh: area-weighted mean of s1²+s2²+s1⁻²+s2⁻².
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
