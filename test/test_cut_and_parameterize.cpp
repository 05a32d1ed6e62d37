// cut_and_parameterize() end to end on disks with an obvious place to cut (a
// cone's apex, a hemisphere, a tall narrow spike): seams appear there, E_d
// drops well below the best map of the uncut disk, the atlas is valid (see
// cut_result_checks.h) and CGAL's own parameterizers accept the seam mesh.
// Then the contract of the options: scale invariance, determinism, user
// seams kept, per-face λ, progress callback and cancellation, invalid
// parameters, several passes, and the timings and counts of the result.
#include "cut_result_checks.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <iomanip>
#include <map>
#include <set>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace cut_test;

namespace {

template <typename Mesh>
using vertex_t = typename boost::graph_traits<Mesh>::vertex_descriptor;
template <typename Mesh>
using edge_t = typename boost::graph_traits<Mesh>::edge_descriptor;
template <typename Mesh>
using face_t = typename boost::graph_traits<Mesh>::face_descriptor;

/// E_d of the best flip-free map of the uncut disk (symmetric Dirichlet).
template <typename Mesh>
double uncut_distortion(const Mesh& mesh)
{
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  CUT_ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
  return SMP::distortion_energy(mesh, uv);
}

/// Vertices of seam edges.
template <typename Mesh>
std::set<vertex_t<Mesh>> seam_vertices(const Mesh& mesh, const Cut_run<Mesh>& run)
{
  std::set<vertex_t<Mesh>> result;
  for(auto e : edges(mesh))
    if(run.is_seam(e))
    {
      result.insert(source(e, mesh));
      result.insert(target(e, mesh));
    }
  return result;
}

/// Builds the seam mesh of the run's seams and flattens it with CGAL's LSCM
/// and ARAP from its longest border: both must succeed with finite UVs on
/// every corner.
template <typename Mesh>
void check_cgal_parameterizers_accept_the_seams(const Mesh& mesh, const Cut_run<Mesh>& run)
{
  auto sem = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto svm = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto e : edges(mesh)) put(sem, e, run.is_seam(e));
  auto seam_mesh = SMP::make_seam_mesh(mesh, sem, svm); // CGAL's parameterize() wants it non-const
  using Seam_mesh = decltype(seam_mesh);
  const long chi = long(num_vertices(seam_mesh)) - long(num_edges(seam_mesh)) + long(num_faces(seam_mesh));
  EXPECT_EQ(chi, 1L);
  EXPECT_EQ(number_of_border_cycles(seam_mesh), std::size_t(1));
  const auto border = PMP::longest_border(seam_mesh).first;
  ASSERT_TRUE(border != boost::graph_traits<Seam_mesh>::null_halfedge());
  // the UVs of cut_and_parameterize are a valid vertex UV map of the seam mesh
  auto& r = const_cast<Cut_run<Mesh>&>(run);
  EXPECT_EQ(SMP::number_of_flipped_faces(seam_mesh, r.uvs()), std::size_t(0));
  EXPECT_REL(SMP::distortion_energy(seam_mesh, r.uvs(), SMP::parameters::uv_scale(run.result.uv_scale)), run.result.distortion, 1e-9);
  {
    auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
    const SMP::Error_code status = SMP::parameterize(seam_mesh, SMP::LSCM_parameterizer_3<Seam_mesh>(), border, uv);
    EXPECT_TRUE(status == SMP::OK) << "LSCM on the seam mesh: " << SMP::error_message(status);
    std::size_t non_finite = 0;
    for(auto h : halfedges(mesh))
      if(!is_border(h, mesh))
      {
        const Point_2 p = get(uv, target(typename boost::graph_traits<Seam_mesh>::halfedge_descriptor(h), seam_mesh));
        if(!std::isfinite(p.x()) || !std::isfinite(p.y())) ++non_finite;
      }
    EXPECT_EQ(non_finite, std::size_t(0));
  }
  {
    auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
    // ARAP's final MVC post-processing step re-embeds ARAP's own result and
    // reports ERROR_NON_CONVEX_BORDER when that result's border overlaps
    // itself (spike); that is about ARAP's map, not about the seam mesh.
    const SMP::Error_code status = SMP::parameterize(seam_mesh, SMP::ARAP_parameterizer_3<Seam_mesh>(), border, uv);
    EXPECT_TRUE(status == SMP::OK || status == SMP::ERROR_NON_CONVEX_BORDER) << "ARAP on the seam mesh: " << SMP::error_message(status);
  }
}

