// The inner solvers of the UV minimizations (Inner_solver): the
// quasi-Newton solver on a factorized proxy of the Hessian against projected
// Newton, and the gradient-only evaluation it relies on.
#include "generators.h"
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Bounding_box_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <cmath>
#include <random>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;

namespace {

struct Solver_chart
{
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Chart_mesh mesh;
  std::vector<int> corner_uv;
  ic::UV_vector tutte;
};

/// The uncut chart mesh of a generated disk and its Tutte map; REQUIREs success.
void make_solver_chart(const Soup& soup, Solver_chart& chart)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(soup);
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), chart.surface) == ic::Indexing_status::OK);
  ic::build_chart_mesh(chart.surface, std::vector<char>(chart.surface.edges.size(), 0), chart.mesh, chart.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(chart.mesh, chart.tutte) == ic::Embedding_status::OK);
}

/// Weights of the kind the alternation uses (v² + γ, some tiny).
std::vector<double> alternation_like_weights(std::size_t faces)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> v(0., 1.);
  std::vector<double> w(faces);
  for(std::size_t f = 0; f < faces; ++f)
  {
    const double value = f % 5 == 0 ? 1e-3 * v(random) : v(random);
    w[f] = value * value + 1e-7;
  }
  return w;
}

} // namespace

// The quasi-Newton iterations ask the terms for their gradient alone: it must
// be the gradient that add_gradient_and_hessian() gives.
TEST(InnerSolvers, gradient_alone_equals_the_gradient_with_the_hessian)
{
  Solver_chart chart;
  make_solver_chart(wavy_disk_soup(8, 22, 5), chart);
  const std::vector<double> weights = alternation_like_weights(chart.mesh.number_of_faces());
  ic::Distortion_term distortion(chart.mesh, weights);
  // a box much smaller than the chart: every border vertex is outside it
  ic::Bounding_box_term box(chart.mesh, 2., 300.);
  box.update(chart.tutte);
  for(ic::Energy_term* term : std::vector<ic::Energy_term*>{&distortion, &box})
  {
    ic::Hessian_assembler hessian;
    term->declare_elements(hessian);
    hessian.finalize(int(chart.tutte.size()));
    Eigen::VectorXd with_hessian = Eigen::VectorXd::Zero(chart.tutte.size());
    Eigen::VectorXd alone = Eigen::VectorXd::Zero(chart.tutte.size());
    term->add_gradient_and_hessian(chart.tutte, with_hessian, hessian);
    term->add_gradient(chart.tutte, alone);
    ASSERT_TRUE(with_hessian.norm() > 0.);
    EXPECT_EQ((with_hessian - alone).norm(), 0.);
  }
}

// Both solvers minimize the same energy from the Tutte map, with the weights
// of an alternation: the quasi-Newton solver reaches Newton's minimum,
// never flips a face, and factorizes less often than it iterates.
TEST(InnerSolvers, quasi_newton_reaches_the_newton_minimum_with_fewer_factorizations)
{
  for(const Soup& soup : {hemisphere_soup(7, 20), wavy_disk_soup(8, 22, 5), cone_soup(6, 16, 1., 1.5)})
  {
    Solver_chart chart;
    make_solver_chart(soup, chart);
    const std::vector<double> weights = alternation_like_weights(chart.mesh.number_of_faces());
    ic::UV_vector newton_x = chart.tutte, quasi_x = chart.tutte;
    ic::Distortion_minimizer newton(chart.mesh, weights, false, 0., 0., SMP::Inner_solver::NEWTON);
    ic::Distortion_minimizer quasi(chart.mesh, weights, false, 0., 0., SMP::Inner_solver::PROXY_QUASI_NEWTON);
    const ic::Newton_report a = newton.minimize(newton_x, 500, 1e-9);
    const ic::Newton_report b = quasi.minimize(quasi_x, 2000, 1e-9);
    ASSERT_EQ(int(a.status), int(ic::Newton_status::CONVERGED));
    ASSERT_EQ(int(b.status), int(ic::Newton_status::CONVERGED));
    EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, quasi_x), 0);
    EXPECT_TRUE(b.energy < b.initial_energy);
    EXPECT_NEAR(b.energy, a.energy, 1e-6 * a.energy);
    // every step reused a factorization: more solves than factorizations
    EXPECT_TRUE(b.factorizations < b.iterations) << b.factorizations << " factorizations, " << b.iterations << " iterations";
    EXPECT_TRUE(b.solves > b.factorizations);
  }
}

