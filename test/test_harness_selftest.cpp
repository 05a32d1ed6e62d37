// The harness itself can fail: failing checks are counted, REQUIRE leaves
// the test, a failing or check-less test makes run_all() return non-zero.
#include "test_harness.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace {

/// Runs `f` with the harness's counters saved and restored; returns the
/// number of failures `f` caused.
template <typename F>
std::size_t failures_caused_by(F&& f)
{
  std::cerr << "  (self-test: the FAILED lines that follow are expected)\n";
  const cut_test::State saved = cut_test::state();
  cut_test::state().failures = 0;
  f();
  const std::size_t caused = cut_test::state().failures;
  cut_test::state() = saved;
  return caused;
}

/// Runs run_all() on the given tests only, restoring the registry and counters.
int run_isolated(std::vector<cut_test::Test_case> tests, const char* filter = nullptr)
{
  std::cout << "  (self-test: a nested run follows, its failures are expected)" << std::endl;
  const cut_test::State saved = cut_test::state();
  std::vector<cut_test::Test_case> registry;
  registry.swap(cut_test::registry());
  cut_test::registry() = std::move(tests);
  char name[] = "selftest";
  std::string filter_text = filter ? filter : "";
  char* argv[] = {name, &filter_text[0], nullptr};
  const int result = cut_test::run_all(filter ? 2 : 1, argv);
  cut_test::registry().swap(registry);
  cut_test::state() = saved;
  return result;
}

} // namespace

CUT_TEST(failing_checks_are_counted)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  bool results[6] = {};
  const std::size_t caused = failures_caused_by([&] {
    results[0] = CHECK(1 + 1 == 3);
    results[1] = CHECK_EQ(2, 3);
    results[2] = CHECK_NEAR(1., 1.1, 0.05);
    results[3] = CHECK_NEAR(nan, nan, 1.);
    results[4] = CHECK_REL(1., 2., 0.1);
    results[5] = CHECK_MSG(false, "value " << 42);
  });
  CHECK_EQ(caused, std::size_t(6));
  for(bool r : results) CHECK(!r);
}

CUT_TEST(passing_checks_are_not_counted)
{
  bool results[4] = {};
  const std::size_t caused = failures_caused_by([&] {
    results[0] = CHECK(1 + 1 == 2);
    results[1] = CHECK_EQ(3, 3);
    results[2] = CHECK_NEAR(1., 1. + 1e-12, 1e-9);
    results[3] = CHECK_REL(1e6, 1e6 + 1e-4, 1e-9);
  });
  CHECK_EQ(caused, std::size_t(0));
  for(bool r : results) CHECK(r);
}

CUT_TEST(require_leaves_the_test)
{
  bool reached_after = false, aborted = false;
  const std::size_t caused = failures_caused_by([&] {
    try
    {
      REQUIRE(false);
      reached_after = true;
    }
    catch(const cut_test::Abort_test&)
    {
      aborted = true;
    }
  });
  CHECK(aborted);
  CHECK(!reached_after);
  CHECK_EQ(caused, std::size_t(1));
}

CUT_TEST(run_all_reports_failing_tests)
{
  auto pass = [] { CHECK(true == true); };
  auto fail = [] { CHECK(false); };
  auto throws = [] { throw std::runtime_error("boom"); };
  auto no_check = [] {};
  CHECK_EQ(run_isolated({{"pass", pass}}), 0);
  CHECK_EQ(run_isolated({{"pass", pass}, {"fail", fail}}), 1);
  CHECK_EQ(run_isolated({{"throws", throws}}), 1);
  CHECK_EQ(run_isolated({{"no_check", no_check}}), 1);
  // the filter selects by substring; no match is an error
  CHECK_EQ(run_isolated({{"pass", pass}, {"fail", fail}}, "pa"), 0);
  CHECK_EQ(run_isolated({{"pass", pass}}, "nothing"), 2);
}

CUT_TEST_MAIN()
