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
// Measurements: the manual's page "Design and measurements: energies and
// inner solvers" (doc/design/solver.dox).

// mesh/Chart_mesh.h
/// Relative height (and first side) below which a face's rest shape is clamped as degenerate: no NaN from needles.
constexpr double degenerate_ratio = 1e-4;
/// Vertices closer than this times the bounding box diagonal are welded (weld_colocal_vertices).
constexpr double colocal_vertex_tolerance = 1e-6;

// energy/symmetric_dirichlet.h, first_collapse_time()
/// Leading coefficient below this fraction of the largest: the collapse equation is solved as linear.
constexpr double collapse_linear_ratio = 1e-14;
/// A discriminant down to minus this times b^2 is a double root: round-off must not hide a uniform shrink.
constexpr double collapse_discriminant_slack = 1e-12;

// linalg/Sparse_cholesky.h
/// Unknowns from which METIS orders the simplicial factorization (if built with it): faster than AMD from 20k.
constexpr std::ptrdiff_t metis_threshold = 30000;
/// Unknowns from which CHOLMOD's supernodal factorization takes over (if built with it): faster from about 5k.
constexpr std::ptrdiff_t cholmod_threshold = 8000;
/// The same where the process runs OpenMP regions of one thread without a team (openmp_regions_without_team()):
/// CHOLMOD's small regions then cost no system call, and it is faster from a few hundred unknowns.
constexpr std::ptrdiff_t cholmod_threshold_without_team = 1000;
/// CHOLMOD's supernode relaxation (columns; fraction of zeros): merged more eagerly than its defaults (4, 16, 48;
/// 0.8, 0.1, 0.05), its work around each supernode outweighing the extra zeros.
constexpr std::size_t cholmod_nrelax[3] = {12, 32, 96};
constexpr double cholmod_zrelax[3] = {0.8, 0.2, 0.1};

// util/parallel_for.h
/// Indices per TBB task of parallel_for(): per-face loops of a few hundred flops each.
constexpr std::size_t parallel_grain = 512;

// geometry/box_pairs.h
/// A box spanning more grid cells than this is tested against every box: the cost stays at most quadratic.
constexpr long box_grid_max_cells = 64;

// geometry/segment_contacts.h
/// Slack on the segment parameter of a contact: conservative near tangency (a point at the segment's end counts).
constexpr double contact_parameter_slack = 1e-9;
/// Leading coefficient below this fraction of the largest: the contact equation is solved as linear.
constexpr double contact_linear_ratio = 1e-12;

// energy/Border_barrier_term.h
/// Barrier distance ε relative to the mean 3D border edge length.
constexpr double barrier_relative_distance = 0.25;
/// Border vertices per task of the barrier's pair search (Border_barrier_term::map_candidate_pairs()): a
/// chart with fewer is searched on the calling thread.
constexpr std::size_t barrier_pair_block = 256;
/// Energy of a pair at ε/2 relative to the mean face area.
constexpr double barrier_relative_weight = 1.;
/// A border segment shorter in UV than this times the unsquashed ε is squashed: its ε follows its UV length.
constexpr double barrier_squashed = 0.1;
/// Close pairs outside the pattern join it once they are this fraction of the declared pairs...
constexpr double barrier_pattern_growth = 1. / 16.;
/// ... or after this many Newton iterations: a new pattern per iteration was most of the time.
constexpr int barrier_pattern_delay = 4;

// energy/Bounding_box_term.h
/// Fraction of its rectangle a chart is meant to fill: 1, so that it fits only by filling it.
constexpr double box_target_fill = 1.;

// solver/tutte_embedding.h
/// Distance between the centres of neighbouring charts' circles, in radii: a gap of a fifth of a radius.
constexpr double tutte_circle_spacing = 2.2;

// solver/Energy_terms_core.h
/// Newton_settings::max_iterations by default.
constexpr int newton_max_iterations = 500;
/// Newton_settings::tolerance by default: a decrease of the area-weighted mean distortion, scale-free.
constexpr double newton_tolerance = 1e-9;
/// Slow_tail::window by default: the steps over which the slow-tail rule measures the decrease.
constexpr int slow_tail_window = 20;
/// Slow_tail::ratio by default: a relative decrease over the window below which a minimization crawls.
constexpr double slow_tail_ratio = 1e-3;
/// Mean energy (Psi; E_d 24) above which reweighted proxy steps come first: far above any chart's minimum.
constexpr double reweighted_start_energy = 10.;
/// Distortion_minimizer's reweighted start: proxy steps while each leaves at most this fraction of the energy.
constexpr double reweighted_start_ratio = 0.8;
/// Distortion_minimizer's longest line-search step, in whole steps: longer steps cut projected Newton's slow tails.
constexpr double step_growth = 64.;
/// The fill-reducing ordering is kept while the Hessian's entries stay within 1/this of those it was computed for.
constexpr std::ptrdiff_t ordering_kept_within = 50;
/// Diagonal shift relative to the mean diagonal: removes the rigid-motion null space of the Hessian.
constexpr double hessian_shift = 1e-9;
/// Factorizations tried, the shift multiplied by hessian_shift_growth after each failure.
constexpr int factorization_attempts = 6;
constexpr double hessian_shift_growth = 100.;
/// Armijo's sufficient-decrease constant of the line search.
constexpr double armijo = 1e-4;
/// Halvings of the step before the line search gives up.
constexpr int line_search_halvings = 60;
/// Fraction of the flip-free step bound the line search starts from (at the bound itself a face collapses).
constexpr double step_bound_fraction = 0.9;

