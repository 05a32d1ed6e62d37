// What cut_and_parameterize() returns: its error code, the measures of the
// result and the work done (Cut_and_parameterize_result), and where the time
// went (Cut_and_parameterize_timings).
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_RESULT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_RESULT_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
/// Wall-clock time, in seconds (`std::chrono::steady_clock`), of the phases of
/// one call to `cut_and_parameterize()`. The parts add up to at most `total`:
/// the rest goes to argument checks, writing the outputs, the statistics of the
/// result and the progress callback. Under `distortion_bound`, each phase sums
/// the seconds of all the runs of the search; two runs at a time at once, they
/// can add up to more than `total`. Measuring changes nothing in the result.
/// After an error, the phases not reached are 0.
struct Cut_and_parameterize_timings
{
  double initialization = 0.; ///< indexing of the mesh, initial cut, chart mesh and Tutte map
  double u_steps = 0.;        ///< Newton minimizations of the UVs inside the alternation
  double v_steps = 0.;        ///< solves of the discontinuity field v
  double cut_extraction = 0.; ///< cut paths from v, and cutting the chart mesh along them
  double final_solve = 0.;    ///< final solve on the cut mesh, injective re-solve included
  double packing = 0.;        ///< packing of the charts into the square
  double total = 0.;          ///< the whole call
};

/// \ingroup PkgCutParameterizationRef
/// Outcome of `cut_and_parameterize()`.
struct Cut_and_parameterize_result
{
  Error_code error = OK;               ///< `OK` or the reason of the failure
  std::size_t number_of_charts = 0;    ///< connected components of the cut mesh
  std::size_t number_of_seam_edges = 0;///< seam edges (mesh boundary excluded)
  std::size_t newton_iterations = 0;   ///< total projected Newton iterations
  /// numeric Cholesky factorizations of the Newton Hessians (below 8,000
  /// unknowns an iteration may reuse the last one, fewer than one per
  /// iteration then; the Tutte and v solves, one factorization each, not counted)
  std::size_t number_of_factorizations = 0;
  /// solves with a factorization (forward and back substitutions) of those
  /// minimizations: one per Newton iteration, more where the inner solver
  /// reuses a factorization (`inner_solver`)
  std::size_t number_of_solves = 0;
  /// the part of `newton_iterations` spent in the alternation's u-steps (the
  /// rest: the final solves, the trials of splits and zips)
  std::size_t alternation_newton_iterations = 0;
  /// the part of `newton_iterations` spent in final solves without box (the
  /// trials' of the splits and of the bound search included)
  std::size_t final_solve_newton_iterations = 0;
  /// the part of `newton_iterations` spent in the box's solves (trials' included)
  std::size_t box_newton_iterations = 0;
  /// the part of `newton_iterations` spent relaxing maps that judge trial
  /// cuts and zips (the rest, beside these three and the alternation's: the
  /// first u-steps' and the rerouted seams' solves)
  std::size_t relax_newton_iterations = 0;
  /// the part of `number_of_factorizations` spent in the alternation's u-steps
  std::size_t alternation_factorizations = 0;
  /// the part of `number_of_solves` spent in the alternation's u-steps
  std::size_t alternation_solves = 0;
  /// factorizations of the v-steps' systems: the v-steps whose conjugate
  /// gradient did not converge (their symbolic analysis is done once per
  /// pass, at the first; not counted above)
  std::size_t v_step_factorizations = 0;
  std::size_t number_of_degenerate_faces = 0; ///< faces whose rest shape was clamped (zero area, needles)
  std::size_t number_of_isolated_vertices = 0; ///< vertices in no face: ignored, they have no UV
  std::size_t number_of_welded_vertices = 0;   ///< vertices merged into a colocal one (`weld_colocal_vertices`)
  std::size_t number_of_hard_edges = 0;        ///< edges cut as hard edges (`hard_edge_angle`), given seams apart
  double initial_distortion = 0.;      ///< E_d of the initial (Tutte) map
  double distortion = 0.;              ///< E_d of the result
  double seam_length = 0.;             ///< E_s of the result (initial cut included)
  /// pairs of UV border segments that cross properly (0: the atlas has no overlap)
  std::size_t border_crossings = 0;
  /// total UV area / area of the packing square (the unit square unless `world_units`)
  double uv_coverage = 0.;
  /// UV length per unit of 3D length (the common scale of all charts; 1 with `world_units`)
  double uv_scale = 1.;
  /// with `distortion_bound`: whether `distortion` is within it (if not, no
  /// seam cost tried reached it and the result is the lowest E_d found);
  /// always `true` without a bound
  bool distortion_bound_met = true;
  /// where the time went
  Cut_and_parameterize_timings timings;
  /// `true` if `error` is `OK`
  bool ok() const { return error == OK; }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
