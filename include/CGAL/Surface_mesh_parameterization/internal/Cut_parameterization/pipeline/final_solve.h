// The final solve on the cut mesh: the map without the box (charts whose
// border crossed put back to a valid start, or cut into overlap-free
// pieces), then the box's solve; beside it, the same seams rerouted
// (final_solve_with_rerouting()); after greedy splits, the pieces' solve
// (final_solve_after_splits()); from a map carried from a solved copy, the
// box's fit where the copy was solved under it (carried_box_solve(),
// final_solve_from_carried()). Box and barrier are arguments.
#ifndef CGAL_SMP_CUT_INTERNAL_FINAL_SOLVE_H
#define CGAL_SMP_CUT_INTERNAL_FINAL_SOLVE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/carried_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/overlap_partition.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The bounding box of a final solve: each chart pulled into a rectangle of
/// `aspect_ratio` (0: no box) with `stiffness` (0: none), weakened then
/// dropped where it costs more than `budget` over the map without it, or
/// takes E_d above `ceiling` (where the map without box is below it).
struct Box
{
  double aspect_ratio = 0.;
  double stiffness = 0.;
  double budget = std::numeric_limits<double>::infinity();
  double ceiling = std::numeric_limits<double>::infinity();
  double tolerance = tuning::box_tolerance; // Newton tolerance of the box's solve

  /// The stiffness of the box's solve (0: no box).
  double final_stiffness() const { return aspect_ratio > 0. ? stiffness : 0.; }
};

/// The explicit inputs of a final solve: the border barrier (global
/// injectivity), the box, the charts cut into pieces where they overlap
/// themselves on more than `overlap_partition_faces` faces (0: never), the
/// cap on Newton iterations and the inner solver.
struct Final_solve_args
{
  bool global_injectivity = true;
  Box box;
  int overlap_partition_faces = tuning::overlap_partition_faces;
  // no box's solve where the charts were cut into more overlap-free pieces than this (0: any number)
  int box_max_pieces = tuning::box_max_pieces;
  int max_iterations = 500;
  // Newton iterations at most of the barrier's solve without box of charts cut into overlap-free
  // pieces, per round while E_d is above the default target (0: max_iterations; hard-surface parts,
  // pipeline/plan.h: E_d settles long before the barrier)
  int pieces_max_iterations = 0;
  Inner_solver solver = Inner_solver::NEWTON;
  double tolerance_factor = 1.; // the Newton tolerances below times this (Preset::FAST)
};

