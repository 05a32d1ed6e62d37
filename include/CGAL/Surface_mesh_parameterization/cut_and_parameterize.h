#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_AND_PARAMETERIZE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_AND_PARAMETERIZE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/atlas_validity.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <functional>
#include <limits>

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
  /// the part of `number_of_factorizations` spent in the alternation's u-steps
  std::size_t alternation_factorizations = 0;
  /// the part of `number_of_solves` spent in the alternation's u-steps
  std::size_t alternation_solves = 0;
  /// factorizations of the v-steps' systems, one per v-step (their symbolic
  /// analysis is done once per pass; not counted above)
  std::size_t v_step_factorizations = 0;
  std::size_t number_of_degenerate_faces = 0; ///< faces whose rest shape was clamped (zero area, needles)
  std::size_t number_of_isolated_vertices = 0; ///< vertices in no face: ignored, they have no UV
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

namespace internal {
namespace cut {

/// Writable face map that drops what it is given (no v output requested).
struct Ignored_face_map
{
  template <typename Key, typename Value>
  friend void put(const Ignored_face_map&, const Key&, const Value&) {}
};

/// UV of every corner at its halfedge; a border halfedge gets the UV of the
/// corner at its target in the face across.
template <typename TriangleMesh, typename HalfedgeUVMap>
void write_corner_uvs(const TriangleMesh& mesh, const Indexed_surface<TriangleMesh>& surface,
                      const Map_state& state, HalfedgeUVMap uvmap)
{
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
  auto uv = [&](int corner) {
    const int i = state.corner_uv[corner];
    return Point_2(state.x[2*i], state.x[2*i+1]);
  };
  for(std::size_t c = 0; c < state.corner_uv.size(); ++c)
    put(uvmap, surface.corner_halfedge[c / 3][c % 3], uv(int(c)));
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < 0)
      put(uvmap, opposite(surface.face_edge_halfedge(fe), mesh), uv(fe));
}

/// No `forbidden_seam_edge_map` given: nothing is forbidden.
template <typename Surface>
bool read_forbidden_edges(const Surface&, CGAL::internal_np::Param_not_found, Map_state&) { return true; }

/// Reads the forbidden edges into `state.rules.forbidden` (left empty if none is
/// flagged; flags on border edges are ignored). False if an edge is both a
/// given seam and forbidden.
template <typename Surface, typename ForbiddenEdgeMap>
bool read_forbidden_edges(const Surface& surface, const ForbiddenEdgeMap& forbidden_map, Map_state& state)
{
  std::vector<char> forbidden(surface.edges.size(), 0);
  bool any = false;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    if(get(forbidden_map, surface.edges[e])) { forbidden[e] = 1; any = true; }
  for(std::size_t fe = 0; fe < surface.twin.size(); ++fe)
    if(surface.twin[fe] < 0) forbidden[surface.edge_of[fe]] = 0;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    if(forbidden[e] && state.is_cut[e]) return false;
  if(any) state.rules.forbidden.swap(forbidden);
  return true;
}

/// Seams = cut edges that are not on the mesh's boundary.
template <typename Surface, typename SeamEdgeMap>
void write_seams(const Surface& surface, const Map_state& state, SeamEdgeMap seam_edge_map)
{
  std::vector<char> border(surface.edges.size(), 0);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < 0) border[surface.edge_of[fe]] = 1;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    put(seam_edge_map, surface.edges[e], bool(state.is_cut[e] && !border[e]));
}

/// Copies the phases' times, and `total` from `start` to now.
inline void fill_timings(const Work_log& log, Steady_clock::time_point start, Cut_and_parameterize_result& result)
{
  Cut_and_parameterize_timings& t = result.timings;
  t.initialization = log.timings.initialization;
  t.u_steps = log.timings.u_steps;
  t.v_steps = log.timings.v_steps;
  t.cut_extraction = log.timings.cut_extraction;
  t.final_solve = log.timings.final_solve;
  t.packing = log.timings.packing;
  t.total = seconds_since(start);
}

