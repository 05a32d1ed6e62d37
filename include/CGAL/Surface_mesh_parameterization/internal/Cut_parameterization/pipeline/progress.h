// The progress reports of a run: the callback of the options, called by the
// stages that report (alternation, cuts, splits, the finished atlas).
#ifndef CGAL_SMP_CUT_INTERNAL_PROGRESS_H
#define CGAL_SMP_CUT_INTERNAL_PROGRESS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>

#include <functional>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The callback a stage reports to (empty: none); false from it cancels.
using Progress = std::function<bool(const Cut_and_parameterize_progress&)>;

/// Alternations of one pass: iterations_per_epsilon per value of ε, halved
/// from epsilon_start while above epsilon_end.
inline int alternations_per_pass(const Cut_parameterization_options& o)
{
  int n = 0;
  for(double eps = o.epsilon_start; eps > o.epsilon_end; eps *= 0.5) n += o.iterations_per_epsilon;
  return n;
}

/// The report of `phase` with these values.
inline Cut_and_parameterize_progress progress_report(const char* phase, int pass, int alternation,
                                                      int per_pass, double epsilon, double distortion)
{
  Cut_and_parameterize_progress p;
  p.phase = phase;
  p.pass = pass;
  p.alternation = alternation;
  p.alternations_per_pass = per_pass;
  p.epsilon = epsilon;
  p.distortion = distortion;
  return p;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
