// Named parameters of the cut-and-parameterize package. CGAL 5.5 looks named
// parameters up by tag type, so the package declares its own tags here
// without touching CGAL. Each option `name(value)` starts a pack and
// `name(value, pack)` appends to an existing one, e.g.
//   namespace SMP = CGAL::Surface_mesh_parameterization;
//   SMP::parameters::lambda(2., SMP::parameters::number_of_passes(2))
//     .vertex_point_map(vpm)            // CGAL's own options chain as members
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_NAMED_PARAMETERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
/// The inner solver of every minimization of the UVs (the alternation's
/// u-steps, the final solve, the trials of splits and zips): named parameter
/// `inner_solver`.
enum class Inner_solver
{
  /// projected Newton: one factorization of the projected Hessian per iteration
  NEWTON,
  /// the projected Hessian factorized at a few iterates only, with L-BFGS
  /// updates on top of the last factorization in between: more iterations
  /// (2-4 times); fewer factorizations on meshes of thousands of faces, not
  /// always on small ones
  PROXY_QUASI_NEWTON
};

/// \ingroup PkgCutParameterizationRef
/// How much work a run of `cut_and_parameterize()` does: named parameter
/// `preset`.
enum class Preset
{
  /// quality first: the method as described, every stage
  DEFAULT,
  /// for interactive use: the cuts decided on a small simplified copy, no
  /// rerouting of the seams, looser Newton tolerances, no search for the
  /// default distortion target; the same guarantees
  FAST
};

#define CGAL_SMP_CUT_NAMED_PARAMETER(TAG, NAME)                                          \
  namespace internal_np { enum TAG { NAME }; }                                   \
  namespace parameters {                                                                 \
  template <typename K>                                                                  \
  CGAL::Named_function_parameters<K, internal_np::TAG> NAME(const K& k)                  \
  {                                                                                      \
    return CGAL::Named_function_parameters<K, internal_np::TAG>(k);                      \
  }                                                                                      \
  template <typename K, typename T, typename Tag, typename Base>                         \
  CGAL::Named_function_parameters<K, internal_np::TAG, CGAL::Named_function_parameters<T, Tag, Base>> \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& pack)            \
  {                                                                                      \
    return {k, pack};                                                                    \
  }                                                                                      \
  }

/// Distortion solver: per-face weight w_f (face -> double), default 1.
CGAL_SMP_CUT_NAMED_PARAMETER(face_weight_map_t, face_weight_map)
/// Distortion solver: start from the UVs in the map instead of Tutte (bool).
CGAL_SMP_CUT_NAMED_PARAMETER(initialize_from_uv_map_t, initialize_from_uv_map)
/// Newton stopping tolerance on the decrease of the mean distortion (double).
CGAL_SMP_CUT_NAMED_PARAMETER(stopping_tolerance_t, stopping_tolerance)
/// Seam cost λ, relative to the mean edge length (double, default 1).
CGAL_SMP_CUT_NAMED_PARAMETER(lambda_t, lambda)
/// Per-face λ (face -> double), multiplies `lambda`.
CGAL_SMP_CUT_NAMED_PARAMETER(face_lambda_map_t, face_lambda_map)
/// The result must have E_d at most this (double >= 4; default: no bound): λ is searched for it.
CGAL_SMP_CUT_NAMED_PARAMETER(distortion_bound_t, distortion_bound)
/// Edges never cut (edge -> bool): not by the initial cut, the alternation's cuts or any later step.
CGAL_SMP_CUT_NAMED_PARAMETER(forbidden_seam_edge_map_t, forbidden_seam_edge_map)
/// ε at the first alternation, relative to the mean edge length (default 0.1).
CGAL_SMP_CUT_NAMED_PARAMETER(epsilon_start_t, epsilon_start)
/// ε is halved while it stays above this value (default 0.01).
CGAL_SMP_CUT_NAMED_PARAMETER(epsilon_end_t, epsilon_end)
/// Alternations (u-step, v-step) per value of ε (default 3).
CGAL_SMP_CUT_NAMED_PARAMETER(iterations_per_epsilon_t, iterations_per_epsilon)
/// γ, keeps the distortion weight v² + γ positive (default 1e-7).
CGAL_SMP_CUT_NAMED_PARAMETER(gamma_t, gamma)
/// Passes of optimize -> extract cuts -> cut (default 1).
CGAL_SMP_CUT_NAMED_PARAMETER(number_of_passes_t, number_of_passes)
/// Output: face -> double, the discontinuity field v.
CGAL_SMP_CUT_NAMED_PARAMETER(face_discontinuity_map_t, face_discontinuity_map)
/// Callback bool(const Progress&); returning false stops the run.
CGAL_SMP_CUT_NAMED_PARAMETER(progress_callback_t, progress_callback)
/// Keep only cut paths at least this fraction of the longest one (default 0.2).
CGAL_SMP_CUT_NAMED_PARAMETER(minimum_relative_cut_length_t, minimum_relative_cut_length)
/// true: refuse degenerate faces with ERROR_DEGENERATE_FACE instead of clamping them (default false).
CGAL_SMP_CUT_NAMED_PARAMETER(reject_degenerate_faces_t, reject_degenerate_faces)
/// true: vertices at the same position (within 1e-6 of the bounding box diagonal) are one vertex of the
/// unwrapping (default true).
CGAL_SMP_CUT_NAMED_PARAMETER(weld_colocal_vertices_t, weld_colocal_vertices)
/// Interior edges whose dihedral angle exceeds this many degrees are seams (double in [0, 180]; default: none).
CGAL_SMP_CUT_NAMED_PARAMETER(hard_edge_angle_t, hard_edge_angle)
/// Above twice this many faces the cuts are decided on a simplified copy (int >= 0, default 10000; 0: never).
CGAL_SMP_CUT_NAMED_PARAMETER(multiresolution_faces_t, multiresolution_faces)
/// Inner solver of the distortion minimizations (`Inner_solver`, default `Inner_solver::NEWTON`).
CGAL_SMP_CUT_NAMED_PARAMETER(inner_solver_t, inner_solver)
/// How much work a run does (`Preset`, default `Preset::DEFAULT`; `Preset::FAST` for interactive use).
CGAL_SMP_CUT_NAMED_PARAMETER(preset_t, preset)

