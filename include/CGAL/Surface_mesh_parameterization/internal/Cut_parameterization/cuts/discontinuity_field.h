// The v-step of the Ambrosio–Tortorelli alternation: with the UVs fixed the
// energy is quadratic in the per-face field v, minimized by one SPD solve
//   (diag(A_f (λ_f/(4ε) + Ψ_f)) + λ ε ℓ² L) v = (λ_f A_f / (4ε))_f
// (the manual, "The Method", with ε and λ relative to the mean edge length ℓ). L is the
// dual face Laplacian, w_e = λ_e |e| / |c_f - c_g| across every edge that is
// interior to the cut mesh. Each solve starts from the last v, by a
// preconditioned conjugate gradient, a Cholesky factorization where that
// does not converge (linalg/Pcg_or_cholesky.h).
#ifndef CGAL_SMP_CUT_INTERNAL_DISCONTINUITY_FIELD_H
#define CGAL_SMP_CUT_INTERNAL_DISCONTINUITY_FIELD_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Pcg_or_cholesky.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

struct Dual_edge { int f, g; double weight; };

/// Dual edges of the cut mesh: faces sharing an edge that is not cut.
/// Weight |e| / |c_f - c_g| times the mean λ of the two faces.
template <typename Surface>
std::vector<Dual_edge> dual_edges(const Surface& surface, const std::vector<char>& is_cut,
                                  const std::vector<double>& face_lambda)
{
  std::vector<Vector3> centroid(surface.number_of_faces());
  for(std::size_t f = 0; f < centroid.size(); ++f)
  {
    const auto& cv = surface.corner_vertex[f];
    centroid[f] = (surface.points[cv[0]] + surface.points[cv[1]] + surface.points[cv[2]]) / 3.;
  }
  std::vector<Dual_edge> result;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int tw = surface.twin[fe];
    if(tw < fe || is_cut[surface.edge_of[fe]]) continue;
    const int f = fe / 3, g = tw / 3;
    const double distance = (centroid[f] - centroid[g]).norm();
    if(!(distance > 0.)) continue; // coincident centroids: no meaningful gradient
    const double lambda = 0.5 * (face_lambda[f] + face_lambda[g]);
    result.push_back({f, g, lambda * surface.edge_length(fe) / distance});
  }
  return result;
}

class Discontinuity_solver
{
  std::vector<Dual_edge> edges_;
  std::vector<double> area_, lambda_;
  Sparse_matrix matrix_;     // lower triangle
  std::vector<int> diagonal_slot_, edge_slot_;
  Pcg_or_cholesky solver_;

public:
  /// `cg_iterations`: of the conjugate gradient of each solve before its
  /// Cholesky fallback (0: Cholesky only).
  Discontinuity_solver(std::vector<Dual_edge> edges, std::vector<double> face_area,
                       std::vector<double> face_lambda, int cg_iterations = tuning::v_step_cg_iterations)
    : edges_(std::move(edges)), area_(std::move(face_area)), lambda_(std::move(face_lambda)),
      solver_(cg_iterations)
  {
    const int n = int(area_.size());
    std::vector<Eigen::Triplet<double>> entries;
    for(int f = 0; f < n; ++f) entries.emplace_back(f, f, 1.);
    for(const Dual_edge& e : edges_)
      entries.emplace_back((std::max)(e.f, e.g), (std::min)(e.f, e.g), 1.);
    matrix_.resize(n, n);
    matrix_.setFromTriplets(entries.begin(), entries.end());
    matrix_.makeCompressed();
    auto slot = [&](int r, int c) {
      const int* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[c];
      const int* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[c + 1];
      return int(std::lower_bound(begin, end, r) - matrix_.innerIndexPtr());
    };
    for(int f = 0; f < n; ++f) diagonal_slot_.push_back(slot(f, f));
    for(const Dual_edge& e : edges_)
      edge_slot_.push_back(slot((std::max)(e.f, e.g), (std::min)(e.f, e.g)));
  }

  /// Minimizer v of the AT energy for the given per-face distortion Ψ_f.
  /// `epsilon` and `lambda` are relative, `mean_edge` is ℓ; `v` on entry is
  /// the start of the iterative solve (the last v; any other size: 0).
  /// False on a failed solve.
  bool solve(const std::vector<double>& distortion, double epsilon, double lambda,
             double mean_edge, Eigen::VectorXd& v)
  {
    const int n = int(area_.size());
    std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.);
    double* values = matrix_.valuePtr();
    Eigen::VectorXd rhs(n);
    const double coupling = lambda * epsilon * mean_edge * mean_edge;
    for(int f = 0; f < n; ++f)
    {
      const double mass = lambda * lambda_[f] * area_[f] / (4. * epsilon);
      values[diagonal_slot_[f]] += mass + area_[f] * distortion[f];
      rhs[f] = mass;
    }
    for(std::size_t k = 0; k < edges_.size(); ++k)
    {
      const Dual_edge& e = edges_[k];
      const double w = coupling * e.weight;
      values[diagonal_slot_[e.f]] += w;
      values[diagonal_slot_[e.g]] += w;
      values[edge_slot_[k]] -= w;
    }
    return solver_.solve(matrix_, rhs, v);
  }

  /// Solves that fell back to a factorization.
  std::size_t factorizations() const { return solver_.factorizations(); }

  const Sparse_matrix& matrix() const { return matrix_; }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