// The whole method with the quasi-Newton inner solver: a valid atlas (no
// flip, no crossing border, in the unit square) with the distortion Newton
// reaches on the same mesh (compared without the box: the box's budget may
// keep it for one solver and drop it for the other, 4.145 against 4.085
// here); its iterations reuse factorizations. (Below
// 8,000 unknowns Newton reuses its last factorization too, as a
// preconditioner: the two counts of factorizations do not compare here.)
TEST(InnerSolvers, cut_and_parameterize_with_the_quasi_newton_solver)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(16, 32, 1.5, 0.2));
  Cut_run<Surface_mesh> newton(mesh), quasi(mesh);
  newton.run(SMP::parameters::inner_solver(SMP::Inner_solver::NEWTON));
  quasi.run(SMP::parameters::inner_solver(SMP::Inner_solver::PROXY_QUASI_NEWTON));
  check_cut_result(mesh, newton);
  check_cut_result(mesh, quasi);
  Cut_run<Surface_mesh> newton_unboxed(mesh), quasi_unboxed(mesh);
  newton_unboxed.run(SMP::parameters::inner_solver(SMP::Inner_solver::NEWTON, SMP::parameters::bounding_box_stiffness(0.)));
  quasi_unboxed.run(SMP::parameters::inner_solver(SMP::Inner_solver::PROXY_QUASI_NEWTON, SMP::parameters::bounding_box_stiffness(0.)));
  check_cut_result(mesh, newton_unboxed);
  check_cut_result(mesh, quasi_unboxed);
  EXPECT_TRUE(quasi_unboxed.result.distortion <= newton_unboxed.result.distortion + 0.05)
    << quasi_unboxed.result.distortion << " against " << newton_unboxed.result.distortion;
  // the alternation's u-steps (weights fixed in each) reuse their factorizations
  EXPECT_TRUE(quasi.result.alternation_factorizations < quasi.result.alternation_newton_iterations)
    << quasi.result.alternation_factorizations << " factorizations, " << quasi.result.alternation_newton_iterations
    << " iterations; in all " << quasi.result.number_of_factorizations << ", " << quasi.result.newton_iterations;
  EXPECT_TRUE(quasi.result.number_of_solves > quasi.result.number_of_factorizations);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(InnerSolvers, quasi_newton_result_does_not_depend_on_the_thread_count)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(24, 48, 1.5, 0.2)); // over 2000 faces: loops split
  expect_same_result_for_thread_counts(mesh, {1, 2, 5}, [](Cut_run<Surface_mesh>& run) {
    return run.run(SMP::parameters::inner_solver(SMP::Inner_solver::PROXY_QUASI_NEWTON));
  });
}
#else
TEST(InnerSolvers, quasi_newton_result_does_not_depend_on_the_thread_count)
{
  GTEST_SKIP() << "built without TBB: one thread only";
}
#endif

// The slow-tail rule on given energies: it stops at the first step, from
// `after` on, where the energy fell by less than `ratio` of itself over the
// last `window` steps; never while it falls faster, never when `after` is 0.
TEST(InnerSolvers, slow_tail_rule_stops_where_the_energy_crawls)
{
  const ic::Slow_tail rule{100, 20, 1e-3};
  ic::Tail_watch fast(rule), slow(rule), off(ic::Slow_tail{0, 20, 1e-3}), late(rule);
  double e_fast = 1., e_slow = 1., e_late = 1.;
  for(int step = 1; step <= 400; ++step)
  {
    e_fast *= 0.999;  // 2% over 20 steps
    e_slow *= 0.9999; // 0.2% over 20 steps
    EXPECT_FALSE(fast.crawls(e_fast)) << step;
    EXPECT_FALSE(off.crawls(1.)) << step;
    // the crawl starts at step 150; the 20 steps before step 170 all crawl
    e_late *= step < 150 ? 0.999 : 0.99999;
    const bool late_stops = late.crawls(e_late);
    EXPECT_EQ(late_stops, step >= 169) << step;
    const bool slow_stops = slow.crawls(e_slow);
    EXPECT_FALSE(slow_stops) << step;
  }
  // a constant energy crawls as soon as `after` is reached
  ic::Tail_watch flat(rule);
  for(int step = 1; step <= 120; ++step) EXPECT_EQ(flat.crawls(2.), step >= 100) << step;
}

