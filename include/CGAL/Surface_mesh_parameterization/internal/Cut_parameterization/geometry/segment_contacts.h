// Vertex-segment geometry of the border barrier (Border_barrier_term.h):
// the distance from a point to a segment with its gradient, and the first
// time at which a moving point meets a moving segment (continuous collision
// detection, a quadratic in the step length).
#ifndef CGAL_SMP_CUT_INTERNAL_SEGMENT_CONTACTS_H
#define CGAL_SMP_CUT_INTERNAL_SEGMENT_CONTACTS_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Vector2 = Eigen::Vector2d; // as in mesh/Chart_mesh.h

/// Distance from p to the segment ab; `s` is the parameter of the closest
/// point a + s (b - a), `n` the unit vector from it to p (zero if d = 0).
/// The gradient of the distance is n for p, -(1-s) n for a and -s n for b.
inline double point_segment_distance(const Vector2& p, const Vector2& a, const Vector2& b, double& s, Vector2& n)
{
  const Vector2 e = b - a;
  const double length2 = e.squaredNorm();
  s = length2 > 0. ? (std::min)(1., (std::max)(0., (p - a).dot(e) / length2)) : 0.;
  const Vector2 r = p - (a + s * e);
  const double d = r.norm();
  n = d > 0. ? Vector2(r / d) : Vector2(0., 0.);
  return d;
}

/// First t in [0, 1] at which p + t dp lies on the segment from a + t da to
/// b + t db; +infinity if none. Conservative near tangency: a root whose
/// point is within a relative tuning::contact_parameter_slack of the
/// segment's ends counts.
inline double first_contact_time(const Vector2& p, const Vector2& dp, const Vector2& a, const Vector2& da,
                                 const Vector2& b, const Vector2& db)
{
  auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const Vector2 e = b - a, de = db - da, q = p - a, dq = dp - da;
  // f(t) = cross(e + t de, q + t dq) = c0 + c1 t + c2 t^2: p on the segment's line
  const double c0 = cross(e, q), c1 = cross(e, dq) + cross(de, q), c2 = cross(de, dq);
  double roots[2];
  int n = 0;
  const double scale = (std::max)({std::abs(c0), std::abs(c1), std::abs(c2)});
  if(!(scale > 0.)) // on the segment's line all along: a contact if on the segment at either end
  {
    auto on_segment = [&](double t) {
      const Vector2 et = e + t * de, qt = q + t * dq;
      const double length2 = et.squaredNorm();
      const double s = length2 > 0. ? qt.dot(et) / length2 : 0.;
      return s >= -tuning::contact_parameter_slack && s <= 1. + tuning::contact_parameter_slack;
    };
    return on_segment(0.) || on_segment(1.) ? 0. : std::numeric_limits<double>::infinity();
  }
  if(std::abs(c2) <= tuning::contact_linear_ratio * scale)
  {
    if(c1 != 0.) roots[n++] = -c0 / c1;
  }
  else
  {
    const double disc = c1 * c1 - 4. * c2 * c0;
    if(disc >= 0.)
    {
      // stable roots: q = -(c1 + sign(c1) sqrt(disc)) / 2, t = q / c2 and c0 / q
      const double root = std::sqrt(disc);
      const double qq = -0.5 * (c1 + (c1 >= 0. ? root : -root));
      if(c2 != 0.) roots[n++] = qq / c2;
      if(qq != 0.) roots[n++] = c0 / qq;
    }
  }
  std::sort(roots, roots + n);
  for(int k = 0; k < n; ++k)
  {
    const double t = roots[k];
    if(!(t >= 0. && t <= 1.)) continue;
    const Vector2 et = e + t * de, qt = q + t * dq;
    const double length2 = et.squaredNorm();
    const double s = length2 > 0. ? qt.dot(et) / length2 : 0.;
    if(s >= -tuning::contact_parameter_slack && s <= 1. + tuning::contact_parameter_slack) return t;
  }
  return std::numeric_limits<double>::infinity();
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
