// The atlas is usable as a texture: global injectivity (no crossing UV
// borders, the barrier of Border_barrier_term.h), packing into the unit square,
// the bounding-box term.
//
// Shapes built to overlap when laid flat (a spiral ramp, a thin annulus on a
// saddle, cut open, a saddle disk with a deep slit) are first unwrapped with
// global_injectivity(false), which must overlap (so the test can fail), then
// with the defaults, which must not (check_cut_result() recounts crossings
// from the outputs and checks the unit square and the coverage). The energy
// terms' gradients are checked against finite differences.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Bounding_box_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/carried_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Seam_closing_term.h>

#include <limits>
#include <map>
#include <random>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = SMP::parameters;
namespace ic = SMP::internal::cut;
using namespace cut_test;

namespace {

std::vector<std::pair<std::string, Soup>> overlapping_shapes()
{
  return {{"spiral ramp", spiral_ramp_soup(72, 4)},
          {"thin saddle annulus cut once", saddle_annulus_soup(120, 4)},
          {"saddle with a deep slit", slit_saddle_soup(10, 36, 2)}};
}

/// E_d each shape must stay below with global injectivity, in the order of
/// overlapping_shapes(): what the method reaches (measured) plus a margin.
const double injective_distortion_bound[] = {4.02, 4.03, 4.17}; // reached: 4.0004, 4.0042, 4.1161

/// Unwraps `soup` without, then with global injectivity; returns the E_d of both.
template <typename Mesh>
std::pair<double, double> unwrap_both_ways(const Soup& soup)
{
  Mesh mesh;
  build_mesh(soup, mesh);
  Cut_run<Mesh> free_run(mesh);
  free_run.run(P::global_injectivity(false));
  check_cut_result(mesh, free_run);
  // the shape does overlap when nothing prevents it
  CUT_ASSERT_TRUE(free_run.result.border_crossings > 0) << "the test shape does not overlap without the barrier";

  Cut_run<Mesh> run(mesh);
  run.run();
  check_cut_result(mesh, run); // no crossing, UVs in [0,1], coverage = UV area
  EXPECT_EQ(run.result.border_crossings, std::size_t(0));
  EXPECT_TRUE(run.result.uv_coverage > 0.1);
  return {free_run.result.distortion, run.result.distortion};
}

/// Chart mesh of a generated disk and a random admissible map near its Tutte embedding.
struct Disk_chart
{
  ic::Indexed_surface<Surface_mesh> surface;
  ic::Chart_mesh mesh;
  std::vector<int> corner_uv;
  ic::UV_vector x;
};

void make_disk_chart(const Soup& soup, Disk_chart& chart)
{
  Surface_mesh mesh;
  build_mesh(soup, mesh);
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), chart.surface) == ic::Indexing_status::OK);
  ic::build_chart_mesh(chart.surface, std::vector<char>(chart.surface.edges.size(), 0), chart.mesh, chart.corner_uv);
  ASSERT_TRUE(ic::disk_charts_embedding(chart.mesh, chart.x) == ic::Embedding_status::OK);
}

/// Central differences of term.value along random directions against the gradient.
void check_gradient(ic::Energy_term& term, const ic::UV_vector& x, std::uint64_t seed)
{
  ic::Hessian_assembler hessian;
  term.declare_elements(hessian);
  hessian.finalize(int(x.size()));
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
  term.add_gradient_and_hessian(x, gradient, hessian);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for(int trial = 0; trial < 5; ++trial)
  {
    Eigen::VectorXd d(x.size());
    for(Eigen::Index i = 0; i < d.size(); ++i) d[i] = normal(rng);
    const double h = 1e-5 * (std::min)(1., 0.5 * term.max_step(x, d));
    const double numeric = (term.value(x + h * d) - term.value(x - h * d)) / (2. * h);
    const double analytic = gradient.dot(d);
    EXPECT_TRUE(std::abs(numeric - analytic) <= 1e-4 * std::abs(analytic) + 1e-12) << "directional derivative " << analytic << " vs finite differences " << numeric;
  }
}

} // namespace

template <typename Mesh>
class InjectivityTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(InjectivityTyped, Mesh_types);

