// The options of cut_and_parameterize() as one struct: the value of every
// named parameter that is not a property map, and the rules that give an
// option left unset its value (the default bounding box). Front ends (the
// command line, the Python module, the Blender add-on) fill this struct and
// leave unset what the user did not give; the rules live here only.
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_OPTIONS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
/// State reported to the `progress_callback` named parameter.
struct Cut_and_parameterize_progress
{
  const char* phase = "";      ///< "initialize", "alternate", "cut", "split" (a greedy split judged), "final"
  int pass = 0;                ///< current pass, from 0
  int alternation = 0;         ///< alternations done in this pass
  int alternations_per_pass = 0; ///< alternations of one pass (the same in every pass)
  double epsilon = 0.;         ///< current ε (relative to the mean edge length)
  double distortion = 0.;      ///< current E_d (of the v-weighted map while alternating)
};

/// \ingroup PkgCutParameterizationRef
/// The value options of `cut_and_parameterize()`, one field per named
/// parameter of the same name (the property maps stay named parameters);
/// each field's meaning, range and default are in the named-parameter table
/// of `cut_and_parameterize()`.
/// Pass it whole with the named parameter
/// `parameters::cut_parameterization_options()`; a named parameter given
/// beside it overrides its field. A field left unset (`std::nullopt`) takes
/// the value that the library's rule gives it (see
/// `bounding_box_stiffness_value()` and the functions beside it), so front
/// ends leave unset what their user did not give.
///
/// \code{.cpp}
/// namespace SMP = CGAL::Surface_mesh_parameterization;
/// SMP::Cut_parameterization_options options;
/// options.lambda = 2.;
/// options.bounding_box_aspect_ratio = 2.; // a tight 2:1 box
/// SMP::cut_and_parameterize(mesh, seams, uvmap,
///   SMP::parameters::cut_parameterization_options(options, SMP::parameters::number_of_passes(2)));
/// \endcode
struct Cut_parameterization_options
{
  // the method
  double lambda = 1.;                     ///< seam cost λ, relative to the mean edge length (> 0)
  double distortion_bound = 0.;           ///< E_d the result must reach (>= 4), 0: none
  double epsilon_start = 0.1;             ///< ε of the first alternation, relative to the mean edge length
  double epsilon_end = 0.01;              ///< ε is halved while it stays above this value
  int iterations_per_epsilon = 3;         ///< alternations (u-step, v-step) per value of ε
  double gamma = 1e-7;                    ///< keeps the distortion weight v² + γ positive
  int number_of_passes = 1;               ///< passes of optimize, extract cuts, cut
  double minimum_relative_cut_length = 0.2; ///< cut paths shorter than this fraction of the longest are dropped
  int number_of_iterations = 500;         ///< the most Newton iterations of one minimization
  int multiresolution_faces = 10000;      ///< above this many faces the first u-step runs on a simplified copy (0: never)
  Inner_solver inner_solver = Inner_solver::NEWTON; ///< the inner solver of every minimization
  Preset preset = Preset::DEFAULT;        ///< FAST: less work for interactive use (see `with_preset()`)
  bool reject_degenerate_faces = false;   ///< refuse degenerate faces instead of clamping them
  bool weld_colocal_vertices = false;     ///< vertices at one position are one vertex of the unwrapping
  std::optional<double> hard_edge_angle;  ///< edges of a larger dihedral angle (degrees) are seams; unset: none
  // the atlas
  bool global_injectivity = true;         ///< no chart overlaps itself or another
  int texture_size = 1024;                ///< texels per side of the texture (the padding's scale)
  double padding = 2.;                    ///< gap between charts, in texels
  double texels_per_unit = 0.;            ///< pack_scene_atlas() only: texels per unit of 3D length, 0: the most that fit
  std::optional<double> stacking_tolerance; ///< pack_scene_atlas() only: rigid copies share texels within this; unset: none
  /// a chart filling less than this fraction of its minimum-area bounding rectangle is cut into pieces
  /// that fill more before packing (new seams); unset: never
  std::optional<double> split_charts_for_packing;
  bool world_units = false;               ///< keep the 3D scale instead of filling the unit square
  std::optional<double> bounding_box_aspect_ratio;      ///< unset: 1, a square
  std::optional<double> bounding_box_stiffness;         ///< unset: see bounding_box_stiffness_value()
  std::optional<double> bounding_box_distortion_budget; ///< unset: see bounding_box_distortion_budget_value()
  /// called with the state of the run; returning false stops it (`ERROR_CANCELED`)
  std::function<bool(const Cut_and_parameterize_progress&)> progress_callback;

  /// Width / height of the box each chart is pulled into (0: no box).
  /// \pre none (the value is checked by `cut_and_parameterize()`)
  /// \post the field if set, else 1
  double bounding_box_aspect_ratio_value() const { return bounding_box_aspect_ratio.value_or(1.); }

