// One mesh through cut_and_parameterize(), as both comparisons (default mode
// and --optcuts) run it: the named parameters the options ask for, --repeat
// timed runs (the median time), and the figures of the result, with flipped
// faces and UV border crossings recounted on the output and E_d and E_s
// checked against parameterization_metrics.h.
#ifndef CUT_PARAM_BENCHMARK_BENCHMARK_RUN_H
#define CUT_PARAM_BENCHMARK_BENCHMARK_RUN_H

#include "benchmark_mesh.h"
#include "median.h"
#include "mesh_list.h"
#include "options.h"
#include "reference_tables.h"
#include "table_output.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace cut_benchmark {

namespace SMP = CGAL::Surface_mesh_parameterization;

struct Run_result
{
  std::string status;          // "ok", an error name, or a failure to read
  std::size_t faces = 0;
  bool ran = false;            // the algorithm was called
  bool ok = false;
  double time = NaN;           // median wall time of the algorithm (s)
  std::size_t newton = 0, charts = 0, flipped = 0, crossings = 0;
  std::size_t factorizations = 0, solves = 0; // of the inner solver (every phase)
  std::size_t u_factorizations = 0, u_solves = 0, v_factorizations = 0; // of the alternation's u- and v-steps
  // Newton iterations per phase: alternation (u-steps), final solves without box, box solves, relaxations
  // judging trials; the rest of `newton` is the first u-steps' and the rerouted seams' solves
  std::size_t u_newton = 0, final_newton = 0, box_newton = 0, relax_newton = 0;
  std::size_t welded = 0;      // vertices welded to a colocal one
  double distortion = NaN, seam_length = NaN, coverage = NaN;
  bool bound_met = true;       // distortion_bound_met (true without a bound)
  std::string note;
};

