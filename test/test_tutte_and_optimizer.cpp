// Tutte initialization (internal tutte_embedding) and the distortion
// optimizer (symmetric_dirichlet_parameterize, internal Distortion_minimizer)
// on generated disks: no flipped face ever, energy strictly below Tutte's,
// developable patches reach E_d = 4, results do not depend on the scale;
// the sparse Cholesky solver on systems below and above its METIS threshold;
// the Hessian assembler's patterns, merged or built whole.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Hessian_assembler.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/linalg/Sparse_cholesky.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;

namespace {

struct Named_soup
{
  const char* name;
  Soup soup;
};

/// The generated disks every test runs on.
std::vector<Named_soup> disks()
{
  return {{"grid", grid_soup(10, 8, 1.5, 1.)},
          {"hemisphere", hemisphere_soup(7, 20)},
          {"wavy disk", wavy_disk_soup(8, 22, 5)},
          {"cone", cone_soup(6, 16, 1., 1.5)},
          {"cylinder patch", cylinder_patch_soup(10, 6, 1., 2., 1.5)}};
}

template <typename Mesh>
struct Chart
{
  ic::Indexed_surface<Mesh> surface;
  ic::Chart_mesh mesh;
  std::vector<int> corner_uv;
};

/// The uncut chart mesh of `mesh`; REQUIREs success.
template <typename Mesh>
void make_chart(const Mesh& mesh, Chart<Mesh>& chart)
{
  ASSERT_TRUE(ic::index_surface(mesh, get(CGAL::vertex_point, mesh), chart.surface) == ic::Indexing_status::OK);
  // no face of a generated disk is degenerate (none gets its rest shape clamped)
  ASSERT_EQ(ic::build_chart_mesh(chart.surface, std::vector<char>(chart.surface.edges.size(), 0), chart.mesh,
                                  chart.corner_uv), std::size_t(0));
}

double signed_area(const ic::Chart_mesh& mesh, const ic::UV_vector& x, std::size_t f)
{
  return 0.5 * mesh.uv_edges(x, f).determinant();
}

/// The lower triangle of a grid Laplacian over side x side nodes with
/// `diagonal` on its diagonal (positive definite when diagonal > 4).
ic::Sparse_matrix screened_grid_laplacian(int side, double diagonal)
{
  std::vector<Eigen::Triplet<double>> triplets;
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j)
    {
      const int k = i * side + j;
      triplets.emplace_back(k, k, diagonal);
      if(i > 0) triplets.emplace_back(k, k - side, -1.);
      if(j > 0) triplets.emplace_back(k, k - 1, -1.);
    }
  ic::Sparse_matrix A(side * side, side * side);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

} // namespace

template <typename Mesh>
class TutteAndOptimizerTyped : public ::testing::Test
{
};
TYPED_TEST_SUITE(TutteAndOptimizerTyped, Mesh_types);

