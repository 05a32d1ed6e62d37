// Per-face symmetric Dirichlet energy of a 2x2 Jacobian, its gradient and
// its projected (PSD) Hessian from the analytic eigensystem of
// Smith, De Goes, Kim 2019, "Analytic eigensystems for isotropic distortion
// energies", specialised to 2D.
#ifndef CGAL_SMP_CUT_INTERNAL_SYMMETRIC_DIRICHLET_H
#define CGAL_SMP_CUT_INTERNAL_SYMMETRIC_DIRICHLET_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Matrix2 = Eigen::Matrix2d;
using Vector4 = Eigen::Matrix<double, 4, 1>;
using Matrix4 = Eigen::Matrix<double, 4, 4>;

/// Psi = 1/2 (s1^2 + s2^2 + s1^-2 + s2^-2) - 2, +inf for a collapsed or flipped map.
inline double symmetric_dirichlet(const Matrix2& J)
{
  const double det = J.determinant();
  if(!(det > 0.)) return std::numeric_limits<double>::infinity();
  const double frob2 = J.squaredNorm();
  return 0.5 * frob2 * (1. + 1. / (det * det)) - 2.;
}

/// sigma1^2 + sigma2^2 + sigma1^-2 + sigma2^-2 (the E_d integrand, 4 at an isometry).
inline double symmetric_dirichlet_measure(const Matrix2& J)
{
  return 2. * (symmetric_dirichlet(J) + 2.);
}

/// Signed singular value decomposition J = U diag(s1, s2) V^T of a 2x2 matrix
/// with U, V rotations; s2 < 0 iff det J < 0. Closed form, no iteration and
/// no angle: with U = rotation(phi) and V^T = rotation(theta), it keeps the
/// cosines and sines of a1 = phi - theta and a2 = phi + theta, which are
/// (F, G) / R and (E, H) / Q below. Every product of an entry of U with one
/// of V, all the projected Hessian needs, is half a sum of these; U() and V()
/// build the rotations themselves (for checks).
struct Signed_svd_2
{
  double s1, s2;
  double cos1, sin1, cos2, sin2; // of a1 = phi - theta and a2 = phi + theta

  explicit Signed_svd_2(const Matrix2& J)
  {
    const double E = 0.5 * (J(0,0) + J(1,1)), F = 0.5 * (J(0,0) - J(1,1));
    const double G = 0.5 * (J(1,0) + J(0,1)), H = 0.5 * (J(1,0) - J(0,1));
    const double Q = std::sqrt(E * E + H * H), R = std::sqrt(F * F + G * G);
    s1 = Q + R;
    s2 = Q - R;
    // a zero (F, G) or (E, H) leaves its angle free: 0
    if(R > 0.) { cos1 = F / R; sin1 = G / R; }
    else { cos1 = 1.; sin1 = 0.; }
    if(Q > 0.) { cos2 = E / Q; sin2 = H / Q; }
    else { cos2 = 1.; sin2 = 0.; }
  }

  Matrix2 U() const { return rotation(0.5 * (angle1() + angle2())); }
  Matrix2 V() const { return rotation(0.5 * (angle2() - angle1())).transpose(); }

private:
  double angle1() const { return std::atan2(sin1, cos1); }
  double angle2() const { return std::atan2(sin2, cos2); }
  static Matrix2 rotation(double a)
  {
    Matrix2 R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    return R;
  }
};

inline Vector4 vectorize(const Matrix2& M) // column-major
{
  return Vector4(M(0,0), M(1,0), M(0,1), M(1,1));
}

/// dPsi/dJ, vectorized column-major. Precondition: det J > 0.
inline Vector4 symmetric_dirichlet_gradient(const Matrix2& J)
{
  const double det = J.determinant();
  const double frob2 = J.squaredNorm();
  Matrix2 cofactor;
  cofactor << J(1,1), -J(1,0), -J(0,1), J(0,0);
  const Matrix2 G = (1. + 1. / (det * det)) * J - (frob2 / (det * det * det)) * cofactor;
  return vectorize(G);
}