TYPED_TEST(InjectivityTyped, overlapping_shapes_come_out_injective)
{
  std::size_t k = 0;
  for(const auto& shape : overlapping_shapes())
  {
    SCOPED_TRACE(shape.first);
    const auto distortion = unwrap_both_ways<TypeParam>(shape.second);
    EXPECT_GE(distortion.second, 4.);
    EXPECT_LT(distortion.second, injective_distortion_bound[k++]) << "E_d without the barrier " << distortion.first;
  }
}

TEST(Injectivity, world_units_keep_the_scale_and_stay_injective)
{
  Surface_mesh mesh;
  build_mesh(spiral_ramp_soup(72, 4), mesh);
  Cut_run<Surface_mesh> run(mesh);
  run.run(P::world_units(true));
  check_cut_result(mesh, run);
  EXPECT_EQ(run.result.uv_scale, 1.);
  // the ramp is about 2π · 1.5 long: in world units its UVs span more than 1
  double extent = 0.;
  for(auto h : halfedges(mesh)) extent = (std::max)({extent, std::abs(run.uv(h).x()), std::abs(run.uv(h).y())});
  EXPECT_TRUE(extent > 1.);
}

TEST(Injectivity, no_change_where_nothing_overlaps)
{
  // a disk whose map does not overlap: the same UVs with or without the barrier
  Surface_mesh mesh;
  build_mesh(wavy_disk_soup(10, 30, 3), mesh);
  Cut_run<Surface_mesh> free_run(mesh), run(mesh);
  free_run.run(P::global_injectivity(false));
  run.run();
  check_cut_result(mesh, free_run);
  check_cut_result(mesh, run);
  ASSERT_EQ(free_run.result.border_crossings, std::size_t(0));
  EXPECT_EQ(run.result.distortion, free_run.result.distortion);
  EXPECT_EQ(run.result.newton_iterations, free_run.result.newton_iterations);
  std::size_t different = 0;
  for(auto h : halfedges(mesh)) different += run.uv(h) != free_run.uv(h);
  EXPECT_EQ(different, std::size_t(0));
}

/// Distance from `p` to the segment `s` in UV.
double point_segment_distance(const Point_2& p, const std::array<Point_2, 2>& s)
{
  const double dx = s[1].x() - s[0].x(), dy = s[1].y() - s[0].y();
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0. ? ((p.x() - s[0].x()) * dx + (p.y() - s[0].y()) * dy) / l2 : 0.;
  t = (std::max)(0., (std::min)(1., t));
  const double ex = s[0].x() + t * dx - p.x(), ey = s[0].y() + t * dy - p.y();
  return std::sqrt(ex * ex + ey * ey);
}

TEST(Injectivity, padding_and_texture_size_are_honoured)
{
  // two disjoint disks: their UVs are at least padding / texture_size apart
  Surface_mesh mesh;
  build_mesh(two_components_soup(6), mesh);
  for(const double padding : {0., 4., 32.})
  {
    SCOPED_TRACE("padding " + std::to_string(padding));
    Cut_run<Surface_mesh> run(mesh);
    run.run(P::padding(padding, P::texture_size(256)));
    const auto report = check_cut_result(mesh, run);
    ASSERT_EQ(report.box.size(), std::size_t(2));
    // the closest points of the two charts' borders (charts packed by shape)
    std::vector<std::array<Point_2, 2>> border[2];
    for(auto h : halfedges(mesh))
      if(is_border(h, mesh))
      {
        const auto f = face(opposite(h, mesh), mesh);
        const int k = report.chart_of_face.at(f);
        border[k].push_back({run.uv(opposite(h, mesh)), run.uv(prev(opposite(h, mesh), mesh))});
      }
    double gap = std::numeric_limits<double>::infinity();
    for(const auto& s : border[0])
      for(const auto& t : border[1])
        gap = (std::min)({gap, point_segment_distance(s[0], t), point_segment_distance(s[1], t),
                          point_segment_distance(t[0], s), point_segment_distance(t[1], s)});
    EXPECT_TRUE(gap >= padding / 256. * (1. - 1e-9)) << "gap " << gap << " below the padding";
    for(const auto& box : report.box)
      EXPECT_TRUE(box[0] >= padding / 256. - 1e-12 && box[1] >= padding / 256. - 1e-12 &&
            box[2] <= 1. - padding / 256. + 1e-12 && box[3] <= 1. - padding / 256. + 1e-12);
  }
}