/// Atlas: keep every chart free of self-overlap (no crossing UV borders) with a border barrier (bool, default true).
CGAL_SMP_CUT_NAMED_PARAMETER(global_injectivity_t, global_injectivity)
/// Atlas: width and height of the texture in texels, sets the padding's scale (int, default 1024).
CGAL_SMP_CUT_NAMED_PARAMETER(texture_size_t, texture_size)
/// Atlas: gap between charts and to the square's sides, in texels (double, default 2).
CGAL_SMP_CUT_NAMED_PARAMETER(padding_t, padding)
/// Atlas: true keeps the 3D scale (UV in world units, charts still packed without overlap) instead of
/// scaling the atlas into the unit square (bool, default false).
CGAL_SMP_CUT_NAMED_PARAMETER(world_units_t, world_units)
/// Scene atlas (pack_scene_atlas()): texels per unit of 3D length (double, default 0: the largest that
/// fits one page).
CGAL_SMP_CUT_NAMED_PARAMETER(texels_per_unit_t, texels_per_unit)
/// Atlas: width / height of a rectangle that the final solve pulls each chart into (double; default 1;
/// 0: off).
CGAL_SMP_CUT_NAMED_PARAMETER(bounding_box_aspect_ratio_t, bounding_box_aspect_ratio)
/// Atlas: how hard the bounding box pulls (double >= 0; default 5, a gentle pull; 300 packs tightly;
/// 0: off).
CGAL_SMP_CUT_NAMED_PARAMETER(bounding_box_stiffness_t, bounding_box_stiffness)
/// Atlas: the largest increase of E_d that the bounding box may cost; where it costs more, its pull is
/// weakened, then dropped (double >= 0; default 0.045 for the default box, no limit once
/// `bounding_box_aspect_ratio` or `bounding_box_stiffness` is given).
CGAL_SMP_CUT_NAMED_PARAMETER(bounding_box_distortion_budget_t, bounding_box_distortion_budget)

/// Visibility (face_visibility()): rays cast per face (int >= 1, default 64).
CGAL_SMP_CUT_NAMED_PARAMETER(number_of_rays_t, number_of_rays)
/// Visibility (face_visibility()): faces farther than this do not block (double > 0, default: no limit).
CGAL_SMP_CUT_NAMED_PARAMETER(maximum_distance_t, maximum_distance)

/// Scene atlas (pack_scene_atlas()): per mesh, the index of the mesh it is an instance of, which it shares
/// texels with (std::vector<int>; -1: none).
CGAL_SMP_CUT_NAMED_PARAMETER(instance_of_t, instance_of)
/// Scene atlas (pack_scene_atlas()): given, meshes equal to an earlier one up to a rigid motion, within this
/// distance relative to its bounding box diagonal, share its texels (double >= 0; default: no detection).
CGAL_SMP_CUT_NAMED_PARAMETER(stacking_tolerance_t, stacking_tolerance)
/// Atlas (cut_and_parameterize(), pack_scene_atlas()): given, a chart filling less than this fraction of its
/// minimum-area bounding rectangle is cut into pieces that fill more before packing (double in (0, 1];
/// default: charts never cut for packing).
CGAL_SMP_CUT_NAMED_PARAMETER(split_charts_for_packing_t, split_charts_for_packing)

/// Metrics: UV length per 3D length of the map measured (e.g. `uv_scale` of a
/// packed atlas); the UVs are divided by it (double, default 1).
CGAL_SMP_CUT_NAMED_PARAMETER(uv_scale_t, uv_scale)

#undef CGAL_SMP_CUT_NAMED_PARAMETER

/// \ingroup PkgCutParameterizationRef
/// `bounding_box_stiffness` of the default box, a square: a gentle pull that
/// rounds charts off at little cost in distortion (measured against 3, 4
/// and 10 in the manual, \ref Cut_parameterization_atlas_box).
constexpr double gentle_bounding_box_stiffness = 5.;
/// \ingroup PkgCutParameterizationRef
/// `bounding_box_stiffness` when `bounding_box_aspect_ratio` is given: the
/// chart fills its box tightly (measured in the manual,
/// \ref Cut_parameterization_atlas_box).
constexpr double tight_bounding_box_stiffness = 300.;
/// \ingroup PkgCutParameterizationRef
/// `bounding_box_distortion_budget` of the default box: the largest E_d
/// increase over the same final solve without box; where the box costs more,
/// it is weakened, then dropped (\ref Cut_parameterization_atlas_box).
constexpr double gentle_bounding_box_distortion_budget = 0.045;
/// \ingroup PkgCutParameterizationRef
/// `multiresolution_faces` at most under `Preset::FAST`: the cuts of a mesh
/// above twice this many faces are decided on a copy of about this size
/// (measured in the manual, \ref Cut_parameterization_fast_preset).
constexpr int fast_multiresolution_faces = 1000;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