/// Equal up to a relative tolerance; NaN equals NaN, infinities themselves.
inline bool nearly_equal(double a, double b, double rel = 1e-6)
{
  if(std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if(std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= rel * std::max(1., std::max(std::abs(a), std::abs(b)));
}

/// The options given (the library's rules for the others: a box asked for
/// is tight and kept whatever it costs), with `distortion_bound` (0: none),
/// passed whole to the library.
inline auto method_parameters(const Options& opt, double distortion_bound)
{
  SMP::Cut_parameterization_options o = opt.method;
  o.distortion_bound = distortion_bound;
  return SMP::parameters::cut_parameterization_options(o);
}

/// "lambda X, passes N, box aspect ratio R stiffness S[, overlaps allowed]; time:
/// median of N runs", for the header of a table.
inline std::string parameters_text(const Options& opt)
{
  std::ostringstream os;
  const SMP::Cut_parameterization_options& o = opt.method;
  os << "lambda " << (opt.given_option("lambda") ? fixed(o.lambda, 3) : std::string("default")) << ", passes "
     << (opt.given_option("number_of_passes") ? std::to_string(o.number_of_passes) : std::string("default"))
     << ", box aspect ratio " << fixed(o.bounding_box_aspect_ratio_value(), 3)
     << " stiffness " << fixed(o.bounding_box_stiffness_value(), 1) << (o.global_injectivity ? "" : ", overlaps allowed")
     << (o.inner_solver == SMP::Inner_solver::NEWTON ? "" : ", inner solver proxy quasi-Newton")
     << (o.preset == SMP::Preset::FAST ? ", preset fast" : "")
     << "; time: median of " << opt.repeat_count() << " run" << (opt.repeat_count() > 1 ? "s" : "");
  return os.str();
}

/// "yes", "NO", or "-" for -1 (nothing to compare with).
inline std::string pass_text(int p) { return p < 0 ? "-" : (p ? "yes" : "NO"); }

/// "1", "0", or "" for -1 (a CSV field).
inline std::string pass_csv(int p) { return p < 0 ? std::string() : std::to_string(p); }

template <typename NamedParameters>
void run_method(Mesh& mesh, int repeat, const NamedParameters& np, Run_result& out)
{
  auto seam = mesh.add_property_map<Mesh::Edge_index, bool>("e:benchmark_seam", false).first;
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:benchmark_uv").first;

  std::vector<double> times;
  SMP::Cut_and_parameterize_result first;
  bool varies = false;
  for(int r = 0; r < repeat; ++r)
  {
    for(auto e : mesh.edges()) put(seam, e, false);
    for(auto h : mesh.halfedges()) put(uv, h, Kernel::Point_2(0., 0.));

    const auto start = std::chrono::steady_clock::now();
    const SMP::Cut_and_parameterize_result res = SMP::cut_and_parameterize(mesh, seam, uv, np);
    const auto stop = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double>(stop - start).count());
    out.ran = true;

    if(r == 0) first = res;
    else if(res.error != first.error || !nearly_equal(res.distortion, first.distortion, 1e-9)
            || !nearly_equal(res.seam_length, first.seam_length, 1e-9))
      varies = true;
    if(res.error != SMP::OK) break; // a failing mesh fails again; do not time it N times
  }

  out.time = median(times);
  out.status = SMP::error_name(first.error);
  out.ok = first.ok();
  if(varies) out.note = "results vary across runs (first run shown)";
  if(!out.ok) return;

  out.newton = first.newton_iterations;
  out.factorizations = first.number_of_factorizations;
  out.solves = first.number_of_solves;
  out.u_factorizations = first.alternation_factorizations;
  out.u_solves = first.alternation_solves;
  out.v_factorizations = first.v_step_factorizations;
  out.u_newton = first.alternation_newton_iterations;
  out.final_newton = first.final_solve_newton_iterations;
  out.box_newton = first.box_newton_iterations;
  out.relax_newton = first.relax_newton_iterations;
  out.welded = first.number_of_welded_vertices;
  out.charts = first.number_of_charts;
  out.distortion = first.distortion;
  out.seam_length = first.seam_length;
  out.coverage = first.uv_coverage;
  out.bound_met = first.distortion_bound_met;
  // The maps hold the last run; with deterministic runs it is the first one.
  out.flipped = SMP::number_of_flipped_faces(mesh, uv);
  out.crossings = SMP::number_of_border_crossings(mesh, uv);
  if(!varies)
  {
    const double ed = SMP::distortion_energy(mesh, uv, SMP::parameters::uv_scale(first.uv_scale));
    const double es = SMP::seam_length(mesh, seam);
    if(!nearly_equal(ed, first.distortion) || !nearly_equal(es, first.seam_length))
    {
      std::ostringstream os;
      os.precision(6);
      os << "metrics on the output disagree with the result: E_d " << ed << ", E_s " << es;
      out.note = os.str();
    }
  }
}

/// Reads the mesh and runs the method --repeat times; with --quick, a mesh
/// too big is not run (status "skipped").
template <typename NamedParameters>
Run_result benchmark_mesh(const Mesh_entry& entry, const Options& opt, const NamedParameters& np)
{
  Run_result out;
  if(entry.file.empty()) { out.status = "NOT_FOUND"; return out; }
  Mesh mesh;
  try
  {
    if(!CGAL::IO::read_polygon_mesh(entry.file.string(), mesh, CGAL::parameters::verbose(false)))
    {
      out.status = "READ_FAILED";
      return out;
    }
  }
  catch(const std::exception& e)
  {
    out.status = "READ_FAILED";
    out.note = e.what();
    return out;
  }
  out.faces = mesh.number_of_faces();
  if(opt.quick && out.faces >= QUICK_MAX_FACES) { out.status = "skipped"; return out; }
  try
  {
    run_method(mesh, opt.repeat_count(), np, out);
  }
  catch(const std::exception& e)
  {
    out.ok = false;
    out.status = "EXCEPTION";
    out.note = e.what();
  }
  return out;
}

/// benchmark_mesh() with a progress line on std::cerr: "[i/n] name ... status (t s)".
template <typename NamedParameters>
Run_result benchmark_mesh_logged(std::size_t i, std::size_t n, const Mesh_entry& entry, const Options& opt,
                                 const NamedParameters& np)
{
  std::cerr << "[" << i << "/" << n << "] " << entry.name << " ... " << std::flush;
  Run_result run = benchmark_mesh(entry, opt, np);
  std::cerr << run.status;
  if(run.ran) std::cerr << " (" << time_text(run.time) << " s)";
  std::cerr << "\n";
  if(!run.note.empty()) std::cerr << "  note: " << run.note << "\n";
  return run;
}

} // namespace cut_benchmark

#endif