TEST(Injectivity, bounding_box_term_fills_the_square)
{
  // a flat 4:1 rectangle: packed as it is (on the square's diagonal) it covers
  // 4 / (5 / sqrt(2))² = 0.32 of the square at most; the gentle square box
  // rounds it off a little, a tight 1:1 box (an explicit aspect ratio) much
  // more, still without flips or crossings. (By default the gentle box would
  // cost this strip more than its distortion budget and be dropped: see the
  // next test; an explicit stiffness keeps it.)
  Surface_mesh mesh;
  build_mesh(grid_soup(24, 6, 4., 1.), mesh);
  Cut_run<Surface_mesh> plain(mesh), gentle(mesh), boxed(mesh), stiff(mesh);
  plain.run(P::bounding_box_stiffness(0.));
  gentle.run(P::bounding_box_stiffness(SMP::gentle_bounding_box_stiffness));
  boxed.run(P::bounding_box_aspect_ratio(1.));
  stiff.run(P::bounding_box_aspect_ratio(1., P::bounding_box_stiffness(SMP::gentle_bounding_box_stiffness)));
  for(const auto* run : {&plain, &gentle, &boxed, &stiff}) check_cut_result(mesh, *run);
  EXPECT_TRUE(plain.result.uv_coverage < 0.321);
  EXPECT_TRUE(gentle.result.uv_coverage > plain.result.uv_coverage + 0.01) << "coverage " << plain.result.uv_coverage << " -> " << gentle.result.uv_coverage;
  EXPECT_TRUE(boxed.result.uv_coverage > gentle.result.uv_coverage + 0.2) << "coverage " << gentle.result.uv_coverage << " -> " << boxed.result.uv_coverage;
  // the price of the box
  EXPECT_TRUE(plain.result.distortion < gentle.result.distortion);
  EXPECT_TRUE(gentle.result.distortion < boxed.result.distortion);
  // an explicit stiffness wins over the tight default of an explicit ratio:
  // the gentle square again, the same map
  EXPECT_EQ(stiff.result.uv_coverage, gentle.result.uv_coverage);
  EXPECT_EQ(stiff.result.distortion, gentle.result.distortion);
  // ratio 0 turns the box off, as stiffness 0 does
  Cut_run<Surface_mesh> off(mesh);
  off.run(P::bounding_box_aspect_ratio(0.));
  EXPECT_EQ(off.result.distortion, plain.result.distortion);
  // wrong values are refused
  Cut_run<Surface_mesh> bad(mesh);
  EXPECT_EQ(bad.run(P::bounding_box_aspect_ratio(-1.)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(bad.run(P::bounding_box_stiffness(-1.)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(bad.run(P::bounding_box_stiffness(std::numeric_limits<double>::infinity())).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(bad.run(P::padding(-1.)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(bad.run(P::texture_size(0)).error, SMP::ERROR_WRONG_PARAMETER);
}

TEST(Injectivity, bounding_box_stays_within_its_distortion_budget)
{
  // the flat 4:1 rectangle again: without box it maps isometrically; the
  // gentle square box costs it more than 0.01 of E_d, so a budget of 0.01
  // weakens the box until it costs less (or drops it)
  Surface_mesh mesh;
  build_mesh(grid_soup(24, 6, 4., 1.), mesh);
  Cut_run<Surface_mesh> plain(mesh), capped(mesh), free_box(mesh);
  plain.run(P::bounding_box_stiffness(0.));
  capped.run(P::bounding_box_distortion_budget(0.01));
  free_box.run(P::bounding_box_distortion_budget(std::numeric_limits<double>::infinity()));
  for(const auto* run : {&plain, &capped, &free_box}) check_cut_result(mesh, *run);
  EXPECT_TRUE(free_box.result.distortion > plain.result.distortion + 0.01) << "E_d " << plain.result.distortion << " -> " << free_box.result.distortion;
  EXPECT_TRUE(capped.result.distortion <= plain.result.distortion + 0.01 + 1e-6) << "E_d " << plain.result.distortion << " -> " << capped.result.distortion;
  EXPECT_TRUE(capped.result.distortion < free_box.result.distortion);
  // the default budget holds too (here the box is dropped)
  Cut_run<Surface_mesh> gentle(mesh);
  gentle.run();
  check_cut_result(mesh, gentle);
  EXPECT_TRUE(gentle.result.distortion <= plain.result.distortion + SMP::gentle_bounding_box_distortion_budget + 1e-6);
  // an explicit stiffness lifts the budget: the box is kept as asked
  Cut_run<Surface_mesh> asked(mesh);
  asked.run(P::bounding_box_stiffness(SMP::gentle_bounding_box_stiffness));
  EXPECT_EQ(asked.result.distortion, free_box.result.distortion);
  Cut_run<Surface_mesh> bad(mesh);
  EXPECT_EQ(bad.run(P::bounding_box_distortion_budget(-0.1)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(bad.run(P::bounding_box_distortion_budget(std::nan(""))).error, SMP::ERROR_WRONG_PARAMETER);
}

// Where the box is dropped, the result is the map the final solve found
// without it, not a map solved again from the boxed one (which stopped at
// E_d 4.138 here, against 4.085 without box).
TEST(Injectivity, a_dropped_box_leaves_the_map_without_box)
{
  Surface_mesh mesh;
  build_mesh(spike_disk_soup(16, 32, 1.5, 0.2), mesh);
  Cut_run<Surface_mesh> plain(mesh), gentle(mesh), free_box(mesh);
  plain.run(P::bounding_box_stiffness(0.));
  gentle.run();
  free_box.run(P::bounding_box_distortion_budget(std::numeric_limits<double>::infinity()));
  for(const auto* run : {&plain, &gentle, &free_box}) check_cut_result(mesh, *run);
  // the box costs more than its budget: it is dropped
  ASSERT_TRUE(free_box.result.distortion > plain.result.distortion + SMP::gentle_bounding_box_distortion_budget)
    << "E_d " << plain.result.distortion << " -> " << free_box.result.distortion;
  EXPECT_NEAR(gentle.result.distortion, plain.result.distortion, 1e-4);
  EXPECT_TRUE(gentle.seam_vector() == plain.seam_vector());
}

/// The Tutte map of a flat disk squashed across: opposite border parts come
/// within the barrier distance of each other, without flips or crossings.
ic::UV_vector squashed(const Disk_chart& chart, double factor)
{
  ic::UV_vector x = chart.x;
  for(Eigen::Index i = 1; i < x.size(); i += 2) x[i] *= factor;
  return x;
}

TEST(Injectivity, border_barrier_gradient_matches_finite_differences)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(4, 16), chart);
  ic::Border_barrier_term barrier(chart.mesh);
  ASSERT_TRUE(barrier.epsilon() > 0.);
  // far apart: no pair, no energy, the pattern stays
  EXPECT_TRUE(barrier.update(chart.x) == ic::Energy_term::Update::VALUES);
  EXPECT_EQ(barrier.number_of_declared_pairs(), std::size_t(0));
  EXPECT_EQ(barrier.value(chart.x), 0.);
  // squashed: pairs come close, the pattern grows, the energy is positive
  const ic::UV_vector x = squashed(chart, 0.03);
  ASSERT_TRUE(!barrier.has_crossing(x));
  EXPECT_TRUE(barrier.update(x) == ic::Energy_term::Update::MORE_ELEMENTS);
  EXPECT_TRUE(barrier.number_of_declared_pairs() > 0);
  EXPECT_TRUE(barrier.value(x) > 0.);
  EXPECT_TRUE(barrier.update(x) == ic::Energy_term::Update::NONE); // nothing new at the same x
  check_gradient(barrier, x, 1);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  ic::UV_vector y = x;
  for(Eigen::Index i = 0; i < y.size(); ++i) y[i] += jitter(rng);
  barrier.update(y);
  ASSERT_TRUE(std::isfinite(barrier.value(y)) && barrier.value(y) > 0.);
  check_gradient(barrier, y, 2);
}

// A border vertex on a segment of its chart in floating point, but off it
// for the exact predicates (the two sides of a slit of zero width, as on
// CGAL's boeing.off after the alternation): the barrier's energy there is
// infinite, so the chart counts as crossing itself (the final solve then
// restarts it), though no two segments meet exactly.
TEST(Injectivity, a_vertex_on_a_segment_in_floating_point_is_a_crossing)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(4, 16), chart);
  // the border loop: next[a] = b for each border segment ab
  std::map<std::pair<int, int>, int> directed;
  for(const auto& t : chart.mesh.faces)
    for(int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}] = 1;
  std::map<int, int> next;
  std::vector<std::array<int, 2>> border;
  for(const auto& t : chart.mesh.faces)
    for(int k = 0; k < 3; ++k)
      if(!directed.count({t[(k + 1) % 3], t[k]}))
      {
        next[t[k]] = t[(k + 1) % 3];
        border.push_back({t[k], t[(k + 1) % 3]});
      }
  ASSERT_EQ(border.size(), std::size_t(16));
  // v goes onto the segment wz after it (w its next vertex)
  const int v = border[0][0], w = next.at(v), z = next.at(w);
  const ic::Vector2 a(chart.x[2 * w], chart.x[2 * w + 1]), b(chart.x[2 * z], chart.x[2 * z + 1]);
  using Point = CGAL::Epick::Point_2;
  ic::Vector2 p;
  bool found = false;
  for(int k = 1; k < 1000 && !found; ++k)
  {
    p = a + (double(k) / 1000.) * (b - a);
    double t;
    ic::Vector2 n;
    found = ic::point_segment_distance(p, a, b, t, n) == 0.
            && CGAL::orientation(Point(a.x(), a.y()), Point(b.x(), b.y()), Point(p.x(), p.y())) != CGAL::COLLINEAR;
  }
  ASSERT_TRUE(found);
  ic::UV_vector x = chart.x;
  x[2 * v] = p.x();
  x[2 * v + 1] = p.y();
  EXPECT_EQ(ic::count_border_crossings(border, x, nullptr, 1, true), std::size_t(0)); // exactly, nothing meets
  ic::Border_barrier_term barrier(chart.mesh);
  EXPECT_EQ(barrier.charts_with_crossing(chart.x), std::vector<char>(1, 0));
  EXPECT_EQ(barrier.charts_with_crossing(x), std::vector<char>(1, 1));
  barrier.update(x);
  EXPECT_FALSE(std::isfinite(barrier.value(x)));
}

TEST(Injectivity, border_barrier_hessian_is_positive_semidefinite)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(4, 16), chart);
  auto hessian_at = [](ic::Border_barrier_term& barrier, const ic::UV_vector& x) {
    ic::Hessian_assembler hessian;
    barrier.declare_elements(hessian);
    hessian.finalize(int(x.size()));
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    barrier.add_gradient_and_hessian(x, gradient, hessian);
    return Eigen::MatrixXd(Eigen::MatrixXd(hessian.matrix()).selfadjointView<Eigen::Lower>());
  };
  auto expect_psd = [](const Eigen::MatrixXd& H) {
    ASSERT_TRUE(H.norm() > 0.);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(H);
    EXPECT_TRUE(eigen.eigenvalues().minCoeff() >= -1e-9 * eigen.eigenvalues().maxCoeff());
  };
  // every close pair in the pattern
  const ic::UV_vector x = squashed(chart, 0.03);
  ic::Border_barrier_term barrier(chart.mesh);
  barrier.update(x);
  ASSERT_EQ(barrier.number_of_undeclared_close_pairs(x), std::size_t(0));
  expect_psd(hessian_at(barrier, x));
  // a pattern made where the disk was round, the disk squashed since: the
  // pairs that came close add only their diagonal blocks, and the matrix
  // stays PSD; their gradient counts in full
  ic::Border_barrier_term late(chart.mesh);
  late.update(squashed(chart, 0.5));
  const std::size_t declared = late.number_of_declared_pairs();
  ASSERT_TRUE(!late.has_crossing(x));
  ASSERT_TRUE(late.number_of_undeclared_close_pairs(x) > 0);
  expect_psd(hessian_at(late, x));
  EXPECT_EQ(late.number_of_declared_pairs(), declared);
  check_gradient(late, x, 3);
}

/// The barrier searches its pairs in blocks of border vertices on all cores
/// and reuses the pairs value() found for the gradient at the same map: on
/// a chart with several blocks of border vertices, the energy, gradient,
/// Hessian and step bound are the same bits on one thread as on all, and
/// with the reuse as without it, also once update() changed ε in between.
TEST(Injectivity, border_barrier_is_the_same_on_any_thread_count_and_with_its_reuse)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(3, int(3 * ic::tuning::barrier_pair_block)), chart);
  const ic::UV_vector x = squashed(chart, 0.002);
  ic::UV_vector step = ic::UV_vector::Zero(x.size());
  for(Eigen::Index i = 1; i < x.size(); i += 2) step[i] = -2. * x[i]; // the disk flat on its axis halfway
  struct Outputs
  {
    double value = 0., step_bound = 0.;
    Eigen::VectorXd gradient;
    std::vector<double> hessian;
    std::size_t pairs = 0;
  };
  // `value_first`: value() at x before the gradient (its pairs reused); `detour`: update() at another map
  // and value() there first, then update() at x again (ε changed twice, the reuse must not apply)
  auto outputs = [&](bool value_first, bool detour) {
    ic::Border_barrier_term barrier(chart.mesh);
    if(detour)
    {
      const ic::UV_vector y = squashed(chart, 0.004);
      barrier.update(y);
      barrier.value(y);
      barrier.value(x);
    }
    barrier.update(x);
    Outputs out;
    if(value_first) out.value = barrier.value(x);
    ic::Hessian_assembler hessian;
    barrier.declare_elements(hessian);
    hessian.finalize(int(x.size()));
    out.gradient = Eigen::VectorXd::Zero(x.size());
    barrier.add_gradient_and_hessian(x, out.gradient, hessian);
    out.hessian.assign(hessian.matrix().valuePtr(), hessian.matrix().valuePtr() + hessian.matrix().nonZeros());
    if(!value_first) out.value = barrier.value(x);
    out.step_bound = barrier.max_step(x, step);
    out.pairs = barrier.number_of_declared_pairs();
    return out;
  };
  // after the detour the pattern holds the pairs declared there too (its Hessian differs in layout)
  auto expect_same = [](const Outputs& a, const Outputs& b, bool same_pattern = true) {
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.step_bound, b.step_bound);
    EXPECT_TRUE(a.gradient == b.gradient);
    if(!same_pattern) return;
    EXPECT_EQ(a.pairs, b.pairs);
    EXPECT_TRUE(a.hessian == b.hessian);
  };
  const Outputs reference = outputs(false, false);
  // the test means something: pairs in several blocks, energy, a contact within the step
  ASSERT_TRUE(reference.pairs > 2 * ic::tuning::barrier_pair_block);
  ASSERT_TRUE(reference.value > 0. && std::isfinite(reference.value));
  ASSERT_TRUE(reference.step_bound > 0. && reference.step_bound <= 0.5);
  ASSERT_TRUE(reference.gradient.norm() > 0.);
  expect_same(outputs(true, false), reference);
  expect_same(outputs(true, true), reference, false);
  expect_same(outputs(true, true), outputs(false, true));
