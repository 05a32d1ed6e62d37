// Every threshold and tuning constant of the method, in one place: each with
// a one-line reason; the measurements behind the values are in the manual's
// page "Design and measurements" (doc/design/).
#ifndef CGAL_SMP_CUT_INTERNAL_TUNING_H
#define CGAL_SMP_CUT_INTERNAL_TUNING_H

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace tuning {

// ---- Linear algebra, energies and inner solvers (linalg/, mesh/, energy/, solver/)



// ---- end of the solver section



// ---- Cuts, seams, atlas and the plan (cuts/, seams/, atlas/, pipeline/)
// (measurements: doc/design/pipeline.dox, page CutParamDesignPipeline)

// -- the alternation (pipeline/alternation.h)
/// u-steps after the first only track a v that changes anyway: capped.
constexpr int alternation_newton_iterations = 50;
/// with the quasi-Newton solver the later u-steps' cap is this many times
/// the above (its iterations cost a gradient and a solve, Newton's a factorization)
constexpr int quasi_newton_iteration_factor = 3;
/// Newton tolerance of the u-steps: they only decide where to cut.
constexpr double alternation_tolerance = 1e-5;
/// u-steps stop in a slow tail: after this many iterations, ...
constexpr int alternation_slow_tail_after = 100;
/// ... less than this ratio of the energy gained over this window
constexpr int alternation_slow_tail_window = 20;
constexpr double alternation_slow_tail_ratio = 1e-3;

// -- the final solve (pipeline/final_solve.h)
/// Newton tolerance of the final solve without barrier or box.
constexpr double final_tolerance = 1e-7;
/// with the barrier or before a box: these terms make Newton converge linearly only
constexpr double constrained_tolerance = 1e-5;
/// the box's solve: a gentle preference whose active set converges linearly
constexpr double box_tolerance = 1e-4;
/// the box's solve where the cuts came from a simplified copy (each iteration a solve of the whole mesh)
constexpr double large_mesh_box_tolerance = 1e-3;
/// a crossing chart overlapping itself on more than this many faces is cut into overlap-free pieces
constexpr int overlap_partition_faces = 10000;
/// after greedy splits on a cut mesh of at most this many faces, the split map is also solved in pieces
constexpr int split_pieces_max_faces = 1000;
/// Newton iterations at most of each solve of those pieces (their barrier converges slowly)
constexpr int split_pieces_newton_iterations = 50;
/// the box is weakened by this factor where it costs more than its budget, ...
constexpr double box_weakening = 0.7;
/// ... at most this many times, then dropped
constexpr int box_weakenings = 2;
/// the alternation's seams rerouted within this many rings at the final solve (0: never)
constexpr int rerouting_rings = 1;
/// and kept if E_d stays within this allowance of the seams not rerouted
constexpr double rerouting_allowance = 0.01;

// -- greedy splits (cuts/greedy_splits.h, pipeline/plan.h)
/// without a bound, splits start above this E_d: the field v could not place the cuts (low-poly models)
constexpr double low_poly_distortion = 5.;
/// without a bound, a map above this E_d (not above low_poly_distortion) is split down to it
constexpr double default_distortion_target = 4.6;
/// splits kept at most per round
constexpr int split_max_splits = 64;
/// most distorted vertices tried per split
constexpr int split_candidates = 3;
/// Newton iterations that judge a split
constexpr int split_newton_iterations = 30;
/// a split pays if E_d falls by at least this per unit of E_s it adds
constexpr double split_gain = 0.15;
/// rounds of splits and final solve at most (the final solve may end above the goal)
constexpr int split_rounds = 3;
/// a vertex's bound on its gain, from its last judged decrease, with this margin (lazy judging)
constexpr double lazy_judging_margin = 1.25;
/// on a large mesh every trial solves the whole map: splits go in batches of one
/// per multiresolution_faces faces, at most this many
constexpr std::size_t split_batch_max = 16;

// -- seams (seams/)
/// zips solved at most by the merges
constexpr int merge_max_trials = 48;
/// Newton iterations that judge a zip
constexpr int merge_newton_iterations = 20;
/// under a bound: seams rerouted within this many rings (0: never)
constexpr int seam_straightening_rings = 3;
/// final solves at most that undo zips (halving their number) until the bound holds
constexpr int merge_undo_tries = 3;

// -- the plan and the bound search (pipeline/plan.h, pipeline/bound_search.h)
/// up to this many faces two trials run at once, each on its own state; above, one after the other (memory)
constexpr std::size_t two_states_at_once_max_faces = 250000;
/// up to this many faces, a run without bound that ends above the default target gets the bound search at it
constexpr std::size_t default_target_search_max_faces = 2000;
/// up to this many faces the bound search has split trials (each split judged by solves of the whole mesh)
constexpr std::size_t split_trial_max_faces = 25000;
/// most distorted vertices judged per split by the split trial that keeps the best of them
constexpr int best_split_candidates = 6;
/// the λ search: halvings of λ at most (λ / 64)
constexpr int bound_steps_down = 6;
/// doublings of λ at most (λ · 8)
constexpr int bound_steps_up = 3;
/// rounds between failing and passing λ, each narrowing the interval 3 times
constexpr int bound_refinements = 1;
/// a λ candidate whose seams are this many times the shortest split trial's is not shortened (it cannot win)
constexpr double lambda_candidate_length_ratio = 1.5;
/// the multiresolution copy's λ is scaled by (mean edge ratio)^this
constexpr double coarse_lambda_exponent = 0.25;



// ---- end of the pipeline section

} // namespace tuning
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
