// Global injectivity as an energy term: a scaffold (Jiang, Schaefer, Panozzo
// 2017, "Simplicial complex augmentation framework for bijective maps").
// The free space around each chart, inside a box, is triangulated with a
// constrained Delaunay triangulation whose constraints are the chart's UV
// border. Scaffold triangles carry a small symmetric Dirichlet energy
// relative to their own shape at the time they were built, and the step
// bound keeps them from collapsing: a border can only pass through another
// by collapsing a scaffold triangle first, so it never does. The scaffold
// is rebuilt at every Newton iteration (update()). As a last guard, a map
// whose border crosses itself is not admissible (value() is +infinity).
#ifndef CGAL_SMP_CUT_INTERNAL_SCAFFOLD_TERM_H
#define CGAL_SMP_CUT_INTERNAL_SCAFFOLD_TERM_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Energy_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/border_crossings.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

class Scaffold_term : public Energy_term
{
  using K = CGAL::Epick;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds,
                                                         CGAL::No_constraint_intersection_requiring_constructions_tag>;

  std::vector<std::array<int, 2>> segments_; // UV border, per chart
  std::vector<int> segment_chart_;
  int number_of_charts_ = 0;
  double weight_ = 0.;                       // energy weight of one scaffold triangle

  // The scaffold: corners are UV vertices (>= 0) or fixed box corners (-1 - k).
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Matrix2> rest_inverse_;
  std::vector<Vector2> fixed_;
  std::vector<int> elements_;

  Vector2 corner(const UV_vector& x, int id) const
  {
    return id >= 0 ? Vector2(x[2*id], x[2*id+1]) : fixed_[-1 - id];
  }

  Matrix2 edges(const UV_vector& x, std::size_t s) const
  {
    const auto& t = triangles_[s];
    const Vector2 p0 = corner(x, t[0]);
    Matrix2 D;
    D.col(0) = corner(x, t[1]) - p0;
    D.col(1) = corner(x, t[2]) - p0;
    return D;
  }

  /// Step of the edge matrix: fixed corners do not move.
  Matrix2 edge_step(const UV_vector& dx, std::size_t s) const
  {
    const auto& t = triangles_[s];
    auto step = [&](int id) { return id >= 0 ? Vector2(dx[2*id], dx[2*id+1]) : Vector2(0., 0.); };
    Matrix2 D;
    D.col(0) = step(t[1]) - step(t[0]);
    D.col(1) = step(t[2]) - step(t[0]);
    return D;
  }

public:
  /// `relative_weight`: weight of one scaffold triangle relative to the mean
  /// face area of the chart mesh.
  explicit Scaffold_term(const Chart_mesh& mesh, double relative_weight = 1e-2)
    : segments_(border_segments(mesh))
  {
    const std::vector<int> chart = chart_of_faces(mesh, number_of_charts_);
    std::vector<int> chart_of_vertex(mesh.number_of_vertices, 0);
    for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
      for(int v : mesh.faces[f]) chart_of_vertex[v] = chart[f];
    segment_chart_.reserve(segments_.size());
    for(const auto& s : segments_) segment_chart_.push_back(chart_of_vertex[s[0]]);
    weight_ = relative_weight * mesh.total_area() / double((std::max)(std::size_t(1), mesh.number_of_faces()));
  }

  std::size_t number_of_triangles() const { return triangles_.size(); }

  /// True if two segments of some chart's border that share no vertex meet
  /// at x (cross, touch or overlap: a border that only touches itself is
  /// refused too, so that round-off in the packing cannot make it cross).
  bool has_crossing(const UV_vector& x) const
  {
    return count_border_crossings(segments_, x, &segment_chart_, 1, true) > 0;
  }

  /// Per chart (ids of chart_of_faces()): true if its border meets itself at x.
  std::vector<char> charts_with_crossing(const UV_vector& x) const
  {
    std::vector<char> crossing(number_of_charts_, 0);
    std::vector<std::vector<std::array<int, 2>>> segments(number_of_charts_);
    for(std::size_t i = 0; i < segments_.size(); ++i) segments[segment_chart_[i]].push_back(segments_[i]);
    for(int c = 0; c < number_of_charts_; ++c)
      crossing[c] = count_border_crossings(segments[c], x, nullptr, 1, true) > 0;
    return crossing;
  }

  /// Rebuilds the scaffold around the charts at x (which must be admissible).
  Update update(const UV_vector& x) override
  {
    const std::vector<std::array<int, 3>> previous = triangles_;
    triangles_.clear();
    rest_inverse_.clear();
    fixed_.clear();
    for(int c = 0; c < number_of_charts_; ++c) triangulate_chart(x, c);
    return triangles_ == previous ? Update::VALUES : Update::ELEMENTS;
  }

  void declare_elements(Hessian_assembler& hessian) override
  {
    elements_.clear();
    for(const auto& t : triangles_)
    {
      std::vector<int> dofs;
      for(int id : t)
        if(id >= 0) { dofs.push_back(2*id); dofs.push_back(2*id+1); }
      elements_.push_back(hessian.add_element(dofs));
    }
  }

  double value(const UV_vector& x) const override
  {
    if(has_crossing(x)) return std::numeric_limits<double>::infinity();
    double energy = 0.;
    for(std::size_t s = 0; s < triangles_.size(); ++s)
      energy += weight_ * symmetric_dirichlet(edges(x, s) * rest_inverse_[s]);
    return energy;
  }