void print(const std::string& what, const SMP::Cut_and_parameterize_result& r, double uncut)
{
  std::cout << std::defaultfloat << std::setprecision(6) << "    " << what << ": " << r.number_of_seam_edges
            << " seam edges, " << r.number_of_charts << " charts, E_d " << r.distortion << " (uncut " << uncut
            << "), E_s " << r.seam_length << std::endl;
}

/// The timings of a result: finite, non-negative, the phases within the
/// total; and at least one Cholesky factorization per Newton iteration
/// (each iteration factorizes its Hessian, and so does the step that finds
/// convergence). `completed`: the run went to the end (not canceled).
void check_timings(const SMP::Cut_and_parameterize_result& r, bool completed = true)
{
  const SMP::Cut_and_parameterize_timings& t = r.timings;
  const double parts[] = {t.initialization, t.u_steps, t.v_steps, t.cut_extraction, t.final_solve, t.packing};
  double sum = 0.;
  for(const double x : parts)
  {
    EXPECT_TRUE(std::isfinite(x) && x >= 0.) << "phase time " << x;
    sum += x;
  }
  EXPECT_TRUE(std::isfinite(t.total) && t.total > 0.) << "total time " << t.total;
  // the phases are disjoint intervals inside the total's
  EXPECT_TRUE(sum <= t.total * (1. + 1e-9) + 1e-6) << "phases " << sum << " s, total " << t.total << " s";
  if(completed)
  {
    EXPECT_TRUE(r.number_of_factorizations > 0); // at least the first direction and the converged one
    EXPECT_TRUE(r.newton_iterations > 0);
    EXPECT_TRUE(t.initialization > 0. && t.final_solve > 0.);
  }
}

// A straight seam from the apex to the border unrolls this cone isometrically (E_d = 4).
const double cone_height = 6.;
Soup tall_cone() { return cone_soup(12, 32, 1., cone_height); } // 736 faces, apex first
Soup bowl() { return sphere_cap_soup(12, 36, 0.9 * pi); }       // 828 faces, deep bowl
Soup spike() { return spike_disk_soup(16, 32, 1.5, 0.2); } // 992 faces

} // namespace

// --- obvious places to cut --------------------------------------------------

template <typename Mesh>
class CutAndParameterizeTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(CutAndParameterizeTyped, Mesh_types);

TYPED_TEST(CutAndParameterizeTyped, cone_is_cut_to_its_apex)
{
  const Soup soup = tall_cone();
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  const vertex_t<TypeParam> apex = vertex_of[0];
  ASSERT_TRUE(std::abs(get(get(CGAL::vertex_point, mesh), apex).z() - cone_height) < 1e-12);
  const double uncut = uncut_distortion(mesh);

  Cut_run<TypeParam> run(mesh);
  run.run();
  const auto report = check_cut_result(mesh, run);
  print("cone", run.result, uncut);
  ASSERT_TRUE(report.valid);
  EXPECT_TRUE(run.result.number_of_seam_edges > 0);
  // a seam reaches the apex or its one-ring (the apex is the only curved point)
  const auto on_seam = seam_vertices(mesh, run);
  bool near_apex = on_seam.count(apex) > 0;
  for(auto w : vertices_around_target(halfedge(apex, mesh), mesh)) near_apex = near_apex || on_seam.count(w) > 0;
  EXPECT_TRUE(near_apex) << "no seam vertex in the apex's one-ring";
  // and it is connected to the border (else the chart would not be a disk,
  // checked above); at least half of the excess distortion goes away (a
  // straight seam from the apex to the border gives E_d = 4)
  EXPECT_TRUE(run.result.distortion < uncut - 0.5 && run.result.distortion < 0.5 * (uncut + 4.)) << "E_d " << run.result.distortion << " vs uncut " << uncut;
  EXPECT_TRUE(run.result.initial_distortion > run.result.distortion);
  check_timings(run.result);
  EXPECT_TRUE(run.result.timings.u_steps > 0. && run.result.timings.v_steps > 0.);
  check_cgal_parameterizers_accept_the_seams(mesh, run);
}