TYPED_TEST(TutteAndOptimizerTyped, tutte_embedding_has_no_flipped_face)
{
  for(const Named_soup& disk : disks())
  {
    SCOPED_TRACE(disk.name);
    TypeParam mesh;
    build_mesh(disk.soup, mesh);
    Chart<TypeParam> chart;
    make_chart(mesh, chart);
    const auto loops = ic::boundary_loops(chart.mesh);
    ASSERT_EQ(loops.size(), std::size_t(1));
    // the loop pinned on the circle of the mesh's area, centered off the origin
    const double radius = std::sqrt(chart.mesh.total_area() / pi);
    ic::Pinned_loop pinned;
    pinned.vertices = loops.front();
    pinned.radius = radius;
    pinned.center = ic::Vector2(0.3, -2.);
    ic::UV_vector x;
    ASSERT_TRUE(ic::tutte_embedding(chart.mesh, {pinned}, ic::Boundary_spacing::ARC_LENGTH, x));
    ASSERT_TRUE(x.allFinite());
    EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, x), 0);
    double min_area = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < chart.mesh.number_of_faces(); ++f)
      min_area = (std::min)(min_area, signed_area(chart.mesh, x, f));
    EXPECT_TRUE(min_area > 0.);

    // the border sits on the circle, counterclockwise
    const auto& loop = loops.front();
    double polygon_area = 0.;
    for(std::size_t i = 0; i < loop.size(); ++i)
    {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT_NEAR(std::hypot(x[2 * a] - 0.3, x[2 * a + 1] + 2.), radius, 1e-12 * radius);
      polygon_area += 0.5 * (x[2 * a] * x[2 * b + 1] - x[2 * b] * x[2 * a + 1]);
    }
    EXPECT_TRUE(polygon_area > 0.);
    // flip-free and a disk: the faces tile the border polygon exactly
    double uv_area = 0.;
    for(std::size_t f = 0; f < chart.mesh.number_of_faces(); ++f) uv_area += signed_area(chart.mesh, x, f);
    EXPECT_REL(uv_area, polygon_area, 1e-12);

    // uniform Tutte: every interior vertex is the mean of its neighbors
    std::map<int, std::set<int>> neighbors;
    for(const auto& t : chart.mesh.faces)
      for(int k = 0; k < 3; ++k)
      {
        neighbors[t[k]].insert(t[(k + 1) % 3]);
        neighbors[t[(k + 1) % 3]].insert(t[k]);
      }
    const std::set<int> border(loop.begin(), loop.end());
    int interior = 0;
    for(const auto& entry : neighbors)
    {
      if(border.count(entry.first)) continue;
      ++interior;
      double mx = 0., my = 0.;
      for(int n : entry.second)
      {
        mx += x[2 * n];
        my += x[2 * n + 1];
      }
      mx /= double(entry.second.size());
      my /= double(entry.second.size());
      EXPECT_NEAR(x[2 * entry.first], mx, 1e-10 * radius);
      EXPECT_NEAR(x[2 * entry.first + 1], my, 1e-10 * radius);
    }
    EXPECT_TRUE(interior > 0);
  }
}

TYPED_TEST(TutteAndOptimizerTyped, disk_charts_embedding_separates_components)
{
  // three disks of different sizes: each on its own circle, no flip, no overlap
  Soup soup = grid_soup(4, 4, 1., 1.);
  soup.append(hemisphere_soup(4, 12, 2.).translate(5., 0., 0.));
  soup.append(wavy_disk_soup(4, 12, 2).scale(0.5).translate(-5., 0., 0.));
  TypeParam mesh;
  build_mesh(soup, mesh);
  Chart<TypeParam> chart;
  make_chart(mesh, chart);
  int number_of_charts = 0;
  const std::vector<int> chart_of_face = ic::chart_of_faces(chart.mesh, number_of_charts);
  ASSERT_EQ(number_of_charts, 3);
  ic::UV_vector x;
  ASSERT_TRUE(ic::disk_charts_embedding(chart.mesh, x) == ic::Embedding_status::OK);
  EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, x), 0);
  // UV bounding boxes of the charts are disjoint, and each chart's UV area is
  // at most its 3D area (a polygon inscribed in the circle of that area)
  std::vector<std::array<double, 4>> box(3, {1e300, -1e300, 1e300, -1e300});
  std::vector<double> uv_area(3, 0.), area(3, 0.);
  for(std::size_t f = 0; f < chart.mesh.number_of_faces(); ++f)
  {
    const int c = chart_of_face[f];
    uv_area[c] += signed_area(chart.mesh, x, f);
    area[c] += chart.mesh.area[f];
    for(int v : chart.mesh.faces[f])
    {
      box[c][0] = (std::min)(box[c][0], x[2 * v]);
      box[c][1] = (std::max)(box[c][1], x[2 * v]);
      box[c][2] = (std::min)(box[c][2], x[2 * v + 1]);
      box[c][3] = (std::max)(box[c][3], x[2 * v + 1]);
    }
  }
  for(int a = 0; a < 3; ++a)
  {
    EXPECT_TRUE(uv_area[a] > 0.5 * area[a]);
    EXPECT_TRUE(uv_area[a] <= area[a] * (1. + 1e-12));
    for(int b = a + 1; b < 3; ++b)
    {
      const bool apart = box[a][1] < box[b][0] || box[b][1] < box[a][0] || box[a][3] < box[b][2]
                         || box[b][3] < box[a][2];
      EXPECT_TRUE(apart) << "charts " << a << " and " << b << " overlap in UV";
    }
  }
  // a chart with a hole is not a disk
  Chart<TypeParam> holed;
  TypeParam holed_mesh;
  build_mesh(disk_with_holes_soup(5, 1), holed_mesh);
  make_chart(holed_mesh, holed);
  EXPECT_TRUE(ic::disk_charts_embedding(holed.mesh, x) == ic::Embedding_status::NOT_DISKS);
}

