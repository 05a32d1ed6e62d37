// Two levels. The final solve's start of a large mesh: the map of a copy
// simplified from the cut input, solved there and carried back
// (start_from_solved_copy(), called by the plan; the Tutte map only for the
// charts it does not start). Where to cut on a mesh of a
// few thousand faces (decide_cuts_on_two_levels(), not called: measured
// worse in doc/design/pipeline.dox): the
// alternation's upper ε levels on a simplified copy (a quarter of the
// faces), cut where the input's initial cut is; the copy's map carried to
// the input by undoing the simplification (pipeline/progressive_map.h), v
// carried per face; then the last ε level and the cut extraction on the
// input, so that the seams come from the input's own field v.
#ifndef CGAL_SMP_CUT_INTERNAL_TWO_LEVELS_H
#define CGAL_SMP_CUT_INTERNAL_TWO_LEVELS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/carried_map_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/alternation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/final_solve.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/multiresolution.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progressive_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progressive_simplification.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The faces of the two-level copy of a mesh of `faces` faces.
inline std::size_t two_level_coarse_faces(std::size_t faces)
{
  return (std::max)(tuning::two_level_min_coarse_faces, std::size_t(double(faces) * tuning::two_level_face_ratio));
}

/// The map of the initial cut mesh in `state` carried from the copy's
/// (`coarse_state` on `coarse`) by undo_collapses(); false, `state`
/// untouched, unless it is valid on every chart (the alternation's levels
/// are common to all charts: a chart from its Tutte map would get the last
/// level only).
template <typename Surface>
bool carry_coarse_map(const Surface& surface, const Coarse_surface& coarse, const Map_state& coarse_state,
                      Map_state& state)
{
  Carried_map carried;
  if(!undo_collapses(surface, coarse, coarse_state.chart, coarse_state.x, state.chart, carried)) return false;
  for(char valid : carried.valid)
    if(!valid) return false;
  state.x = std::move(carried.x);
  return true;
}

/// Where to cut on two levels (see above) at seam cost `lambda`, from
/// `state.is_cut` (the user's seams): the input's initial cut, a copy of
/// two_level_coarse_faces() faces keeping it, the ε levels but the last
/// tuning::two_level_fine_levels on the copy at λ scaled as the coarse
/// copy's (tuning::coarse_lambda_exponent), its map and v carried back
/// (carry_coarse_map(), transfer_face_field()), then decide_cuts() on the
/// input from its last levels. Returns false, with `state` at its initial
/// cut mesh, where the copy could not be made, cut as the input, solved or
/// carried (the caller then decides at full resolution); else `status` is
/// the result.
template <typename Surface>
bool decide_cuts_on_two_levels(const Surface& surface, const std::vector<double>& face_lambda, double lambda,
                               const Cut_parameterization_options& o, const Progress& progress, Map_state& state,
                               Work_log& log, Error_code& status)
{
  const int levels = number_of_eps_levels(o);
  const int fine_levels = tuning::two_level_fine_levels;
  if(levels <= fine_levels) return false;
  status = start_cut_mesh(surface, o, progress, state, log);
  if(status != OK) return true;
  Scoped_timer initialization(log.timings.initialization);
  Coarse_surface coarse;
  if(!simplify_for_carrying(surface, state.is_cut, state.rules.forbidden, face_lambda,
                            two_level_coarse_faces(surface.number_of_faces()), coarse))
    return false;
  Map_state coarse_state;
  coarse_state.is_cut = coarse.is_cut;
  coarse_state.rules.forbidden = coarse.forbidden;
  coarse_state.rules.edge_factor = edge_lambda_factors(coarse.surface, coarse.face_lambda);
  // the copy must be cut where the input is: its initial cut adds nothing
  if(initial_map(coarse.surface, coarse_state) != OK || coarse_state.is_cut != coarse.is_cut) return false;
  initialization.stop();
  const double coarse_lambda
    = lambda * std::pow(mean_edge_length(surface) / mean_edge_length(coarse.surface), tuning::coarse_lambda_exponent);
  status = alternate_levels(coarse.surface, coarse.face_lambda, coarse_lambda, o, progress, 0,
                            Eps_levels{0, levels - fine_levels}, coarse_state, log);
  if(status == ERROR_CANCELED) return true;
  if(status != OK) return (status = OK), false; // the copy's solve failed: the input's may not
  Scoped_timer carrying(log.timings.initialization);
  if(!carry_coarse_map(surface, coarse, coarse_state, state)) return false;
  state.v = transfer_face_field(surface, coarse, coarse_state.v);
  carrying.stop();
  status = decide_cuts(surface, face_lambda, lambda, o, progress, state, log, Eps_levels{levels - fine_levels});
  return true;
}

/// The faces of the solved copy that starts the final solve of a mesh of
/// `faces` faces: `smallest` times the largest power of
/// tuning::solved_copy_level_ratio that leaves it at most half of `faces`,
/// and `smallest` at least; that copy starts from one of that ratio fewer
/// faces, and so on down to `smallest` (solved_copy_map()).
inline std::size_t solved_copy_faces(std::size_t faces, std::size_t smallest)
{
  const std::size_t ratio = tuning::solved_copy_level_ratio;
  std::size_t copy = smallest;
  while(copy * ratio <= faces / 2) copy *= ratio;
  return copy;
}