/// One Newton minimization of the final solve on the cut mesh of `state`
/// (weights 1), with the border barrier if `injective` and a box of
/// `stiffness` (0: none). Its tolerance: the box's, else constrained under
/// the barrier or before a box's solve (`boxed`), else final.
inline Error_code final_minimization(const Final_solve_args& args, bool injective, double stiffness, bool boxed,
                                     Map_state& state, Work_log& log)
{
  Distortion_minimizer minimizer(state.chart, std::vector<double>(state.chart.number_of_faces(), 1.), injective,
                                 stiffness > 0. ? args.box.aspect_ratio : 0., stiffness, args.solver);
  const double tolerance = args.tolerance_factor
                           * (stiffness > 0. ? args.box.tolerance
                                             : (injective || boxed ? tuning::constrained_tolerance : tuning::final_tolerance));
  // the box's solve stops in a slow tail: where the box pushes borders against the barrier,
  // each step is cut short at a contact while the Newton decrement stays above the tolerance
  const Slow_tail tail = stiffness > 0. ? Slow_tail{tuning::box_slow_tail_after, tuning::box_slow_tail_window,
                                                    tuning::box_slow_tail_ratio}
                                        : Slow_tail{};
  const Newton_report report = minimizer.minimize(state.x, args.max_iterations, tolerance, tail);
  (stiffness > 0. ? log.box_work : log.final_work) += log.count(report);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// What the final solve without box leaves to the box's solve.
struct Unboxed_final_map
{
  double distortion = 0.; // E_d of the map without box (before any restart)
  bool barrier = false;   // the border barrier is on (it stays on)
  bool restart = false;   // a chart crossed itself and starts again from its Tutte map
                          // or a carried map (`distortion` is then that of an invalid map)
  int pieces = 0;         // charts after a chart was cut into overlap-free pieces (0: none was)
};

/// Cuts the charts of `state` flagged in `charts` (ids of chart_of_faces())
/// into pieces free of overlap (overlap_free_pieces()), then makes every
/// chart a disk (make_disks()) and carries the map over
/// (rebuild_cut_mesh()): each piece starts from its part of the map. Returns
/// false, with `state` untouched, if the pieces would cut a forbidden edge.
template <typename Surface>
bool cut_into_overlap_free_pieces(const Surface& surface, const std::vector<char>& charts, Map_state& state)
{
  int number_of_charts = 0;
  const std::vector<int> chart = chart_of_faces(state.chart, number_of_charts);
  std::vector<char> split(state.chart.number_of_faces(), 0);
  for(std::size_t f = 0; f < split.size(); ++f) split[f] = charts[std::size_t(chart[f])];
  int pieces = 0;
  const std::vector<int> piece = overlap_free_pieces(state.chart, state.x, split, pieces);
  std::vector<char> is_cut = state.is_cut;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int twin = surface.twin[std::size_t(fe)];
    if(twin < 0) continue;
    const std::size_t f = std::size_t(fe / 3), g = std::size_t(twin / 3);
    if(!split[f] || !split[g] || piece[f] == piece[g]) continue;
    const int e = surface.edge_of[std::size_t(fe)];
    if(state.rules.is_forbidden(e)) return false;
    is_cut[std::size_t(e)] = 1;
  }
  if(!make_disks(surface, is_cut, state.rules)) return false;
  state.is_cut.swap(is_cut);
  rebuild_cut_mesh(surface, state);
  return true;
}

/// Per chart of `mesh` (ids of chart_of_faces()): the E_d of the map `x`.
inline std::vector<double> chart_distortions(const Chart_mesh& mesh, const UV_vector& x)
{
  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(mesh, charts);
  std::vector<double> sum(std::size_t(charts), 0.), area(std::size_t(charts), 0.);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const std::size_t c = std::size_t(chart_of_face[f]);
    sum[c] += mesh.area[f] * symmetric_dirichlet_measure(mesh.jacobian(x, f));
    area[c] += mesh.area[f];
  }
  for(std::size_t c = 0; c < sum.size(); ++c) sum[c] /= area[c];
  return sum;
}

/// True if some chart of the map `x` of `mesh` has an E_d above
/// tuning::tutte_restart_max_distortion: as a start, that Tutte map would
/// make the barrier's solve crawl. A chart where `carried` (if given) is
/// valid is not a Tutte map: the few faces the carrying crushes do not make
/// it crawl (doc/design/pipeline.dox).
inline bool too_distorted_for_the_barrier(const Chart_mesh& mesh, const UV_vector& x,
                                          const Carried_map* carried = nullptr)
{
  const std::vector<double> distortion = chart_distortions(mesh, x);
  for(std::size_t c = 0; c < distortion.size(); ++c)
    if(!(distortion[c] <= tuning::tutte_restart_max_distortion) && !(carried != nullptr && carried->valid[c]))
      return true;
  return false;
}

/// Per chart of `state` (ids of chart_of_faces()): the E_d of its Tutte map
/// (disk_charts_embedding()), infinite where there is none.
inline std::vector<double> tutte_distortions(const Map_state& state)
{
  UV_vector tutte;
  if(disk_charts_embedding(state.chart, tutte) != Embedding_status::OK)
  {
    int charts = 0;
    chart_of_faces(state.chart, charts);
    return std::vector<double>(std::size_t(charts), std::numeric_limits<double>::infinity());
  }
  return chart_distortions(state.chart, tutte);
}