  /// The box's stiffness: as given, else tight (300) for a box asked for by
  /// its aspect ratio, else gentle (5) for the default square.
  /// \pre none (the value is checked by `cut_and_parameterize()`)
  /// \post the field if set, else `tight_bounding_box_stiffness` or `gentle_bounding_box_stiffness`
  double bounding_box_stiffness_value() const
  {
    if(bounding_box_stiffness) return *bounding_box_stiffness;
    return bounding_box_aspect_ratio ? tight_bounding_box_stiffness : gentle_bounding_box_stiffness;
  }

  /// The largest E_d increase the box may cost: as given, else none for a
  /// box the user asked for (aspect ratio or stiffness given), else the
  /// default box's budget (0.045).
  /// \pre none (the value is checked by `cut_and_parameterize()`)
  /// \post the field if set, else +∞ or `gentle_bounding_box_distortion_budget`
  double bounding_box_distortion_budget_value() const
  {
    if(bounding_box_distortion_budget) return *bounding_box_distortion_budget;
    return bounding_box_aspect_ratio || bounding_box_stiffness ? std::numeric_limits<double>::infinity()
                                                               : gentle_bounding_box_distortion_budget;
  }
};

namespace internal_np { enum cut_parameterization_options_t { cut_parameterization_options }; }
namespace parameters {
/// \ingroup PkgCutParameterizationRef
/// Named parameter of `cut_and_parameterize()`: a whole
/// `Cut_parameterization_options`; the other named parameters of the same
/// pack override its fields. This overload starts a pack.
/// \tparam K `Cut_parameterization_options`
/// \param k the options
/// \pre none (the values are checked by the function the pack is passed to)
/// \post the pack holds a copy of `k` (later changes to `k` do not reach it)
template <typename K>
CGAL::Named_function_parameters<K, internal_np::cut_parameterization_options_t>
cut_parameterization_options(const K& k)
{
  return CGAL::Named_function_parameters<K, internal_np::cut_parameterization_options_t>(k);
}
/// \ingroup PkgCutParameterizationRef
/// Named parameter of `cut_and_parameterize()`: a whole
/// `Cut_parameterization_options`, added to the pack `pack` (of this package
/// or of %CGAL), whose other named parameters override its fields.
/// \tparam K `Cut_parameterization_options`
/// \param k the options
/// \param pack the named parameters it is added to
/// \pre none (the values are checked by the function the pack is passed to)
/// \post the pack holds a copy of `k` in front of `pack`
template <typename K, typename T, typename Tag, typename Base>
CGAL::Named_function_parameters<K, internal_np::cut_parameterization_options_t,
                                CGAL::Named_function_parameters<T, Tag, Base>>
cut_parameterization_options(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& pack)
{
  return {k, pack};
}
} // namespace parameters