TYPED_TEST(CutAndParameterizeTyped, deep_bowl_is_cut_from_its_border)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  const double uncut = uncut_distortion(mesh);
  Cut_run<TypeParam> run(mesh);
  run.run();
  const auto report = check_cut_result(mesh, run);
  print("deep bowl", run.result, uncut);
  ASSERT_TRUE(report.valid);
  EXPECT_TRUE(run.result.number_of_seam_edges > 0);
  // seams of a disk whose chart stays a disk start at the border
  bool touches_border = false;
  for(auto v : seam_vertices(mesh, run)) touches_border = touches_border || is_border(v, mesh);
  EXPECT_TRUE(touches_border);
  EXPECT_TRUE(run.result.distortion < uncut - 0.3) << "E_d " << run.result.distortion << " vs uncut " << uncut;
  if(report.number_of_charts == 1) check_cgal_parameterizers_accept_the_seams(mesh, run);
}

TYPED_TEST(CutAndParameterizeTyped, spike_is_cut)
{
  const double height = 1.5;
  const Soup soup = spike();
  TypeParam mesh;
  build_mesh(soup, mesh);
  const double uncut = uncut_distortion(mesh);
  Cut_run<TypeParam> run(mesh);
  run.run();
  const auto report = check_cut_result(mesh, run);
  print("spike", run.result, uncut);
  ASSERT_TRUE(report.valid);
  // seams climb the spike: some seam vertex is above half its height
  double highest = -1.;
  for(auto v : seam_vertices(mesh, run)) highest = (std::max)(highest, get(get(CGAL::vertex_point, mesh), v).z());
  EXPECT_TRUE(highest > 0.5 * height) << "highest seam vertex at z = " << highest;
  EXPECT_TRUE(run.result.distortion < uncut - 0.5) << "E_d " << run.result.distortion << " vs uncut " << uncut;
  if(report.number_of_charts == 1) check_cgal_parameterizers_accept_the_seams(mesh, run);
}

// --- contract of the options -------------------------------------------------

TYPED_TEST(CutAndParameterizeTyped, scale_invariance)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  Cut_run<TypeParam> run(mesh);
  run.run();
  ASSERT_TRUE(run.result.ok());
  for(const double s : {1e-3, 1e3})
  {
    SCOPED_TRACE("scale " + to_text(s));
    Soup scaled = soup;
    scaled.scale(s);
    TypeParam other;
    build_mesh(scaled, other);
    Cut_run<TypeParam> other_run(other);
    other_run.run();
    check_cut_result(other, other_run);
    EXPECT_TRUE(other_run.seam_vector() == run.seam_vector());
    EXPECT_EQ(other_run.result.number_of_seam_edges, run.result.number_of_seam_edges);
    EXPECT_REL(other_run.result.distortion, run.result.distortion, 1e-6);
    EXPECT_REL(other_run.result.seam_length, run.result.seam_length, 1e-6);
  }
}

TYPED_TEST(CutAndParameterizeTyped, determinism)
{
  const Soup soup = spike();
  TypeParam mesh;
  build_mesh(soup, mesh);
  Cut_run<TypeParam> a(mesh), b(mesh);
  a.run();
  b.run();
  ASSERT_TRUE(a.result.ok() && b.result.ok());
  expect_identical_outputs({a.seam_vector(), b.seam_vector()}, {a.uv_vector(), b.uv_vector()});
  EXPECT_TRUE(a.result.distortion == b.result.distortion);
  EXPECT_EQ(a.result.newton_iterations, b.result.newton_iterations);
}

// Parallel loops write per-index slots and reduce in index order: the
// output must not depend on how many threads run them (skipped without TBB;
// above the CHOLMOD and METIS thresholds: test_determinism_large.cpp).
TEST(CutAndParameterize, determinism_across_thread_counts)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(24, 48, 1.5, 0.2)); // over 2000 faces: loops split
  expect_same_result_for_thread_counts(mesh, {1, 2, 5}, [](Cut_run<Surface_mesh>& run) { return run.run(); });
}