/// The charts of `state` flagged in `crossing` put back to a valid start:
/// the carried map where `carried` holds a valid map of the chart, else the
/// Tutte map (whose border is convex).
inline Error_code restart_crossing_charts(const std::vector<char>& crossing, const Carried_map* carried,
                                          Map_state& state)
{
  auto carried_valid = [&](int c) { return carried != nullptr && carried->valid[std::size_t(c)]; };
  bool need_tutte = false;
  for(int c = 0; c < int(crossing.size()); ++c) need_tutte = need_tutte || (crossing[c] && !carried_valid(c));
  UV_vector tutte;
  if(need_tutte)
  {
    const Embedding_status embedding = disk_charts_embedding(state.chart, tutte);
    if(embedding == Embedding_status::NOT_DISKS) return ERROR_NO_TOPOLOGICAL_DISC;
    if(embedding == Embedding_status::SOLVE_FAILED) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    if(embedding == Embedding_status::FLIPPED) return ERROR_NO_1_TO_1_MAPPING;
  }
  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(state.chart, charts);
  for(std::size_t f = 0; f < state.chart.number_of_faces(); ++f)
    if(crossing[chart_of_face[f]])
    {
      const UV_vector& start = carried_valid(chart_of_face[f]) ? carried->x : tutte;
      for(int v : state.chart.faces[f]) state.x.segment<2>(2 * v) = start.segment<2>(2 * v);
    }
  return OK;
}

/// The final solve on the cut mesh without the box. With global
/// injectivity, a chart whose border then crosses itself is put back to a
/// valid start (restart_crossing_charts(), `carried`: the map the splits
/// started from, carried over their cuts, or the map carried from a solved
/// copy that the solve started from) for final_solve_box() to solve
/// again under the border barrier; a crossing chart without a carried map
/// that overlaps itself on more than `args.overlap_partition_faces` faces,
/// or whose Tutte map has an E_d above tuning::tutte_restart_max_distortion
/// (the holes of a CAD part squashed onto one circle: from there each of
/// hundreds of barrier steps is cut short where a border vertex meets a
/// segment), is cut into overlap-free pieces instead, each from its part of
/// the map. From a Tutte map (`from_tutte_map`; or a map carried from a
/// solved copy, valid in `carried` on the charts it starts) the barrier is on
/// from the first solve, unless a chart's Tutte map is above that E_d
/// (args.overlap_partition_faces > 0, too_distorted_for_the_barrier()): it
/// is then solved without, its crossing charts cut into pieces.
template <typename Surface>
Error_code final_solve_without_box(const Surface& surface, const Final_solve_args& args, bool from_tutte_map,
                                   Map_state& state, Work_log& log, Unboxed_final_map& unboxed,
                                   const Carried_map* carried = nullptr)
{
  // a Tutte map too distorted for the barrier is solved without it first (see above)
  const bool barrier_first = args.global_injectivity && from_tutte_map
                             && !(args.overlap_partition_faces > 0
                                  && too_distorted_for_the_barrier(state.chart, state.x, carried));
  const Error_code status =
    final_minimization(args, barrier_first, 0., args.box.final_stiffness() > 0., state, log);
  if(status != OK) return status;
  unboxed.distortion = mean_distortion(state.chart, state.x);
  unboxed.barrier = barrier_first;
  if(!args.global_injectivity || barrier_first) return OK;
  std::vector<char> crossing = Border_barrier_term(state.chart).charts_with_crossing(state.x);
  if(std::find(crossing.begin(), crossing.end(), 1) == crossing.end()) return OK;
  auto carried_valid = [&](int c) { return carried != nullptr && carried->valid[std::size_t(c)]; };
  // where it overlaps itself much, a chart is cut into pieces that do not
  if(args.overlap_partition_faces > 0)
  {
    const std::vector<std::size_t> overlapping = self_overlapping_face_counts(state.chart, state.x);
    std::vector<double> tutte_distortion; // computed where needed
    std::vector<char> cut_up(crossing.size(), 0);
    for(std::size_t c = 0; c < crossing.size(); ++c)
    {
      if(!crossing[c] || carried_valid(int(c))) continue;
      if(overlapping[c] > std::size_t(args.overlap_partition_faces)) cut_up[c] = 1;
      else
      {
        if(tutte_distortion.empty()) tutte_distortion = tutte_distortions(state);
        cut_up[c] = tutte_distortion[c] > tuning::tutte_restart_max_distortion;
      }
    }
    if(std::find(cut_up.begin(), cut_up.end(), 1) != cut_up.end() && cut_into_overlap_free_pieces(surface, cut_up, state))
    {
      carried = nullptr; // its charts are those of the chart mesh before
      chart_of_faces(state.chart, unboxed.pieces);
      crossing = Border_barrier_term(state.chart).charts_with_crossing(state.x);
      unboxed.barrier = unboxed.restart = true;
    }
  }
  const Error_code restarted = restart_crossing_charts(crossing, carried, state);
  if(restarted != OK) return restarted;
  unboxed.barrier = unboxed.restart = true;
  return OK;
}