  void add_gradient_and_hessian(const UV_vector& x, Eigen::VectorXd& gradient,
                                Hessian_assembler& hessian) const override
  {
    Eigen::Matrix<double, 6, 6> block;
    for(std::size_t s = 0; s < triangles_.size(); ++s)
    {
      const Matrix2 J = edges(x, s) * rest_inverse_[s];
      const Eigen::Matrix<double, 4, 6> B = jacobian_operator(rest_inverse_[s]);
      const Eigen::Matrix<double, 6, 1> g = weight_ * (B.transpose() * symmetric_dirichlet_gradient(J));
      const Eigen::Matrix<double, 6, 6> H = weight_ * (B.transpose() * symmetric_dirichlet_projected_hessian(J) * B);
      // keep the rows and columns of the free corners, in order
      int free[6], n = 0;
      for(int k = 0; k < 3; ++k)
        if(triangles_[s][k] >= 0)
        {
          const int id = triangles_[s][k];
          gradient[2*id] += g[2*k];
          gradient[2*id+1] += g[2*k+1];
          free[n++] = 2*k;
          free[n++] = 2*k+1;
        }
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j) block(i, j) = H(free[i], free[j]);
      hessian.add(elements_[s], block);
    }
  }

  double max_step(const UV_vector& x, const UV_vector& dx) const override
  {
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t s = 0; s < triangles_.size(); ++s)
      t = (std::min)(t, first_collapse_time(edges(x, s), edge_step(dx, s)));
    return t;
  }

private:
  /// Scaffold of chart c: the CDT of its border and a box around it, the
  /// faces between them (odd nesting level from the outside).
  void triangulate_chart(const UV_vector& x, int c)
  {
    const double inf = std::numeric_limits<double>::infinity();
    Vector2 low(inf, inf), high(-inf, -inf);
    for(std::size_t i = 0; i < segments_.size(); ++i)
      if(segment_chart_[i] == c)
      {
        const Vector2 p(x[2*segments_[i][0]], x[2*segments_[i][0]+1]);
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
      }
    if(!(low.x() <= high.x())) return; // a closed chart has no border
    const Vector2 center = 0.5 * (low + high);
    const double half = (std::max)((high - low).maxCoeff(), 1e-300); // box of twice the chart's extent

    CDT cdt;
    const int first_fixed = int(fixed_.size());
    std::vector<CDT::Vertex_handle> box;
    for(int k = 0; k < 4; ++k)
    {
      const Vector2 p = center + half * Vector2(k == 1 || k == 2 ? 1. : -1., k >= 2 ? 1. : -1.);
      fixed_.push_back(p);
      box.push_back(cdt.insert(K::Point_2(p.x(), p.y())));
      box.back()->info() = -1 - (first_fixed + k);
    }
    try
    {
      // a point inserted twice (the two sides of a slit) keeps the UV vertex of its first insertion
      std::unordered_map<int, CDT::Vertex_handle> vertex;
      CDT::Face_handle hint;
      auto insert = [&](int v) {
        auto it = vertex.find(v);
        if(it != vertex.end()) return it->second;
        const std::size_t before = cdt.number_of_vertices();
        const CDT::Vertex_handle h = cdt.insert(K::Point_2(x[2*v], x[2*v+1]), hint);
        if(cdt.number_of_vertices() > before) h->info() = v;
        hint = h->face();
        vertex.emplace(v, h);
        return h;
      };
      for(int k = 0; k < 4; ++k) cdt.insert_constraint(box[k], box[(k + 1) % 4]);
      // all points first: inserting a constraint may delete the hint's face
      std::vector<std::pair<CDT::Vertex_handle, CDT::Vertex_handle>> constraints;
      for(std::size_t i = 0; i < segments_.size(); ++i)
        if(segment_chart_[i] == c)
        {
          const CDT::Vertex_handle a = insert(segments_[i][0]), b = insert(segments_[i][1]);
          if(a != b) constraints.emplace_back(a, b);
        }
      for(const auto& ab : constraints) cdt.insert_constraint(ab.first, ab.second);
    }
    catch(const typename CDT::Intersection_of_constraints_exception&)
    {
      fixed_.resize(first_fixed); // no scaffold for this chart now: value() still guards
      return;
    }

    // nesting level of each face: 0 outside the box, 1 between the box and
    // the border (the scaffold), 2 inside the chart, 3 in a hole, ...
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::deque<CDT::Edge> border;
    auto flood = [&](CDT::Face_handle start, int level) {
      std::deque<CDT::Face_handle> queue{start};
      while(!queue.empty())
      {
        const CDT::Face_handle f = queue.front();
        queue.pop_front();
        if(f->info() != -1) continue;
        f->info() = level;
        for(int i = 0; i < 3; ++i)
        {
          const CDT::Face_handle g = f->neighbor(i);
          if(g->info() != -1) continue;
          if(cdt.is_constrained(CDT::Edge(f, i))) border.emplace_back(f, i);
          else queue.push_back(g);
        }
      }
    };
    flood(cdt.infinite_face(), 0);
    while(!border.empty())
    {
      const CDT::Edge e = border.front();
      border.pop_front();
      const CDT::Face_handle g = e.first->neighbor(e.second);
      if(g->info() == -1) flood(g, e.first->info() + 1);
    }

    const double min_area = 1e-14 * half * half;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
      if(f->info() % 2 != 1) continue;
      const std::array<int, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      triangles_.push_back(t);
      const Matrix2 D = edges(x, triangles_.size() - 1);
      if(!(D.determinant() > 2. * min_area)) { triangles_.pop_back(); continue; } // a sliver of round-off
      rest_inverse_.push_back(D.inverse());
    }
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