TYPED_TEST(TutteAndOptimizerTyped, optimizer_lowers_the_energy_below_tutte_without_flips)
{
  for(const Named_soup& disk : disks())
  {
    SCOPED_TRACE(disk.name);
    TypeParam mesh;
    build_mesh(disk.soup, mesh);
    auto tutte_uv = vertex_uv_map(mesh);
    // no Newton iteration: the Tutte embedding itself
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, tutte_uv, CGAL::parameters::number_of_iterations(0)), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, tutte_uv), std::size_t(0));
    const double tutte_energy = SMP::distortion_energy(mesh, tutte_uv);
    EXPECT_TRUE(std::isfinite(tutte_energy));

    auto uv = vertex_uv_map(mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    const double energy = SMP::distortion_energy(mesh, uv);
    EXPECT_TRUE(std::isfinite(energy));
    EXPECT_TRUE(energy >= 4.);
    EXPECT_TRUE(energy < tutte_energy) << "optimized " << energy << " vs Tutte " << tutte_energy;
    for(auto v : vertices(mesh)) EXPECT_TRUE(std::isfinite(get(uv, v).x()) && std::isfinite(get(uv, v).y()));

    // restarting from the optimum keeps it (no flip, no increase)
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::initialize_from_uv_map(true)), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    EXPECT_TRUE(SMP::distortion_energy(mesh, uv) <= energy * (1. + 1e-12));
  }
}

TYPED_TEST(TutteAndOptimizerTyped, every_newton_iteration_is_flip_free_and_decreasing)
{
  for(const Named_soup& disk : disks())
  {
    SCOPED_TRACE(disk.name);
    TypeParam mesh;
    build_mesh(disk.soup, mesh);
    Chart<TypeParam> chart;
    make_chart(mesh, chart);
    const auto loops = ic::boundary_loops(chart.mesh);
    ASSERT_EQ(loops.size(), std::size_t(1));
    ic::UV_vector x;
    ASSERT_TRUE(ic::disk_charts_embedding(chart.mesh, x) == ic::Embedding_status::OK);
    ic::Distortion_minimizer minimizer(chart.mesh, std::vector<double>(chart.mesh.number_of_faces(), 1.));
    double previous = ic::mean_distortion(chart.mesh, x);
    const double tutte = previous;
    bool converged = false;
    for(int iteration = 0; iteration < 100 && !converged; ++iteration)
    {
      const ic::Newton_report report = minimizer.minimize(x, 1, 1e-9);
      ASSERT_TRUE(report.ok());
      EXPECT_EQ(ic::number_of_flipped_faces(chart.mesh, x), 0);
      const double e = ic::mean_distortion(chart.mesh, x);
      EXPECT_TRUE(e <= previous) << "iteration " << iteration << ": " << e << " > " << previous;
      EXPECT_TRUE(report.energy <= report.initial_energy);
      previous = e;
      converged = report.status == ic::Newton_status::CONVERGED;
    }
    EXPECT_TRUE(converged);
    EXPECT_TRUE(previous < tutte);
  }
}