TYPED_TEST(CutAndParameterizeTyped, user_seams_are_kept)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  // a path from the border vertex of smallest x to a vertex near the pole
  vertex_t<TypeParam> from = *vertices(mesh).begin(), to = from;
  bool found_border = false;
  for(auto v : vertices(mesh))
  {
    if(is_border(v, mesh) && (!found_border || get(vpm, v).x() < get(vpm, from).x()))
    {
      from = v;
      found_border = true;
    }
    const auto p = get(vpm, v), q = get(vpm, to);
    if(std::abs(p.z() - 0.95) + std::abs(p.y()) < std::abs(q.z() - 0.95) + std::abs(q.y())) to = v;
  }
  ASSERT_TRUE(is_border(from, mesh));
  const auto user = shortest_edge_path(mesh, from, to);
  ASSERT_TRUE(user.size() >= 5);
  Cut_run<TypeParam> run(mesh);
  for(auto e : user) run.seam_storage[e] = true;
  run.run();
  check_cut_result(mesh, run);
  std::size_t kept = 0;
  for(auto e : user) kept += run.is_seam(e) ? 1 : 0;
  EXPECT_EQ(kept, user.size());
  EXPECT_TRUE(run.result.number_of_seam_edges >= user.size());

  // a user seam on the border is not a seam (seams are interior edges)
  Cut_run<TypeParam> border_run(mesh);
  const auto border_edge = edge(halfedge(from, mesh), mesh);
  ASSERT_TRUE(is_border(border_edge, mesh));
  border_run.seam_storage[border_edge] = true;
  border_run.run();
  check_cut_result(mesh, border_run);
  EXPECT_TRUE(!border_run.is_seam(border_edge));
}

// A single inner edge given as a seam, away from the border: alone, no map
// can open it (the corners on its two sides stay joined at both ends), so
// it is joined to the border by the cheapest path (check_cut_result() fails
// on a seam piece floating inside a chart). A flat disk needs no seam of its own.
TYPED_TEST(CutAndParameterizeTyped, a_lone_user_seam_edge_is_joined_to_the_border)
{
  TypeParam mesh;
  build_mesh(flat_disk_soup(8, 24), mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  auto radius = [&](vertex_t<TypeParam> v) { const auto p = get(vpm, v); return std::hypot(p.x(), p.y()); };
  // the edge whose midpoint is nearest to the point (0.4, 0) of the unit disk
  auto lone = *edges(mesh).begin();
  double best = std::numeric_limits<double>::infinity();
  for(auto e : edges(mesh))
  {
    const auto p = get(vpm, source(e, mesh)), q = get(vpm, target(e, mesh));
    const double d = std::hypot(0.5 * (p.x() + q.x()) - 0.4, 0.5 * (p.y() + q.y()));
    if(d < best) { best = d; lone = e; }
  }
  ASSERT_FALSE(is_border(source(lone, mesh), mesh) || is_border(target(lone, mesh), mesh));
  ASSERT_LT(std::max(radius(source(lone, mesh)), radius(target(lone, mesh))), 0.7);
  Cut_run<TypeParam> run(mesh);
  run.seam_storage[lone] = true;
  run.run(SMP::parameters::lambda(20.));
  check_cut_result(mesh, run);
  EXPECT_TRUE(run.is_seam(lone));
  // it opened: the two faces of the edge do not share the UVs of both its ends
  const auto h = halfedge(lone, mesh), o = opposite(h, mesh);
  const bool joined_at_target = run.uv(h) == run.uv(prev(o, mesh));
  const bool joined_at_source = run.uv(prev(h, mesh)) == run.uv(o);
  EXPECT_FALSE(joined_at_target && joined_at_source);
  EXPECT_GT(run.result.number_of_seam_edges, std::size_t(1)); // the path to the border came with it
  EXPECT_EQ(run.result.number_of_charts, std::size_t(1));
}

TYPED_TEST(CutAndParameterizeTyped, face_lambda_map_keeps_seams_out_of_a_region)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  check_cut_result(mesh, plain);
  ASSERT_TRUE(plain.result.number_of_seam_edges > 0);
  // mean direction (angle around the axis) of the seams found
  double sx = 0., sy = 0.;
  for(auto v : seam_vertices(mesh, plain))
  {
    sx += get(vpm, v).x();
    sy += get(vpm, v).y();
  }
  const double direction = std::atan2(sy, sx);
  // protect the sector of ±60° around it, away from the pole
  auto region = get(CGAL::dynamic_face_property_t<bool>(), mesh);
  auto lambda = get(CGAL::dynamic_face_property_t<double>(), mesh);
  std::size_t protected_faces = 0;
  for(auto f : faces(mesh))
  {
    double cx = 0., cy = 0.;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      cx += get(vpm, v).x() / 3.;
      cy += get(vpm, v).y() / 3.;
    }
    double d = std::atan2(cy, cx) - direction;
    while(d > pi) d -= 2. * pi;
    while(d < -pi) d += 2. * pi;
    const bool in = std::abs(d) < pi / 3. && std::hypot(cx, cy) > 0.25;
    put(region, f, in);
    put(lambda, f, in ? 100. : 1.);
    protected_faces += in ? 1 : 0;
  }
  ASSERT_TRUE(protected_faces > 50);
  auto seams_in_region = [&](const Cut_run<TypeParam>& run) {
    std::size_t n = 0;
    for(auto e : edges(mesh))
    {
      if(!run.is_seam(e)) continue;
      const auto h = halfedge(e, mesh);
      if(get(region, face(h, mesh)) || get(region, face(opposite(h, mesh), mesh))) ++n;
    }
    return n;
  };
  const std::size_t before = seams_in_region(plain);
  EXPECT_TRUE(before > 0);
  Cut_run<TypeParam> weighted(mesh);
  weighted.run(SMP::parameters::face_lambda_map(lambda));
  check_cut_result(mesh, weighted);
  const std::size_t after = seams_in_region(weighted);
  std::cout << "    seam edges in the protected region: " << before << " without the map, " << after
            << " with it (" << weighted.result.number_of_seam_edges << " in all)" << std::endl;
  EXPECT_TRUE(after < before);
  EXPECT_TRUE(weighted.result.number_of_seam_edges > 0); // the bowl still needs a cut, elsewhere
}

