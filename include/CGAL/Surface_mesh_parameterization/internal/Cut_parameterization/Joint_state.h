// The state of the cut mesh that the joint optimization works on (which
// edges are cut, the chart mesh, its map, the counters), and the one way to
// cut it further (apply_cuts()).
#ifndef CGAL_SMP_CUT_INTERNAL_JOINT_STATE_H
#define CGAL_SMP_CUT_INTERNAL_JOINT_STATE_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cut_extraction.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/initial_cut.h>

#include <Eigen/Core>

#include <vector>

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
  void add(const Joint_timings& other) { add_since(other, Joint_timings()); }
  /// Adds the seconds of `later` spent after `earlier` (the same run's
  /// timings at an earlier point).
  void add_since(const Joint_timings& later, const Joint_timings& earlier)
  {
    initialization += later.initialization - earlier.initialization;
    u_steps += later.u_steps - earlier.u_steps;
    v_steps += later.v_steps - earlier.v_steps;
    cut_extraction += later.cut_extraction - earlier.cut_extraction;
    final_solve += later.final_solve - earlier.final_solve;
    packing += later.packing - earlier.packing;
  }
};

/// Work of the inner solver in a phase: iterations, numeric Cholesky
/// factorizations and solves with them.
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
  friend Solver_counts operator-(Solver_counts a, const Solver_counts& b)
  {
    a.iterations -= b.iterations;
    a.factorizations -= b.factorizations;
    a.solves -= b.solves;
    return a;
  }
};

/// The state of the cut mesh: which edges are cut, its chart mesh and UVs.
struct Joint_state
{
  std::vector<char> is_cut;      // per surface edge
  Cut_rules rules;               // forbidden edges and the cost of cutting each edge
  Chart_mesh chart;
  std::vector<int> corner_uv;    // per surface corner
  UV_vector x;
  Eigen::VectorXd v;             // per face
  std::size_t newton_iterations = 0;
  std::size_t factorizations = 0;   // numeric Cholesky factorizations of the Newton solves
  std::size_t solves = 0;           // solves with those factorizations
  Solver_counts u_step_work;        // the part of the three above spent in the alternation's u-steps
  std::size_t v_step_factorizations = 0; // of the v-steps' systems, one per v-step (not in the above)
  std::size_t degenerate_faces = 0; // faces whose rest shape was clamped
  double initial_distortion = 0.;
  double distortion = 0.;           // E_d of the final map, before packing scales it
  // chart, x and v hold the initial cut mesh after the alternation's first
  // u-step (prepare_first_u_step()): the first pass starts at its v-step
  bool first_u_step_done = false;
  Packing_result packing;
  Joint_timings timings;

  /// The counts of the inner solver's work (iterations, factorizations, solves).
  Solver_counts work() const { return {newton_iterations, factorizations, solves}; }
  void set_work(const Solver_counts& w)
  {
    newton_iterations = w.iterations;
    factorizations = w.factorizations;
    solves = w.solves;
  }
  /// Adds the counts of `other` (a trial, or a state solved beside this one).
  void add_work(const Joint_state& other)
  {
    newton_iterations += other.newton_iterations;
    factorizations += other.factorizations;
    solves += other.solves;
  }
  /// Adds every record of work (the counts, the u-steps' part, the v-step
  /// factorizations, the timings) that `later` holds beyond `earlier`, the
  /// state it started from (a run from a copy of `earlier`).
  void add_work_since(const Joint_state& later, const Joint_state& earlier)
  {
    Solver_counts counts = work();
    counts += later.work() - earlier.work();
    set_work(counts);
    u_step_work += later.u_step_work - earlier.u_step_work;
    v_step_factorizations += later.v_step_factorizations - earlier.v_step_factorizations;
    timings.add_since(later.timings, earlier.timings);
  }
  /// Every record of work of `other` in place of this state's.
  void set_work_records(const Joint_state& other)
  {
    set_work(other.work());
    u_step_work = other.u_step_work;
    v_step_factorizations = other.v_step_factorizations;
    timings = other.timings;
  }

  /// Adds the work of one minimization (a Newton_report) to the counts;
  /// returns it as Solver_counts.
  template <typename Report>
  Solver_counts count(const Report& report)
  {
    const Solver_counts work{std::size_t(report.iterations), std::size_t(report.factorizations),
                             std::size_t(report.solves)};
    newton_iterations += work.iterations;
    factorizations += work.factorizations;
    solves += work.solves;
    return work;
  }
};

/// Up to this many faces, the work that runs two trials at once, each on its
/// own Joint_state (the λ search's runs, the zips of seam_merging.h), does
/// so; above, one after the other, so that peak memory stays that of one
/// state (bimba_i_f10000 refined to 640k faces: 2.6 GB for a run). Either
/// way gives the same result.
constexpr std::size_t two_states_at_once_max_faces = 250000;

/// Rebuilds the chart mesh of `state` from `state.is_cut`, which holds the
/// cuts of the current chart mesh and maybe more, and carries the UVs over:
/// both sides of a new cut start where the uncut vertex was, so the map
/// stays flip-free.
template <typename Surface>
void rebuild_cut_mesh(const Surface& surface, Joint_state& state)
{
  const std::vector<int> old_corner_uv = state.corner_uv;
  const UV_vector old_x = state.x;
  build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  state.x.resize(2 * state.chart.number_of_vertices);
  for(std::size_t c = 0; c < old_corner_uv.size(); ++c)
    state.x.template segment<2>(2 * state.corner_uv[c]) = old_x.template segment<2>(2 * old_corner_uv[c]);
}

/// Cuts the edges of `paths`, then joins any closed slit (a path that does
/// not reach the boundary) to the boundary by a short path, so every chart
/// stays a topological disk (make_disks()). Rebuilds the chart mesh and
/// carries the UVs over (rebuild_cut_mesh()).
///
/// With forbidden edges, a slit may have no way to the boundary: then the
/// paths are taken one at a time, and those whose slit cannot be opened
/// are left out.
template <typename Surface>
void apply_cuts(const Surface& surface, const std::vector<Cut_path>& paths, Joint_state& state)
{
  const std::vector<char> before = state.is_cut;
  for(const Cut_path& path : paths)
    for(int e : path.edges) state.is_cut[e] = 1;
  if(!make_disks(surface, state.is_cut, state.rules))
  {
    state.is_cut = before;
    for(const Cut_path& path : paths)
    {
      std::vector<char> trial = state.is_cut;
      for(int e : path.edges) trial[e] = 1;
      if(make_disks(surface, trial, state.rules)) state.is_cut.swap(trial);
    }
  }
  rebuild_cut_mesh(surface, state);
}

/// 3D length of the cut edges that are not on the mesh's border.
template <typename Surface>
double seam_length_3d(const Surface& surface, const std::vector<char>& is_cut)
{
  double length = 0.;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] > fe && is_cut[surface.edge_of[fe]]) length += surface.edge_length(fe);
  return length;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