TYPED_TEST(TutteAndOptimizerTyped, tiny_and_zero_weights_still_never_flip)
{
  // Weights w_f >= 0 are allowed, and the result must be flip-free whatever
  // they are. A tiny weight (the joint method's gamma = 1e-7) keeps a weak
  // barrier; a zero weight has none, only the step bound protects the face.
  for(double small : {1e-7, 0.})
  for(const Named_soup& disk : disks())
  {
    SCOPED_TRACE(std::string(disk.name) + ", every third face of weight " + to_text(small));
    TypeParam mesh;
    build_mesh(disk.soup, mesh);
    auto weight = get(CGAL::dynamic_face_property_t<double>(), mesh);
    std::size_t i = 0;
    for(auto f : faces(mesh)) put(weight, f, (i++ % 3 == 0) ? small : 1.);
    auto uv = vertex_uv_map(mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, SMP::parameters::face_weight_map(weight)), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    EXPECT_TRUE(std::isfinite(SMP::distortion_energy(mesh, uv)));
    // "a line search that never lets a face collapse": no UV triangle is
    // numerically collapsed either (a face at 1e-15 of the mean UV area is
    // flip-free only by the luck of rounding)
    double min_area = std::numeric_limits<double>::infinity(), total = 0.;
    for(auto f : faces(mesh))
    {
      auto h = halfedge(f, mesh);
      const Point_2 a = get(uv, source(h, mesh)), b = get(uv, target(h, mesh)), c = get(uv, target(next(h, mesh), mesh));
      const double area = 0.5 * CGAL::cross_product(CGAL::Vector_3<Kernel>(b.x() - a.x(), b.y() - a.y(), 0),
                                                    CGAL::Vector_3<Kernel>(c.x() - a.x(), c.y() - a.y(), 0)).z();
      min_area = (std::min)(min_area, area);
      total += area;
    }
    const double mean = total / double(num_faces(mesh));
    EXPECT_TRUE(min_area > 1e-10 * mean) << "smallest UV area / mean UV area = " << min_area / mean;
  }
}

TYPED_TEST(TutteAndOptimizerTyped, developable_patches_reach_isometry)
{
  Soup flat = grid_soup(8, 8, 1., 1.);
  jitter_xy(flat, 0.03, 17);
  const Named_soup patches[] = {{"flat jittered grid", flat},
                                {"flat disk", flat_disk_soup(5, 16)},
                                {"cylinder patch", cylinder_patch_soup(12, 6, 1., 2., 1.5)},
                                {"thin cylinder patch", cylinder_patch_soup(16, 4, 0.2, 3., 0.5)},
                                {"strip without interior vertex", grid_soup(7, 1, 3.5, 0.5)},
                                {"bent strip without interior vertex", cylinder_patch_soup(7, 1, 1., 2., 0.4)}};
  for(const Named_soup& patch : patches)
  {
    SCOPED_TRACE(patch.name);
    TypeParam mesh;
    build_mesh(patch.soup, mesh);
    auto uv = vertex_uv_map(mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    const double energy = SMP::distortion_energy(mesh, uv);
    EXPECT_TRUE(energy >= 4. && energy - 4. <= 1e-6) << "E_d - 4 = " << energy - 4.;
  }
}

TYPED_TEST(TutteAndOptimizerTyped, optimum_does_not_depend_on_scale)
{
  std::vector<Point_2> reference;
  double reference_energy = 0.;
  for(double s : {1., 1e-3, 1e3})
  {
    SCOPED_TRACE("scale " + to_text(s));
    Soup soup = wavy_disk_soup(8, 22, 5);
    soup.scale(s);
    TypeParam mesh;
    const auto vertex_of = build_mesh(soup, mesh);
    auto uv = vertex_uv_map(mesh);
    ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv), SMP::OK);
    EXPECT_EQ(SMP::number_of_flipped_faces(mesh, uv), std::size_t(0));
    const double energy = SMP::distortion_energy(mesh, uv);
    std::vector<Point_2> scaled;
    for(auto v : vertex_of) scaled.push_back(Point_2(get(uv, v).x() / s, get(uv, v).y() / s));
    if(s == 1.)
    {
      reference = scaled;
      reference_energy = energy;
      continue;
    }
    EXPECT_REL(energy, reference_energy, 1e-8);
    // the UVs themselves scale with the mesh (same start, same iterations)
    double deviation = 0.;
    for(std::size_t i = 0; i < scaled.size(); ++i)
      deviation = (std::max)(deviation, std::sqrt(CGAL::squared_distance(scaled[i], reference[i])));
    EXPECT_TRUE(deviation <= 1e-6) << "max UV deviation / scale = " << deviation;
  }
}