// Both solvers stop under the rule with the status SLOW_TAIL after the
// steps it allows, the map flip-free and lower than at the start; without
// it, the same minimization runs on to convergence.
TEST(InnerSolvers, both_solvers_stop_in_a_slow_tail)
{
  Solver_chart chart;
  make_solver_chart(cone_soup(6, 16, 1., 1.5), chart);
  const std::vector<double> weights(chart.mesh.number_of_faces(), 1.);
  // from the third step on, stop unless a step gains a million times the energy left
  const ic::Slow_tail rule{3, 1, 1e6};
  for(SMP::Inner_solver solver : {SMP::Inner_solver::NEWTON, SMP::Inner_solver::PROXY_QUASI_NEWTON})
  {
    ic::UV_vector stopped = chart.tutte, converged = chart.tutte;
    ic::Distortion_minimizer a(chart.mesh, weights, false, 0., 0., solver), b(chart.mesh, weights, false, 0., 0., solver);
    const ic::Newton_report with_rule = a.minimize(stopped, 2000, 1e-9, rule);
    const ic::Newton_report without = b.minimize(converged, 2000, 1e-9);
    ASSERT_EQ(int(with_rule.status), int(ic::Newton_status::SLOW_TAIL));
    // (a quasi-Newton iteration may end without a step: a stale direction refused)
    if(solver == SMP::Inner_solver::NEWTON) EXPECT_EQ(with_rule.iterations, 3);
    EXPECT_TRUE(with_rule.iterations >= 3);
    EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, stopped), 0);
    EXPECT_TRUE(with_rule.energy < with_rule.initial_energy);
    ASSERT_EQ(int(without.status), int(ic::Newton_status::CONVERGED));
    EXPECT_TRUE(without.iterations > with_rule.iterations) << without.iterations;
    EXPECT_TRUE(without.energy <= with_rule.energy);
  }
}

// SLIM's reweighted proxy of Psi at J (the reweighted start's model): its
// gradient at J, W^2 (J - R) with R the closest rotation, is Psi's
// gradient, and its Hessian is positive definite, for mild, stretched and
// crushed faces alike.
TEST(InnerSolvers, reweighted_proxy_has_the_gradient_of_psi_and_is_positive_definite)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-3.1, 3.1), exponent(-4., 2.);
  auto rotation = [](double a) {
    ic::Matrix2 R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    return R;
  };
  for(int trial = 0; trial < 200; ++trial)
  {
    const double s1 = std::pow(10., exponent(random)), s2 = std::pow(10., exponent(random));
    const ic::Matrix2 U = rotation(angle(random)), V = rotation(angle(random));
    const ic::Matrix2 J = U * Eigen::Vector2d(s1, s2).asDiagonal() * V.transpose();
    const ic::Matrix4 H = ic::symmetric_dirichlet_reweighted_proxy_hessian(J);
    const ic::Vector4 proxy_gradient = H * ic::vectorize(J - U * V.transpose());
    const ic::Vector4 gradient = ic::symmetric_dirichlet_gradient(J);
    EXPECT_LE((proxy_gradient - gradient).norm(), 1e-9 * gradient.norm()) << "s = " << s1 << ", " << s2;
    const Eigen::SelfAdjointEigenSolver<ic::Matrix4> eigen(H);
    EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.) << "s = " << s1 << ", " << s2;
  }
}

// From a Tutte map that crushes most of the chart (a finger: its base on
// the circle, the tube squeezed inside; E_d above a million), the
// reweighted start reaches the minimum that projected Newton alone reaches,
// in fewer iterations and without flipping a face; with the quasi-Newton
// solver too. From a map near its minimum it takes no step: the same
// iterations with and without it.
TEST(InnerSolvers, reweighted_start_reaches_the_same_minimum_from_a_crushed_map_in_fewer_iterations)
{
  Solver_chart chart;
  make_solver_chart(finger_soup(40, 12), chart);
  const double tutte_distortion = ic::mean_distortion(chart.mesh, chart.tutte);
  ASSERT_GT(tutte_distortion, 1e6);
  const std::vector<double> weights(chart.mesh.number_of_faces(), 1.);
  for(SMP::Inner_solver solver : {SMP::Inner_solver::NEWTON, SMP::Inner_solver::PROXY_QUASI_NEWTON})
  {
    ic::UV_vector with = chart.tutte, without = chart.tutte;
    ic::Distortion_minimizer a(chart.mesh, weights, true, 0., 0., solver), b(chart.mesh, weights, true, 0., 0., solver);
    b.set_reweighted_start(0.);
    const ic::Newton_report started = a.minimize(with, 2000, 1e-9);
    const ic::Newton_report plain = b.minimize(without, 2000, 1e-9);
    ASSERT_EQ(int(started.status), int(ic::Newton_status::CONVERGED));
    ASSERT_EQ(int(plain.status), int(ic::Newton_status::CONVERGED));
    EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, with), 0);
    EXPECT_NEAR(started.energy, plain.energy, 1e-6 * plain.energy);
    EXPECT_LT(started.iterations, plain.iterations) << "E_d from " << tutte_distortion;
    if(solver == SMP::Inner_solver::NEWTON) EXPECT_LT(started.factorizations, plain.factorizations);
    // near its minimum, no reweighted step
    ic::UV_vector again = with, again_plain = with;
    const ic::Newton_report near = a.minimize(again, 2000, 1e-9);
    const ic::Newton_report near_plain = b.minimize(again_plain, 2000, 1e-9);
    EXPECT_EQ(near.iterations, near_plain.iterations);
    EXPECT_EQ(again, again_plain);
  }
}