TYPED_TEST(CutAndParameterizeTyped, progress_callback_and_cancel)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  using Progress = SMP::Cut_and_parameterize_progress;
  struct Call { std::string phase; int pass, alternation, per_pass; double epsilon; };
  std::vector<Call> calls;
  const std::function<bool(const Progress&)> record = [&](const Progress& p) {
    calls.push_back({p.phase, p.pass, p.alternation, p.alternations_per_pass, p.epsilon});
    return true;
  };
  Cut_run<TypeParam> run(mesh);
  run.run(SMP::parameters::progress_callback(record, SMP::parameters::number_of_passes(2)));
  check_cut_result(mesh, run);
  ASSERT_TRUE(!calls.empty());
  EXPECT_EQ(calls.front().phase, std::string("initialize"));
  EXPECT_EQ(calls.back().phase, std::string("final"));
  // defaults: ε = 0.1, 0.05, 0.025, 0.0125 (> 0.01), 3 alternations each
  std::map<int, std::vector<Call>> alternations;
  for(const Call& c : calls)
  {
    EXPECT_EQ(c.per_pass, 12);
    if(c.phase == "alternate") alternations[c.pass].push_back(c);
  }
  EXPECT_TRUE(alternations.size() >= 1);
  for(const auto& entry : alternations)
  {
    SCOPED_TRACE("pass " + std::to_string(entry.first));
    const auto& list = entry.second;
    EXPECT_EQ(list.size(), std::size_t(12));
    for(std::size_t i = 0; i < list.size(); ++i)
    {
      EXPECT_EQ(list[i].alternation, int(i) + 1); // increasing, from 1
      if(i > 0) EXPECT_TRUE(list[i].epsilon <= list[i - 1].epsilon);
    }
    if(!list.empty())
    {
      EXPECT_NEAR(list.front().epsilon, 0.1, 1e-15);
      EXPECT_NEAR(list.back().epsilon, 0.0125, 1e-15);
    }
  }

  // returning false stops the run; the outputs are left as they were
  for(const int stop_at : {0, 3})
  {
    SCOPED_TRACE("cancel after " + std::to_string(stop_at) + " alternations");
    int seen = 0;
    const std::function<bool(const Progress&)> cancel = [&](const Progress& p) {
      ++seen;
      return !(std::string(p.phase) == "initialize" ? stop_at == 0 : p.alternation >= stop_at);
    };
    Cut_run<TypeParam> canceled(mesh);
    canceled.fill_sentinels();
    canceled.run(SMP::parameters::progress_callback(cancel, SMP::parameters::face_discontinuity_map(canceled.v())));
    EXPECT_EQ(canceled.result.error, SMP::ERROR_CANCELED);
    check_timings(canceled.result, false);
    EXPECT_EQ(seen, stop_at == 0 ? 1 : stop_at + 1);
    canceled.expect_outputs_untouched();
  }
}