TYPED_TEST(TutteAndOptimizerTyped, vertex_point_map_is_used)
{
  // positions given through a vertex_point_map (the mesh's own, scaled by 2)
  // give the same map as a mesh built scaled by 2, for the optimizer and the metrics
  using vertex_descriptor = typename boost::graph_traits<TypeParam>::vertex_descriptor;
  Soup soup = hemisphere_soup(5, 14);
  TypeParam mesh;
  const auto vertex_of = build_mesh(soup, mesh);
  auto scaled_points = get(CGAL::dynamic_vertex_property_t<Point_3>(), mesh);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    put(scaled_points, v, Point_3(2. * p.x(), 2. * p.y(), 2. * p.z()));
  }
  auto uv = vertex_uv_map(mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, uv, CGAL::parameters::vertex_point_map(scaled_points)), SMP::OK);
  const double energy = SMP::distortion_energy(mesh, uv, CGAL::parameters::vertex_point_map(scaled_points));
  EXPECT_REL(SMP::surface_area(mesh, CGAL::parameters::vertex_point_map(scaled_points)), 4. * SMP::surface_area(mesh), 1e-12);

  TypeParam big;
  const auto big_vertex_of = build_mesh(soup.scale(2.), big);
  auto big_uv = vertex_uv_map(big);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(big, big_uv), SMP::OK);
  EXPECT_REL(energy, SMP::distortion_energy(big, big_uv), 1e-10);
  double deviation = 0.;
  for(std::size_t i = 0; i < vertex_of.size(); ++i)
    deviation = (std::max)(deviation, std::sqrt(CGAL::squared_distance(get(uv, vertex_of[i]), get(big_uv, big_vertex_of[i]))));
  EXPECT_TRUE(deviation <= 1e-9) << "max UV deviation " << deviation;
  // the map of the unscaled mesh is not the same: the map was really computed from the given points
  auto plain_uv = vertex_uv_map(mesh);
  ASSERT_EQ(SMP::symmetric_dirichlet_parameterize(mesh, plain_uv), SMP::OK);
  EXPECT_TRUE(std::abs(get(plain_uv, vertex_of[1]).x() - get(uv, vertex_of[1]).x()) > 1e-3);
}

TEST(TutteAndOptimizer, sparse_cholesky_solves_large_systems)
{
  // a screened grid Laplacian below cholmod_threshold (AMD-ordered LDLT) and
  // just above metis_threshold (CHOLMOD when built with it, else METIS-ordered
  // LLT when built with METIS, else AMD): the solver gives the solution of
  // Eigen's AMD LDLT, with a tiny residual, and refactors a matrix of the
  // same pattern
  for(const int side : {int(std::sqrt(0.9 * double(ic::Sparse_cholesky::cholmod_threshold()))),
                        int(std::ceil(std::sqrt(double(ic::Sparse_cholesky::metis_threshold)))) + 1})
  {
    SCOPED_TRACE("grid side " + std::to_string(side));
    const int n = side * side;
    const ic::Sparse_matrix A = screened_grid_laplacian(side, 4.001); // lower triangle only
    Eigen::VectorXd b(n);
    for(int k = 0; k < n; ++k) b[k] = std::sin(0.37 * k) + 0.1 * (k % 7);
    ic::Sparse_cholesky solver;
    solver.analyze(A);
    Eigen::VectorXd x;
    ASSERT_TRUE(solver.factorize(A));
    ASSERT_TRUE(solver.solve(b, x));
    const Eigen::VectorXd residual = A.selfadjointView<Eigen::Lower>() * x - b;
    EXPECT_TRUE(residual.norm() <= 1e-12 * b.norm()) << "relative residual " << residual.norm() / b.norm();
    Eigen::SimplicialLDLT<ic::Sparse_matrix, Eigen::Lower> reference(A);
    EXPECT_TRUE((x - reference.solve(b)).norm() <= 1e-10 * x.norm()) << "differs from AMD LDLT";
    // same pattern, new values: factorize again without a new analysis
    ic::Sparse_matrix B = 2. * A;
    ASSERT_TRUE(solver.factorize(B));
    ASSERT_TRUE(solver.solve(b, x));
    EXPECT_TRUE((2. * x - reference.solve(b)).norm() <= 1e-10 * x.norm()) << "refactorization differs";
  }
}


