// What the tests share besides the mesh generators: GoogleTest, a relative
// comparison, and number formatting for messages.
//
//   EXPECT_REL(a, b, 1e-9);   // |a - b| <= 1e-9 * max(|a|, |b|), NaN fails
//   ASSERT_REL(a, b, 1e-9);   // the same, leaving the test on failure
//   CUT_ASSERT_TRUE(x) << m;  // ASSERT_TRUE in a function that returns a value
#ifndef CUT_PARAM_TEST_SUPPORT_H
#define CUT_PARAM_TEST_SUPPORT_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cut_test {

/// `value` with 17 significant digits, for messages.
template <typename T>
std::string to_text(const T& value)
{
  std::ostringstream os;
  os << std::setprecision(17) << value;
  return os.str();
}

/// GoogleTest predicate formatter: |a - b| <= rel * max(|a|, |b|).
inline ::testing::AssertionResult relatively_near(const char* ea, const char* eb, const char*, double a, double b,
                                                  double rel)
{
  const double scale = (std::max)(std::abs(a), std::abs(b));
  if(std::abs(a - b) <= rel * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << ea << " ~ " << eb << " (relative " << rel << "): " << to_text(a) << " vs "
                                       << to_text(b) << ", relative difference "
                                       << to_text(scale > 0. ? std::abs(a - b) / scale : 0.);
}

/// Thrown by CUT_ASSERT_*: GoogleTest reports the test as failed.
struct Test_abandoned : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The failure of a CUT_ASSERT_*: collects the streamed message, records it
/// as a GoogleTest failure and throws Test_abandoned when the statement ends.
class Abandon_test
{
public:
  Abandon_test(const char* file, int line, const char* what) : file_(file), line_(line) { message_ << what; }
  Abandon_test(const Abandon_test&) = delete;
  template <typename T>
  Abandon_test& operator<<(const T& x)
  {
    message_ << x;
    return *this;
  }
  ~Abandon_test() noexcept(false)
  {
    ADD_FAILURE_AT(file_, line_) << message_.str();
    throw Test_abandoned(message_.str());
  }

private:
  std::ostringstream message_;
  const char* file_;
  int line_;
};

} // namespace cut_test

// ASSERT_TRUE and ASSERT_EQ for functions that return a value (GoogleTest's
// ASSERT_* only work in functions returning void): leave the test by an
// exception. Messages stream as with ASSERT_*.
#define CUT_ASSERT_TRUE(cond)                                                                       \
  if(static_cast<bool>(cond)) {} else ::cut_test::Abandon_test(__FILE__, __LINE__, "required: " #cond)
#define CUT_ASSERT_EQ(a, b)                                                                         \
  if((a) == (b)) {} else ::cut_test::Abandon_test(__FILE__, __LINE__, "required: " #a " == " #b)

#define EXPECT_REL(a, b, rel) EXPECT_PRED_FORMAT3(::cut_test::relatively_near, a, b, rel)
#define ASSERT_REL(a, b, rel) ASSERT_PRED_FORMAT3(::cut_test::relatively_near, a, b, rel)

#endif