template <typename Surface>
Error_code start_from_solved_copy(const Surface& surface, const std::vector<double>& face_lambda, std::size_t faces,
                                  std::size_t smallest, const Final_solve_args& final, Map_state& state, Work_log& log,
                                  Carried_map* from_copy = nullptr);

/// The map of a copy of about `faces` faces simplified from the cut mesh in
/// `state` keeping its cuts, solved there under `final` without cutting
/// charts into pieces, then carried back to `state.chart` by
/// undo_collapses() and relaxed where the carrying crushed faces
/// (relax_carried_map()). The copy starts from its Tutte map and runs
/// final_solve(), box included (its budget judged there), or, where `faces`
/// is at least tuning::solved_copy_level_ratio times `smallest`, from a
/// copy of its own of that ratio fewer faces solved the same way
/// (start_from_solved_copy()): each level starts near its solution, and one
/// carried under the box only runs carried_box_solve(). `carried.box_stiffness`
/// is the box the copy's map was solved under. Returns the number of charts
/// of `state` on which `carried` is valid (no flip, no crossing border); 0
/// where the copy could not be made, cut as the input or solved.
template <typename Surface>
int solved_copy_map(const Surface& surface, const std::vector<double>& face_lambda, std::size_t faces,
                    std::size_t smallest, const Final_solve_args& final, const Map_state& state, Work_log& log,
                    Carried_map& carried)
{
  Coarse_surface coarse;
  if(!simplify_for_carrying(surface, state.is_cut, state.rules.forbidden, face_lambda, faces, coarse)) return 0;
  Map_state copy;
  copy.is_cut = coarse.is_cut;
  copy.rules.forbidden = coarse.forbidden;
  // the copy must be cut where the input is: its initial cut adds nothing
  if(initial_cut_mesh(coarse.surface, copy) != OK || copy.is_cut != coarse.is_cut) return 0;
  Final_solve_args copy_args = final;
  copy_args.overlap_partition_faces = 0; // no pieces: the copy keeps the input's cuts
  Carried_map below;
  const std::size_t next = faces / tuning::solved_copy_level_ratio;
  const Error_code start = next >= smallest
                             ? start_from_solved_copy(coarse.surface, coarse.face_lambda, next, smallest, copy_args,
                                                      copy, log, &below)
                             : tutte_map(copy);
  if(start != OK) return 0;
  double box_stiffness = 0.;
  if(final_solve_from_carried(coarse.surface, copy_args, true, below, std::numeric_limits<double>::infinity(), copy,
                              log, &box_stiffness)
     != OK)
    return 0;
  if(!undo_collapses(surface, coarse, copy.chart, copy.x, state.chart, carried)) return 0;
  relax_carried_map(state.chart, carried.valid, carried.x);
  carried.box_stiffness = box_stiffness;
  return int(std::count(carried.valid.begin(), carried.valid.end(), char(1)));
}

/// The start of the final solve of a large mesh: `state` holds the input's
/// cut mesh (cut where a copy decided) with its Tutte map, or without a map
/// (`state.x` empty, initial_cut_mesh()). Each chart whose map carried from
/// a solved copy (solved_copy_map()) is valid starts from it, the others
/// from their Tutte map, computed (tutte_map()) only where a chart needs it.
/// `from_copy`, if given, gets the carried map and, per chart, whether it
/// starts from it (`valid`; empty where the copy could not be made, cut as
/// the input or solved). `faces`: the copy's size; `smallest`: the
/// smallest copy of the chain below it (solved_copy_map()). Returns the
/// Tutte map's status, OK where none was needed.
template <typename Surface>
Error_code start_from_solved_copy(const Surface& surface, const std::vector<double>& face_lambda, std::size_t faces,
                                  std::size_t smallest, const Final_solve_args& final, Map_state& state, Work_log& log,
                                  Carried_map* from_copy)
{
  Carried_map carried;
  const int valid = solved_copy_map(surface, face_lambda, faces, smallest, final, state, log, carried);
  if(valid == 0) carried = Carried_map{}; // nothing carried: no chart flagged
  const bool every_chart = valid > 0 && valid == int(carried.valid.size());
  // every chart from the copy: no Tutte map to solve
  if(!every_chart && state.x.size() != Eigen::Index(2 * state.chart.number_of_vertices))
  {
    const Error_code status = tutte_map(state);
    if(status != OK) return status;
  }
  if(every_chart) state.x = carried.x;
  else if(valid > 0)
  {
    int charts = 0;
    const std::vector<int> chart_of_face = chart_of_faces(state.chart, charts);
    for(std::size_t f = 0; f < state.chart.number_of_faces(); ++f)
      if(carried.valid[std::size_t(chart_of_face[f])])
        for(int v : state.chart.faces[f]) state.x.segment<2>(2 * v) = carried.x.segment<2>(2 * v);
  }
  if(from_copy != nullptr) *from_copy = std::move(carried);
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