/// Hessian of Psi w.r.t. vec(J), with negative eigenvalues clamped to zero.
/// Precondition: det J > 0.
///
/// Only the twist's eigenvalue can be negative; it is clamped (its absolute
/// value instead took more Newton iterations: see the manual, Design and
/// measurements).
///
/// Its eigenvectors are vec(U M V^T) for M = diag(1, 0), diag(0, 1), the
/// twist [0 -1; 1 0] / sqrt 2 and the flip [0 1; 1 0] / sqrt 2, written out
/// from Signed_svd_2's cosines and sines (no atan2, sin, cos or pow: several
/// times faster than through U and V).
inline Matrix4 symmetric_dirichlet_projected_hessian(const Matrix2& J)
{
  const Signed_svd_2 svd(J);
  const double s1 = svd.s1, s2 = svd.s2;
  const double d = s1 * s2, p3 = d * d * d;
  const double s1sq = s1 * s1, s2sq = s2 * s2;
  const double scale1 = 1. + 3. / (s1sq * s1sq);
  const double scale2 = 1. + 3. / (s2sq * s2sq);
  const double flip  = 1. + (s1sq + d + s2sq) / p3;
  const double twist = (std::max)(0., 1. - (s1sq - d + s2sq) / p3);

  // cos(phi)cos(theta), sin(phi)sin(theta), sin(phi)cos(theta), cos(phi)sin(theta)
  const double A = 0.5 * (svd.cos1 + svd.cos2), B = 0.5 * (svd.cos1 - svd.cos2);
  const double C = 0.5 * (svd.sin2 + svd.sin1), D = 0.5 * (svd.sin2 - svd.sin1);
  const double r = std::sqrt(0.5);
  const Vector4 q1(A, C, -D, -B), q2(-B, D, -C, A);
  const Vector4 qt(-r * svd.sin2, r * svd.cos2, -r * svd.cos2, -r * svd.sin2);
  const Vector4 ql(-r * svd.sin1, r * svd.cos1, r * svd.cos1, r * svd.sin1);
  return scale1 * q1 * q1.transpose() + scale2 * q2 * q2.transpose()
       + twist * qt * qt.transpose() + flip * ql * ql.transpose();
}

/// Hessian w.r.t. vec(J) of the reweighted quadratic proxy of Psi at J
/// (the local-global proxy of SLIM, Rabinovich et al. 2017):
/// Q(K) = 1/2 |W (K - R)|^2, R = U V^T the rotation closest to J and
/// W^2 = U diag(w1^2, w2^2) U^T with w_i^2 = (s_i - s_i^-3) / (s_i - 1)
/// = (s_i + 1)(s_i^2 + 1) / s_i^3, so that Q's gradient at J is Psi's: a
/// step on Q is a step toward the rotation of every face at once, however
/// far from it (projected Newton, on s^-2, grows a crushed face by 4/3 per
/// iteration). Its Hessian is I_2 (x) W^2, positive definite; W^2 needs only
/// the angle 2 phi of U = rotation(phi), i.e. a1 + a2 of Signed_svd_2.
/// Precondition: det J > 0.
inline Matrix4 symmetric_dirichlet_reweighted_proxy_hessian(const Matrix2& J)
{
  const Signed_svd_2 svd(J);
  auto weight = [](double s) { return (s + 1.) * (s * s + 1.) / (s * s * s); };
  const double w1 = weight(svd.s1), w2 = weight(svd.s2);
  const double c = svd.cos1 * svd.cos2 - svd.sin1 * svd.sin2; // cos(2 phi)
  const double s = svd.sin1 * svd.cos2 + svd.cos1 * svd.sin2; // sin(2 phi)
  const double mean = 0.5 * (w1 + w2), half = 0.5 * (w1 - w2);
  Matrix2 W2;
  W2 << mean + half * c, half * s, half * s, mean - half * c;
  Matrix4 H = Matrix4::Zero();
  H.block<2, 2>(0, 0) = W2;
  H.block<2, 2>(2, 2) = W2;
  return H;
}

/// Linear map from the 6 UV coordinates (u0,v0,u1,v1,u2,v2) of a face to
/// vec(J), J = [x1-x0, x2-x0] * rest_inverse.
inline Eigen::Matrix<double, 4, 6> jacobian_operator(const Matrix2& rest_inverse)
{
  Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
  for(int c = 0; c < 2; ++c)
    for(int r = 0; r < 2; ++r)
    {
      const int row = 2 * c + r; // column-major index of J(r,c)
      B(row, 2 + r) = rest_inverse(0, c);
      B(row, 4 + r) = rest_inverse(1, c);
      B(row, 0 + r) = -(rest_inverse(0, c) + rest_inverse(1, c));
    }
  return B;
}

/// Smallest t in (0, +inf) with det(Ds + t dDs) = 0, +inf if none.
/// Ds, dDs: edge matrices [x1-x0, x2-x0] of the face and of the step.
inline double first_collapse_time(const Matrix2& Ds, const Matrix2& dDs)
{
  const double a = dDs.determinant();
  const double b = Ds(0,0) * dDs(1,1) + dDs(0,0) * Ds(1,1)
                 - Ds(0,1) * dDs(1,0) - dDs(0,1) * Ds(1,0);
  const double c = Ds.determinant();
  const double inf = std::numeric_limits<double>::infinity();
  const double scale = (std::max)({std::abs(a), std::abs(b), std::abs(c)});
  if(scale == 0.) return inf;
  if(std::abs(a) <= tuning::collapse_linear_ratio * scale) // linear
    return (b < 0.) ? -c / b : inf;
  double disc = b * b - 4. * a * c;
  // a uniform shrink to a point has a double root: round-off can make the
  // discriminant slightly negative, which must not hide that collapse
  if(disc < 0.)
  {
    if(disc < -tuning::collapse_discriminant_slack * b * b) return inf;
    disc = 0.;
  }
  // numerically stable roots
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double t1 = q / a, t2 = (q != 0.) ? c / q : inf;
  double best = inf;
  if(t1 > 0.) best = t1;
  if(t2 > 0. && t2 < best) best = t2;
  return best;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