namespace {

/// E(x) = 1/2 |x - c|^2 with a Hessian `stiffness` times too stiff: the
/// whole Newton step goes 1/stiffness of the way to the minimum c.
class Stiff_model_term : public ic::Energy_term
{
  Eigen::VectorXd c_;
  double stiffness_;
  std::vector<int> elements_;

public:
  Stiff_model_term(Eigen::VectorXd c, double stiffness) : c_(std::move(c)), stiffness_(stiffness) {}
  void declare_elements(ic::Hessian_assembler& hessian) override
  {
    elements_.clear();
    for(int v = 0; 2 * v < c_.size(); ++v) elements_.push_back(hessian.add_element({2 * v, 2 * v + 1}));
  }
  double value(const ic::UV_vector& x) const override { return 0.5 * (x - c_).squaredNorm(); }
  void add_gradient(const ic::UV_vector& x, Eigen::VectorXd& gradient) const override { gradient += x - c_; }
  void add_gradient_and_hessian(const ic::UV_vector& x, Eigen::VectorXd& gradient,
                                ic::Hessian_assembler& hessian) const override
  {
    gradient += x - c_;
    for(int element : elements_) hessian.add(element, Eigen::Matrix2d(stiffness_ * Eigen::Matrix2d::Identity()));
  }
};

} // namespace

// The line search's longer steps (Newton_settings::step_growth): where the
// model is four times stiffer than the energy, the whole step passes and
// goes a quarter of the way; steps of 2 and 4 times it lower the energy
// further, 8 times it does not. So one iteration reaches the minimum, where
// the plain line search converges linearly (energy x 9/16 per iteration);
// with the growth capped at 2, one iteration goes half of the way.
TEST(InnerSolvers, longer_steps_reach_the_minimum_of_a_stiff_model_at_once)
{
  Eigen::VectorXd c(8), x0(8);
  c << 1., 2., -1., 0.5, 3., -2., 0., 1.;
  x0 << 0., 0., 0., 0., 0., 0., 0., 0.;
  auto run = [&](double growth, int iterations, ic::UV_vector& x) {
    Stiff_model_term term(c, 4.);
    ic::Projected_newton_solver solver({&term}, 8);
    ic::Newton_settings settings;
    settings.max_iterations = iterations;
    settings.tolerance = 1e-12;
    settings.step_growth = growth;
    x = x0;
    return solver.minimize(x, settings);
  };
  ic::UV_vector grown, plain, capped;
  const ic::Newton_report with_growth = run(64., 100, grown);
  const ic::Newton_report without = run(1., 100, plain);
  EXPECT_EQ(int(with_growth.status), int(ic::Newton_status::CONVERGED));
  EXPECT_LE(with_growth.iterations, 2);
  EXPECT_LT((grown - c).norm(), 1e-8 * c.norm());
  EXPECT_EQ(int(without.status), int(ic::Newton_status::CONVERGED));
  EXPECT_GT(without.iterations, 20);
  EXPECT_GT(without.energy, with_growth.energy);
  run(2., 1, capped);
  EXPECT_NEAR((capped - c).norm(), 0.5 * c.norm(), 1e-8 * c.norm());
}

// On a chart no flat map fits (a steep cone), projected Newton ends in a
// tail of whole steps that each gain little (default_step_growth): with the
// longer steps, both solvers reach the same minimum in fewer iterations,
// without a flipped face, with the border barrier and without.
TEST(InnerSolvers, longer_steps_reach_the_same_minimum_in_fewer_iterations)
{
  Solver_chart chart;
  make_solver_chart(cone_soup(6, 16, 1., 3.), chart);
  const std::vector<double> weights(chart.mesh.number_of_faces(), 1.);
  for(SMP::Inner_solver solver : {SMP::Inner_solver::NEWTON, SMP::Inner_solver::PROXY_QUASI_NEWTON})
    for(bool barrier : {false, true})
    {
      ic::UV_vector grown = chart.tutte, plain = chart.tutte;
      ic::Distortion_minimizer a(chart.mesh, weights, barrier, 0., 0., solver),
                               b(chart.mesh, weights, barrier, 0., 0., solver);
      b.set_step_growth(1.);
      const ic::Newton_report with_growth = a.minimize(grown, 2000, 1e-9);
      const ic::Newton_report without = b.minimize(plain, 2000, 1e-9);
      ASSERT_EQ(int(with_growth.status), int(ic::Newton_status::CONVERGED));
      ASSERT_EQ(int(without.status), int(ic::Newton_status::CONVERGED));
      EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, grown), 0);
      EXPECT_NEAR(with_growth.energy, without.energy, 1e-6 * without.energy);
      EXPECT_LT(with_growth.iterations, without.iterations)
        << (solver == SMP::Inner_solver::NEWTON ? "Newton" : "quasi-Newton") << (barrier ? ", barrier" : "");
    }
}
