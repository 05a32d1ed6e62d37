// forbidden_seam_edge_map: no seam of the output is a forbidden edge, on
// disks, closed genus-0, genus-1 and genus-2 surfaces (where the initial cut
// must route around them), at full resolution and on the multiresolution
// copy; forbidding every seam of a default run still gives a valid atlas;
// constraints that leave no cut (every edge of a closed surface, a band
// around the tube of a torus) give ERROR_FORBIDDEN_EDGES_BLOCK_CUT; an edge
// both given as a seam and forbidden gives ERROR_WRONG_PARAMETER.
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <unordered_map>
#include <utility>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

template <typename Mesh>
using Edge_flags = std::unordered_map<typename boost::graph_traits<Mesh>::edge_descriptor, bool>;

template <typename Mesh>
Edge_flags<Mesh> no_edge(const Mesh& mesh)
{
  Edge_flags<Mesh> flags;
  for(auto e : edges(mesh)) flags[e] = false;
  return flags;
}

/// Runs cut_and_parameterize() with `forbidden` (and the extra named
/// parameters `np`), then checks the result and that no seam is forbidden.
template <typename Mesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
SMP::Error_code run_forbidding(const Mesh& mesh, Edge_flags<Mesh>& forbidden, cut_test::Cut_run<Mesh>& run,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  run.run(SMP::parameters::forbidden_seam_edge_map(boost::make_assoc_property_map(forbidden), np));
  if(run.result.error != SMP::OK) return run.result.error;
  cut_test::check_cut_result(mesh, run);
  std::size_t forbidden_seams = 0;
  for(auto e : edges(mesh)) forbidden_seams += (run.is_seam(e) && forbidden.at(e)) ? 1 : 0;
  EXPECT_EQ(forbidden_seams, 0u);
  return run.result.error;
}

/// Forbids the seams of a default run, then runs again: a valid atlas with
/// seams, none of them a forbidden edge.
template <typename Mesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void forbid_default_seams(const cut_test::Soup& soup, const NamedParameters& np = CGAL::parameters::default_values())
{
  const Mesh mesh = cut_test::make_mesh<Mesh>(soup);
  cut_test::Cut_run<Mesh> first(mesh);
  first.run(np);
  ASSERT_EQ(first.result.error, SMP::OK);
  ASSERT_GT(first.number_of_seam_edges(), 0u);
  Edge_flags<Mesh> forbidden = no_edge(mesh);
  for(auto e : edges(mesh)) forbidden[e] = first.is_seam(e);

  cut_test::Cut_run<Mesh> second(mesh);
  ASSERT_EQ(run_forbidding(mesh, forbidden, second, np), SMP::OK);
  EXPECT_GT(second.number_of_seam_edges(), 0u);
}

/// Edges whose endpoints are soup vertices in `band` (by index).
template <typename Mesh>
Edge_flags<Mesh> edges_within(const Mesh& mesh, const cut_test::Vertex_of<Mesh>& vertex_of,
                              const std::vector<char>& band)
{
  std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> index;
  for(std::size_t i = 0; i < vertex_of.size(); ++i) index[vertex_of[i]] = i;
  Edge_flags<Mesh> flags = no_edge(mesh);
  for(auto e : edges(mesh))
    flags[e] = band[index.at(source(e, mesh))] && band[index.at(target(e, mesh))];
  return flags;
}

} // namespace

template <typename Mesh>
class Forbidden_seams : public ::testing::Test {};
TYPED_TEST_SUITE(Forbidden_seams, cut_test::Mesh_types);

TYPED_TEST(Forbidden_seams, closed_sphere_routes_around_the_default_seams)
{
  forbid_default_seams<TypeParam>(cut_test::sphere_soup(8));
}

TYPED_TEST(Forbidden_seams, torus_routes_around_the_default_seams)
{
  forbid_default_seams<TypeParam>(cut_test::torus_soup(24, 12));
}

TYPED_TEST(Forbidden_seams, double_torus_routes_around_the_default_seams)
{
  forbid_default_seams<TypeParam>(cut_test::double_torus_soup(10));
}

TYPED_TEST(Forbidden_seams, disk_with_holes_routes_around_the_default_seams)
{
  forbid_default_seams<TypeParam>(cut_test::disk_with_holes_soup(13, 2));
}

// the cuts decided on a simplified copy and carried back avoid them too
TYPED_TEST(Forbidden_seams, multiresolution_routes_around_the_default_seams)
{
  forbid_default_seams<TypeParam>(cut_test::sphere_soup(24), SMP::parameters::multiresolution_faces(400));
}

