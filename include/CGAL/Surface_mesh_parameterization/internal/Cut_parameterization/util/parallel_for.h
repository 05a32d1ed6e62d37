// Runs an index loop, or two tasks, on all cores when TBB is linked
// (CGAL_LINKED_WITH_TBB), serially otherwise. Callers write to per-index
// slots (or per-task results) only, so results do not depend on the number
// of threads.
#ifndef CGAL_SMP_CUT_INTERNAL_PARALLEL_FOR_H
#define CGAL_SMP_CUT_INTERNAL_PARALLEL_FOR_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <cstddef>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/parallel_invoke.h>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

template <typename Function>
void parallel_for(std::size_t n, const Function& function)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, tuning::parallel_grain),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for(std::size_t i = range.begin(); i != range.end(); ++i) function(i);
                    });
#else
  for(std::size_t i = 0; i < n; ++i) function(i);
#endif
}

/// Calls f(i) for every i < n, each as a task of its own where TBB is
/// linked (for a few heavy, independent calls), serially otherwise; f(i)
/// must write only what belongs to i.
template <typename Function>
void parallel_tasks(std::size_t n, const Function& function)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(std::size_t(0), n, function, tbb::simple_partitioner());
#else
  for(std::size_t i = 0; i < n; ++i) function(i);
#endif
}

/// Runs f() and g(), at once where TBB is linked and `at_once`, one after
/// the other otherwise. They must not share what they write.
template <typename F, typename G>
void parallel_invoke(const F& f, const G& g, bool at_once = true)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(at_once)
  {
    tbb::parallel_invoke(f, g);
    return;
  }
#else
  (void)at_once;
#endif
  f();
  g();
}

/// Calls f(i) for every i < n, two at a time (parallel_invoke(), with
/// `at_once`), the pairs one after the other; f(i) must write only what
/// belongs to i.
template <typename F>
void in_pairs(std::size_t n, const F& f, bool at_once = true)
{
  for(std::size_t i = 0; i < n; i += 2)
  {
    if(i + 1 < n) parallel_invoke([&] { f(i); }, [&] { f(i + 1); }, at_once);
    else f(i);
  }
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