// solver/Projected_newton_solver.h
/// Conjugate-gradient iterations preconditioned by the last factorization before a new one is made.
constexpr int reuse_iterations = 3;
/// Their target residual relative to the gradient: an inexact Newton step, never used to decide convergence.
constexpr double reuse_tolerance = 0.2;

// solver/Proxy_quasi_newton_solver.h
/// L-BFGS curvature pairs kept (16: the same counts within 3%).
constexpr int lbfgs_memory = 8;
/// The proxy is factorized again once a step gains less than this fraction of the first step after it.
constexpr double refactorization_ratio = 0.1;
/// A pair is kept only where s.y exceeds this times |s| |y|: the update stays positive definite.
constexpr double lbfgs_curvature = 1e-10;

// linalg/Pcg_or_cholesky.h (the v-step, cuts/discontinuity_field.h)
/// Conjugate-gradient iterations before the Cholesky fallback: the v-step's matrix is nearly diagonal.
constexpr int v_step_cg_iterations = 200;
/// Their target residual relative to the right-hand side: v within round-off of the factorized solve's.
constexpr double v_step_cg_tolerance = 1e-12;

// ---- The fast preset (Preset::FAST; pipeline/plan.h, pipeline/final_solve.h)
/// The final solves' Newton tolerances, and the alternation's after its first u-step, are multiplied by
/// this: interactive use, the map is judged by eye.
constexpr double fast_tolerance_factor = 10.;

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
/// the box's solve of a map carried from a copy solved with the box: at most this many Newton iterations
/// (the copy's box set the charts' shapes; each iteration a solve of the finer mesh)
constexpr int carried_box_iterations = 8;
/// ... and on a mesh of more than large_carried_box_faces faces, at most this many (there each iteration
/// factors a Hessian of hundreds of thousands of unknowns, and the fit's E_d settles within these)
constexpr int large_carried_box_iterations = 3;
constexpr std::size_t large_carried_box_faces = 100000;
/// the box's solve stops in a slow tail: after this many iterations, ...
constexpr int box_slow_tail_after = 60;
/// ... less than this ratio of the energy gained over this window (steps stopped at barrier contacts)
constexpr int box_slow_tail_window = 20;
constexpr double box_slow_tail_ratio = 1e-3;
/// a crossing chart overlapping itself on more than this many faces is cut into overlap-free pieces
constexpr int overlap_partition_faces = 10000;
/// so is one whose Tutte map has an E_d above this (holes of a CAD part on one circle): the barrier's solve
/// from it crawls, each step stopped where a border vertex meets a segment
constexpr double tutte_restart_max_distortion = 1000.;
/// no box's solve where a final solve cut the charts into more overlap-free pieces than this (CAD plates
/// with dozens of holes: the box pushed each piece against its own border, then was dropped over its budget)
constexpr int box_max_pieces = 32;
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
/// a hard-surface part (pipeline/plan.h, is_hard_surface()): at least this many sharp creases ...
constexpr std::size_t hard_surface_min_creases = 500;
/// ... and this fraction of the interior edges, ...
constexpr double hard_surface_crease_fraction = 0.1;
/// ... a crease's dihedral angle above this (degrees)
constexpr double hard_surface_crease_degrees = 60.;
/// its splits go in batches of this many (one per feature: hundreds of splits; 8: the 48-tooth gear 4.3 s
/// against 3.1 s, 16: no faster, longer seams) ...
constexpr int hard_surface_split_batch = 12;
/// ... and up to this many per round (each round ends in a final solve under the barrier)
constexpr int hard_surface_max_splits = 256;
/// Newton iterations at most of its barrier's solve of charts cut into overlap-free pieces, per round
/// while E_d is above default_distortion_target: E_d settles within them while the barrier still
/// pushes border pairs apart (plate with 12x10 holes: 46)
constexpr int hard_surface_pieces_newton_iterations = 20;
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

// -- the copy that decides the cuts of a very large mesh (pipeline/plan.h)
/// above this many times multiresolution_faces faces the copy is made in two stages ...
constexpr std::size_t staged_cut_copy_min_ratio = 32;
/// ... the first on the index arrays, to this many times multiresolution_faces faces
constexpr std::size_t staged_cut_copy_ratio = 16;

// -- the solved copies that start the final solve of a mesh cut on a copy (pipeline/two_levels.h)
/// Faces of one copy over those of the copy that starts its solve: a mesh of 8 times
/// multiresolution_faces or more starts from a chain of copies (640k faces: 160k, 40k, 10k).
constexpr std::size_t solved_copy_level_ratio = 4;