/// The rest of the final solve: the charts put back to a valid start solved
/// again under the barrier without box, then the box's solve from the
/// converged map (under the barrier with global injectivity). Where the box
/// costs more than its budget (or takes E_d above its ceiling), it is
/// weakened, then dropped: the map without box is the result. No box where
/// the final solve cut the charts into more than `args.box_max_pieces` pieces.
/// `kept_stiffness`, if given, gets the stiffness of the box the result was
/// solved under (0: none). Where the charts were cut into pieces, the solve without box does at
/// most `args.pieces_max_iterations` Newton iterations if that is above 0,
/// and as many again (within `args.max_iterations`) while it ran to that cap,
/// lowered E_d and left it above tuning::default_distortion_target.
inline Error_code final_solve_box(const Final_solve_args& args, const Unboxed_final_map& unboxed, Map_state& state,
                                  Work_log& log, double* kept_stiffness = nullptr)
{
  // many pieces: the box pushes each against its own border, every step stopped at a contact, and
  // ends weakened twice and dropped over its budget (plates with 8x6 and 12x10 holes)
  const bool too_many_pieces = args.box_max_pieces > 0 && unboxed.pieces > args.box_max_pieces;
  double stiffness = too_many_pieces ? 0. : args.box.final_stiffness();
  const bool barrier = unboxed.barrier || (stiffness > 0. && args.global_injectivity);
  Final_solve_args unboxed_args = args; // the pieces' solve without box: capped where asked
  if(unboxed.pieces > 0 && args.pieces_max_iterations > 0)
    unboxed_args.max_iterations = (std::min)(args.max_iterations, args.pieces_max_iterations);
  auto solve = [&](double s) { return final_minimization(s > 0. ? args : unboxed_args, barrier, s, true, state, log); };
  // the capped solve without box goes on, a cap at a time, while E_d stays above the default
  // target and a round ran to its cap and lowered it: the cap is for an E_d that has settled
  auto solve_unboxed = [&] {
    const int cap = unboxed_args.max_iterations;
    if(cap >= args.max_iterations) return solve(0.);
    double before = mean_distortion(state.chart, state.x);
    for(int done = cap;; done += cap)
    {
      const std::size_t start = log.final_work.iterations;
      const Error_code status = solve(0.);
      const double after = mean_distortion(state.chart, state.x);
      const bool settled = log.final_work.iterations - start < std::size_t(cap)
                           || !(after > tuning::default_distortion_target && after < before);
      if(status != OK || settled || done + cap > args.max_iterations) return status;
      before = after;
    }
  };
  Error_code status = OK;
  double unboxed_distortion = unboxed.distortion;
  if(unboxed.restart && stiffness > 0.)
  {
    status = solve_unboxed();
    unboxed_distortion = mean_distortion(state.chart, state.x);
  }
  // the map without box, converged: where the box is dropped, the result
  UV_vector without_box;
  if(stiffness > 0.) without_box = state.x;
  if(status == OK && (unboxed.restart || stiffness > 0.)) status = stiffness > 0. ? solve(stiffness) : solve_unboxed();
  // the box's cost in distortion, over the map without box, stays within the budget
  // and below the ceiling where the map without box is
  const double ceiling = unboxed_distortion <= args.box.ceiling ? args.box.ceiling
                                                                : std::numeric_limits<double>::infinity();
  const double highest = (std::min)(unboxed_distortion + args.box.budget, ceiling);
  for(int weaker = 0;
      status == OK && stiffness > 0. && weaker < tuning::box_weakenings + 1 && mean_distortion(state.chart, state.x) > highest;
      ++weaker)
  {
    stiffness = weaker < tuning::box_weakenings ? tuning::box_weakening * stiffness : 0.;
    if(stiffness > 0.) status = solve(stiffness);
    else state.x = std::move(without_box);
  }
  if(kept_stiffness != nullptr) *kept_stiffness = stiffness;
  return status;
}