TYPED_TEST(CutAndParameterizeTyped, invalid_parameters)
{
  const Soup soup = cone_soup(4, 12);
  TypeParam mesh;
  build_mesh(soup, mesh);
  namespace P = SMP::parameters;
  auto expect_wrong = [&](const auto& np, const char* what) {
    SCOPED_TRACE(what);
    Cut_run<TypeParam> run(mesh);
    run.fill_sentinels();
    run.run(P::face_discontinuity_map(run.v(), np));
    EXPECT_EQ(run.result.error, SMP::ERROR_WRONG_PARAMETER);
    run.expect_outputs_untouched();
  };
  expect_wrong(P::lambda(-1.), "lambda -1");
  expect_wrong(P::lambda(0.), "lambda 0");
  expect_wrong(P::epsilon_start(0.01, P::epsilon_end(0.1)), "epsilon_end > epsilon_start");
  expect_wrong(P::epsilon_end(-0.01), "epsilon_end < 0");
  expect_wrong(P::iterations_per_epsilon(0), "iterations_per_epsilon 0");
  expect_wrong(P::gamma(-1e-7), "gamma < 0");
  expect_wrong(P::number_of_passes(-1), "passes -1");
  expect_wrong(P::minimum_relative_cut_length(1.5), "minimum_relative_cut_length 1.5");
  auto negative = get(CGAL::dynamic_face_property_t<double>(), mesh);
  for(auto f : faces(mesh)) put(negative, f, 1.);
  put(negative, *faces(mesh).begin(), -2.);
  expect_wrong(P::face_lambda_map(negative), "a negative face lambda");
  // and a valid set of the same options works
  Cut_run<TypeParam> ok(mesh);
  ok.run(P::lambda(0.5, P::epsilon_start(0.2, P::epsilon_end(0.02, P::iterations_per_epsilon(2)))));
  check_cut_result(mesh, ok);
}

TYPED_TEST(CutAndParameterizeTyped, two_passes_extend_the_seams_of_one)
{
  const Soup soup = bowl();
  TypeParam mesh;
  build_mesh(soup, mesh);
  Cut_run<TypeParam> one(mesh), two(mesh);
  one.run(SMP::parameters::number_of_passes(1));
  two.run(SMP::parameters::number_of_passes(2));
  check_cut_result(mesh, one);
  check_cut_result(mesh, two);
  check_timings(one.result);
  check_timings(two.result);
  print("1 pass", one.result, 0.);
  print("2 passes", two.result, 0.);
  // the first pass of a 2-pass run is the 1-pass run: its seams are kept
  std::size_t lost = 0;
  for(auto e : edges(mesh))
    if(one.is_seam(e) && !two.is_seam(e)) ++lost;
  EXPECT_EQ(lost, std::size_t(0));
  EXPECT_TRUE(two.result.number_of_seam_edges >= one.result.number_of_seam_edges);
  EXPECT_TRUE(two.result.distortion <= one.result.distortion + 1e-3) << "E_d 2 passes " << two.result.distortion << " vs 1 pass " << one.result.distortion;
  // no pass: only the initial cut (none for a disk), i.e. the uncut optimum
  Cut_run<TypeParam> none(mesh);
  none.run(SMP::parameters::number_of_passes(0));
  check_cut_result(mesh, none);
  check_timings(none.result);
  EXPECT_TRUE(none.result.timings.u_steps == 0. && none.result.timings.v_steps == 0.);
  EXPECT_EQ(none.result.number_of_seam_edges, std::size_t(0));
  EXPECT_REL(none.result.distortion, uncut_distortion(mesh), 1e-3);
}

