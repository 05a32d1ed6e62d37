// The rules every cut obeys: forbidden edges (never cut) and the cost per
// unit of length of cutting each edge (the λ factor of its faces). Used by
// the initial cut, the cut extraction and the multiresolution transfer.
#ifndef CGAL_SMP_CUT_INTERNAL_CUT_RULES_H
#define CGAL_SMP_CUT_INTERNAL_CUT_RULES_H

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// True if edge `e` is flagged in `flags` (an empty vector flags nothing).
inline bool is_flagged(const std::vector<char>& flags, int e) { return !flags.empty() && flags[e]; }

/// What every cut must respect, per surface edge: edges never cut, and the
/// cost of cutting an edge per unit of 3D length (the mean λ factor of its
/// faces, as in the Ambrosio–Tortorelli term), so that the paths that join
/// or open charts follow cheap seams. Empty vectors: nothing forbidden,
/// every factor 1.
struct Cut_rules
{
  std::vector<char> forbidden;
  std::vector<double> edge_factor;

  bool is_forbidden(int e) const { return is_flagged(forbidden, e); }
  /// Cost of cutting the edge of face-edge `fe`.
  template <typename Surface>
  double cost(const Surface& surface, int fe) const
  {
    const double length = surface.edge_length(fe);
    return edge_factor.empty() ? length : length * edge_factor[surface.edge_of[fe]];
  }
};

/// The λ factors the alternation sees: `face_lambda`, times
/// `enclosed_factor` on the faces whose three edges are all forbidden (or on
/// the border). No seam can border such a face, so the field v is kept from
/// opening there, and the cuts it asks for land where they can be made.
template <typename Surface>
std::vector<double> lambda_with_forbidden_faces(const Surface& surface, const std::vector<double>& face_lambda,
                                                const std::vector<char>& forbidden, double enclosed_factor = 100.)
{
  std::vector<double> lambda = face_lambda;
  if(forbidden.empty()) return lambda;
  for(std::size_t f = 0; f < lambda.size(); ++f)
  {
    bool enclosed = true;
    for(int k = 0; k < 3; ++k)
    {
      const int fe = int(3*f) + k;
      enclosed = enclosed && (surface.twin[fe] < 0 || forbidden[surface.edge_of[fe]]);
    }
    if(enclosed) lambda[f] *= enclosed_factor;
  }
  return lambda;
}

/// Per surface edge: the mean of `face_lambda` over its faces; empty if
/// every factor is 1.
template <typename Surface>
std::vector<double> edge_lambda_factors(const Surface& surface, const std::vector<double>& face_lambda)
{
  if(std::all_of(face_lambda.begin(), face_lambda.end(), [](double x) { return x == 1.; })) return {};
  std::vector<double> sum(surface.edges.size(), 0.), count(surface.edges.size(), 0.);
  for(int fe = 0; fe < int(surface.edge_of.size()); ++fe)
  {
    sum[surface.edge_of[fe]] += face_lambda[fe / 3];
    count[surface.edge_of[fe]] += 1.;
  }
  for(std::size_t e = 0; e < sum.size(); ++e) sum[e] = count[e] > 0. ? sum[e] / count[e] : 1.;
  return sum;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
