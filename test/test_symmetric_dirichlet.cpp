// Per-face symmetric Dirichlet energy (internal/Cut_parameterization/energy/symmetric_dirichlet.h):
// value against singular values, gradient against central finite
// differences (w.r.t. the Jacobian and w.r.t. the 6 UV coordinates of a
// face), projected Hessian against the PSD projection of the finite-
// difference Hessian and its analytic eigenvalues, PSD-ness on random and
// near-degenerate Jacobians, and first_collapse_time against a brute-force scan.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>

namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;
using ic::Matrix2;
using ic::Matrix4;
using ic::Vector4;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

namespace {

Matrix2 rotation(double a)
{
  Matrix2 R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

double log_uniform(Rng& rng, double lo, double hi)
{
  return std::exp(rng.uniform(std::log(lo), std::log(hi)));
}

/// R(a) diag(s1, s2) R(b) with s1, s2 log-uniform in [lo, hi]: det > 0.
Matrix2 random_jacobian(Rng& rng, double lo, double hi)
{
  Matrix2 S = Matrix2::Zero();
  S(0, 0) = log_uniform(rng, lo, hi);
  S(1, 1) = log_uniform(rng, lo, hi);
  return rotation(rng.uniform(0., 2. * pi)) * S * rotation(rng.uniform(0., 2. * pi));
}

Matrix2 unvec(const Vector4& v)
{
  Matrix2 M;
  M << v[0], v[2], v[1], v[3];
  return M;
}

/// Central differences of Ψ w.r.t. vec(J).
Vector4 fd_gradient(const Matrix2& J, double h)
{
  Vector4 g;
  const Vector4 x = ic::vectorize(J);
  for(int k = 0; k < 4; ++k)
  {
    Vector4 xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    g[k] = (ic::symmetric_dirichlet(unvec(xp)) - ic::symmetric_dirichlet(unvec(xm))) / (2. * h);
  }
  return g;
}

/// Central differences of the (analytic) gradient: the true Hessian, symmetrized.
Matrix4 fd_hessian(const Matrix2& J, double h)
{
  Matrix4 H;
  const Vector4 x = ic::vectorize(J);
  for(int k = 0; k < 4; ++k)
  {
    Vector4 xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    H.col(k) = (ic::symmetric_dirichlet_gradient(unvec(xp)) - ic::symmetric_dirichlet_gradient(unvec(xm))) / (2. * h);
  }
  return 0.5 * (H + H.transpose());
}

/// Negative eigenvalues of a symmetric matrix clamped to 0.
template <int N>
Eigen::Matrix<double, N, N> psd_projection(const Eigen::Matrix<double, N, N>& H)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(H);
  Eigen::Matrix<double, N, 1> d = es.eigenvalues();
  for(int i = 0; i < N; ++i) d[i] = (std::max)(0., d[i]);
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

/// A 3D triangle with a random shape (not too thin) and a random position.
std::array<ic::Vector3, 3> random_triangle(Rng& rng)
{
  for(;;)
  {
    std::array<ic::Vector3, 3> p;
    for(auto& q : p) q = ic::Vector3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    const double longest = (std::max)({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
    if(area > 0.05 * longest * longest) return p;
  }
}

/// A one-face chart with the rest shape of `p`.
ic::Chart_mesh one_face_chart(const std::array<ic::Vector3, 3>& p)
{
  ic::Chart_mesh chart;
  chart.number_of_vertices = 3;
  chart.resize_faces(1);
  chart.faces[0] = {0, 1, 2};
  chart.set_rest_shape(0, p[0], p[1], p[2]);
  return chart;
}

/// Random UVs of a face with positive orientation.
Vector6 random_positive_uv(Rng& rng)
{
  for(;;)
  {
    Vector6 x;
    for(int i = 0; i < 6; ++i) x[i] = rng.uniform(-1., 1.);
    const double det = (x[2] - x[0]) * (x[5] - x[1]) - (x[3] - x[1]) * (x[4] - x[0]);
    if(det > 0.05) return x;
  }
}

double face_energy(const ic::Chart_mesh& chart, const Vector6& x)
{
  const ic::UV_vector u = x;
  return chart.area[0] * ic::symmetric_dirichlet(chart.jacobian(u, 0));
}

Vector6 face_gradient(const ic::Chart_mesh& chart, const Vector6& x)
{
  const ic::UV_vector u = x;
  return chart.area[0] * (ic::jacobian_operator(chart.rest_inverse[0]).transpose()
                          * ic::symmetric_dirichlet_gradient(chart.jacobian(u, 0)));
}

} // namespace

TEST(SymmetricDirichlet, rest_shape_keeps_edge_lengths_and_area)
{
  Rng rng(13);
  for(int trial = 0; trial < 200; ++trial)
  {
    const auto p = random_triangle(rng);
    ic::Chart_mesh chart;
    chart.resize_faces(1);
    EXPECT_TRUE(!chart.set_rest_shape(0, p[0], p[1], p[2])); // not clamped
    const Matrix2 rest = chart.rest_inverse[0].inverse();
    const ic::Vector2 e1 = rest.col(0), e2 = rest.col(1);
    EXPECT_REL(e1.norm(), (p[1] - p[0]).norm(), 1e-12);
    EXPECT_REL(e2.norm(), (p[2] - p[0]).norm(), 1e-12);
    EXPECT_REL((e2 - e1).norm(), (p[2] - p[1]).norm(), 1e-12);
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    EXPECT_REL(chart.area[0], area, 1e-12);
    EXPECT_TRUE(rest.determinant() > 0.); // counterclockwise rest shape
    EXPECT_REL(0.5 * rest.determinant(), area, 1e-12);
  }
  // degenerate faces are clamped to a finite, positive rest shape
  const ic::Vector3 o(1, 2, 3), a(2, 2, 3), b(3, 2, 3);
  const std::array<ic::Vector3, 3> degenerate[] = {
    {o, a, b},                             // collinear
    {o, a, a},                             // two equal corners
    {o, o, o},                             // a point
    {o, b, ic::Vector3(2, 2 + 1e-9, 3)}};  // a needle
  for(const auto& p : degenerate)
  {
    ic::Chart_mesh chart;
    chart.resize_faces(1);
    EXPECT_TRUE(chart.set_rest_shape(0, p[0], p[1], p[2], 0.5));
    EXPECT_TRUE(chart.rest_inverse[0].allFinite());
    EXPECT_TRUE(chart.rest_inverse[0].determinant() > 0.);
    EXPECT_TRUE(chart.area[0] > 0. && std::isfinite(chart.area[0]));
  }
}

TEST(SymmetricDirichlet, psi_matches_singular_values)
{
  Rng rng(11);
  for(int trial = 0; trial < 200; ++trial)
  {
    const Matrix2 J = random_jacobian(rng, 0.1, 10.);
    Eigen::JacobiSVD<Matrix2> svd(J);
    const double s1 = svd.singularValues()[0], s2 = svd.singularValues()[1];
    const double expected = 0.5 * (s1 * s1 + s2 * s2 + 1. / (s1 * s1) + 1. / (s2 * s2)) - 2.;
    EXPECT_REL(ic::symmetric_dirichlet(J), expected, 1e-12);
    EXPECT_REL(ic::symmetric_dirichlet_measure(J), 2. * expected + 4., 1e-12);
  }
  // 0 at rotations, +inf when flipped or collapsed
  for(double a : {0., 0.3, 2., -1.})
  {
    EXPECT_NEAR(ic::symmetric_dirichlet(rotation(a)), 0., 1e-14);
    EXPECT_NEAR(ic::symmetric_dirichlet_measure(rotation(a)), 4., 1e-14);
    EXPECT_TRUE(ic::symmetric_dirichlet_gradient(rotation(a)).norm() < 1e-14);
  }
  Matrix2 mirror;
  mirror << 1, 0, 0, -1;
  EXPECT_TRUE(std::isinf(ic::symmetric_dirichlet(mirror)));
  EXPECT_TRUE(std::isinf(ic::symmetric_dirichlet(Matrix2::Zero())));
  Matrix2 rank1;
  rank1 << 1, 2, 2, 4;
  EXPECT_TRUE(std::isinf(ic::symmetric_dirichlet(rank1)));
  // isotropic: Ψ(s I) = s² + s⁻² - 2
  EXPECT_REL(ic::symmetric_dirichlet(2. * Matrix2::Identity()), 4. + 0.25 - 2., 1e-15);
}

TEST(SymmetricDirichlet, signed_svd_reconstructs_the_matrix)
{
  Rng rng(12);
  for(int trial = 0; trial < 300; ++trial)
  {
    Matrix2 J;
    for(int i = 0; i < 4; ++i) J(i / 2, i % 2) = rng.uniform(-2., 2.);
    const ic::Signed_svd_2 svd(J);
    Matrix2 S = Matrix2::Zero();
    S(0, 0) = svd.s1;
    S(1, 1) = svd.s2;
    EXPECT_TRUE((svd.U() * S * svd.V().transpose() - J).norm() <= 1e-13 * (1. + J.norm()));
    EXPECT_NEAR(svd.U().determinant(), 1., 1e-13);
    EXPECT_NEAR(svd.V().determinant(), 1., 1e-13);
    EXPECT_TRUE((svd.U().transpose() * svd.U() - Matrix2::Identity()).norm() < 1e-13);
    EXPECT_TRUE(svd.s1 >= std::abs(svd.s2));
    EXPECT_EQ(svd.s2 < 0., J.determinant() < 0.);
  }
}

TEST(SymmetricDirichlet, gradient_wrt_jacobian_matches_finite_differences)
{
  Rng rng(1);
  for(int trial = 0; trial < 300; ++trial)
  {
    const Matrix2 J = trial % 3 == 0 ? random_jacobian(rng, 0.5, 2.) : random_jacobian(rng, 0.15, 6.);
    const Vector4 g = ic::symmetric_dirichlet_gradient(J);
    const Vector4 fd = fd_gradient(J, 1e-6 * J.norm());
    EXPECT_TRUE((g - fd).norm() <= 1e-6 * (1. + g.norm())) << "trial " << trial << " |g - fd| = " << (g - fd).norm() << ", |g| = " << g.norm();
  }
}

TEST(SymmetricDirichlet, gradient_wrt_face_uvs_matches_finite_differences)
{
  Rng rng(2);
  for(int trial = 0; trial < 200; ++trial)
  {
    const ic::Chart_mesh chart = one_face_chart(random_triangle(rng));
    const Vector6 x = random_positive_uv(rng);
    // the Jacobian operator is the linear map x -> vec(J)
    const ic::UV_vector u = x;
    const Vector4 vec_j = ic::jacobian_operator(chart.rest_inverse[0]) * x;
    EXPECT_TRUE((vec_j - ic::vectorize(chart.jacobian(u, 0))).norm() <= 1e-12 * (1. + vec_j.norm()));

    const Vector6 g = face_gradient(chart, x);
    Vector6 fd;
    const double h = 1e-6;
    for(int k = 0; k < 6; ++k)
    {
      Vector6 xp = x, xm = x;
      xp[k] += h;
      xm[k] -= h;
      fd[k] = (face_energy(chart, xp) - face_energy(chart, xm)) / (2. * h);
    }
    EXPECT_TRUE((g - fd).norm() <= 1e-5 * (1. + g.norm())) << "trial " << trial << " |g - fd| = " << (g - fd).norm() << ", |g| = " << g.norm();
    // translation invariance: the gradient sums to zero per coordinate
    EXPECT_NEAR(g[0] + g[2] + g[4], 0., 1e-10 * (1. + g.norm()));
    EXPECT_NEAR(g[1] + g[3] + g[5], 0., 1e-10 * (1. + g.norm()));
  }
}

TEST(SymmetricDirichlet, projected_hessian_is_the_psd_projection_of_the_true_hessian)
{
  Rng rng(3);
  int psd_cases = 0, indefinite_cases = 0;
  for(int trial = 0; trial < 400; ++trial)
  {
    const Matrix2 J = random_jacobian(rng, 0.3, 3.);
    const Matrix4 P = ic::symmetric_dirichlet_projected_hessian(J);
    const Matrix4 H = fd_hessian(J, 1e-6 * J.norm());
    const double scale = H.norm();
    EXPECT_TRUE((P - P.transpose()).norm() <= 1e-12 * scale);
    const double min_eigenvalue = Eigen::SelfAdjointEigenSolver<Matrix4>(H).eigenvalues()[0];
    if(min_eigenvalue > 1e-6 * scale)
    {
      ++psd_cases; // the true Hessian is PSD: the projection must leave it unchanged
      EXPECT_TRUE((P - H).norm() <= 1e-6 * scale) << "trial " << trial << " |P - H| / |H| = " << (P - H).norm() / scale;
    }
    else if(min_eigenvalue < -1e-6 * scale)
      ++indefinite_cases;
    EXPECT_TRUE((P - psd_projection<4>(H)).norm() <= 1e-6 * scale) << "trial " << trial << " |P - proj(H)| / |H| = " << (P - psd_projection<4>(H)).norm() / scale;
  }
  // both regimes were exercised
  EXPECT_TRUE(psd_cases > 20);
  EXPECT_TRUE(indefinite_cases > 20);
}

TEST(SymmetricDirichlet, face_hessian_wrt_uvs_matches_finite_differences_where_psd)
{
  Rng rng(4);
  int compared = 0;
  for(int trial = 0; trial < 200; ++trial)
  {
    const ic::Chart_mesh chart = one_face_chart(random_triangle(rng));
    const Vector6 x = random_positive_uv(rng);
    const ic::UV_vector u = x;
    const Matrix2 J = chart.jacobian(u, 0);
    const auto B = ic::jacobian_operator(chart.rest_inverse[0]);
    const Matrix6 P = chart.area[0] * (B.transpose() * ic::symmetric_dirichlet_projected_hessian(J) * B);
    Matrix6 H;
    const double h = 1e-6;
    for(int k = 0; k < 6; ++k)
    {
      Vector6 xp = x, xm = x;
      xp[k] += h;
      xm[k] -= h;
      H.col(k) = (face_gradient(chart, xp) - face_gradient(chart, xm)) / (2. * h);
    }
    H = 0.5 * (H + H.transpose());
    const double scale = H.norm();
    // P is PSD and annihilates translations
    const auto eig = Eigen::SelfAdjointEigenSolver<Matrix6>(P).eigenvalues();
    EXPECT_TRUE(eig[0] >= -1e-9 * eig[5]);
    Vector6 tx, ty;
    tx << 1, 0, 1, 0, 1, 0;
    ty << 0, 1, 0, 1, 0, 1;
    EXPECT_TRUE((P * tx).norm() <= 1e-9 * scale);
    EXPECT_TRUE((P * ty).norm() <= 1e-9 * scale);
    const Matrix4 HJ = fd_hessian(J, 1e-6 * J.norm());
    if(Eigen::SelfAdjointEigenSolver<Matrix4>(HJ).eigenvalues()[0] > 1e-6 * HJ.norm())
    {
      ++compared;
      EXPECT_TRUE((P - H).norm() <= 1e-5 * scale) << "trial " << trial << " |P - H| / |H| = " << (P - H).norm() / scale;
    }
  }
  EXPECT_TRUE(compared > 20);
}

TEST(SymmetricDirichlet, projected_hessian_has_the_analytic_eigenvalues_and_is_psd)
{
  Rng rng(5);
  auto check_one = [](const Matrix2& J, int trial) {
    const Matrix4 P = ic::symmetric_dirichlet_projected_hessian(J);
    ASSERT_TRUE(P.allFinite());
    Eigen::SelfAdjointEigenSolver<Matrix4> es(0.5 * (P + P.transpose()));
    const auto ev = es.eigenvalues();
    const double scale = ev.cwiseAbs().maxCoeff();
    EXPECT_TRUE(ev[0] >= -1e-9 * scale) << "trial " << trial << " min eigenvalue " << ev[0] << " scale " << scale
                                                << " J = [" << J(0, 0) << ", " << J(0, 1) << "; " << J(1, 0)
                                                << ", " << J(1, 1) << "]";
    // eigenvalues of the true Hessian in terms of the singular values, negative ones clamped
    Eigen::JacobiSVD<Matrix2> svd(J);
    const double s1 = svd.singularValues()[0], s2 = svd.singularValues()[1];
    const double p3 = std::pow(s1 * s2, 3);
    std::array<double, 4> expected = {1. + 3. / std::pow(s1, 4), 1. + 3. / std::pow(s2, 4),
                                      1. + (s1 * s1 + s1 * s2 + s2 * s2) / p3,
                                      (std::max)(0., 1. - (s1 * s1 - s1 * s2 + s2 * s2) / p3)};
    std::sort(expected.begin(), expected.end());
    // J's rounding perturbs s2 by about eps * s1 (relative eps * s1 / s2), and
    // 1 + 3 / s2^4 by four times that: no method can do better
    const double conditioning = 64. * std::numeric_limits<double>::epsilon() * s1 / s2;
    for(int i = 0; i < 4; ++i)
      EXPECT_TRUE(std::abs(ev[i] - expected[i]) <= (1e-9 + conditioning) * scale) << "trial " << trial << " eigenvalue " << i << ": " << ev[i] << " vs " << expected[i];
  };
  int trial = 0;
  for(; trial < 300; ++trial) check_one(random_jacobian(rng, 0.05, 20.), trial);
  // near-degenerate: one tiny singular value, or both, or a strong stretch
  for(; trial < 600; ++trial)
  {
    Matrix2 S = Matrix2::Zero();
    S(0, 0) = log_uniform(rng, 0.01, 1000.);
    S(1, 1) = log_uniform(rng, 1e-4, 1e-2);
    if(trial % 2) std::swap(S(0, 0), S(1, 1));
    check_one(rotation(rng.uniform(0., 2. * pi)) * S * rotation(rng.uniform(0., 2. * pi)), trial);
  }
  // nearly equal singular values (the flip/twist formulas divide by nothing,
  // but the SVD's rotations are ill-defined there)
  for(; trial < 700; ++trial)
  {
    const double s = log_uniform(rng, 0.1, 10.);
    Matrix2 S = Matrix2::Zero();
    S(0, 0) = s;
    S(1, 1) = s * (1. + rng.uniform(0., 1e-10));
    check_one(rotation(rng.uniform(0., 2. * pi)) * S * rotation(rng.uniform(0., 2. * pi)), trial);
  }
  // random entries with det > 0, some nearly singular
  while(trial < 1000)
  {
    Matrix2 J;
    for(int i = 0; i < 4; ++i) J(i / 2, i % 2) = rng.uniform(-1., 1.);
    if(trial % 2) J(1, 1) = J(0, 1) * J(1, 0) / J(0, 0) + rng.uniform(1e-6, 1e-3) * (J(0, 0) > 0 ? 1. : -1.);
    if(!(J.determinant() > 0.)) continue;
    check_one(J, trial++);
  }
  check_one(Matrix2::Identity(), -1);
  check_one(rotation(1.), -2);
}

namespace {

double det_at(const Matrix2& Ds, const Matrix2& dDs, double t) { return (Ds + t * dDs).determinant(); }

/// First t in (0, T] where det(Ds + t dDs) <= 0, by scanning then bisecting; +inf if none seen.
double brute_force_collapse_time(const Matrix2& Ds, const Matrix2& dDs, double T, int samples)
{
  double previous = 0.;
  for(int i = 1; i <= samples; ++i)
  {
    const double t = T * i / samples;
    if(det_at(Ds, dDs, t) <= 0.)
    {
      double lo = previous, hi = t; // det(lo) > 0 >= det(hi)
      for(int k = 0; k < 200 && hi - lo > 0.; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        if(mid <= lo || mid >= hi) break;
        (det_at(Ds, dDs, mid) > 0. ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = t;
  }
  return std::numeric_limits<double>::infinity();
}

} // namespace

TEST(SymmetricDirichlet, first_collapse_time_matches_a_brute_force_scan)
{
  Rng rng(6);
  const double T = 5.;
  int with_root = 0, without_root = 0;
  for(int trial = 0; trial < 2000; ++trial)
  {
    Matrix2 Ds, dDs;
    do
    {
      for(int i = 0; i < 4; ++i) Ds(i / 2, i % 2) = rng.uniform(-1., 1.);
    } while(!(Ds.determinant() > 1e-3));
    const double step_scale = log_uniform(rng, 0.01, 10.);
    for(int i = 0; i < 4; ++i) dDs(i / 2, i % 2) = step_scale * rng.uniform(-1., 1.);
    if(trial % 5 == 0) dDs.col(0).setZero(); // det linear in t (rank-one step)
    const double t_lib = ic::first_collapse_time(Ds, dDs);
    const double t_brute = brute_force_collapse_time(Ds, dDs, T, 4000);
    EXPECT_TRUE(t_lib > 0.) << "trial " << trial;
    if(std::isfinite(t_brute))
    {
      ++with_root;
      EXPECT_TRUE(std::abs(t_lib - t_brute) <= 1e-8 * (1. + t_brute)) << "trial " << trial << ": library " << t_lib << " vs scan " << t_brute;
    }
    else
    {
      ++without_root;
      // no sign change seen up to T: the library's root, if any before T, is a
      // genuine (touching or closely paired) root the scan stepped over
      if(t_lib <= T)
        EXPECT_TRUE(std::abs(det_at(Ds, dDs, t_lib)) <= 1e-9 * (Ds.squaredNorm() + t_lib * t_lib * dDs.squaredNorm())) << "trial " << trial << ": library " << t_lib << ", det there " << det_at(Ds, dDs, t_lib);
    }
    // never a collapse strictly before the returned time
    if(std::isfinite(t_lib))
      for(int i = 1; i < 100; ++i)
      {
        const double t = t_lib * i / 100.;
        EXPECT_TRUE(det_at(Ds, dDs, t) > 0.) << "trial " << trial << " det <= 0 at " << t << " < " << t_lib;
      }
  }
  EXPECT_TRUE(with_root > 200);
  EXPECT_TRUE(without_root > 200);
}

TEST(SymmetricDirichlet, first_collapse_time_special_cases)
{
  Matrix2 Ds;
  Ds << 2., 0.5, 0.1, 1.;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ic::first_collapse_time(Ds, Matrix2::Zero()), inf);
  EXPECT_EQ(ic::first_collapse_time(Ds, Ds), inf);                       // growing
  EXPECT_EQ(ic::first_collapse_time(Ds, rotation(0.7) * Ds - Ds), inf); // det(t) > 0 for all t: no real root
  // collapse onto a segment: det linear in t, root at 1/2
  Matrix2 I = Matrix2::Identity(), squash;
  squash << 0., 0., 0., -2.;
  EXPECT_NEAR(ic::first_collapse_time(I, squash), 0.5, 1e-15);
  // mirror: det(I + t diag(0, -2)) = 1 - 2t, same root; diag(-2, -2): (1-2t)^2, touches 0 at 1/2
  Matrix2 both;
  both << -2., 0., 0., -2.;
  EXPECT_NEAR(ic::first_collapse_time(I, both), 0.5, 1e-12);
  // uniform shrink of a generic triangle to a point at t = 1: det(t) = (1-t)^2 det,
  // a double root, known to about sqrt(eps) only
  EXPECT_NEAR(ic::first_collapse_time(Ds, -Ds), 1., 1e-7);
  EXPECT_NEAR(ic::first_collapse_time(Ds, -0.25 * Ds), 4., 4e-7);
  // two distinct roots: det(I + t diag(-1, -3)) = (1 - t)(1 - 3t): first at 1/3
  Matrix2 two;
  two << -1., 0., 0., -3.;
  EXPECT_NEAR(ic::first_collapse_time(I, two), 1. / 3., 1e-14);
  // the same, scaled: the root does not depend on the units
  for(double s : {1e-6, 1e-3, 1e3, 1e6})
  {
    EXPECT_REL(ic::first_collapse_time(s * I, s * two), 1. / 3., 1e-13);
    EXPECT_REL(ic::first_collapse_time(s * Ds, -s * Ds), 1., 1e-9);
  }
  // a pure shear never changes the area
  Matrix2 shear_step;
  shear_step << 0., 0., -1., 0.; // I + t S = [[1, 0], [-t, 1]], det = 1
  EXPECT_EQ(ic::first_collapse_time(I, shear_step), inf);
}

TEST(SymmetricDirichlet, first_collapse_time_finds_a_uniform_shrink_to_a_point)
{
  // the collapse of a random triangle to a point must be found
  // (otherwise a step of 2/k turns the triangle by 180 degrees, det > 0 again,
  // and the line search's cap misses it)
  Rng rng(7);
  int missed = 0, late = 0, trials = 0;
  while(trials < 2000)
  {
    Matrix2 D;
    for(int i = 0; i < 4; ++i) D(i / 2, i % 2) = rng.uniform(-1., 1.);
    if(!(D.determinant() > 1e-3)) continue;
    ++trials;
    const double k = log_uniform(rng, 0.05, 20.);
    const double t = ic::first_collapse_time(D, -k * D);
    if(!std::isfinite(t)) ++missed;
    else if(t > (1. / k) * (1. + 1e-12) || t < (1. / k) * (1. - 1e-6)) ++late;
  }
  EXPECT_TRUE(missed == 0) << missed << " of " << trials << " uniform shrinks to a point got +inf";
  EXPECT_TRUE(late == 0) << late << " of " << trials << " uniform shrinks to a point got a wrong time";
}

