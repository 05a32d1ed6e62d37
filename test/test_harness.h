// A tiny self-contained test harness (no external dependency).
//
//   CUT_TEST(name) { CHECK(x > 0); CHECK_NEAR(a, b, 1e-9); }
//   CUT_TYPED_TEST(name, cut_test::Type_list<A, B>) { TestType t; ... }
//   int main(int argc, char** argv) { return cut_test::run_all(argc, argv); }
//
// CHECK* records a failure and goes on; REQUIRE* records it and leaves the
// current test (by exception). run_all() runs every registered test whose
// name contains argv[1] (all when absent) and returns non-zero if any check
// failed, any test threw, or no test ran.
#ifndef CUT_PARAM_TEST_HARNESS_H
#define CUT_PARAM_TEST_HARNESS_H

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace cut_test {

struct Test_case
{
  std::string name;
  std::function<void()> body;
};

inline std::vector<Test_case>& registry()
{
  static std::vector<Test_case> tests;
  return tests;
}

inline bool register_test(std::string name, std::function<void()> body)
{
  registry().push_back({std::move(name), std::move(body)});
  return true;
}

struct State
{
  std::size_t checks = 0;
  std::size_t failures = 0;      // in the current test
  std::size_t max_reported = 20; // per test, to keep logs short
};

inline State& state()
{
  static State s;
  return s;
}

/// Thrown by REQUIRE to abandon the current test.
struct Abort_test {};

/// Extra context printed with every failure while it lives (e.g. the mesh type, a seed).
class Scoped_context
{
public:
  explicit Scoped_context(std::string text) { stack().push_back(std::move(text)); }
  ~Scoped_context() { stack().pop_back(); }
  Scoped_context(const Scoped_context&) = delete;
  Scoped_context& operator=(const Scoped_context&) = delete;
  static std::vector<std::string>& stack()
  {
    static std::vector<std::string> s;
    return s;
  }
};

inline void report_failure(const char* file, int line, const std::string& what)
{
  State& s = state();
  ++s.failures;
  if(s.failures > s.max_reported) return;
  std::cerr << "  FAILED " << file << ":" << line << ": " << what << "\n";
  for(const std::string& c : Scoped_context::stack()) std::cerr << "    while: " << c << "\n";
  if(s.failures == s.max_reported) std::cerr << "  (further failures of this test not shown)\n";
}

template <typename T>
std::string to_text(const T& value)
{
  std::ostringstream os;
  os << std::setprecision(17) << value;
  return os.str();
}

inline bool check(bool ok, const char* file, int line, const std::string& what)
{
  ++state().checks;
  if(!ok) report_failure(file, line, what);
  return ok;
}

template <typename A, typename B>
bool check_eq(const A& a, const B& b, const char* ea, const char* eb, const char* file, int line)
{
  const bool ok = (a == b);
  return check(ok, file, line,
               std::string(ea) + " == " + eb + "  (" + to_text(a) + " vs " + to_text(b) + ")");
}

/// |a - b| <= tol; NaN never passes.
inline bool check_near(double a, double b, double tol, const char* ea, const char* eb,
                       const char* file, int line)
{
  const bool ok = std::abs(a - b) <= tol;
  return check(ok, file, line,
               std::string("|") + ea + " - " + eb + "| <= " + to_text(tol) + "  (" + to_text(a)
               + " vs " + to_text(b) + ", diff " + to_text(std::abs(a - b)) + ")");
}

/// |a - b| <= rel * max(|a|, |b|); NaN never passes.
inline bool check_rel(double a, double b, double rel, const char* ea, const char* eb,
                      const char* file, int line)
{
  const double scale = (std::max)(std::abs(a), std::abs(b));
  const bool ok = std::abs(a - b) <= rel * scale;
  return check(ok, file, line,
               std::string(ea) + " ~ " + eb + " (relative " + to_text(rel) + ")  (" + to_text(a)
               + " vs " + to_text(b) + ", relative diff "
               + to_text(scale > 0 ? std::abs(a - b) / scale : 0.) + ")");
}

template <typename... Ts>
struct Type_list {};

template <typename T>
struct Type_tag { using type = T; };

/// Readable name of a test type; specialize for the types you test with.
template <typename T>
struct Type_name
{
  static std::string get() { return typeid(T).name(); }
};

template <typename F>
bool register_typed(const std::string&, Type_list<>, F&&) { return true; }

template <typename T, typename... Ts, typename F>
bool register_typed(const std::string& name, Type_list<T, Ts...>, F&& f)
{
  register_test(name + "<" + Type_name<T>::get() + ">", [f]() { f(Type_tag<T>()); });
  return register_typed(name, Type_list<Ts...>(), f);
}

inline int run_all(int argc, char** argv)
{
  const std::string filter = argc > 1 ? argv[1] : "";
  std::size_t run = 0, failed = 0, total_checks = 0;
  std::vector<std::string> failed_names;
  for(const Test_case& t : registry())
  {
    if(!filter.empty() && t.name.find(filter) == std::string::npos) continue;
    ++run;
    state().failures = 0;
    state().checks = 0;
    std::cout << "[ RUN  ] " << t.name << std::endl;
    const auto start = std::chrono::steady_clock::now();
    try
    {
      t.body();
    }
    catch(const Abort_test&)
    {
      // failure already recorded
    }
    catch(const std::exception& e)
    {
      report_failure(__FILE__, __LINE__, std::string("uncaught exception: ") + e.what());
    }
    catch(...)
    {
      report_failure(__FILE__, __LINE__, "uncaught unknown exception");
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    total_checks += state().checks;
    if(state().checks == 0 && state().failures == 0)
      report_failure(__FILE__, __LINE__, "test made no check");
    if(state().failures > 0)
    {
      ++failed;
      failed_names.push_back(t.name);
      std::cout << "[ FAIL ] " << t.name << " (" << state().failures << " failed checks, "
                << std::fixed << std::setprecision(1) << ms << " ms)" << std::endl;
    }
    else
      std::cout << "[  OK  ] " << t.name << " (" << state().checks << " checks, "
                << std::fixed << std::setprecision(1) << ms << " ms)" << std::endl;
  }
  std::cout << run << " tests, " << failed << " failed, " << total_checks << " checks" << std::endl;
  for(const std::string& n : failed_names) std::cout << "  failed: " << n << std::endl;
  if(run == 0)
  {
    std::cout << "no test matched filter '" << filter << "'" << std::endl;
    return 2;
  }
  return failed == 0 ? 0 : 1;
}

} // namespace cut_test

#define CUT_TEST_CAT2(a, b) a##b
#define CUT_TEST_CAT(a, b) CUT_TEST_CAT2(a, b)

#define CUT_TEST(name)                                                                    \
  static void name();                                                                     \
  static const bool CUT_TEST_CAT(name, _registered) = ::cut_test::register_test(#name, &name); \
  static void name()

/// Defines a test template over `TestType`, instantiated for every type of TYPE_LIST.
#define CUT_TYPED_TEST(name, TYPE_LIST)                                                   \
  template <typename TestType> static void name();                                        \
  static const bool CUT_TEST_CAT(name, _registered) = ::cut_test::register_typed(         \
    #name, TYPE_LIST(), [](auto tag) { name<typename decltype(tag)::type>(); });           \
  template <typename TestType> static void name()

#define CHECK(cond) ::cut_test::check(static_cast<bool>(cond), __FILE__, __LINE__, #cond)
#define CHECK_MSG(cond, msg)                                                               \
  ::cut_test::check(static_cast<bool>(cond), __FILE__, __LINE__,                          \
                    std::string(#cond) + "  [" + [&] { std::ostringstream os_; os_ << msg; return os_.str(); }() + "]")
#define CHECK_EQ(a, b) ::cut_test::check_eq((a), (b), #a, #b, __FILE__, __LINE__)
#define CHECK_NEAR(a, b, tol) ::cut_test::check_near((a), (b), (tol), #a, #b, __FILE__, __LINE__)
#define CHECK_REL(a, b, rel) ::cut_test::check_rel((a), (b), (rel), #a, #b, __FILE__, __LINE__)

#define REQUIRE(cond)                                                                      \
  do { if(!CHECK(cond)) throw ::cut_test::Abort_test(); } while(0)
#define REQUIRE_MSG(cond, msg)                                                             \
  do { if(!CHECK_MSG(cond, msg)) throw ::cut_test::Abort_test(); } while(0)
#define REQUIRE_EQ(a, b)                                                                   \
  do { if(!CHECK_EQ(a, b)) throw ::cut_test::Abort_test(); } while(0)

#define CUT_TEST_MAIN()                                                                    \
  int main(int argc, char** argv) { return ::cut_test::run_all(argc, argv); }

#endif