TEST(TutteAndOptimizer, sparse_cholesky_reads_the_lower_triangle_of_any_storage)
{
  // Above cholmod_threshold (CHOLMOD permutes the matrix itself, value by
  // value): a matrix stored whole (both triangles, the upper one spoiled so
  // that reading it would show) and one left uncompressed give the solution
  // of the lower triangle alone, and refactorize after new values
  const int side = int(std::ceil(std::sqrt(double(ic::Sparse_cholesky::cholmod_threshold())))) + 1, n = side * side;
  const ic::Sparse_matrix lower = screened_grid_laplacian(side, 4.5);
  ic::Sparse_matrix whole = lower.selfadjointView<Eigen::Lower>();
  for(int col = 0; col < n; ++col)
    for(ic::Sparse_matrix::InnerIterator it(whole, col); it; ++it)
      if(it.row() < col) it.valueRef() = 1e3; // above the diagonal: never read
  ic::Sparse_matrix uncompressed = lower;
  uncompressed.uncompress();
  uncompressed.reserve(Eigen::VectorXi::Constant(n, 2)); // room left in every column
  ASSERT_FALSE(uncompressed.isCompressed());
  Eigen::VectorXd b(n), expected, x;
  for(int k = 0; k < n; ++k) b[k] = std::cos(0.11 * k);
  ic::Sparse_cholesky reference;
  ASSERT_TRUE(reference.factorize(lower) && reference.solve(b, expected));
  for(const ic::Sparse_matrix* A : {&whole, &uncompressed})
  {
    ic::Sparse_cholesky solver;
    solver.analyze(*A);
    ASSERT_TRUE(solver.factorize(*A) && solver.solve(b, x));
    EXPECT_TRUE((x - expected).norm() <= 1e-12 * expected.norm()) << "storage " << (A == &whole ? "whole" : "uncompressed");
    ic::Sparse_matrix doubled = 2. * (*A);
    if(A == &uncompressed) { doubled.uncompress(); doubled.reserve(Eigen::VectorXi::Constant(n, 2)); }
    ASSERT_TRUE(solver.factorize(doubled) && solver.solve(b, x));
    EXPECT_TRUE((2. * x - expected).norm() <= 1e-12 * expected.norm()) << "refactorization";
  }
}

#ifdef CGAL_SMP_CUT_USE_CHOLMOD
TEST(TutteAndOptimizer, serial_openmp_scope_and_cholmod_keep_the_callers_openmp_setting)
{
  // Serial_openmp_scope turns nested OpenMP regions off (max active levels
  // 0) while it lives and gives the thread's setting back; a system of
  // CHOLMOD's size (a grid Laplacian plus identity) is then solved right,
  // and the caller's setting is the same after. (Whether CHOLMOD's regions
  // actually ran on one thread is not observable from here.)
  if(omp_get_max_active_levels == nullptr || omp_set_max_active_levels == nullptr)
    GTEST_SKIP() << "no OpenMP runtime in this process";
  const int before = omp_get_max_active_levels();
  omp_set_max_active_levels(2);
  {
    ic::Serial_openmp_scope serial;
    EXPECT_EQ(omp_get_max_active_levels(), 0);
  }
  EXPECT_EQ(omp_get_max_active_levels(), 2);
  const int side = int(std::ceil(std::sqrt(double(ic::Sparse_cholesky::cholmod_threshold())))) + 1, n = side * side;
  const ic::Sparse_matrix A = screened_grid_laplacian(side, 5.);
  Eigen::VectorXd b(n), x;
  for(int k = 0; k < n; ++k) b[k] = std::sin(0.07 * k);
  ic::Sparse_cholesky cholesky;
  cholesky.analyze(A, 1);
  ASSERT_TRUE(cholesky.factorize(A) && cholesky.solve(b, x));
  const Eigen::VectorXd residual = A.selfadjointView<Eigen::Lower>() * x - b;
  EXPECT_TRUE(residual.norm() <= 1e-12 * b.norm()) << "relative residual " << residual.norm() / b.norm();
  EXPECT_EQ(omp_get_max_active_levels(), 2);
  omp_set_max_active_levels(before);
}
#endif

