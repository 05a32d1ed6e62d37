// Springs between the UV copies of the surface vertices of a seam that is
// about to be closed:  k * sum over pairs (a, b) of |x_a - x_b|^2.
// Minimized together with the distortion (whose flip-free step bound keeps
// every face valid), it brings the two sides of the seam together before
// they are joined, so that joining them flips no face (seam_merging.h).
#ifndef CGAL_SMP_CUT_INTERNAL_SEAM_CLOSING_TERM_H
#define CGAL_SMP_CUT_INTERNAL_SEAM_CLOSING_TERM_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Seam_closing_term : public Energy_term
{
  std::vector<std::array<int, 2>> pairs_; // UV vertex indices
  double stiffness_;
  int first_element_ = 0;

public:
  /// Precondition: `stiffness` >= 0, the indices of `pairs` are UV vertices of x.
  Seam_closing_term(std::vector<std::array<int, 2>> pairs, double stiffness)
    : pairs_(std::move(pairs)), stiffness_(stiffness)
  {}

  void set_stiffness(double stiffness) { stiffness_ = stiffness; }
  const std::vector<std::array<int, 2>>& pairs() const { return pairs_; }

  /// Largest distance between the two UV vertices of a pair.
  double largest_gap(const UV_vector& x) const
  {
    double gap = 0.;
    for(const auto& p : pairs_)
      gap = (std::max)(gap, (x.template segment<2>(2 * p[0]) - x.template segment<2>(2 * p[1])).norm());
    return gap;
  }

  void declare_elements(Hessian_assembler& hessian) override
  {
    for(std::size_t i = 0; i < pairs_.size(); ++i)
    {
      const int a = pairs_[i][0], b = pairs_[i][1];
      const int element = hessian.add_element({2 * a, 2 * a + 1, 2 * b, 2 * b + 1});
      if(i == 0) first_element_ = element;
    }
  }

  double value(const UV_vector& x) const override
  {
    double e = 0.;
    for(const auto& p : pairs_) e += (x.template segment<2>(2 * p[0]) - x.template segment<2>(2 * p[1])).squaredNorm();
    return stiffness_ * e;
  }

  void add_gradient(const UV_vector& x, Eigen::VectorXd& gradient) const override
  {
    for(const auto& p : pairs_)
    {
      const Eigen::Vector2d g = 2. * stiffness_ * (x.template segment<2>(2 * p[0]) - x.template segment<2>(2 * p[1]));
      gradient.template segment<2>(2 * p[0]) += g;
      gradient.template segment<2>(2 * p[1]) -= g;
    }
  }

  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    Eigen::Matrix4d block = Eigen::Matrix4d::Zero();
    for(int d = 0; d < 2; ++d)
    {
      block(d, d) = block(d + 2, d + 2) = 2. * stiffness_;
      block(d, d + 2) = block(d + 2, d) = -2. * stiffness_;
    }
    add_gradient(x, gradient);
    for(std::size_t i = 0; i < pairs_.size(); ++i) hessian.add(first_element_ + int(i), block);
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
