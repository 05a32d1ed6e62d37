// Per-face symmetric Dirichlet energy of a 2x2 Jacobian, its gradient and
// its projected (PSD) Hessian from the analytic eigensystem of
// Smith, De Goes, Kim 2019, "Analytic eigensystems for isotropic distortion
// energies", specialised to 2D.
#ifndef CGAL_SMP_CUT_INTERNAL_SYMMETRIC_DIRICHLET_H
#define CGAL_SMP_CUT_INTERNAL_SYMMETRIC_DIRICHLET_H

#include <Eigen/Dense>
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
/// with U, V rotations; s2 < 0 iff det J < 0. Closed form, no iteration.
struct Signed_svd_2
{
  Matrix2 U, V;
  double s1, s2;

  explicit Signed_svd_2(const Matrix2& J)
  {
    const double E = 0.5 * (J(0,0) + J(1,1)), F = 0.5 * (J(0,0) - J(1,1));
    const double G = 0.5 * (J(1,0) + J(0,1)), H = 0.5 * (J(1,0) - J(0,1));
    const double Q = std::hypot(E, H), R = std::hypot(F, G);
    s1 = Q + R;
    s2 = Q - R;
    const double a1 = std::atan2(G, F), a2 = std::atan2(H, E);
    const double theta = 0.5 * (a2 - a1), phi = 0.5 * (a2 + a1);
    U << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
    // J = U diag V^T with V^T = rotation(theta)
    V << std::cos(theta), std::sin(theta), -std::sin(theta), std::cos(theta);
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
inline Matrix4 symmetric_dirichlet_projected_hessian(const Matrix2& J)
{
  const Signed_svd_2 svd(J);
  const double s1 = svd.s1, s2 = svd.s2;
  const double p3 = std::pow(s1 * s2, 3);
  const double scale1 = 1. + 3. / std::pow(s1, 4);
  const double scale2 = 1. + 3. / std::pow(s2, 4);
  const double flip  = 1. + (s1 * s1 + s1 * s2 + s2 * s2) / p3;
  const double twist = (std::max)(0., 1. - (s1 * s1 - s1 * s2 + s2 * s2) / p3);

  const double r = std::sqrt(0.5);
  Matrix2 D1, D2, T, L;
  D1 << 1, 0, 0, 0;
  D2 << 0, 0, 0, 1;
  T << 0, -r, r, 0;
  L << 0, r, r, 0;
  const Matrix2& U = svd.U;
  const Matrix2 Vt = svd.V.transpose();
  const Vector4 q1 = vectorize(U * D1 * Vt), q2 = vectorize(U * D2 * Vt);
  const Vector4 qt = vectorize(U * T * Vt), ql = vectorize(U * L * Vt);
  return scale1 * q1 * q1.transpose() + scale2 * q2 * q2.transpose()
       + twist * qt * qt.transpose() + flip * ql * ql.transpose();
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
  if(std::abs(a) <= 1e-14 * scale) // linear
    return (b < 0.) ? -c / b : inf;
  double disc = b * b - 4. * a * c;
  // a uniform shrink to a point has a double root: round-off can make the
  // discriminant slightly negative, which must not hide that collapse
  if(disc < 0.)
  {
    if(disc < -1e-12 * b * b) return inf;
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