// The Hessian assembler builds the pattern of a sequence of elements again
// by merging the elements after the kept leading ones (border barrier pairs
// after the faces): the matrix, its values and the diagonal are those of a
// fresh assembler given the same elements, through trailing elements added
// to the last build's (merged into it), dropped or drawn anew, a changed
// leading element and a new dimension.
TEST(TutteAndOptimizer, hessian_assembler_merged_pattern_equals_a_fresh_one)
{
  const int n = 60;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> dof(0, n - 1);
  std::vector<std::vector<int>> leading;
  for(int e = 0; e < 40; ++e) leading.push_back({dof(rng), dof(rng), dof(rng), dof(rng), dof(rng), dof(rng)});
  ic::Hessian_assembler kept;
  auto build = [&](ic::Hessian_assembler& h, const std::vector<std::vector<int>>& elements, int dimension) {
    h.clear();
    for(const auto& e : elements) h.add_element(e);
    h.finalize(dimension);
    h.set_zero();
    for(std::size_t e = 0; e < elements.size(); ++e)
    {
      const std::size_t m = elements[e].size();
      Eigen::MatrixXd block(m, m);
      for(std::size_t i = 0; i < m; ++i)
        for(std::size_t j = 0; j < m; ++j) block(i, j) = 1. + double((e * 7 + i * 3 + j * 3 + i * j) % 11);
      h.add(int(e), block);
    }
    h.add_to_diagonal(0.5);
  };
  auto random_element = [&](int e) {
    return e % 3 == 0 ? std::vector<int>{dof(rng), dof(rng)} : std::vector<int>{dof(rng), dof(rng), dof(rng), dof(rng)};
  };
  std::vector<std::vector<int>> trailing;
  for(int round = 0; round < 16; ++round)
  {
    SCOPED_TRACE("round " + std::to_string(round));
    // rounds 0-3, 8-10 and 13-15 add trailing elements to those of the round before (the pattern
    // built last is merged into), 4 and 11 draw them anew, 12 drops some; 6 changes a leading element
    if(round == 4 || round == 11) trailing.clear();
    if(round == 12) trailing.resize(trailing.size() / 2);
    const int added = round == 5 || round == 6 || round == 7 || round == 12 ? 0 : 1 + (round * 17) % 7;
    for(int e = 0; e < added; ++e) trailing.push_back(random_element(e));
    if(round == 5 || round == 7) trailing = {random_element(1), random_element(2)};
    std::vector<std::vector<int>> elements = leading;
    if(round == 6) elements[3] = {dof(rng), dof(rng)}; // a leading element changed
    elements.insert(elements.end(), trailing.begin(), trailing.end());
    const int dimension = round == 9 ? n + 4 : n;
    ic::Hessian_assembler fresh;
    build(kept, elements, dimension);
    build(fresh, elements, dimension);
    const ic::Sparse_matrix& a = kept.matrix();
    const ic::Sparse_matrix& b = fresh.matrix();
    ASSERT_EQ(a.rows(), b.rows());
    ASSERT_EQ(a.nonZeros(), b.nonZeros());
    ASSERT_TRUE(a.isCompressed());
    EXPECT_TRUE(std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1, b.outerIndexPtr()));
    EXPECT_TRUE(std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()));
    EXPECT_TRUE(std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr()));
    EXPECT_EQ(kept.mean_diagonal(), fresh.mean_diagonal());
    // each column's rows strictly increasing, from its diagonal down (the solvers' compressed storage)
    for(int c = 0; c < a.cols(); ++c)
    {
      ASSERT_LT(a.outerIndexPtr()[c], a.outerIndexPtr()[c + 1]);
      EXPECT_EQ(a.innerIndexPtr()[a.outerIndexPtr()[c]], c);
      for(int k = a.outerIndexPtr()[c] + 1; k < a.outerIndexPtr()[c + 1]; ++k)
        EXPECT_LT(a.innerIndexPtr()[k - 1], a.innerIndexPtr()[k]);
    }
    // the lower triangle and full diagonal of the sum of the blocks
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(dimension, dimension);
    for(int d = 0; d < dimension; ++d) dense(d, d) = 0.5;
    for(std::size_t e = 0; e < elements.size(); ++e)
      for(std::size_t i = 0; i < elements[e].size(); ++i)
        for(std::size_t j = 0; j < elements[e].size(); ++j)
          if(elements[e][i] >= elements[e][j])
            dense(elements[e][i], elements[e][j]) += 1. + double((e * 7 + i * 3 + j * 3 + i * j) % 11);
    EXPECT_EQ((Eigen::MatrixXd(a) - dense).norm(), 0.);
  }
}

