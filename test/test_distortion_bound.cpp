// distortion_bound: the result's E_d is within the bound when a seam cost
// reaches it (a deep bowl at 4.2), a loose bound never lengthens the seams
// of the default run, a bound no run reaches (4 on a curved surface, also
// after the greedy splits that follow the λ search) keeps the lowest E_d
// found and says so, and bounds below 4 are refused. Every
// result is a valid atlas (check_cut_result()).
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <limits>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

template <typename Mesh>
class Distortion_bound : public ::testing::Test
{
};
TYPED_TEST_SUITE(Distortion_bound, Mesh_types);

namespace {

// a spherical cap reaching 150 degrees from its pole: seams needed
Soup wide_cap() { return sphere_cap_soup(10, 32, 5. * pi / 6.); }

} // namespace

TYPED_TEST(Distortion_bound, a_reachable_bound_holds)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  check_cut_result(mesh, plain);
  ASSERT_GT(plain.result.distortion, 4.2); // the bound asks for more than the default gives

  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(4.2));
  check_cut_result(mesh, bounded);
  EXPECT_TRUE(bounded.result.distortion_bound_met);
  EXPECT_LE(bounded.result.distortion, 4.2);
  EXPECT_GT(bounded.result.seam_length, plain.result.seam_length); // it took more seams
}

TYPED_TEST(Distortion_bound, a_loose_bound_never_lengthens_the_seams)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(plain.result.distortion + 0.5));
  check_cut_result(mesh, bounded);
  EXPECT_TRUE(bounded.result.distortion_bound_met);
  EXPECT_LE(bounded.result.distortion, plain.result.distortion + 0.5);
  EXPECT_LE(bounded.result.seam_length, plain.result.seam_length + 1e-12);
}

TYPED_TEST(Distortion_bound, an_unreachable_bound_keeps_the_lowest_distortion)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  Cut_run<TypeParam> plain(mesh);
  plain.run();
  Cut_run<TypeParam> bounded(mesh);
  bounded.run(SMP::parameters::distortion_bound(4.));
  check_cut_result(mesh, bounded);
  EXPECT_FALSE(bounded.result.distortion_bound_met);
  EXPECT_GT(bounded.result.distortion, 4.);
  EXPECT_LE(bounded.result.distortion, plain.result.distortion); // the default λ was one of the runs
  EXPECT_TRUE(plain.result.distortion_bound_met);                // no bound: nothing to miss
}

TYPED_TEST(Distortion_bound, bounds_below_four_are_refused)
{
  const TypeParam mesh = make_mesh<TypeParam>(wide_cap());
  for(double bad : {3.9, -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    SCOPED_TRACE("bound " + to_text(bad));
    Cut_run<TypeParam> run(mesh);
    run.run(SMP::parameters::distortion_bound(bad));
    EXPECT_EQ(run.result.error, SMP::ERROR_WRONG_PARAMETER);
    EXPECT_EQ(run.number_of_seam_edges(), 0u); // outputs untouched
  }
}