template <typename Surface>
void fill_statistics(const Surface& surface, const Map_state& state, const Work_log& log, const Packing_result& packing,
                     Cut_and_parameterize_result& result)
{
  int charts = 0;
  chart_of_faces(state.chart, charts);
  result.number_of_charts = std::size_t(charts);
  double seam = 0.;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] > fe && state.is_cut[surface.edge_of[fe]])
    {
      seam += surface.edge_length(fe);
      ++result.number_of_seam_edges;
    }
  result.seam_length = seam / std::sqrt(state.chart.total_area() / M_PI);
  result.newton_iterations = log.work.iterations;
  result.number_of_factorizations = log.work.factorizations;
  result.number_of_solves = log.work.solves;
  result.alternation_newton_iterations = log.u_step_work.iterations;
  result.alternation_factorizations = log.u_step_work.factorizations;
  result.alternation_solves = log.u_step_work.solves;
  result.v_step_factorizations = log.v_step_factorizations;
  result.number_of_degenerate_faces = state.degenerate_faces;
  result.initial_distortion = state.initial_distortion;
  result.distortion = state.distortion;
  result.uv_coverage = packing.coverage;
  result.uv_scale = packing.scale;
  result.border_crossings = count_border_crossings(border_segments(state.chart), state.x);
}

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
///
/// Cuts a triangle mesh and computes a flip-free, low-distortion UV map of
/// the cut mesh, optimizing seams and distortion together with the
/// Ambrosio–Tortorelli method of Weill-Duflos, Coeurjolly, de Goes and
/// Lachaud (2023).
///
/// A per-face discontinuity field v ∈ (0,1] and the UVs are optimized
/// alternately on E = Σ_f A_f (v_f² + γ) Ψ_f(u) + λ A_f (ε |∇v|² + (1−v_f)²/(4ε))
/// while ε decreases from `epsilon_start` to `epsilon_end`; cuts are then
/// extracted along the faces with v < 1/2 and the cut mesh is re-optimized
/// without weights (v = 1).
///
/// \tparam TriangleMesh a model of `FaceGraph` (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
/// \tparam SeamEdgeMap a `ReadWritePropertyMap`, edge → bool
/// \tparam HalfedgeUVMap a `WritablePropertyMap`, halfedge → 2D point
///
/// \param mesh the input triangle mesh: any topology (disks, closed or
///   higher-genus surfaces, several boundaries, several components); parts
///   that are not disks are first opened by an initial cut
/// \param seam_edge_map input: seams the user already has (kept);
///   output: all seams (input ones plus those found)
/// \param uvmap output: for every halfedge h with a face, the UV of the
///   corner at `target(h)` in `face(h)`; for border halfedges the UV of the
///   corner at their target in the adjacent face. Corners shared across a
///   non-seam edge get identical UVs, so the map is usable as the vertex UV
///   map of `CGAL::Seam_mesh` built from `seam_edge_map` (see `make_seam_mesh()`).
/// \param np optional named parameters (in `CGAL::Surface_mesh_parameterization::parameters`
///   unless marked CGAL):
///   - `lambda`: seam cost λ, relative to the mean edge length; default 1
///   - `face_lambda_map`: face → double multiplying λ (assisted cutting); default 1
///   - `forbidden_seam_edge_map`: edge → bool, edges that no seam may use:
///     the initial cut routes around them, the alternation's cuts and the
///     multiresolution transfer avoid them. An edge both in `seam_edge_map`
///     and forbidden gives `ERROR_WRONG_PARAMETER`; flags on border edges are
///     ignored. Default: none
///   - `epsilon_start`, `epsilon_end`: ε range, relative to the mean edge length; default 0.1, 0.01
///   - `iterations_per_epsilon`: alternations per ε; default 3
///   - `gamma`: default 1e-7
///   - `number_of_passes`: optimize → cut rounds; default 1
///   - `minimum_relative_cut_length`: keep cut paths at least this fraction of the longest; default 0.2
///   - `reject_degenerate_faces`: bool, return `ERROR_DEGENERATE_FACE` on a degenerate face
///     instead of clamping it; default false
///   - `face_discontinuity_map`: output face → double, the field v of the last pass
///   - `progress_callback`: `std::function<bool(const Cut_and_parameterize_progress&)>`;
///     returning false stops the run with `ERROR_CANCELED` (outputs are then unchanged)
///   - `global_injectivity`: bool, no chart overlaps itself (a border barrier keeps UV
///     borders from crossing, see below); default true
///   - `texture_size`: int ≥ 1, texels per side of the texture; default 1024
///   - `padding`: double ≥ 0, gap in texels between charts and to the square's
///     sides; default 2
///   - `world_units`: bool, keep the 3D scale (charts still packed apart) instead
///     of scaling the atlas into the unit square; default false
///   - `bounding_box_aspect_ratio`: double ≥ 0, the final solve pulls each
///     chart into a rectangle of this width / height (of the chart's area), so
///     that it fills the atlas better at some cost in distortion; 0 turns the
///     box off. Default: a square with a gentle pull (stiffness 5) within a
///     distortion budget; given explicitly, the box is filled tightly
///     (stiffness 300) unless `bounding_box_stiffness` says otherwise
///   - `bounding_box_stiffness`: double ≥ 0, how hard the box pulls; 0 turns
///     the box off. Measured on the 21 meshes of the benchmark with a square:
///     the default raises the unit-square coverage from 0.535 to 0.610 (mean)
///     and from 0.354 to 0.471 (min) at E_d +0.023 (mean, +0.044 at most);
///     300 reaches 0.77 at E_d +0.24. Default 5, or 300 when `bounding_box_aspect_ratio` is given
///   - `bounding_box_distortion_budget`: double ≥ 0 (may be infinite), the
///     largest increase of E_d that the box may cost over the final solve
///     without it; where it costs more, its stiffness is multiplied by 0.7
///     and the solve redone from the boxed map, at most twice, then the box
///     is dropped. Default 0.045 (`gentle_bounding_box_distortion_budget`)
///     for the default box; no limit (the box is kept as asked) once
///     `bounding_box_aspect_ratio` or `bounding_box_stiffness` is given
///   - `distortion_bound`: double ≥ 4, the result's E_d must be at most this,
///     with seams as short as the search finds. Two kinds of trials: on
///     meshes of at most 25,000 faces, two split trials that add cuts
///     greedily (see below) from the initial cut until E_d is within the
///     bound, beside the run at the given λ; and, only where no split trial
///     reaches the bound (or none ran), whole runs with the seam cost λ
///     halved (at most 6 times) until E_d is within the bound, or doubled
///     (at most 3 times) while it is, then one round that cuts the interval
///     between passing and failing λ in three. The candidates are the
///     passing split trials and the passing λ run with the shortest seams
///     (next to split trials, only if its seams are less than 1.5 times
///     theirs); the seams of each are rerouted along shorter paths (the
///     ends of seams from the mesh border may slide along it), zipped back
///     from their tips and rerouted again where the bound allows, and the
///     shortest win; the bounding box comes last, within what the bound
///     leaves. If no trial reaches the bound, cuts are added greedily to the
///     least distorted run and to the run at the given λ; if neither
///     reaches it, the result with the lowest E_d is returned and
///     `distortion_bound_met` is false. At most 11 runs (the initial map and
///     first u-step, which do not depend on λ, done once), two or three at
///     a time, at once where TBB is linked and the mesh has at most 250,000
///     faces (the result does not depend on the number of threads; a
///     progress callback is called by one run at a time, and the split
///     trials report each split judged, phase "split"). Default: no bound
///   - `multiresolution_faces`: int ≥ 0; on a mesh of more than twice this
///     many faces, the alternation decides the cuts on a copy simplified to
///     about this many faces (CGAL's Surface_mesh_simplification, keeping the
///     border, the given seams and the input's vertices), the cuts are carried
///     back as shortest edge paths, and the final solve runs on the input. 0:
///     always at full resolution. Default 10000 (the benchmark meshes, at most
///     20k faces, are unchanged)
///   - `inner_solver`: `Inner_solver`, the solver of every minimization of
///     the UVs. `Inner_solver::NEWTON` (default): projected Newton, one
///     factorization of the projected Hessian per iteration.
///     `Inner_solver::PROXY_QUASI_NEWTON`: that Hessian factorized at a few
///     iterates only, L-BFGS updates on top of it in between (fewer
///     factorizations, more iterations, each a gradient and a solve); every
///     guarantee is the same (no flipped face, no crossing border, the same
///     result for any number of threads). Measured in the manual ("Inner
///     solvers"): about half the factorizations for 2-4 times the
///     iterations, no faster at 10k-40k faces on 2 cores
///   - `vertex_point_map` (CGAL): default `get(vertex_point, mesh)`
///   - `number_of_iterations` (CGAL): maximum Newton iterations per u-step; default 500
///
/// Low-poly inputs: when the final map has E_d above 5 (faces too large for
/// the field v to place cuts: a cube, a game asset), cuts are added one at a
/// time, each the cheapest edge path from the vertex off the seams around
/// which the map is most distorted to the border of its chart (forbidden
/// edges and the λ map respected), kept while each lowers E_d by at least
/// 0.15 per unit of E_s it adds; then the final solve runs again. A map
/// with E_d between 4.6 and 5 is split the same way until E_d is at most
/// 4.6, on meshes of at most twice `multiresolution_faces` faces. Where the
/// result still has E_d above 4.6 on a mesh of at most 2,000 faces, the
/// search of `distortion_bound` at 4.6 runs from the same input, and its
/// result is kept if it meets 4.6 (the splits are judged on maps without the
/// border barrier, which can cross their own border: CGAL's mpi.off, 180
/// faces, 5.11 -> 4.59 in 3 charts), unless a box is kept whatever it costs
/// (an explicit `bounding_box_aspect_ratio` or stiffness). Not with
/// `number_of_passes(0)` (the seams are then the given ones only).
///
/// Without `distortion_bound`, where the alternation ran on the mesh itself
/// (not on a simplified copy), the final solve of its seams runs alongside
/// (on another core, with TBB) the final solve of the same seams rerouted
/// along the cheapest edge paths between their nodes within one ring; the
/// rerouted seams are kept if their E_d is at most 0.01 above. Both always
/// run, so the result does not depend on the number of threads.
///
/// The result is a texture atlas: the final solve runs from the alternation's
/// map; if a chart's UV border then crosses itself, that solve is redone from a
/// Tutte embedding of the cut mesh with a border barrier energy term (each
/// border vertex is repelled from the border segments of its chart that come
/// close, and no Newton step goes past the first contact), which never lets a
/// border cross. The charts are then rotated, scaled by one
/// common factor (equal texel density, reported in `uv_scale`) and packed into
/// the unit square. `distortion` is E_d of the map in 3D units (the UVs divided
/// by `uv_scale`).
///
/// Degenerate faces (zero area, needles, coincident corners) are accepted
/// unless `reject_degenerate_faces` is set: their rest shape is clamped to a
/// height of 1e-4 times their longest side (counted in
/// `number_of_degenerate_faces`), so no NaN can appear. Vertices in no face
/// are ignored (counted in `number_of_isolated_vertices`).
///
/// \return a result whose `error` is `OK` or one of: `ERROR_EMPTY_MESH` (no
///   face), `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATE` (a
///   vertex of a face has a NaN or infinite coordinate), `ERROR_NON_MANIFOLD`
///   (a pinched vertex: its faces form several fans; or two edges joining the
///   same two vertices), `ERROR_DEGENERATE_FACE`
///   (only with `reject_degenerate_faces`), `ERROR_WRONG_PARAMETER`,
///   `ERROR_NO_TOPOLOGICAL_DISC` (the initial cut failed),
///   `ERROR_FORBIDDEN_EDGES_BLOCK_CUT` (the forbidden edges leave no cut that
///   opens the mesh into disks, e.g. on a closed surface with every edge forbidden),
///   `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` (a factorization or solve failed),
///   `ERROR_NO_1_TO_1_MAPPING` (the final map would have a flipped face or a
///   non-finite UV; never returned on any mesh tested), `ERROR_CANCELED`.
///   On any error the outputs are left unchanged.
///
/// \pre the mesh is a triangle mesh
/// \post on success: every UV is finite, no face of the UV map is flipped,
///   no two UV border segments cross (with `global_injectivity`), every UV lies
///   in [0,1]² (unless `world_units`) with charts at least `padding` texels
///   apart,
///   every seam edge is an edge of the mesh that is not on its boundary and
///   not flagged in `forbidden_seam_edge_map`, and
///   cutting along the seams leaves every connected component a topological
///   disk (checked by assertions in debug builds)
///
/// \sa \ref PkgCutParameterizationNamedParameters (types, defaults and valid
///   values of the named parameters), \ref Chapter_Cut_parameterization
template <typename TriangleMesh, typename SeamEdgeMap, typename HalfedgeUVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Cut_and_parameterize_result
cut_and_parameterize(const TriangleMesh& mesh, SeamEdgeMap seam_edge_map, HalfedgeUVMap uvmap,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ic = internal::cut;
  using Surface = ic::Indexed_surface<TriangleMesh>;
  using face_descriptor = typename Surface::face_descriptor;

  const ic::Steady_clock::time_point start = ic::Steady_clock::now();
  Cut_and_parameterize_result result;
  ic::Map_state state;
  ic::Work_log log;
  ic::Packing_result packing;
  // every return goes through here, so that the timings are filled after an error too
  auto finish = [&](Error_code error) {
    result.error = error;
    ic::fill_timings(log, start, result);
    return result;
  };
  Surface surface;
  const Error_code indexing = ic::to_error_code(ic::index_surface(mesh, ic::vertex_points(mesh, np), surface));
  if(indexing != OK) return finish(indexing);
  result.number_of_isolated_vertices = surface.isolated_vertices;
  const Cut_parameterization_options options = cut_parameterization_options_from(np);
  if(options.reject_degenerate_faces &&
     ic::number_of_degenerate_faces(surface) > 0)
    return finish(ERROR_DEGENERATE_FACE);

  std::vector<double> face_lambda(surface.number_of_faces());
  const auto lambda_map = choose_parameter(get_parameter(np, internal_np::face_lambda_map),
                                           CGAL::Constant_property_map<face_descriptor, double>(1.));
  for(std::size_t f = 0; f < face_lambda.size(); ++f)
  {
    face_lambda[f] = get(lambda_map, surface.faces[f]);
    if(!(face_lambda[f] > 0.) || !std::isfinite(face_lambda[f])) return finish(ERROR_WRONG_PARAMETER);
  }

  state.is_cut.resize(surface.edges.size());
  for(std::size_t e = 0; e < surface.edges.size(); ++e) state.is_cut[e] = get(seam_edge_map, surface.edges[e]);
  if(!ic::read_forbidden_edges(surface, get_parameter(np, internal_np::forbidden_seam_edge_map), state))
    return finish(ERROR_WRONG_PARAMETER);
  log.timings.initialization = ic::seconds_since(start); // the optimization adds the rest

  const Error_code status =
    ic::run_plan(surface, face_lambda, options, state, log, packing, result.distortion_bound_met);
  if(status != OK) return finish(status);

  ic::write_corner_uvs(mesh, surface, state, uvmap);
  ic::write_seams(surface, state, seam_edge_map);
  auto v_map = choose_parameter(get_parameter(np, internal_np::face_discontinuity_map), ic::Ignored_face_map());
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f) put(v_map, surface.faces[f], state.v.size() ? state.v[f] : 1.);
  ic::fill_statistics(surface, state, log, packing, result);
  CGAL_postcondition(ic::is_valid_atlas(surface, state));
  return finish(OK);
}
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
