// Bounding-box term (the paper's section 6.2, after AutoCuts): pulls each
// chart into a rectangle of a given aspect ratio, so that the chart fills its
// part of the atlas. Each chart gets a rectangle of that aspect ratio and of
// area (chart area) / target_fill, aligned with the principal axes of its
// border and centred on it; the energy is a quadratic penalty on the
// distance by which border vertices lie outside:
//     E = stiffness * sum_c mean_{v in border(c)} (d_x(v)² + d_y(v)²).
// Each rectangle is placed once, at the first update(), on the principal axes
// and the centroid of its chart's border; the distortion energy does not see
// rigid motions, so the chart moves into it.
#ifndef CGAL_SMP_CUT_INTERNAL_BOUNDING_BOX_TERM_H
#define CGAL_SMP_CUT_INTERNAL_BOUNDING_BOX_TERM_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Bounding_box_term : public Energy_term
{
  struct Box
  {
    Vector2 center = Vector2::Zero();
    Matrix2 axes = Matrix2::Identity(); // rows: the rectangle's axes
    Vector2 half_size = Vector2::Ones();
    double weight = 0.;                 // stiffness / number of border vertices
  };

  std::vector<int> vertices_;  // border UV vertices
  std::vector<int> box_of_;    // per entry of vertices_: its chart
  std::vector<Box> boxes_;
  std::vector<int> elements_;
  bool placed_ = false;

public:
  /// `aspect_ratio`: width / height of every chart's rectangle (> 0);
  /// `stiffness`: weight of the mean squared distance outside (> 0).
  Bounding_box_term(const Chart_mesh& mesh, double aspect_ratio, double stiffness = tight_bounding_box_stiffness)
  {
    int charts = 0;
    const std::vector<int> chart = chart_of_faces(mesh, charts);
    std::vector<int> chart_of_vertex(mesh.number_of_vertices, -1);
    std::vector<double> area(charts, 0.);
    for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    {
      for(int v : mesh.faces[f]) chart_of_vertex[v] = chart[f];
      area[chart[f]] += mesh.area[f];
    }
    std::vector<char> on_border(mesh.number_of_vertices, 0);
    for(const auto& s : border_segments(mesh)) on_border[s[0]] = 1;
    std::vector<int> count(charts, 0);
    for(int v = 0; v < mesh.number_of_vertices; ++v)
      if(on_border[v])
      {
        vertices_.push_back(v);
        box_of_.push_back(chart_of_vertex[v]);
        ++count[chart_of_vertex[v]];
      }
    boxes_.resize(charts);
    for(int c = 0; c < charts; ++c)
    {
      const double height = std::sqrt(area[c] / (tuning::box_target_fill * aspect_ratio));
      boxes_[c].half_size = 0.5 * Vector2(aspect_ratio * height, height);
      boxes_[c].weight = count[c] > 0 ? stiffness / count[c] : 0.;
    }
  }

  /// Places the rectangles at the first call (see above); nothing after.
  Update update(const UV_vector& x) override
  {
    if(placed_) return Update::NONE;
    placed_ = true;
    std::vector<Vector2> sum(boxes_.size(), Vector2::Zero());
    std::vector<int> count(boxes_.size(), 0);
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      sum[box_of_[i]] += x.segment<2>(2 * vertices_[i]);
      ++count[box_of_[i]];
    }
    std::vector<Matrix2> scatter(boxes_.size(), Matrix2::Zero());
    for(std::size_t c = 0; c < boxes_.size(); ++c)
      if(count[c] > 0) boxes_[c].center = sum[c] / count[c];
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Vector2 d = x.segment<2>(2 * vertices_[i]) - boxes_[box_of_[i]].center;
      scatter[box_of_[i]] += d * d.transpose();
    }
    for(std::size_t c = 0; c < boxes_.size(); ++c)
    {
      // width along the major axis (eigenvalues in increasing order)
      Eigen::SelfAdjointEigenSolver<Matrix2> eigen(scatter[c]);
      const Vector2 major = eigen.eigenvectors().col(1);
      boxes_[c].axes << major.x(), major.y(), -major.y(), major.x();
    }
    return Update::VALUES;
  }

  void declare_elements(Hessian_assembler& hessian) override
  {
    elements_.clear();
    for(int v : vertices_) elements_.push_back(hessian.add_element({2*v, 2*v+1}));
  }

  double value(const UV_vector& x) const override
  {
    double energy = 0.;
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Box& b = boxes_[box_of_[i]];
      const Vector2 outside = outside_distance(b, x.segment<2>(2 * vertices_[i]));
      energy += b.weight * outside.squaredNorm();
    }
    return energy;
  }

  void add_gradient(const UV_vector& x, Eigen::VectorXd& gradient) const override
  {
    accumulate(x, gradient, nullptr);
  }

  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    accumulate(x, gradient, &hessian);
  }

private:
  /// The gradient, and the Hessian where `hessian` is not null.
  void accumulate(const UV_vector& x, Eigen::VectorXd& gradient, Hessian_assembler* hessian) const
  {
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Box& b = boxes_[box_of_[i]];
      const int v = vertices_[i];
      const Vector2 local = b.axes * (x.segment<2>(2 * v) - b.center);
      Vector2 g_local = Vector2::Zero(), h_local = Vector2::Zero();
      for(int k = 0; k < 2; ++k)
      {
        const double d = std::abs(local[k]) - b.half_size[k];
        if(d <= 0.) continue;
        g_local[k] = 2. * b.weight * d * (local[k] > 0. ? 1. : -1.);
        h_local[k] = 2. * b.weight;
      }
      gradient.segment<2>(2 * v) += b.axes.transpose() * g_local;
      if(hessian != nullptr) hessian->add(elements_[i], Matrix2(b.axes.transpose() * h_local.asDiagonal() * b.axes));
    }
  }

  static Vector2 outside_distance(const Box& b, const Vector2& p)
  {
    const Vector2 local = b.axes * (p - b.center);
    return Vector2((std::max)(0., std::abs(local.x()) - b.half_size.x()),
                   (std::max)(0., std::abs(local.y()) - b.half_size.y()));
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