// a third of the edges, chosen at random, on a torus: the initial cut and the
// alternation find their way between them
TYPED_TEST(Forbidden_seams, torus_with_a_random_third_of_the_edges_forbidden)
{
  using Mesh = TypeParam;
  const Mesh mesh = cut_test::make_mesh<Mesh>(cut_test::torus_soup(24, 12));
  Edge_flags<Mesh> forbidden = no_edge(mesh);
  cut_test::Rng rng(7);
  std::size_t count = 0;
  for(auto e : edges(mesh))
    if(rng.uniform() < 1. / 3.) { forbidden[e] = true; ++count; }
  ASSERT_GT(count, 100u);
  cut_test::Cut_run<Mesh> run(mesh);
  EXPECT_EQ(run_forbidding(mesh, forbidden, run), SMP::OK);
}

// a disk needs no cut: with every edge forbidden it is mapped whole
TYPED_TEST(Forbidden_seams, disk_with_every_edge_forbidden_is_one_chart)
{
  using Mesh = TypeParam;
  const Mesh mesh = cut_test::make_mesh<Mesh>(cut_test::hemisphere_soup(8, 16));
  Edge_flags<Mesh> forbidden = no_edge(mesh);
  for(auto e : edges(mesh)) forbidden[e] = true;
  cut_test::Cut_run<Mesh> run(mesh);
  ASSERT_EQ(run_forbidding(mesh, forbidden, run), SMP::OK);
  EXPECT_EQ(run.number_of_seam_edges(), 0u);
  EXPECT_EQ(run.result.number_of_charts, 1u);
}

TYPED_TEST(Forbidden_seams, closed_surface_with_every_edge_forbidden_is_refused)
{
  using Mesh = TypeParam;
  for(const cut_test::Soup& soup : {cut_test::sphere_soup(6), cut_test::torus_soup(12, 8)})
  {
    const Mesh mesh = cut_test::make_mesh<Mesh>(soup);
    Edge_flags<Mesh> forbidden = no_edge(mesh);
    for(auto e : edges(mesh)) forbidden[e] = true;
    cut_test::Cut_run<Mesh> run(mesh);
    run.fill_sentinels();
    EXPECT_EQ(run_forbidding(mesh, forbidden, run, SMP::parameters::face_discontinuity_map(run.v())),
              SMP::ERROR_FORBIDDEN_EDGES_BLOCK_CUT);
    run.expect_outputs_untouched();
  }
}

// every edge of the band between two meridian rings of a torus: any loop
// around the hole would have to cross the band, so no cut opens the torus
TYPED_TEST(Forbidden_seams, band_around_the_tube_of_a_torus_is_refused)
{
  using Mesh = TypeParam;
  const int nu = 16, nv = 8;
  const cut_test::Soup soup = cut_test::torus_soup(nu, nv);
  Mesh mesh;
  const cut_test::Vertex_of<Mesh> vertex_of = cut_test::build_mesh(soup, mesh);
  std::vector<char> band(soup.points.size(), 0);
  for(int j = 0; j < nv; ++j) band[std::size_t(3 * nv + j)] = band[std::size_t(4 * nv + j)] = 1; // rings 3 and 4
  Edge_flags<Mesh> forbidden = edges_within(mesh, vertex_of, band);
  cut_test::Cut_run<Mesh> run(mesh);
  EXPECT_EQ(run_forbidding(mesh, forbidden, run), SMP::ERROR_FORBIDDEN_EDGES_BLOCK_CUT);

  // the same band with one ring's edges only (no rung across) leaves a way
  std::vector<char> ring(soup.points.size(), 0);
  for(int j = 0; j < nv; ++j) ring[std::size_t(3 * nv + j)] = 1;
  Edge_flags<Mesh> ring_edges = edges_within(mesh, vertex_of, ring);
  cut_test::Cut_run<Mesh> around(mesh);
  EXPECT_EQ(run_forbidding(mesh, ring_edges, around), SMP::OK);
}

TYPED_TEST(Forbidden_seams, an_edge_both_given_as_seam_and_forbidden_is_refused)
{
  using Mesh = TypeParam;
  const Mesh mesh = cut_test::make_mesh<Mesh>(cut_test::sphere_soup(6));
  cut_test::Cut_run<Mesh> run(mesh);
  Edge_flags<Mesh> forbidden = no_edge(mesh);
  for(auto e : edges(mesh))
    if(!is_border(e, mesh))
    {
      forbidden[e] = true;
      run.seam_storage[e] = true;
      break;
    }
  EXPECT_EQ(run_forbidding(mesh, forbidden, run), SMP::ERROR_WRONG_PARAMETER);
}

TEST(Forbidden_seams_error_code, has_a_name_and_a_message)
{
  EXPECT_STREQ(SMP::error_name(SMP::ERROR_FORBIDDEN_EDGES_BLOCK_CUT), "ERROR_FORBIDDEN_EDGES_BLOCK_CUT");
  EXPECT_STRNE(SMP::error_message(SMP::ERROR_FORBIDDEN_EDGES_BLOCK_CUT), "Unknown error");
}