/// The Newton iterations at most of carried_box_solve() on a mesh of `faces` faces.
inline int carried_box_iterations(std::size_t faces)
{
  return faces > tuning::large_carried_box_faces ? tuning::large_carried_box_iterations
                                                 : tuning::carried_box_iterations;
}

/// The box's solve of `state`, a map carried from a copy solved under the
/// box at `stiffness` (its budget judged there, final_solve_box()): under
/// the barrier with global injectivity, at most carried_box_iterations()
/// Newton iterations. The copy's box set the charts' shapes; the solve fits
/// them to this mesh.
inline Error_code carried_box_solve(const Final_solve_args& args, double stiffness, Map_state& state, Work_log& log)
{
  Final_solve_args capped = args;
  capped.max_iterations = (std::min)(args.max_iterations, carried_box_iterations(state.chart.number_of_faces()));
  return final_minimization(capped, args.global_injectivity, stiffness, true, state, log);
}

/// The final solve: final_solve_without_box(), then final_solve_box().
/// `restarted`, if given, tells whether a chart crossed itself and started
/// again; `kept_stiffness`: see final_solve_box().
template <typename Surface>
Error_code final_solve(const Surface& surface, const Final_solve_args& args, bool from_tutte_map, Map_state& state,
                       Work_log& log, const Carried_map* carried = nullptr, bool* restarted = nullptr,
                       double* kept_stiffness = nullptr)
{
  Unboxed_final_map unboxed;
  const Error_code status = final_solve_without_box(surface, args, from_tutte_map, state, log, unboxed, carried);
  if(restarted != nullptr) *restarted = unboxed.restart;
  return status != OK ? status : final_solve_box(args, unboxed, state, log, kept_stiffness);
}

/// True if `carried` starts every chart and was solved under the box: the
/// finer mesh's final solve is then carried_box_solve() alone.
inline bool carried_under_the_box(const Carried_map& carried)
{
  return !carried.valid.empty() && carried.box_stiffness > 0.
         && std::find(carried.valid.begin(), carried.valid.end(), char(0)) == carried.valid.end();
}

/// The final solve of `state` started from `carried`, a map carried from a
/// copy solved under `args` (`carried.valid`: the charts it starts, empty
/// if none): where the copy was solved under the box
/// (carried_under_the_box()), carried_box_solve() alone, followed by
/// final_solve() from the fitted map if its E_d ends above `fit_limit`;
/// else final_solve() from `carried`. `kept_stiffness`, if given, gets the
/// stiffness of the box the result was solved under (0: none).
template <typename Surface>
Error_code final_solve_from_carried(const Surface& surface, const Final_solve_args& args, bool from_tutte_map,
                                    const Carried_map& carried, double fit_limit, Map_state& state, Work_log& log,
                                    double* kept_stiffness = nullptr)
{
  const Carried_map* start = carried.valid.empty() ? nullptr : &carried;
  if(!carried_under_the_box(carried))
    return final_solve(surface, args, from_tutte_map, state, log, start, nullptr, kept_stiffness);
  const Error_code status = carried_box_solve(args, carried.box_stiffness, state, log);
  if(kept_stiffness != nullptr) *kept_stiffness = carried.box_stiffness;
  if(status != OK || !(mean_distortion(state.chart, state.x) > fit_limit)) return status;
  return final_solve(surface, args, from_tutte_map, state, log, start, nullptr, kept_stiffness);
}

/// True if, with `global_injectivity`, a chart of `state` overlaps itself
/// (self_overlapping_faces()): its final solve will start again from a valid
/// start under the border barrier, or cut it into pieces.
inline bool overlaps_itself(bool global_injectivity, const Map_state& state)
{
  if(!global_injectivity) return false;
  int charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(state.chart, charts);
  const std::vector<char> overlapping = self_overlapping_faces(state.chart, state.x, chart_of_face);
  return std::find(overlapping.begin(), overlapping.end(), 1) != overlapping.end();
}

