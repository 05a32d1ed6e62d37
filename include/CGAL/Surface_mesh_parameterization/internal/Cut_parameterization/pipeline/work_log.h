// The work log of a run: the inner solver's work (iterations, factorizations,
// solves), the alternation's part of it, the v-steps' factorizations and the
// wall seconds of each phase. Kept apart from the map state: a trial solved
// on a copy of the state logs into its own log, added to the run's.
#ifndef CGAL_SMP_CUT_INTERNAL_WORK_LOG_H
#define CGAL_SMP_CUT_INTERNAL_WORK_LOG_H

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Wall seconds spent in each phase (Cut_and_parameterize_timings documents them).
struct Joint_timings
{
  double initialization = 0.; // indexing, initial cut, chart mesh, Tutte
  double u_steps = 0.;        // Newton minimizations of the alternation
  double v_steps = 0.;        // discontinuity-field solves
  double cut_extraction = 0.; // extract_cut_paths() and apply_cuts()
  double final_solve = 0.;    // final_solve(), injective re-solve included
  double packing = 0.;

  /// Adds the seconds of `other`.
  void add(const Joint_timings& other)
  {
    initialization += other.initialization;
    u_steps += other.u_steps;
    v_steps += other.v_steps;
    cut_extraction += other.cut_extraction;
    final_solve += other.final_solve;
    packing += other.packing;
  }
};

/// Work of the inner solver: iterations, numeric Cholesky factorizations and
/// solves with them.
struct Solver_counts
{
  std::size_t iterations = 0, factorizations = 0, solves = 0;

  Solver_counts& operator+=(const Solver_counts& other)
  {
    iterations += other.iterations;
    factorizations += other.factorizations;
    solves += other.solves;
    return *this;
  }
};

/// The work log of a run, or of a trial of it.
struct Work_log
{
  Solver_counts work;               // of every minimization of the UVs
  Solver_counts u_step_work;        // the part of `work` spent in the alternation's u-steps
  Solver_counts final_work;         // the part spent in final solves without box (trials' included)
  Solver_counts box_work;           // the part spent in the box's solves (trials' included)
  Solver_counts relax_work;         // the part spent relaxing maps to judge trial cuts and zips
  std::size_t v_step_factorizations = 0; // v-steps solved by a factorization (the conjugate gradient did not converge; not in `work`)
  Joint_timings timings;

  /// Adds the work of one minimization (a Newton_report); returns it.
  template <typename Report>
  Solver_counts count(const Report& report)
  {
    const Solver_counts w{std::size_t(report.iterations), std::size_t(report.factorizations),
                          std::size_t(report.solves)};
    work += w;
    return w;
  }

  /// Adds every record of `other` (a trial's log, or a run beside this one).
  void add(const Work_log& other)
  {
    work += other.work;
    u_step_work += other.u_step_work;
    final_work += other.final_work;
    box_work += other.box_work;
    relax_work += other.relax_work;
    v_step_factorizations += other.v_step_factorizations;
    timings.add(other.timings);
  }
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