namespace internal {
namespace cut {

/// Sets `field` from the named parameter `tag` of `np` where it is given.
template <typename NamedParameters, typename Tag, typename Field>
void read_named_parameter(const NamedParameters& np, Tag tag, Field& field)
{
  using CGAL::parameters::get_parameter;
  using Value = decltype(get_parameter(np, tag));
  if constexpr(!std::is_same_v<std::decay_t<Value>, CGAL::internal_np::Param_not_found>)
    field = get_parameter(np, tag);
}

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
/// The options that the named parameters `np` give: those of the named
/// parameter `cut_parameterization_options` if given (else the defaults),
/// each overridden by the named parameter of its name where `np` has it.
/// This is how `cut_and_parameterize()` reads its value options; front ends
/// may call it to see what a pack amounts to.
///
/// \tparam NamedParameters a sequence of named parameters
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{cut_parameterization_options}
///     \cgalParamDescription{the options to start from}
///     \cgalParamType{`Cut_parameterization_options`}
///     \cgalParamDefault{`Cut_parameterization_options()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{lambda}
///     \cgalParamDescription{overrides the field of the same name; so does every value named
///       parameter of `cut_and_parameterize()`: `distortion_bound`, `epsilon_start`,
///       `epsilon_end`, `iterations_per_epsilon`, `gamma`, `number_of_passes`,
///       `minimum_relative_cut_length`, `number_of_iterations`, `multiresolution_faces`,
///       `inner_solver`, `preset`, `reject_degenerate_faces`, `weld_colocal_vertices`, `hard_edge_angle`, `global_injectivity`,
///       `texture_size`,
///       `padding`, `texels_per_unit`, `stacking_tolerance`, `split_charts_for_packing`, `world_units`, `bounding_box_aspect_ratio`, `bounding_box_stiffness`,
///       `bounding_box_distortion_budget`, `progress_callback` (their types and ranges are in
///       the table of `cut_and_parameterize()`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the field of `cut_parameterization_options`}
///   \cgalParamNEnd
///   \cgalParamNBegin{inner_solver}
///     \cgalParamDescription{overrides `Cut_parameterization_options::inner_solver`}
///     \cgalParamType{`Inner_solver`}
///     \cgalParamDefault{the field of `cut_parameterization_options`}
///   \cgalParamNEnd
///   \cgalParamNBegin{bounding_box_stiffness}
///     \cgalParamDescription{sets `Cut_parameterization_options::bounding_box_stiffness`
///       (left unset when not given, so that the library's rule decides)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the field of `cut_parameterization_options`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{overrides `Cut_parameterization_options::progress_callback`}
///     \cgalParamType{a callable as `bool(const Cut_and_parameterize_progress&)`}
///     \cgalParamDefault{the field of `cut_parameterization_options`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre none: values are not checked here (`cut_and_parameterize()` checks them)
/// \post a field is unset (`std::nullopt`) only if it is unset in the given
///   options and its named parameter is not in `np`
template <typename NamedParameters>
Cut_parameterization_options cut_parameterization_options_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using internal::cut::read_named_parameter;
  Cut_parameterization_options o =
    choose_parameter(get_parameter(np, internal_np::cut_parameterization_options), Cut_parameterization_options());
  read_named_parameter(np, internal_np::lambda, o.lambda);
  read_named_parameter(np, internal_np::distortion_bound, o.distortion_bound);
  read_named_parameter(np, internal_np::epsilon_start, o.epsilon_start);
  read_named_parameter(np, internal_np::epsilon_end, o.epsilon_end);
  read_named_parameter(np, internal_np::iterations_per_epsilon, o.iterations_per_epsilon);
  read_named_parameter(np, internal_np::gamma, o.gamma);
  read_named_parameter(np, internal_np::number_of_passes, o.number_of_passes);
  read_named_parameter(np, internal_np::minimum_relative_cut_length, o.minimum_relative_cut_length);
  read_named_parameter(np, CGAL::internal_np::number_of_iterations, o.number_of_iterations);
  read_named_parameter(np, internal_np::multiresolution_faces, o.multiresolution_faces);
  read_named_parameter(np, internal_np::inner_solver, o.inner_solver);
  read_named_parameter(np, internal_np::preset, o.preset);
  read_named_parameter(np, internal_np::reject_degenerate_faces, o.reject_degenerate_faces);
  read_named_parameter(np, internal_np::weld_colocal_vertices, o.weld_colocal_vertices);
  read_named_parameter(np, internal_np::hard_edge_angle, o.hard_edge_angle);
  read_named_parameter(np, internal_np::global_injectivity, o.global_injectivity);
  read_named_parameter(np, internal_np::texture_size, o.texture_size);
  read_named_parameter(np, internal_np::padding, o.padding);
  read_named_parameter(np, internal_np::texels_per_unit, o.texels_per_unit);
  read_named_parameter(np, internal_np::stacking_tolerance, o.stacking_tolerance);
  read_named_parameter(np, internal_np::split_charts_for_packing, o.split_charts_for_packing);
  read_named_parameter(np, internal_np::world_units, o.world_units);
  read_named_parameter(np, internal_np::bounding_box_aspect_ratio, o.bounding_box_aspect_ratio);
  read_named_parameter(np, internal_np::bounding_box_stiffness, o.bounding_box_stiffness);
  read_named_parameter(np, internal_np::bounding_box_distortion_budget, o.bounding_box_distortion_budget);
  read_named_parameter(np, internal_np::progress_callback, o.progress_callback);
  return o;
}

/// \ingroup PkgCutParameterizationRef
/// The options that a run of `cut_and_parameterize()` uses: `o` itself,
/// except with `o.preset == Preset::FAST`, where `multiresolution_faces`
/// (unless 0) is capped at `fast_multiresolution_faces` (1000), so that the
/// cuts of a mesh above 2000 faces are decided on a copy simplified to about
/// 1000 faces (the plan gives a hard-surface part the default's copy
/// back: \ref Cut_parameterization_fast_preset). The other parts of the preset (no
/// rerouting of the seams, looser final tolerances, no search for the
/// default distortion target, the copy simplified by the library's own
/// quadric collapses instead of CGAL's edge collapse) are the plan's; the
/// looser tolerance of the u-steps after the first is the alternation's.
/// \pre none
/// \post the result equals `o` unless `o.preset == Preset::FAST`
inline Cut_parameterization_options with_preset(Cut_parameterization_options o)
{
  if(o.preset != Preset::FAST) return o;
  if(o.multiresolution_faces > 0) o.multiresolution_faces = (std::min)(o.multiresolution_faces, fast_multiresolution_faces);
  return o;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
