// Weighted symmetric Dirichlet energy  sum_f w_f A_f Psi_f(u), with the
// flip-free step bound of Smith & Schaefer 2015.
#ifndef CGAL_SMP_CUT_INTERNAL_DISTORTION_TERM_H
#define CGAL_SMP_CUT_INTERNAL_DISTORTION_TERM_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Distortion_term : public Energy_term
{
  const Chart_mesh& mesh_;
  const std::vector<double>& weights_; // w_f, read at every evaluation
  std::vector<Eigen::Matrix<double, 4, 6>> jacobian_operators_;
  int first_element_ = 0;
  // per-face results, computed in parallel and summed in face order
  mutable std::vector<double> face_energy_;
  mutable std::vector<Eigen::Matrix<double, 6, 1>> face_gradient_;
  mutable std::vector<Eigen::Matrix<double, 6, 6>> face_hessian_;

  /// Adds the per-face gradients, in face order (the same sum for any thread count).
  void scatter_gradient(Eigen::VectorXd& gradient) const
  {
    for(std::size_t f = 0; f < face_gradient_.size(); ++f)
    {
      const auto& t = mesh_.faces[f];
      for(int k = 0; k < 3; ++k)
      {
        gradient[2*t[k]] += face_gradient_[f][2*k];
        gradient[2*t[k]+1] += face_gradient_[f][2*k+1];
      }
    }
  }

  /// The gradient, and the Hessian of a quadratic model of Psi w.r.t. vec(J)
  /// (`model(J)`, a callable inlined in the per-face loop) carried to the UVs.
  template <typename Model>
  void add_gradient_and_model(const UV_vector& x, Eigen::VectorXd& gradient, Hessian_assembler& hessian,
                              const Model& model) const
  {
    const std::size_t n = mesh_.number_of_faces();
    face_gradient_.resize(n);
    face_hessian_.resize(n);
    parallel_for(n, [&](std::size_t f) {
      const double w = weights_[f] * mesh_.area[f];
      const Matrix2 J = mesh_.jacobian(x, f);
      const auto& B = jacobian_operators_[f];
      face_gradient_[f] = w * (B.transpose() * symmetric_dirichlet_gradient(J));
      face_hessian_[f] = w * (B.transpose() * model(J) * B);
    });
    scatter_gradient(gradient);
    for(std::size_t f = 0; f < n; ++f) hessian.add(first_element_ + int(f), face_hessian_[f]);
  }

public:
  Distortion_term(const Chart_mesh& mesh, const std::vector<double>& weights)
    : mesh_(mesh), weights_(weights)
  {
    jacobian_operators_.reserve(mesh.number_of_faces());
    for(const Matrix2& rest_inverse : mesh.rest_inverse)
      jacobian_operators_.push_back(jacobian_operator(rest_inverse));
  }

  void declare_elements(Hessian_assembler& hessian) override
  {
    for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f)
    {
      const auto& t = mesh_.faces[f];
      const int element = hessian.add_element({2*t[0], 2*t[0]+1, 2*t[1], 2*t[1]+1, 2*t[2], 2*t[2]+1});
      if(f == 0) first_element_ = element;
    }
  }

  /// Sum of w_f A_f: the energy's natural scale, used by scale-free stopping rules.
  double weighted_area() const
  {
    double s = 0.;
    for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f) s += weights_[f] * mesh_.area[f];
    return s;
  }

  double value(const UV_vector& x) const override
  {
    const std::size_t n = mesh_.number_of_faces();
    face_energy_.resize(n);
    parallel_for(n, [&](std::size_t f) {
      face_energy_[f] = weights_[f] * mesh_.area[f] * symmetric_dirichlet(mesh_.jacobian(x, f));
    });
    double energy = 0.;
    for(double e : face_energy_) energy += e;
    return energy;
  }

  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    add_gradient_and_model(x, gradient, hessian,
                           [](const Matrix2& J) { return symmetric_dirichlet_projected_hessian(J); });
  }

  /// With SLIM's reweighted proxy of each face
  /// (symmetric_dirichlet_reweighted_proxy_hessian()).
  void add_gradient_and_reweighted_proxy(const UV_vector& x, Eigen::VectorXd& gradient,
                                         Hessian_assembler& hessian) const override
  {
    add_gradient_and_model(x, gradient, hessian,
                           [](const Matrix2& J) { return symmetric_dirichlet_reweighted_proxy_hessian(J); });
  }

  void add_gradient(const UV_vector& x, Eigen::VectorXd& gradient) const override
  {
    const std::size_t n = mesh_.number_of_faces();
    face_gradient_.resize(n);
    parallel_for(n, [&](std::size_t f) {
      const double w = weights_[f] * mesh_.area[f];
      face_gradient_[f] = w * (jacobian_operators_[f].transpose() * symmetric_dirichlet_gradient(mesh_.jacobian(x, f)));
    });
    scatter_gradient(gradient);
  }

  double max_step(const UV_vector& x, const UV_vector& dx) const override
  {
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f)
      t = (std::min)(t, first_collapse_time(mesh_.uv_edges(x, f), mesh_.uv_edges(dx, f)));
    return t;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
