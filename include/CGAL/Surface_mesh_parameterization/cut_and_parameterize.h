#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_AND_PARAMETERIZE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_AND_PARAMETERIZE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_result.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/atlas_validity.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/colocal_vertices.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/plan.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/user_maps.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/seams/hard_edges.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <functional>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {

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
/// without weights (v = 1) (\ref Cut_parameterization_method).
///
/// The result is a texture atlas: if a chart's UV border crosses itself
/// after the final solve, that solve is redone from a Tutte embedding with a
/// border barrier that never lets a border cross; the charts are then
/// rotated, scaled by one common factor (equal texel density, reported in
/// `uv_scale`) and packed into the unit square (\ref Cut_parameterization_atlas).
/// `distortion` is E_d of the map in 3D units (the UVs divided by `uv_scale`).
///
/// Low-poly inputs, whose faces are too large for the field v to place cuts
/// (a final E_d above 5, or above 4.6 on small meshes), get cuts added
/// greedily, one edge path at a time, while each lowers E_d enough for the
/// seam length it adds (\ref Cut_parameterization_low_poly); not with
/// `number_of_passes(0)`, where the seams are the given ones only.
/// Without `distortion_bound`, the final solve of the alternation's seams
/// runs beside that of the same seams rerouted along cheaper edge paths, and
/// the rerouted ones are kept if their E_d is at most 0.01 above; both always
/// run, so the result does not depend on the number of threads.
///
/// Degenerate faces (zero area, needles, coincident corners) are accepted
/// unless `reject_degenerate_faces` is set: their rest shape is clamped to a
/// height of 1e-4 times their longest side (counted in
/// `number_of_degenerate_faces`), so no NaN can appear. Vertices in no face
/// are ignored (counted in `number_of_isolated_vertices`).
///
/// \tparam TriangleMesh a model of `FaceGraph` (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
/// \tparam SeamEdgeMap a `ReadWritePropertyMap`, edge → bool
/// \tparam HalfedgeUVMap a `WritablePropertyMap`, halfedge → 2D point
/// \tparam NamedParameters a sequence of named parameters (\ref CGAL::Surface_mesh_parameterization::parameters "of this package" or of %CGAL)
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
/// \param np an optional sequence of named parameters among the ones listed
///   below (in `CGAL::Surface_mesh_parameterization::parameters`, except
///   `vertex_point_map` and `number_of_iterations`, %CGAL's). Lengths are
///   relative to the mean edge length ℓ, so the same values give the same
///   result on a mesh scaled by any factor. A value out of its range makes
///   the function return `ERROR_WRONG_PARAMETER` without touching its outputs.
///
/// \cgalNamedParamsBegin
///   \cgalParamSectionBegin{All value options at once}
///   \cgalParamNBegin{cut_parameterization_options}
///     \cgalParamDescription{every value option below in one struct, e.g. filled by a front end;
///       a named parameter given beside it overrides its field}
///     \cgalParamType{`Cut_parameterization_options`}
///     \cgalParamDefault{`Cut_parameterization_options()`: the defaults below}
///   \cgalParamNEnd
///   \cgalParamSectionEnd
///   \cgalParamSectionBegin{The method}
///   \cgalParamNBegin{lambda}
///     \cgalParamDescription{the seam cost λ, relative to ℓ: larger gives fewer and shorter
///       seams and more distortion (\ref Cut_parameterization_parameters)}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_lambda_map}
///     \cgalParamDescription{a factor of λ per face (assisted cutting): seams avoid faces with
///       a large factor and move to faces with a small one (see `visibility_face_lambda()`)}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///       as key type and `double` (> 0, finite) as value type}
///     \cgalParamDefault{`1` on every face}
///   \cgalParamNEnd
///   \cgalParamNBegin{forbidden_seam_edge_map}
///     \cgalParamDescription{edges that no seam may use: the initial cut routes around them, the
///       alternation's cuts and the multiresolution transfer avoid them}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{no edge forbidden}
///     \cgalParamExtra{an edge both in `seam_edge_map` and forbidden gives `ERROR_WRONG_PARAMETER`;
///       flags on border edges are ignored; `ERROR_FORBIDDEN_EDGES_BLOCK_CUT` when no cut opens
///       the mesh into disks without them (\ref Cut_parameterization_constraints)}
///   \cgalParamNEnd
///   \cgalParamNBegin{hard_edge_angle}
///     \cgalParamDescription{every interior edge whose dihedral angle (between the normals of
///       its two faces; 0 where the surface is flat) exceeds this many degrees is a seam from
///       the start, kept like a given seam, as lightmaps need (no chart across a crease); the
///       cut search still adds the cuts the distortion asks for. Forbidden edges are left
///       uncut; faces of zero area make no hard edge; with `weld_colocal_vertices`, the angle
///       is measured on the welded surface (\ref Cut_parameterization_hard_edges)}
///     \cgalParamType{`double`, in [0, 180]}
///     \cgalParamDefault{no hard edge}
///     \cgalParamExtra{the edges cut this way are counted in
///       `Cut_and_parameterize_result::number_of_hard_edges` (given seams apart)}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{the result's E_d must be at most this, with seams as short as the
///       search finds: split trials that add cuts greedily, and runs with λ halved or doubled
///       (at most 11 runs, two or three at a time with TBB; the result does not depend on the
///       number of threads); the candidates' seams are then rerouted and zipped where the
///       bound allows (\ref Cut_parameterization_bound)}
///     \cgalParamType{`double`, ≥ 4 and finite}
///     \cgalParamDefault{no bound}
///     \cgalParamExtra{if no trial reaches the bound, the result with the lowest E_d is
///       returned and `Cut_and_parameterize_result::distortion_bound_met` is `false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{epsilon_start}
///     \cgalParamDescription{ε of the first alternations, relative to ℓ: the width of the
///       diffuse cut regions at the start}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{`0.1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{epsilon_end}
///     \cgalParamDescription{ε is halved while it stays above this value (0.1, 0.05, 0.025,
///       0.0125 with the defaults); equal to `epsilon_start`, no alternation runs}
///     \cgalParamType{`double`, > 0 and ≤ `epsilon_start`}
///     \cgalParamDefault{`0.01`}
///   \cgalParamNEnd
///   \cgalParamNBegin{iterations_per_epsilon}
///     \cgalParamDescription{alternations (u-step, then v-step) per value of ε}
///     \cgalParamType{`int`, ≥ 1}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{gamma}
///     \cgalParamDescription{γ in the distortion weight v² + γ of the u-steps: keeps every
///       face's weight positive, so that a face with v = 0 still cannot flip}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{`1e-7`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_passes}
///     \cgalParamDescription{rounds of "alternate, extract cuts, cut"; later passes extend the
///       seams; 0: only the initial cut and the final solve. Stops early when a pass finds
///       no new cut}
///     \cgalParamType{`int`, ≥ 0}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_relative_cut_length}
///     \cgalParamDescription{a cut branch is kept only if it is at least this fraction of the
///       longest first branch of the pass (0 keeps every branch)}
///     \cgalParamType{`double`, in [0, 1]}
///     \cgalParamDefault{`0.2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most projected Newton iterations of one minimization of the
///       UVs (the first u-step of a pass and the final solve; the other u-steps use at most 50)}
///     \cgalParamType{`int`, ≥ 1 (%CGAL's named parameter)}
///     \cgalParamDefault{`500`}
///   \cgalParamNEnd
///   \cgalParamNBegin{multiresolution_faces}
///     \cgalParamDescription{on a mesh of more than twice this many faces, the cuts are decided
///       on a copy simplified to about this many faces, carried back as shortest edge paths,
///       and the final solve runs on the input (\ref Cut_parameterization_large); 0: always
///       at full resolution}
///     \cgalParamType{`int`, ≥ 0}
///     \cgalParamDefault{`10000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{inner_solver}
///     \cgalParamDescription{the solver of every minimization of the UVs: projected Newton, or
///       its Hessian factorized at a few iterates with L-BFGS updates in between (fewer
///       factorizations, more iterations, the same guarantees; \ref Cut_parameterization_inner_solvers)}
///     \cgalParamType{`Inner_solver`}
///     \cgalParamDefault{`Inner_solver::NEWTON`}
///   \cgalParamNEnd
///   \cgalParamNBegin{preset}
///     \cgalParamDescription{`Preset::FAST` for interactive use: the cuts decided on a copy
///       simplified to about `fast_multiresolution_faces` faces (above twice that size; a
///       hard-surface part keeps the default's copy), no
///       rerouting of the seams, looser Newton tolerances, no search for the default
///       distortion target (`with_preset()`); the same guarantees
///       (\ref Cut_parameterization_fast_preset)}
///     \cgalParamType{`Preset`}
///     \cgalParamDefault{`Preset::DEFAULT`}
///   \cgalParamNEnd
///   \cgalParamNBegin{reject_degenerate_faces}
///     \cgalParamDescription{`true`: a degenerate face (height below 1e-4 times its longest
///       side) makes the function return `ERROR_DEGENERATE_FACE` before any work; `false`:
///       such faces are clamped and counted}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{weld_colocal_vertices}
///     \cgalParamDescription{`true`: vertices closer than 1e-6 times the bounding box diagonal
///       are one vertex of the unwrapping, and border edges that then join the same two
///       vertices (in opposite directions, no third edge between them) one interior edge, so
///       that a mesh exported with split normals or UV islands is unwrapped as the surface
///       it stands for; the outputs stay per halfedge of `mesh` (a glued border edge is
///       never a seam: where the two sides are cut apart, the border already says so).
///       Welds that would pinch a vertex or collapse a face are not made;
///       `false`: each piece is unwrapped as it comes (the library's default; the front
///       ends weld unless told `--no-weld`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices (converted to `double`)}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamSectionEnd
///   \cgalParamSectionBegin{The atlas}
///   \cgalParamNBegin{global_injectivity}
///     \cgalParamDescription{`true`: no chart overlaps itself (a border barrier in the final
///       solve keeps UV borders from crossing), and with the packing no chart overlaps
///       another; `false`: no flipped face only (\ref Cut_parameterization_atlas_injectivity)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_size}
///     \cgalParamDescription{texels per side of the square texture the atlas is packed for; it
///       sets the unit of `padding`}
///     \cgalParamType{`int`, ≥ 1}
///     \cgalParamDefault{`1024`}
///   \cgalParamNEnd
///   \cgalParamNBegin{padding}
///     \cgalParamDescription{gap in texels between charts and to the square's sides, lowered
///       where the charts could not be that far apart (\ref Cut_parameterization_atlas_packing)}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_charts_for_packing}
///     \cgalParamDescription{given, after the parameterization and before packing, every chart
///       whose UV area is less than this fraction of the area of its minimum-area bounding
///       rectangle is cut by straight lines across it (recursive bisection along the rectangle's
///       and the principal axes; the cut that lowers the pieces' rectangle area most, net of a
///       cost for its length and for each piece; forbidden edges never cut) into pieces that
///       fill more. Each piece keeps its UVs (no flip, no overlap, E_d unchanged); the cuts are
///       seams (interior edges), counted in `number_of_charts` and `seam_length`. Where a
///       piece would not be a topological disk, no chart is cut}
///     \cgalParamType{`double`, in (0, 1] (e.g. `0.6`)}
///     \cgalParamDefault{charts never cut for packing}
///   \cgalParamNEnd
///   \cgalParamNBegin{world_units}
///     \cgalParamDescription{`true`: keep the 3D scale (`uv_scale` 1, charts still packed
///       apart) instead of scaling the atlas into the unit square}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{bounding_box_aspect_ratio}
///     \cgalParamDescription{the final solve pulls each chart into a rectangle of this width /
///       height and of the chart's area, so that it fills the atlas better at some cost in
///       distortion; 0: no box (\ref Cut_parameterization_atlas_box)}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`1` (a square) with a gentle pull; given explicitly, a tight box}
///   \cgalParamNEnd
///   \cgalParamNBegin{bounding_box_stiffness}
///     \cgalParamDescription{how hard the box pulls; 0: no box}
///     \cgalParamType{`double`, ≥ 0 and finite}
///     \cgalParamDefault{`gentle_bounding_box_stiffness` (5), or `tight_bounding_box_stiffness`
///       (300) when `bounding_box_aspect_ratio` is given
///       (`Cut_parameterization_options::bounding_box_stiffness_value()`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{bounding_box_distortion_budget}
///     \cgalParamDescription{the largest increase of E_d the box may cost over the final solve
///       without it; where it costs more, its stiffness is multiplied by 0.7 and the solve
///       redone, at most twice, then the box is dropped}
///     \cgalParamType{`double`, ≥ 0 (may be infinite)}
///     \cgalParamDefault{`gentle_bounding_box_distortion_budget` (0.045) for the default box; no
///       limit once `bounding_box_aspect_ratio` or `bounding_box_stiffness` is given
///       (`Cut_parameterization_options::bounding_box_distortion_budget_value()`)}
///   \cgalParamNEnd
///   \cgalParamSectionEnd
///   \cgalParamSectionBegin{Outputs and control}
///   \cgalParamNBegin{face_discontinuity_map}
///     \cgalParamDescription{output: the discontinuity field v of the last pass, in (0, 1] (1
///       everywhere if no pass ran); written only on success}
///     \cgalParamType{a `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///       as key type and `double` as value type}
///     \cgalParamDefault{none: v is not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called after the initial embedding, after every alternation, after
///       each cut, each split judged and at the end; returning `false` stops the run with
///       `ERROR_CANCELED`, the outputs unchanged. Under `distortion_bound`, called by one run
///       at a time}
///     \cgalParamType{a callable as `bool(const Cut_and_parameterize_progress&)`, e.g. a
///       `std::function`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamSectionEnd
/// \cgalNamedParamsEnd
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
///
/// \pre `mesh` is a model of `FaceGraph`; faces that are not triangles give
///   `ERROR_NON_TRIANGULAR_MESH` rather than failing an assertion
/// \pre `seam_edge_map` and `uvmap` are defined on every edge and halfedge of `mesh`
/// \post on error, `seam_edge_map`, `uvmap` and `face_discontinuity_map` are left unchanged
/// \post on success: every UV is finite, no face of the UV map is flipped,
///   no two UV border segments cross (with `global_injectivity`), every UV lies
///   in [0,1]² (unless `world_units`) with charts at least `padding` texels
///   apart,
///   every seam edge is an edge of the mesh that is not on its boundary and
///   not flagged in `forbidden_seam_edge_map`, and
///   cutting along the seams leaves every connected component a topological
///   disk (checked by assertions in debug builds)
///
/// \sa \ref Chapter_Cut_parameterization, `Cut_parameterization_options`,
///   `make_seam_mesh()`, `write_OBJ_with_uvs()`
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
  const Cut_parameterization_options options = with_preset(cut_parameterization_options_from(np));
  std::vector<int> glued; // face-edges joined by welding, whose input edges were on the border
  if(options.weld_colocal_vertices)
    result.number_of_welded_vertices =
      ic::weld_colocal_vertices(surface, ic::tuning::colocal_vertex_tolerance, glued);
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
  if(options.hard_edge_angle)
  {
    if(!(*options.hard_edge_angle >= 0. && *options.hard_edge_angle <= 180.)) return finish(ERROR_WRONG_PARAMETER);
    result.number_of_hard_edges = ic::cut_hard_edges(surface, *options.hard_edge_angle, state.rules, state.is_cut);
  }
  log.timings.initialization = ic::seconds_since(start); // the optimization adds the rest

  const Error_code status =
    ic::run_plan(surface, face_lambda, options, state, log, packing, result.distortion_bound_met);
  if(status != OK) return finish(status);

  ic::write_corner_uvs(mesh, surface, state, uvmap);
  ic::write_seams(surface, state, seam_edge_map);
  ic::write_glued_outputs(mesh, surface, glued, state, uvmap, seam_edge_map);
  auto v_map = choose_parameter(get_parameter(np, internal_np::face_discontinuity_map), ic::Ignored_face_map());
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f) put(v_map, surface.faces[f], state.v.size() ? state.v[f] : 1.);
  ic::fill_statistics(surface, state, log, packing, result);
  CGAL_postcondition(ic::is_valid_atlas(surface, state));
  return finish(OK);
}
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
