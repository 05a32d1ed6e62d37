// The v-step of the Ambrosio–Tortorelli alternation (discontinuity_field.h):
// the sparse solve of Discontinuity_solver agrees with a dense solve of the
// system of METHOD.md assembled here from the mesh itself,
//   (λ/(4ε) Λ M + λ ε ℓ² L + M Ψ) v = λ/(4ε) Λ M 1,
// M = diag(face areas), Λ = diag(per-face λ), L the dual face Laplacian with
// weight ½(λ_f + λ_g) |e| / |c_f − c_g| across every uncut interior edge;
// its solution lies in (0, 1]; v = 1 when Ψ = 0; the dual Laplacian is
// symmetric, has zero row sums, off-diagonal entries ≤ 0, is positive
// semi-definite with one null vector per group of faces joined across uncut
// edges.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/discontinuity_field.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>

#include <Eigen/Dense>

#include <set>
#include <unordered_map>

namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;

namespace {

template <typename Mesh>
struct Problem
{
  using GT = boost::graph_traits<Mesh>;
  ic::Indexed_surface<Mesh> surface;
  std::vector<char> is_cut;           // per surface edge
  std::vector<double> face_lambda;    // per surface face
  std::vector<double> area;           // per surface face, from the mesh
  Eigen::MatrixXd laplacian;          // dense, independent of the library
  double mean_edge = 0.;
  std::size_t dual_components = 0;   // faces joined across uncut interior edges
};

Eigen::Vector3d point_of(const Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

/// Indexes the mesh with the library, then computes areas, the dual
/// Laplacian and ℓ directly from the CGAL mesh.
template <typename Mesh>
void make_problem(const Mesh& mesh, Rng& rng, double cut_fraction, bool random_lambda, Problem<Mesh>& p)
{
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  auto vpm = get(CGAL::vertex_point, mesh);
  ASSERT_TRUE(ic::index_surface(mesh, vpm, p.surface) == ic::Indexing_status::OK);
  const std::size_t nf = p.surface.number_of_faces();
  ASSERT_EQ(nf, std::size_t(num_faces(mesh)));
  std::unordered_map<face_descriptor, int> index;
  for(std::size_t f = 0; f < nf; ++f) index[p.surface.faces[f]] = int(f);

  p.face_lambda.resize(nf);
  for(double& l : p.face_lambda) l = random_lambda ? rng.uniform(0.5, 3.) : 1.;
  p.area.resize(nf);
  std::vector<Eigen::Vector3d> centroid(nf);
  for(face_descriptor f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const Eigen::Vector3d a = point_of(get(vpm, source(h, mesh))), b = point_of(get(vpm, target(h, mesh))),
                          c = point_of(get(vpm, target(next(h, mesh), mesh)));
    p.area[index.at(f)] = 0.5 * (b - a).cross(c - a).norm();
    centroid[index.at(f)] = (a + b + c) / 3.;
  }

  p.is_cut.assign(p.surface.edges.size(), 0);
  std::unordered_map<typename boost::graph_traits<Mesh>::edge_descriptor, int> edge_index;
  for(std::size_t e = 0; e < p.surface.edges.size(); ++e) edge_index[p.surface.edges[e]] = int(e);
  ASSERT_EQ(edge_index.size(), std::size_t(num_edges(mesh)));
  for(auto e : edges(mesh))
    if(!is_border(e, mesh) && rng.uniform() < cut_fraction) p.is_cut[edge_index.at(e)] = 1;

  p.laplacian = Eigen::MatrixXd::Zero(nf, nf);
  std::vector<int> parent(nf);
  for(std::size_t f = 0; f < nf; ++f) parent[f] = int(f);
  auto find = [&](int x) { while(parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  double edge_sum = 0.;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    const double length = (point_of(get(vpm, target(h, mesh))) - point_of(get(vpm, source(h, mesh)))).norm();
    edge_sum += length;
    if(is_border(e, mesh) || p.is_cut[edge_index.at(e)]) continue;
    const int f = index.at(face(h, mesh)), g = index.at(face(opposite(h, mesh), mesh));
    const double w = 0.5 * (p.face_lambda[f] + p.face_lambda[g]) * length / (centroid[f] - centroid[g]).norm();
    p.laplacian(f, g) -= w;
    p.laplacian(g, f) -= w;
    p.laplacian(f, f) += w;
    p.laplacian(g, g) += w;
    parent[find(f)] = find(g);
  }
  p.mean_edge = edge_sum / double(num_edges(mesh));
  std::set<int> roots;
  for(std::size_t f = 0; f < nf; ++f) roots.insert(find(int(f)));
  p.dual_components = roots.size();
}

/// Dense solution of the v-step system of METHOD.md.
template <typename Mesh>
Eigen::VectorXd dense_v(const Problem<Mesh>& p, const std::vector<double>& psi, double eps, double lambda)
{
  const int n = int(p.area.size());
  Eigen::MatrixXd A = lambda * eps * p.mean_edge * p.mean_edge * p.laplacian;
  Eigen::VectorXd b(n);
  for(int f = 0; f < n; ++f)
  {
    const double mass = lambda * p.face_lambda[f] * p.area[f] / (4. * eps);
    A(f, f) += mass + p.area[f] * psi[f];
    b[f] = mass;
  }
  return A.ldlt().solve(b);
}

/// `cg_iterations`: the solver's conjugate-gradient iterations before its
/// Cholesky fallback; with the default, no solve of these small systems
/// falls back, with 1 every solve does, and the results agree either way.
template <typename Mesh>
void check_v_step(const Mesh& mesh, std::uint64_t seed, double cut_fraction,
                  int cg_iterations = ic::tuning::v_step_cg_iterations)
{
  Rng rng(seed);
  Problem<Mesh> p;
  make_problem(mesh, rng, cut_fraction, true, p);
  const std::size_t nf = p.area.size();
  ASSERT_TRUE(nf < 200);

  // the library's own ℓ is the mean edge length
  EXPECT_REL(ic::mean_edge_length(p.surface), p.mean_edge, 1e-12);

  // dual edges: one per uncut interior edge, weights as in METHOD.md
  const std::vector<ic::Dual_edge> dual = ic::dual_edges(p.surface, p.is_cut, p.face_lambda);
  std::set<std::pair<int, int>> pairs;
  std::size_t wrong_weight = 0;
  for(const ic::Dual_edge& d : dual)
  {
    EXPECT_TRUE(d.f != d.g);
    EXPECT_TRUE(pairs.emplace((std::min)(d.f, d.g), (std::max)(d.f, d.g)).second) << "dual edge twice: " << d.f << " " << d.g;
    if(!(std::abs(d.weight + p.laplacian(d.f, d.g)) <= 1e-12 * d.weight)) ++wrong_weight;
  }
  EXPECT_EQ(wrong_weight, std::size_t(0));
  std::size_t expected_pairs = 0;
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t g = f + 1; g < nf; ++g)
      if(p.laplacian(f, g) != 0.) ++expected_pairs;
  EXPECT_EQ(dual.size(), expected_pairs);

  ic::Discontinuity_solver solver(dual, p.area, p.face_lambda, cg_iterations);
  std::size_t solves = 0;
  for(const double eps : {0.1, 0.025})
    for(const double lambda : {1., 0.3})
    {
      SCOPED_TRACE("eps " + to_text(eps) + ", lambda " + to_text(lambda));
      // random Ψ >= 0, a quarter of the faces exactly 0, some large
      std::vector<double> psi(nf);
      for(double& s : psi)
      {
        const double r = rng.uniform();
        s = r < 0.25 ? 0. : (r < 0.9 ? rng.uniform(0., 2.) : rng.uniform(10., 1000.));
      }
      Eigen::VectorXd v;
      ASSERT_TRUE(solver.solve(psi, eps, lambda, p.mean_edge, v));
      ++solves;
      ASSERT_EQ(std::size_t(v.size()), nf);
      const Eigen::VectorXd expected = dense_v(p, psi, eps, lambda);
      EXPECT_TRUE((v - expected).cwiseAbs().maxCoeff() <= 1e-10) << "max |v - v_dense| " << (v - expected).cwiseAbs().maxCoeff();
      EXPECT_TRUE(v.minCoeff() > 0.) << "min v " << v.minCoeff();
      EXPECT_TRUE(v.maxCoeff() <= 1. + 1e-12) << "max v " << v.maxCoeff();
      // large distortion pulls v down
      double v_low = 1.;
      for(std::size_t f = 0; f < nf; ++f)
        if(psi[f] >= 10.) v_low = (std::min)(v_low, v[f]);
      EXPECT_TRUE(v_low < 0.5);

      // Ψ = 0 everywhere: v = 1 (the phase-field term alone has v = 1 as minimizer)
      std::fill(psi.begin(), psi.end(), 0.);
      ASSERT_TRUE(solver.solve(psi, eps, lambda, p.mean_edge, v));
      ++solves;
      // (to the solver's precision: the conjugate gradient stops at a residual of 1e-12)
      EXPECT_TRUE((v - Eigen::VectorXd::Ones(nf)).cwiseAbs().maxCoeff() <= 1e-10) << "max |v - 1| " << (v - Eigen::VectorXd::Ones(nf)).cwiseAbs().maxCoeff();
    }
  EXPECT_EQ(solver.factorizations(), cg_iterations <= 1 ? solves : std::size_t(0));
}

/// The coupling part of the solver's matrix: (matrix with Ψ = 0) − mass,
/// divided by λ ε ℓ², is the dual Laplacian.
template <typename Mesh>
void check_laplacian(const Mesh& mesh, std::uint64_t seed, double cut_fraction)
{
  Rng rng(seed);
  Problem<Mesh> p;
  make_problem(mesh, rng, cut_fraction, true, p);
  const int nf = int(p.area.size());
  ic::Discontinuity_solver solver(ic::dual_edges(p.surface, p.is_cut, p.face_lambda), p.area, p.face_lambda);
  const double eps = 0.05, lambda = 1.7;
  Eigen::VectorXd v;
  ASSERT_TRUE(solver.solve(std::vector<double>(nf, 0.), eps, lambda, p.mean_edge, v));
  const ic::Sparse_matrix& stored = solver.matrix();
  Eigen::MatrixXd lower = Eigen::MatrixXd::Zero(nf, nf);
  std::size_t above_diagonal = 0;
  for(int c = 0; c < stored.outerSize(); ++c)
    for(ic::Sparse_matrix::InnerIterator it(stored, c); it; ++it)
    {
      if(it.row() < it.col()) ++above_diagonal;
      lower(it.row(), it.col()) += it.value();
    }
  EXPECT_EQ(above_diagonal, std::size_t(0)); // the solver reads the lower triangle only
  const double coupling = lambda * eps * p.mean_edge * p.mean_edge;
  for(int f = 0; f < nf; ++f) lower(f, f) -= lambda * p.face_lambda[f] * p.area[f] / (4. * eps);
  Eigen::MatrixXd L = (lower + lower.transpose()) / coupling;
  L.diagonal() /= 2.;

  const double scale = L.diagonal().maxCoeff();
  ASSERT_TRUE(scale > 0.);
  EXPECT_TRUE((L - p.laplacian).cwiseAbs().maxCoeff() <= 1e-10 * scale) << "library vs independent Laplacian " << (L - p.laplacian).cwiseAbs().maxCoeff();
  EXPECT_TRUE((L - L.transpose()).cwiseAbs().maxCoeff() == 0.);
  double worst_row = 0., worst_off = -std::numeric_limits<double>::infinity();
  for(int f = 0; f < nf; ++f)
  {
    worst_row = (std::max)(worst_row, std::abs(L.row(f).sum()));
    for(int g = 0; g < nf; ++g)
      if(g != f) worst_off = (std::max)(worst_off, L(f, g));
  }
  EXPECT_TRUE(worst_row <= 1e-10 * scale) << "row sum " << worst_row;
  EXPECT_TRUE(worst_off <= 0.) << "positive off-diagonal entry " << worst_off;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(L);
  ASSERT_TRUE(eigen.info() == Eigen::Success);
  const Eigen::VectorXd lambdas = eigen.eigenvalues();
  EXPECT_TRUE(lambdas.minCoeff() >= -1e-10 * scale) << "min eigenvalue " << lambdas.minCoeff();
  std::size_t null_space = 0;
  for(int k = 0; k < nf; ++k)
    if(std::abs(lambdas[k]) <= 1e-9 * scale) ++null_space;
  EXPECT_EQ(null_space, p.dual_components);
  if(cut_fraction == 0.) EXPECT_EQ(p.dual_components, std::size_t(1));
}

} // namespace

template <typename Mesh>
class DiscontinuityFieldTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(DiscontinuityFieldTyped, Mesh_types);

TYPED_TEST(DiscontinuityFieldTyped, v_step_matches_dense_solve_on_hemisphere)
{
  TypeParam mesh;
  build_mesh(hemisphere_soup(5, 12), mesh); // 108 faces
  for(double cut_fraction : {0., 0.15})
  {
    SCOPED_TRACE("cut fraction " + to_text(cut_fraction));
    check_v_step(mesh, 7, cut_fraction);
  }
}

TYPED_TEST(DiscontinuityFieldTyped, v_step_cholesky_fallback_matches_dense_solve)
{
  TypeParam mesh;
  build_mesh(hemisphere_soup(5, 12), mesh);
  for(int cg_iterations : {0, 1})
  {
    SCOPED_TRACE("conjugate-gradient iterations " + std::to_string(cg_iterations));
    check_v_step(mesh, 7, 0.15, cg_iterations);
  }
}

TYPED_TEST(DiscontinuityFieldTyped, v_step_matches_dense_solve_on_closed_and_irregular_meshes)
{
  {
    SCOPED_TRACE("sphere");
    TypeParam mesh;
    build_mesh(sphere_soup(4), mesh); // 128 faces, closed
    check_v_step(mesh, 11, 0.1);
  }
  {
    SCOPED_TRACE("wavy disk");
    TypeParam mesh;
    build_mesh(wavy_disk_soup(5, 14, 3), mesh); // 126 faces, irregular
    check_v_step(mesh, 12, 0.);
  }
}

TYPED_TEST(DiscontinuityFieldTyped, dual_laplacian_is_symmetric_zero_row_sum_psd)
{
  {
    SCOPED_TRACE("hemisphere, no cut");
    TypeParam mesh;
    build_mesh(hemisphere_soup(5, 12), mesh);
    check_laplacian(mesh, 3, 0.);
  }
  {
    SCOPED_TRACE("torus, random cuts");
    TypeParam mesh;
    build_mesh(torus_soup(12, 6), mesh); // 144 faces
    check_laplacian(mesh, 4, 0.3);
  }
  {
    SCOPED_TRACE("jittered grid, random cuts");
    Soup soup = grid_soup(8, 8);
    jitter_xy(soup, 0.02, 5);
    TypeParam mesh;
    build_mesh(soup, mesh);
    check_laplacian(mesh, 6, 0.2);
  }
}

TEST(DiscontinuityField, uniform_distortion_gives_uniform_v)
{
  // a uniform Ψ = c gives a uniform v = (λΛ/4ε) / (λΛ/4ε + c) when λ_f is
  // uniform (the Laplacian of a constant is 0), whatever the mesh
  Surface_mesh mesh;
  build_mesh(wavy_disk_soup(4, 10, 9), mesh);
  Rng rng(1);
  Problem<Surface_mesh> p;
  make_problem(mesh, rng, 0.1, false, p);
  ic::Discontinuity_solver solver(ic::dual_edges(p.surface, p.is_cut, p.face_lambda), p.area, p.face_lambda);
  const double eps = 0.05, lambda = 2., c = 3.;
  Eigen::VectorXd v;
  ASSERT_TRUE(solver.solve(std::vector<double>(p.area.size(), c), eps, lambda, p.mean_edge, v));
  const double expected = (lambda / (4. * eps)) / (lambda / (4. * eps) + c);
  EXPECT_TRUE((v.array() - expected).abs().maxCoeff() <= 1e-12) << "max |v - " << expected << "| "
                                                               << (v.array() - expected).abs().maxCoeff();
}

