// A valid map carried over new cuts: where the final solve after the greedy
// splits finds a chart crossing itself, it starts that chart again from the
// map the splits started from (valid: solved under the border barrier), with
// the new cuts opened a little, instead of from its Tutte map.
#ifndef CGAL_SMP_CUT_INTERNAL_CARRIED_MAP_H
#define CGAL_SMP_CUT_INTERNAL_CARRIED_MAP_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// A map of a chart mesh, and per chart whether it is a start for the border barrier.
struct Carried_map
{
  UV_vector x;
  std::vector<char> valid;   // per chart (ids of chart_of_faces())
  double box_stiffness = 0.; // the box `x` was solved under (0: none)
};

/// `carried.x` on the chart mesh `after` from the map `x_before` of `before`, both
/// chart meshes of the same surface (face f of one is face f of the other),
/// `after` with more cuts: each UV vertex of `after` takes the position of
/// its corners in `before`. A cut added since leaves the copies of a vertex
/// at one point, the sides of the cut touching: each copy then moves into
/// its own side, along the inward bisector of its two border edges, by
/// `opening` times its least height over the opposite edges of its faces
/// (alone, it could not flip a face; two copies on one face may), so that
/// the sides part. A copy where the border turns back on itself (a slit's
/// tip, a spike: no bisector) stays. (The opening's measurements: the
/// manual's page CutParamDesignPipeline.)
///
/// `carried.valid` tells, per chart of `after`, whether the carried map is a
/// start for the border barrier: no flipped face and a border that does not
/// meet itself.
///
/// Precondition: every cut edge of `before` is cut in `after` (the vertices
/// of `after` refine those of `before`).
inline void carry_map_over_new_cuts(const Chart_mesh& before, const UV_vector& x_before, const Chart_mesh& after,
                                    Carried_map& carried, double opening = 0.3)
{
  UV_vector& x = carried.x;
  const std::size_t nf = after.number_of_faces();
  const int nv = after.number_of_vertices;
  x.setZero(2 * Eigen::Index(nv));
  std::vector<int> origin(std::size_t(nv), -1);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
      origin[std::size_t(after.faces[f][k])] = before.faces[f][k];
  std::vector<int> copies(std::size_t(before.number_of_vertices), 0);
  for(int v = 0; v < nv; ++v)
  {
    x.segment<2>(2 * v) = x_before.segment<2>(2 * origin[std::size_t(v)]);
    ++copies[std::size_t(origin[std::size_t(v)])];
  }
  // the copies of a split vertex part (see above)
  std::vector<int> in(std::size_t(nv), -1), out(std::size_t(nv), -1), border_count(std::size_t(nv), 0);
  for(const auto& segment : border_segments(after))
  {
    out[std::size_t(segment[0])] = segment[1];
    in[std::size_t(segment[1])] = segment[0];
    ++border_count[std::size_t(segment[0])];
  }
  std::vector<double> height(std::size_t(nv), std::numeric_limits<double>::infinity());
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int v = after.faces[f][k];
      if(copies[std::size_t(origin[std::size_t(v)])] < 2) continue; // only the split vertices move
      const Vector2 p = x.segment<2>(2 * v), a = x.segment<2>(2 * after.faces[f][(k + 1) % 3]),
                    b = x.segment<2>(2 * after.faces[f][(k + 2) % 3]);
      const double length = (b - a).norm();
      const double area2 = (a - p).x() * (b - p).y() - (a - p).y() * (b - p).x();
      height[std::size_t(v)] = (std::min)(height[std::size_t(v)], length > 0. ? area2 / length : 0.);
    }
  UV_vector opened = x;
  auto left = [](const Vector2& d) { return Vector2(-d.y(), d.x()); };
  for(int v = 0; v < nv; ++v)
  {
    const std::size_t i = std::size_t(v);
    if(copies[std::size_t(origin[i])] < 2 || border_count[i] != 1 || !(height[i] > 0.)) continue;
    const Vector2 p = x.segment<2>(2 * v);
    const Vector2 d1 = p - x.segment<2>(2 * in[i]), d2 = x.segment<2>(2 * out[i]) - p;
    if(!(d1.norm() > 0.) || !(d2.norm() > 0.)) continue;
    const Vector2 inward = left(d1.normalized()) + left(d2.normalized());
    if(!(inward.norm() > 1e-9)) continue;
    opened.segment<2>(2 * v) = p + opening * height[i] * inward.normalized();
  }
  x.swap(opened);

  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(after, charts);
  std::vector<char>& valid = carried.valid;
  valid.assign(std::size_t(charts), 1);
  for(std::size_t f = 0; f < nf; ++f)
    if(!(after.uv_edges(x, f).determinant() > 0.)) valid[std::size_t(chart_of_face[f])] = 0;
  const std::vector<char> crossing = Border_barrier_term(after).charts_with_crossing(x);
  for(int c = 0; c < charts; ++c)
    if(crossing[std::size_t(c)]) valid[std::size_t(c)] = 0;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