// -- two levels (pipeline/two_levels.h, pipeline/progressive_map.h; not called by the plan: measured worse)
/// above this many faces (and up to the coarse copy's 2 x multiresolution_faces) the alternation's upper
/// ε levels run on a simplified copy: below, the copy would decide little that the input does not redo
constexpr std::size_t two_level_min_faces = 4000;
/// the copy keeps this fraction of the faces ...
constexpr double two_level_face_ratio = 0.25;
/// ... and at least this many
constexpr std::size_t two_level_min_coarse_faces = 2000;
/// ε levels (the last ones) the input runs from the carried map and v
constexpr int two_level_fine_levels = 1;
/// a restored vertex is placed this far inside its fan's kernel (height over each side / its length)
constexpr double progressive_kernel_margin = 0.05;
/// ... halved at most this many times where the kernel is narrower (then the face would be flat)
constexpr int progressive_margin_halvings = 40;
/// an open fan (on the border) unfolds over at most this fraction of a turn
constexpr double progressive_open_fan_angle = 0.95;

// -- the local relaxation of a carried map (atlas/carried_map_relaxation.h)
/// sweeps over the interior vertices at most (a sweep that moves none ends it)
constexpr int carried_relaxation_sweeps = 3;
/// a vertex moves where a face of its fan has a symmetric Dirichlet energy (0 at an isometry) above this
constexpr double carried_relaxation_energy = 1.;
/// Newton steps per vertex and sweep at most
constexpr int carried_relaxation_steps = 3;
/// fraction of the way to the first collapse of a fan face that a step may go
constexpr double carried_relaxation_reach = 0.8;
/// step halvings of the backtracking at most
constexpr int carried_relaxation_halvings = 20;
/// after the sweeps, a face above this energy is crushed and the fans of its vertices move again (at 1e9
/// a 640k carried map kept a face of 7.6e8 and its fit ended above the default target) ...
constexpr double carried_crushed_energy = 1e4;
/// ... in at most this many more sweeps over them
constexpr int carried_crushed_sweeps = 100;

// -- shape packing (atlas/shape_packing.h)
/// a chart's raster holds every texel its triangles come within this many texels of (rounding)
constexpr double raster_margin_texels = 1e-3;
/// the scale search steps down from the area bound by this factor until the charts pack ...
constexpr double shape_packing_step = 0.93;
/// ... at most this many times (then the rectangle packing is kept) ...
constexpr int shape_packing_steps = 24;
/// ... then bisects this many times
constexpr int shape_packing_refinements = 3;
/// the shape packing is tried only above this many times the rectangle packing's scale
constexpr double shape_packing_margin = 1.01;
/// above this many charts the rectangle packing (about O(n²)) is skipped when the shape packing is on
/// (the layout may then fill less than the rectangles would)
constexpr int rectangle_packing_max_charts = 20000;
/// above this many charts the raster placement (atlas/raster_placement.h) is not tried (time)
constexpr int raster_placement_max_charts = 4000;
/// scene atlas (atlas/scene_packing.h): up to this many charts the raster placement's scale is searched
/// in several drop orders, bisected more finely, and with the charts' free orientations: each is a search
/// of its own
constexpr int raster_orders_max_charts = 200;
/// ... and up to this padding in texels (the raster placement's marking grows with the padding)
constexpr int raster_orders_max_padding = 16;
/// ... in this many orders (atlas/shape_packing.h drop_order())
constexpr int raster_placement_orders = 3;
/// ... each bisected this many times
constexpr int raster_placement_refinements = 6;
/// free orientations (atlas/chart_orientation.h): the quarter turn is sampled in this many angles, once
/// per entry, each a search of the raster placement (its outcome varies with the sampling, the best kept)
constexpr int chart_turn_samples[] = {4, 5};
/// ... a chart leaves its minimum-area frame only for an angle that claims at most this fraction of the
/// texels the frame claims (rounding and ties never turn it)
constexpr double chart_turn_gain = 0.97;
/// ... the texels claimed are counted on a raster of this many texels along the chart's longer side
constexpr double chart_turn_raster_texels = 48.;
/// charts cut for packing (atlas/packing_split.h, option split_charts_for_packing): straight cut lines
/// tried per direction (at these many area quantiles strictly inside the piece)
constexpr int packing_split_positions = 11;
/// ... a piece of fewer faces is not cut, and a side of a cut with fewer faces joins the other side
constexpr int packing_split_min_faces = 24;
/// ... a cut is kept if it lowers the pieces' bounding-rectangle area by more than this fraction, net of
/// its seam cost ...
constexpr double packing_split_min_gain = 0.02;
/// ... which is this many times the cut's UV length over the square root of the piece's rectangle area
constexpr double packing_split_seam_weight = 0.05;
/// ... plus this much per piece added (each costs its padding)
constexpr double packing_split_piece_cost = 0.01;
/// ... and a chart is cut into at most this many pieces
constexpr int packing_split_max_pieces = 32;



// ---- end of the pipeline section

} // namespace tuning
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
