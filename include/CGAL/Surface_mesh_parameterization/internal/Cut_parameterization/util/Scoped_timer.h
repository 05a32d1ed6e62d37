// Wall-clock time of a phase of the method (std::chrono::steady_clock), added
// to a counter of seconds; reported in Cut_and_parameterize_result::timings.
// Reading the clock changes nothing in the computation.
#ifndef CGAL_SMP_CUT_INTERNAL_SCOPED_TIMER_H
#define CGAL_SMP_CUT_INTERNAL_SCOPED_TIMER_H

#include <chrono>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Steady_clock = std::chrono::steady_clock;

/// Seconds from `start` to now.
inline double seconds_since(Steady_clock::time_point start)
{
  return std::chrono::duration<double>(Steady_clock::now() - start).count();
}

/// Adds the time from its construction to stop() (or to its destruction,
/// whichever comes first) to `seconds`.
class Scoped_timer
{
  double* seconds_;
  Steady_clock::time_point start_;

public:
  explicit Scoped_timer(double& seconds) : seconds_(&seconds), start_(Steady_clock::now()) {}
  ~Scoped_timer() { stop(); }
  Scoped_timer(const Scoped_timer&) = delete;
  Scoped_timer& operator=(const Scoped_timer&) = delete;

  void stop()
  {
    if(seconds_ == nullptr) return;
    *seconds_ += seconds_since(start_);
    seconds_ = nullptr;
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