#ifdef CGAL_LINKED_WITH_TBB
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    expect_same(outputs(false, false), reference);
    expect_same(outputs(true, true), reference, false);
  }
#endif
}

/// Where the map squashes the border to a fraction of its 3D length (a Tutte
/// map of a mesh with holes), ε follows the map's scale: the pairs and the
/// energy of a squashed chart are the same at any smaller scale, and a
/// vertex does not pair with every segment (as with one ε in 3D units).
TEST(Injectivity, border_barrier_distance_follows_a_squashed_border)
{
  for(int segments : {48, 96})
  {
    Disk_chart chart;
    make_disk_chart(flat_disk_soup(6, segments), chart);
    const ic::UV_vector x = squashed(chart, 0.03);
    std::vector<std::size_t> pairs;
    std::vector<double> energy;
    for(double scale : {1e-3, 1e-6})
    {
      ic::Border_barrier_term barrier(chart.mesh);
      const ic::UV_vector small = scale * x;
      barrier.update(small);
      pairs.push_back(barrier.number_of_declared_pairs());
      energy.push_back(barrier.value(small));
    }
    EXPECT_EQ(pairs[0], pairs[1]);
    EXPECT_NEAR(energy[0], energy[1], 1e-9 * energy[0]);
    // of the n (n - 3) pairs of a vertex and a segment not incident to it
    const std::size_t n = std::size_t(segments);
    EXPECT_TRUE(pairs[0] > 0 && 3 * pairs[0] < 2 * n * (n - 3)) << pairs[0] << " pairs of " << n * (n - 3);
  }
}

