// Where to cut: the initial cut and map, then the Ambrosio–Tortorelli
// alternation (u-steps: the map under weights v² + γ; v-steps: the
// discontinuity field) at decreasing ε, and the cut paths extracted from v.
// λ (the seam cost) is an argument: the bound search and the coarse copy
// run the alternation at other values.
#ifndef CGAL_SMP_CUT_INTERNAL_ALTERNATION_H
#define CGAL_SMP_CUT_INTERNAL_ALTERNATION_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/vertex_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_extraction.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/discontinuity_field.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progress.h>
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

/// The alternation's u-step number `alternation` (0: the first) with the
/// weights v² + γ of `state.v`: a minimization from `state.x`, capped after
/// the first (tuning::alternation_newton_iterations), stopped in a slow tail;
/// after the first, under Preset::FAST, to tuning::fast_tolerance_factor
/// times the tolerance.
inline Error_code u_step(const Cut_parameterization_options& o, int alternation, Distortion_minimizer& minimizer,
                         Map_state& state, Work_log& log)
{
  Scoped_timer timer(log.timings.u_steps);
  for(Eigen::Index f = 0; f < state.v.size(); ++f) minimizer.weights()[f] = state.v[f] * state.v[f] + o.gamma;
  const int later_cap = tuning::alternation_newton_iterations
                        * (o.inner_solver == Inner_solver::NEWTON ? 1 : tuning::quasi_newton_iteration_factor);
  const int cap = alternation == 0 ? o.number_of_iterations : (std::min)(o.number_of_iterations, later_cap);
  // neither the reweighted start nor longer line-search steps: both moved the cuts
  minimizer.set_reweighted_start(0.);
  minimizer.set_step_growth(1.);
  const Slow_tail slow_tail{tuning::alternation_slow_tail_after, tuning::alternation_slow_tail_window,
                            tuning::alternation_slow_tail_ratio};
  // the later u-steps only track v, the first decides the cuts (loosened too, it moved them)
  const double factor = alternation > 0 && o.preset == Preset::FAST ? tuning::fast_tolerance_factor : 1.;
  const Newton_report report = minimizer.minimize(state.x, cap, factor * tuning::alternation_tolerance, slow_tail);
  log.u_step_work += log.count(report);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// The ε levels of a pass that run: from level `first` (0: ε = epsilon_start;
/// above 0 the pass starts from the map and v a coarser level carried) to
/// before level `end`.
struct Eps_levels
{
  int first = 0;
  int end = std::numeric_limits<int>::max();
};

/// The number of ε levels of a pass (ε halved from epsilon_start while above epsilon_end).
inline int number_of_eps_levels(const Cut_parameterization_options& o)
{
  int levels = 0;
  for(double eps = o.epsilon_start; eps > o.epsilon_end; eps *= 0.5) ++levels;
  return levels;
}

/// The alternation of one pass at seam cost `lambda` over the ε levels
/// `levels`, leaving the map and v in `state`. If `state.first_u_step_done`,
/// its first u-step is the one already done (prepare_first_u_step()).
/// Returns OK, ERROR_CANNOT_SOLVE_LINEAR_SYSTEM or ERROR_CANCELED.
/// Precondition: `state.v` has a value per face if `levels.first > 0`.
template <typename Surface>
Error_code alternate_levels(const Surface& surface, const std::vector<double>& face_lambda, double lambda,
                            const Cut_parameterization_options& o, const Progress& progress, int pass,
                            const Eps_levels& levels, Map_state& state, Work_log& log)
{
  const std::size_t nf = surface.number_of_faces();
  const double mean_edge = mean_edge_length(surface);
  Scoped_timer u_setup(log.timings.u_steps);
  Distortion_minimizer minimizer(state.chart, std::vector<double>(nf, 1.), false, 0., 0., o.inner_solver);
  u_setup.stop();
  Scoped_timer v_setup(log.timings.v_steps);
  Discontinuity_solver v_solver(dual_edges(surface, state.is_cut, face_lambda), state.chart.area, face_lambda);
  if(levels.first == 0) state.v = Eigen::VectorXd::Ones(nf);
  v_setup.stop();
  const bool first_done = state.first_u_step_done;
  state.first_u_step_done = false;
  int alternation = 0, level = 0;
  for(double eps = o.epsilon_start; eps > o.epsilon_end && level < levels.end; eps *= 0.5, ++level)
    for(int i = 0; i < o.iterations_per_epsilon && level >= levels.first; ++i)
    {
      if(!(alternation == 0 && first_done))
      {
        const Error_code status = u_step(o, alternation, minimizer, state, log);
        if(status != OK) return status;
      }
      Scoped_timer v_step(log.timings.v_steps);
      if(!v_solver.solve(face_distortions(state.chart, state.x), eps, lambda, mean_edge, state.v))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      v_step.stop();
      ++alternation;
      if(progress && !progress(progress_report("alternate", pass, alternation, alternations_per_pass(o), eps,
                                               mean_distortion(state.chart, state.x))))
        return ERROR_CANCELED;
    }
  log.v_step_factorizations += v_solver.factorizations(); // the v-steps the conjugate gradient left to Cholesky
  return OK;
}

/// One pass at seam cost `lambda`: the alternation over `levels`
/// (alternate_levels()), then the cut paths from v.
template <typename Surface>
Error_code alternate(const Surface& surface, const std::vector<double>& face_lambda, double lambda,
                     const Cut_parameterization_options& o, const Progress& progress, int pass, Map_state& state,
                     Work_log& log, std::vector<Cut_path>& paths, const Eps_levels& levels = Eps_levels())
{
  const Error_code status = alternate_levels(surface, face_lambda, lambda, o, progress, pass, levels, state, log);
  if(status != OK) return status;
  Scoped_timer extraction(log.timings.cut_extraction);
  paths = extract_cut_paths(surface, state.is_cut, state.rules, state.v, o.minimum_relative_cut_length);
  return OK;
}

/// Completes `state.is_cut` into a cut that leaves every component a disk
/// and builds the chart mesh, without a map (`state.x` emptied).
template <typename Surface>
Error_code initial_cut_mesh(const Surface& surface, Map_state& state)
{
  if(!make_disks(surface, state.is_cut, state.rules))
    return state.rules.forbidden.empty() ? ERROR_NO_TOPOLOGICAL_DISC : ERROR_FORBIDDEN_EDGES_BLOCK_CUT;
  state.degenerate_faces = build_chart_mesh(surface, state.is_cut, state.chart, state.corner_uv);
  state.x.resize(0);
  return OK;
}

/// The Tutte map of the chart mesh of `state` (disk_charts_embedding()) in `state.x`.
inline Error_code tutte_map(Map_state& state)
{
  const Embedding_status embedding = disk_charts_embedding(state.chart, state.x);
  if(embedding == Embedding_status::NOT_DISKS) return ERROR_NO_TOPOLOGICAL_DISC;
  if(embedding == Embedding_status::SOLVE_FAILED) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(embedding == Embedding_status::FLIPPED) return ERROR_NO_1_TO_1_MAPPING;
  return OK;
}

/// Completes `state.is_cut` into a cut that leaves every component a disk,
/// builds the chart mesh and its Tutte map.
template <typename Surface>
Error_code initial_map(const Surface& surface, Map_state& state)
{
  const Error_code status = initial_cut_mesh(surface, state);
  return status != OK ? status : tutte_map(state);
}

/// The initial cut and map of `state` (initial_map()), its E_d, and the
/// progress report "initialize".
template <typename Surface>
Error_code start_cut_mesh(const Surface& surface, const Cut_parameterization_options& o, const Progress& progress,
                          Map_state& state, Work_log& log)
{
  Scoped_timer initialization(log.timings.initialization);
  const Error_code initial = initial_map(surface, state);
  if(initial != OK) return initial;
  state.initial_distortion = mean_distortion(state.chart, state.x);
  initialization.stop();
  if(progress && !progress(progress_report("initialize", 0, 0, alternations_per_pass(o), o.epsilon_start,
                                           state.initial_distortion)))
    return ERROR_CANCELED;
  return OK;
}

/// Where to cut at seam cost `lambda`: from `state.is_cut` (seams given by
/// the user), the initial cut and map (unless `state.first_u_step_done`, or
/// `first_pass.first > 0`: the initial cut mesh with the map and v carried
/// from a coarser level), then the passes of the alternation, each cutting
/// along the paths of v, the first over `first_pass`'s ε levels.
/// Leaves the cut mesh and its map (not yet solved) in `state`.
template <typename Surface>
Error_code decide_cuts(const Surface& surface, const std::vector<double>& face_lambda, double lambda,
                       const Cut_parameterization_options& o, const Progress& progress, Map_state& state,
                       Work_log& log, const Eps_levels& first_pass = Eps_levels())
{
  if(!state.first_u_step_done && first_pass.first == 0)
  {
    const Error_code initial = start_cut_mesh(surface, o, progress, state, log);
    if(initial != OK) return initial;
  }
  for(int pass = 0; pass < o.number_of_passes; ++pass)
  {
    std::vector<Cut_path> paths;
    const Error_code status = alternate(surface, face_lambda, lambda, o, progress, pass, state, log, paths,
                                        pass == 0 ? first_pass : Eps_levels());
    if(status != OK) return status;
    if(paths.empty()) break;
    Scoped_timer extraction(log.timings.cut_extraction);
    apply_cuts(surface, paths, state);
    extraction.stop();
    if(progress && !progress(progress_report("cut", pass, alternations_per_pass(o), alternations_per_pass(o),
                                             o.epsilon_end, mean_distortion(state.chart, state.x))))
      return ERROR_CANCELED;
  }
  return OK;
}

/// The per-face λ with the forbidden edges' faces made dear
/// (lambda_with_forbidden_faces()); sets the cost of cutting each edge in
/// `state.rules` from it.
template <typename Surface>
std::vector<double> cut_costs(const Surface& surface, const std::vector<double>& input_face_lambda, Map_state& state)
{
  std::vector<double> face_lambda = lambda_with_forbidden_faces(surface, input_face_lambda, state.rules.forbidden);
  state.rules.edge_factor = edge_lambda_factors(surface, face_lambda);
  return face_lambda;
}

/// What every run from `state` does first whatever its λ: the initial cut
/// and map, and the alternation's first u-step, whose weights are v² + γ
/// with v = 1 (λ enters at the first v-step). Sets `state.first_u_step_done`,
/// so that the runs from `state` start at the first v-step (the bound
/// search does this once for all its trials).
template <typename Surface>
Error_code prepare_first_u_step(const Surface& surface, const std::vector<double>& input_face_lambda,
                                const Cut_parameterization_options& o, const Progress& progress, Map_state& state,
                                Work_log& log)
{
  cut_costs(surface, input_face_lambda, state);
  const Error_code status = start_cut_mesh(surface, o, progress, state, log);
  if(status != OK) return status;
  state.v = Eigen::VectorXd::Ones(Eigen::Index(surface.number_of_faces()));
  Scoped_timer setup(log.timings.u_steps);
  Distortion_minimizer minimizer(state.chart, std::vector<double>(surface.number_of_faces(), 1.), false, 0., 0.,
                                 o.inner_solver);
  setup.stop();
  const Error_code first = u_step(o, 0, minimizer, state, log);
  if(first != OK) return first;
  state.first_u_step_done = true;
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
