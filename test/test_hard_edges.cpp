// hard_edge_angle: on a box, every one of its 12 sharp edges (90°) is a seam
// at 30° (6 charts, one per side, a valid atlas), none at 100°; the flat
// diagonals never are; a forbidden hard edge stays uncut; without the
// option (or at 180°, which no angle exceeds) the outputs are those of a
// run without it, bit for bit; an angle out of [0, 180] is refused.
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = CGAL::Surface_mesh_parameterization::parameters;
using cut_test::Surface_mesh;

namespace {

template <typename Mesh>
class Hard_edges : public ::testing::Test {};
TYPED_TEST_SUITE(Hard_edges, cut_test::Mesh_types);

/// Edges of `mesh` between two faces that are not coplanar (the box's 12 sides' edges).
template <typename Mesh>
bool is_sharp_box_edge(const Mesh& mesh, typename boost::graph_traits<Mesh>::edge_descriptor e)
{
  const auto h = halfedge(e, mesh);
  auto normal = [&](typename boost::graph_traits<Mesh>::halfedge_descriptor g) {
    const auto vpm = get(CGAL::vertex_point, mesh);
    const auto &a = get(vpm, source(g, mesh)), &b = get(vpm, target(g, mesh)),
               &c = get(vpm, target(next(g, mesh), mesh));
    return CGAL::cross_product(b - a, c - a);
  };
  return CGAL::cross_product(normal(h), normal(opposite(h, mesh))).squared_length() > 1e-12;
}

} // namespace

TYPED_TEST(Hard_edges, every_edge_of_a_box_is_a_seam_at_30_degrees)
{
  const TypeParam mesh = cut_test::make_mesh<TypeParam>(cut_test::box_soup(1., 2., 3.));
  cut_test::Cut_run<TypeParam> run(mesh);
  run.run(P::hard_edge_angle(30.));
  const auto charts = cut_test::check_cut_result(mesh, run);
  EXPECT_EQ(run.result.number_of_hard_edges, 12u);
  EXPECT_EQ(charts.number_of_charts, 6u);
  std::size_t sharp = 0, sharp_seams = 0, flat_seams = 0;
  for(auto e : edges(mesh))
  {
    const bool s = is_sharp_box_edge(mesh, e);
    sharp += s;
    (s ? sharp_seams : flat_seams) += run.is_seam(e);
  }
  EXPECT_EQ(sharp, 12u);
  EXPECT_EQ(sharp_seams, 12u);
  EXPECT_EQ(flat_seams, 0u); // each side is flat: its chart is isometric, nothing to add
  EXPECT_NEAR(run.result.distortion, 4., 1e-6);
}

TYPED_TEST(Hard_edges, no_edge_of_a_box_exceeds_100_degrees)
{
  const TypeParam mesh = cut_test::make_mesh<TypeParam>(cut_test::box_soup());
  cut_test::Cut_run<TypeParam> run(mesh);
  run.run(P::hard_edge_angle(100.));
  cut_test::check_cut_result(mesh, run);
  EXPECT_EQ(run.result.number_of_hard_edges, 0u);
}

TEST(Hard_edges, off_or_at_180_degrees_the_result_is_that_of_a_run_without_the_option)
{
  // a curved mesh with creases: a cylinder patch of 6 facets around (60° between them)
  const Surface_mesh mesh = cut_test::make_mesh<Surface_mesh>(cut_test::cylinder_patch_soup(6, 4, 1., 1.5 * M_PI, 1.));
  cut_test::Cut_run<Surface_mesh> plain(mesh), at_180(mesh), unset(mesh);
  plain.run();
  at_180.run(P::hard_edge_angle(180.));
  SMP::Cut_parameterization_options options; // hard_edge_angle left unset
  unset.run(P::cut_parameterization_options(options));
  ASSERT_TRUE(plain.result.ok());
  EXPECT_EQ(at_180.result.number_of_hard_edges, 0u);
  cut_test::expect_identical_outputs({plain.seam_vector(), at_180.seam_vector(), unset.seam_vector()},
                                     {plain.uv_vector(), at_180.uv_vector(), unset.uv_vector()});
  // at 30°, the 5 creases between the facets (4 edges each) are seams
  cut_test::Cut_run<Surface_mesh> hard(mesh);
  hard.run(P::hard_edge_angle(30.));
  cut_test::check_cut_result(mesh, hard);
  EXPECT_EQ(hard.result.number_of_hard_edges, 20u);
}

TEST(Hard_edges, a_forbidden_hard_edge_is_not_cut)
{
  const Surface_mesh mesh = cut_test::make_mesh<Surface_mesh>(cut_test::box_soup());
  std::unordered_map<Surface_mesh::Edge_index, bool> forbidden;
  Surface_mesh::Edge_index kept;
  for(auto e : edges(mesh))
  {
    forbidden[e] = false;
    if(kept == Surface_mesh::Edge_index() && is_sharp_box_edge(mesh, e)) kept = e;
  }
  forbidden[kept] = true;
  cut_test::Cut_run<Surface_mesh> run(mesh);
  run.run(P::hard_edge_angle(30., P::forbidden_seam_edge_map(boost::make_assoc_property_map(forbidden))));
  const auto charts = cut_test::check_cut_result(mesh, run);
  EXPECT_EQ(run.result.number_of_hard_edges, 11u);
  EXPECT_FALSE(run.is_seam(kept));
  EXPECT_EQ(charts.number_of_charts, 5u); // two sides joined across the kept edge
}

TEST(Hard_edges, an_angle_out_of_range_is_refused_and_nothing_is_written)
{
  const Surface_mesh mesh = cut_test::make_mesh<Surface_mesh>(cut_test::box_soup());
  for(double angle : {-1., 180.5, std::numeric_limits<double>::quiet_NaN()})
  {
    cut_test::Cut_run<Surface_mesh> run(mesh);
    run.fill_sentinels();
    EXPECT_EQ(run.run(P::hard_edge_angle(angle)).error, SMP::ERROR_WRONG_PARAMETER) << angle;
    run.expect_outputs_untouched();
  }
}