TEST(Injectivity, border_barrier_stops_a_border_before_it_crosses_another)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(4, 16), chart);
  ic::Border_barrier_term barrier(chart.mesh);
  barrier.update(chart.x);
  EXPECT_TRUE(!barrier.has_crossing(chart.x));
  // push one border vertex straight across the disk: the step is cut where
  // it would meet the border on the other side
  const auto segments = ic::border_segments(chart.mesh);
  const int v = segments.front()[0];
  ic::UV_vector step = ic::UV_vector::Zero(chart.x.size());
  step.segment<2>(2 * v) = -3. * chart.x.segment<2>(2 * v);
  const double t = barrier.max_step(chart.x, step);
  ASSERT_TRUE(t > 0. && t < 1.);
  EXPECT_TRUE(!barrier.has_crossing(chart.x + 0.99 * t * step));
  EXPECT_TRUE(barrier.has_crossing(chart.x + (std::min)(1., 1.01 * t) * step));
  // a map whose border crosses itself has no finite energy
  ic::UV_vector crossed = chart.x;
  crossed.segment<2>(2 * v) *= -1.5;
  EXPECT_TRUE(barrier.has_crossing(crossed));
  EXPECT_TRUE(std::isinf(barrier.value(crossed)));
  // the chart crossing itself is the one reported
  const std::vector<char> charts = barrier.charts_with_crossing(crossed);
  ASSERT_EQ(charts.size(), std::size_t(1));
  EXPECT_EQ(charts[0], 1);
}