TEST(TutteAndOptimizer, sparse_cholesky_block_ordering)
{
  // two unknowns per grid node coupled as the (u, v) of a UV vertex, below
  // and above metis_threshold: ordering the nodes (block size 2) solves the
  // system as ordering the unknowns does, with the same fill (the factor's
  // cost is measured by the benchmark), and after a change of pattern of the
  // same size the new analysis still solves it, with a new ordering or the old one
  for(const int side : {60, int(std::ceil(std::sqrt(0.5 * double(ic::Sparse_cholesky::metis_threshold)))) + 1})
  {
    SCOPED_TRACE("grid side " + std::to_string(side));
    const int nodes = side * side, n = 2 * nodes;
    auto grid = [&](bool extra_links) {
      std::vector<Eigen::Triplet<double>> triplets;
      auto couple = [&](int p, int q, double w) { // node p >= q: a 2x2 block, lower part
        for(int a = 0; a < 2; ++a)
          for(int c = 0; c < 2; ++c)
            if(2 * p + a >= 2 * q + c) triplets.emplace_back(2 * p + a, 2 * q + c, a == c ? w : 0.25 * w);
      };
      for(int i = 0; i < side; ++i)
        for(int j = 0; j < side; ++j)
        {
          const int k = i * side + j;
          couple(k, k, 8.01);
          if(i > 0) couple(k, k - side, -1.);
          if(j > 0) couple(k, k - 1, -1.);
          if(extra_links && i > 1 && j > 1 && (i + j) % 5 == 0) couple(k, k - 2 * side - 2, -0.5);
        }
      ic::Sparse_matrix A(n, n);
      A.setFromTriplets(triplets.begin(), triplets.end());
      return A;
    };
    Eigen::VectorXd b(n);
    for(int k = 0; k < n; ++k) b[k] = std::cos(0.11 * k) + 0.05 * (k % 5);
    ic::Sparse_cholesky blocks; // analyzed again for the second pattern
    for(const bool extra_links : {false, true})
    {
      const ic::Sparse_matrix A = grid(extra_links);
      Eigen::VectorXd by_unknowns, by_nodes;
      ic::Sparse_cholesky unknowns;
      unknowns.analyze(A, 1);
      blocks.analyze(A, 2);
      ASSERT_TRUE(unknowns.factorize(A) && unknowns.solve(b, by_unknowns));
      ASSERT_TRUE(blocks.factorize(A) && blocks.solve(b, by_nodes));
      const Eigen::VectorXd residual = A.selfadjointView<Eigen::Lower>() * by_nodes - b;
      EXPECT_TRUE(residual.norm() <= 1e-12 * b.norm()) << "relative residual " << residual.norm() / b.norm();
      EXPECT_TRUE((by_nodes - by_unknowns).norm() <= 1e-10 * by_nodes.norm());
    }
    // a pattern grown by a few couplings (border barrier pairs), analyzed with
    // the ordering kept from the plain grid, still solves exactly
    {
      ic::Sparse_cholesky kept;
      kept.analyze(grid(false), 2);
      const ic::Sparse_matrix A = grid(true);
      kept.analyze(A, 2, true);
      Eigen::VectorXd x;
      ASSERT_TRUE(kept.factorize(A) && kept.solve(b, x));
      EXPECT_TRUE((A.selfadjointView<Eigen::Lower>() * x - b).norm() <= 1e-12 * b.norm());
    }
    // an odd size cannot be in blocks of 2: ordered by unknowns
    const ic::Sparse_matrix odd = grid(false).topLeftCorner(n - 1, n - 1);
    ic::Sparse_cholesky solver;
    solver.analyze(odd, 2);
    Eigen::VectorXd x;
    ASSERT_TRUE(solver.factorize(odd) && solver.solve(b.head(n - 1), x));
    EXPECT_TRUE((odd.selfadjointView<Eigen::Lower>() * x - b.head(n - 1)).norm() <= 1e-12 * b.norm());
  }
}