/// final_solve() of the cut mesh in `state`, or, given `rerouted` (the same
/// seams rerouted, with a Tutte map: seams/seam_straightening.h), of those:
/// both solved without box at once (parallel_invoke()), the rerouted seams
/// kept if their E_d is at most that of the first plus `allowance`, then
/// only the seams kept get the box's solve. Where the first map crossed
/// itself, both are solved through, box included, and compared after it.
/// Both solves always run and the choice reads both, so the result does not
/// depend on the number of threads; the work logs add up.
template <typename Surface>
Error_code final_solve_with_rerouting(const Surface& surface, const Final_solve_args& args, double allowance,
                                      bool from_tutte_map, Map_state* rerouted, Map_state& state, Work_log& log)
{
  if(rerouted == nullptr) return final_solve(surface, args, from_tutte_map, state, log);
  Error_code first = OK, second = OK;
  Unboxed_final_map unboxed, rerouted_unboxed;
  Work_log rerouted_log;
  parallel_invoke([&] { first = final_solve_without_box(surface, args, from_tutte_map, state, log, unboxed); },
                  [&] { second = final_solve_without_box(surface, args, true, *rerouted, rerouted_log, rerouted_unboxed); });
  if(first != OK) return first;
  // where the first map crossed itself, its E_d without box is not yet that
  // of a valid map: both are solved through and compared after the box
  const bool solved_through = unboxed.restart;
  if(solved_through)
  {
    parallel_invoke([&] { first = final_solve_box(args, unboxed, state, log); },
                    [&] { if(second == OK) second = final_solve_box(args, rerouted_unboxed, *rerouted, rerouted_log); });
    if(first != OK) return first;
  }
  auto distortion = [&](const Map_state& s, const Unboxed_final_map& u) {
    return solved_through ? mean_distortion(s.chart, s.x) : u.distortion;
  };
  log.add(rerouted_log);
  if(second == OK && distortion(*rerouted, rerouted_unboxed) <= distortion(state, unboxed) + allowance)
  {
    state.is_cut = std::move(rerouted->is_cut);
    state.chart = std::move(rerouted->chart);
    state.corner_uv = std::move(rerouted->corner_uv);
    state.x = std::move(rerouted->x);
    unboxed = rerouted_unboxed;
  }
  return solved_through ? OK : final_solve_box(args, unboxed, state, log);
}

/// The final solve of `state`, a map that greedy splits left (judged without
/// the border barrier), with `carried` (the map the splits started from,
/// carried over their cuts); sets `state.distortion`. With global
/// injectivity, on a cut mesh of at most tuning::split_pieces_max_faces
/// faces, where a chart crossed itself and started again and E_d ends above
/// `goal`, the split map is solved again under `pieces` (its crossing charts
/// cut into overlap-free pieces, each from its part of the split map); the
/// lower E_d is kept.
template <typename Surface>
Error_code final_solve_after_splits(const Surface& surface, const Final_solve_args& args,
                                    const Final_solve_args& pieces, double goal, const Carried_map* carried,
                                    Map_state& state, Work_log& log)
{
  const bool may_cut = args.global_injectivity && goal > 0. && tuning::split_pieces_max_faces > 0
                       && state.chart.number_of_faces() <= std::size_t(tuning::split_pieces_max_faces);
  Map_state cut_up;
  if(may_cut) cut_up = state;
  bool restarted = false;
  Error_code status = final_solve(surface, args, false, state, log, carried, &restarted);
  if(status != OK) return status;
  state.distortion = mean_distortion(state.chart, state.x);
  if(!may_cut || !restarted || state.distortion <= goal) return OK;
  if((status = final_solve(surface, pieces, false, cut_up, log)) != OK) return status;
  cut_up.distortion = mean_distortion(cut_up.chart, cut_up.x);
  if(cut_up.distortion < state.distortion) state = std::move(cut_up);
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