TEST(Injectivity, seam_closing_springs_gradient_matches_finite_differences)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(5, 20), chart);
  const int n = chart.mesh.number_of_vertices;
  ic::Seam_closing_term springs({{0, n - 1}, {1, n / 2}, {2, 3}}, 7.);
  EXPECT_TRUE(springs.value(chart.x) > 0.);
  check_gradient(springs, chart.x, 5);
  // a pair at one point costs nothing
  ic::UV_vector x = chart.x;
  x.segment<2>(2 * (n - 1)) = x.segment<2>(0);
  EXPECT_REL(springs.value(x), springs.value(chart.x) - 7. * (chart.x.segment<2>(0) - chart.x.segment<2>(2 * (n - 1))).squaredNorm(), 1e-12);
}

TEST(Injectivity, bounding_box_gradient_matches_finite_differences)
{
  Disk_chart chart;
  make_disk_chart(flat_disk_soup(5, 20), chart);
  // stretch the disk so that border vertices lie outside the 2:1 box
  ic::UV_vector x = chart.x;
  for(Eigen::Index i = 0; i < x.size(); i += 2) x[i] *= 1.7;
  ic::Bounding_box_term box(chart.mesh, 2.);
  box.update(x);
  EXPECT_TRUE(box.value(x) > 0.);
  check_gradient(box, x, 3);
  // inside the box (the disk shrunk about its center) there is nothing to pay
  ic::UV_vector center = ic::UV_vector::Zero(2);
  for(Eigen::Index i = 0; i < x.size(); i += 2) center += x.segment<2>(i);
  center /= double(x.size() / 2);
  ic::UV_vector small = x;
  for(Eigen::Index i = 0; i < x.size(); i += 2) small.segment<2>(i) = center + 0.1 * (x.segment<2>(i) - center);
  EXPECT_EQ(box.value(small), 0.);
}


// The start of a chart that crossed itself in the final solve after splits
// (carried_map.h): the valid map the splits started from, carried over their
// new cut. On a cone solved under the barrier, then cut from its border
// toward its apex: the carried map is valid (no flipped face, a border that
// does not meet itself), keeps every vertex off the cut where it was, parts
// the two copies of each vertex on the cut, and is a start from which the
// barrier's solve converges in fewer iterations than from the Tutte map.
TEST(Injectivity, a_valid_map_carried_over_a_new_cut_starts_the_barrier_solve)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(cone_soup(8, 24, 1., 1.2));
  ic::Indexed_surface<Surface_mesh> surface;
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), surface) == ic::Indexing_status::OK);
  ic::Chart_mesh before, after;
  std::vector<int> corner_uv;
  std::vector<char> is_cut(surface.edges.size(), 0);
  ic::build_chart_mesh(surface, is_cut, before, corner_uv);
  ic::UV_vector x_before;
  ASSERT_TRUE(ic::disk_charts_embedding(before, x_before) == ic::Embedding_status::OK);
  const std::vector<double> weights(before.number_of_faces(), 1.);
  ic::Distortion_minimizer(before, weights, true).minimize(x_before, 500, 1e-9);
  ASSERT_EQ(ic::number_of_flipped_faces(before, x_before), 0);

  // the cut: from the border vertex of largest x, 5 edges toward the apex
  const std::vector<char> on_border = surface.border_vertices();
  std::vector<std::vector<std::array<int, 2>>> neighbours(surface.number_of_vertices()); // (vertex, edge)
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int a = surface.corner_vertex[f][k], b = surface.corner_vertex[f][(k + 1) % 3];
      neighbours[std::size_t(a)].push_back({b, surface.edge_of[3 * f + std::size_t(k)]});
      neighbours[std::size_t(b)].push_back({a, surface.edge_of[3 * f + std::size_t(k)]});
    }
  auto apex_distance = [&](int v) {
    const auto& p = surface.points[std::size_t(v)];
    return std::hypot(p.x(), p.y());
  };
  int v = -1;
  for(int u = 0; u < int(surface.number_of_vertices()); ++u)
    if(on_border[std::size_t(u)] && (v < 0 || surface.points[std::size_t(u)].x() > surface.points[std::size_t(v)].x()))
      v = u;
  for(int step = 0; step < 5; ++step)
  {
    std::array<int, 2> next{-1, -1};
    for(const auto& n : neighbours[std::size_t(v)])
      if(!on_border[std::size_t(n[0])] && (next[0] < 0 || apex_distance(n[0]) < apex_distance(next[0]))) next = n;
    ASSERT_GE(next[0], 0);
    is_cut[std::size_t(next[1])] = 1;
    v = next[0];
  }
  ic::build_chart_mesh(surface, is_cut, after, corner_uv);
  ASSERT_EQ(after.number_of_vertices, before.number_of_vertices + 5);

  ic::Carried_map carried;
  ic::carry_map_over_new_cuts(before, x_before, after, carried);
  ASSERT_EQ(carried.valid.size(), 1u);
  EXPECT_TRUE(carried.valid[0]);
  EXPECT_EQ(ic::number_of_flipped_faces(after, carried.x), 0);
  EXPECT_EQ(ic::Border_barrier_term(after).charts_with_crossing(carried.x), std::vector<char>(1, 0));
  std::vector<int> origin(std::size_t(after.number_of_vertices)), copies(std::size_t(before.number_of_vertices), 0);
  for(std::size_t f = 0; f < after.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k) origin[std::size_t(after.faces[f][k])] = before.faces[f][k];
  for(int o : origin) ++copies[std::size_t(o)];
  int split = 0;
  for(int u = 0; u < after.number_of_vertices; ++u)
  {
    const int o = origin[std::size_t(u)];
    if(copies[std::size_t(o)] == 1)
      EXPECT_EQ(carried.x.segment<2>(2 * u), x_before.segment<2>(2 * o)) << u;
    else
    {
      ++split;
      for(int w = u + 1; w < after.number_of_vertices; ++w)
        if(origin[std::size_t(w)] == o) EXPECT_GT((carried.x.segment<2>(2 * u) - carried.x.segment<2>(2 * w)).norm(), 0.);
    }
  }
  EXPECT_EQ(split, 10); // the border vertex and the four inside, twice; the tip once

  ic::UV_vector tutte, from_carried = carried.x;
  ASSERT_TRUE(ic::disk_charts_embedding(after, tutte) == ic::Embedding_status::OK);
  const std::vector<double> after_weights(after.number_of_faces(), 1.);
  const ic::Newton_report carried_report = ic::Distortion_minimizer(after, after_weights, true).minimize(from_carried, 500, 1e-9);
  const ic::Newton_report tutte_report = ic::Distortion_minimizer(after, after_weights, true).minimize(tutte, 500, 1e-9);
  ASSERT_EQ(int(carried_report.status), int(ic::Newton_status::CONVERGED));
  ASSERT_EQ(int(tutte_report.status), int(ic::Newton_status::CONVERGED));
  EXPECT_EQ(ic::number_of_flipped_faces(after, from_carried), 0);
  EXPECT_LT(carried_report.iterations, tutte_report.iterations);
  EXPECT_LE(carried_report.energy, tutte_report.energy * (1. + 1e-6));
}
