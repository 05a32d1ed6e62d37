// One unwrapping run as uv_unwrap and the Python module (python/) do it:
// the library's options (uv_unwrap_options.h, filled from the option table)
// passed whole with the property maps, the seam visibility (--hide-seams), the measures taken on
// the output (flipped faces, border crossings, overlap area, UVs in the unit square) and
// the statistics that `uv_unwrap --stats` writes and `unwrap()` returns.
// Both front ends call these, so their results and figures are the same.
#ifndef CUT_PARAM_TOOLS_UNWRAP_RUN_H
#define CUT_PARAM_TOOLS_UNWRAP_RUN_H

#include "mesh_input.h"
#include "printable_text.h"
#include "uv_unwrap_options.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/face_visibility.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace uv_unwrap {

namespace SMP = CGAL::Surface_mesh_parameterization;

/// Called with each progress report of the library (cut_and_parameterize()'s,
/// and face_visibility()'s as phase "visibility"); false cancels.
using Progress = std::function<bool(const SMP::Cut_and_parameterize_progress&)>;

struct Run_summary
{
  std::string input;
  std::string output;                 // empty until written
  std::string status = "ok";          // "ok", ERROR_USAGE, an input error or a library error name
  std::string error;                  // one-line message when status is not "ok"
  std::vector<std::string> warnings;  // input repairs and remarks
  std::size_t vertices = 0, faces = 0, flipped_faces = 0;
  std::size_t border_crossings = 0;   // recounted on the output
  double overlap_area = 0.;           // UV area covered more than once, measured on the output
  bool uv_in_unit_square = false;     // every corner UV of the output in [0,1]²
  SMP::Cut_and_parameterize_result result;
  double time_seconds = 0.;
  double seam_visibility = std::nan(""); // with --hide-seams or --report-visibility
  double visibility_seconds = 0.;
  nlohmann::ordered_json atlas;       // --atlas: the scene atlas (scene_atlas_run.h); null otherwise
};

// The statistics of one run (documented in the README); numbers that are
// not finite become null (JSON has no NaN). File names, messages and
// warnings go through printable_text() (a file name, or a message quoting a
// file, may hold bytes that are not UTF-8, which nlohmann-json refuses), so
// that building and dumping the object never throws on text.
inline nlohmann::ordered_json statistics(const Run_summary& s)
{
  using cut_tools::printable_text;
  const SMP::Cut_and_parameterize_timings& t = s.result.timings;
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); };
  nlohmann::ordered_json j;
  j["input"] = printable_text(s.input);
  j["output"] = s.output.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(printable_text(s.output));
  j["status"] = printable_text(s.status);
  j["error"] = s.status == "ok" ? nlohmann::ordered_json() : nlohmann::ordered_json(printable_text(s.error));
  j["warnings"] = nlohmann::ordered_json::array();
  for(const std::string& w : s.warnings) j["warnings"].push_back(printable_text(w));
  j["vertices"] = s.vertices;
  j["faces"] = s.faces;
  j["degenerate_faces"] = s.result.number_of_degenerate_faces;
  j["welded_vertices"] = s.result.number_of_welded_vertices;
  j["charts"] = s.result.number_of_charts;
  j["seam_edges"] = s.result.number_of_seam_edges;
  j["hard_edges"] = s.result.number_of_hard_edges; // of those seams, cut by hard_edge_angle
  j["seam_length"] = number(s.result.seam_length);
  j["distortion"] = number(s.result.distortion);
  j["distortion_bound_met"] = s.result.distortion_bound_met;
  j["initial_distortion"] = number(s.result.initial_distortion);
  j["flipped_faces"] = s.flipped_faces;
  j["border_crossings"] = s.border_crossings;
  j["overlap_area"] = number(s.overlap_area);
  j["uv_coverage"] = number(s.result.uv_coverage);
  j["uv_scale"] = number(s.result.uv_scale);
  j["uv_in_unit_square"] = s.uv_in_unit_square;
  j["time_seconds"] = number(s.time_seconds);
  j["seam_visibility"] = number(s.seam_visibility);
  j["visibility_seconds"] = number(s.visibility_seconds);
  j["newton_iterations"] = s.result.newton_iterations;
  j["factorizations"] = s.result.number_of_factorizations;
  j["solves"] = s.result.number_of_solves;
  j["timings"] = {{"initialization", number(t.initialization)}, {"u_steps", number(t.u_steps)},
                  {"v_steps", number(t.v_steps)}, {"cut_extraction", number(t.cut_extraction)},
                  {"final_solve", number(t.final_solve)}, {"packing", number(t.packing)},
                  {"total", number(t.total)}};
  if(!s.atlas.is_null()) j["atlas"] = s.atlas;
  if(s.status != "ok") // nothing was measured: no figure rather than zeros
    for(auto& [key, value] : j.items())
      if(value.is_number() || value.is_boolean() || value.is_object())
        if(key != "vertices" && key != "faces") value = nullptr;
  return j;
}

/// The statistics as text: one line (`indent` < 0, for JSON Lines) or
/// indented; invalid UTF-8 that got past printable_text() is replaced
/// (U+FFFD) rather than thrown on.
inline std::string statistics_text(const Run_summary& s, int indent = -1)
{
  return statistics(s).dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

/// cut_and_parameterize() on `mesh` with `options`; fills the summary's
/// result and the counts measured on the output; warnings go to
/// `summary.warnings`. `add_constraints(forbidden, face_lambda)` flags the
/// edges never to cut and multiplies the per-face λ factors (already those of
/// --hide-seams) before the run; `seams` holds the seams to keep. Throws
/// Failure, with the library's error name as status, if the library fails.
template <typename Mesh, typename SeamMap, typename UVMap, typename VMap, typename AddConstraints>
void unwrap_mesh(const Options& options, Mesh& mesh, SeamMap seams, UVMap uvmap, VMap v_field,
                 const Progress& progress, const AddConstraints& add_constraints, Run_summary& summary)
{
  using face_descriptor = typename Mesh::Face_index;
  using edge_descriptor = typename Mesh::Edge_index;
  using halfedge_descriptor = typename Mesh::Halfedge_index;

  // visibility: to steer the seams (--hide-seams) or to report where they lie
  auto visibility = mesh.template add_property_map<face_descriptor, double>("f:visibility", 1.).first;
  auto face_lambda = mesh.template add_property_map<face_descriptor, double>("f:lambda", 1.).first;
  const bool visibility_wanted = options.hide_seams > 0. || options.report_visibility;
  if(visibility_wanted)
  {
    const auto start = std::chrono::steady_clock::now();
    // its reports go to `progress` too, as phase "visibility" (`alternation`
    // the faces done of `alternations_per_pass`): canceling there (Ctrl-C,
    // Python's progress) stops it with ERROR_CANCELED
    const std::size_t face_count = num_faces(mesh);
    const std::function<bool(double)> visibility_progress = [&](double done) {
      if(!progress) return true;
      SMP::Cut_and_parameterize_progress report;
      report.phase = "visibility";
      report.alternation = int(std::lround(done * double(face_count)));
      report.alternations_per_pass = int(face_count);
      return progress(report);
    };
    const SMP::Error_code status =
      SMP::face_visibility(mesh, visibility, SMP::parameters::progress_callback(visibility_progress));
    if(status != SMP::OK)
      throw Failure(std::string("visibility failed: ") + SMP::error_message(status), SMP::error_name(status));
    if(options.hide_seams > 0.) SMP::visibility_face_lambda(mesh, visibility, face_lambda, options.hide_seams);
    summary.visibility_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  auto forbidden = mesh.template add_property_map<edge_descriptor, bool>("e:forbidden", false).first;
  add_constraints(forbidden, face_lambda);

  // the options whole (those not given unset: the library's rules decide),
  // the property maps and the callback beside them
  SMP::Cut_parameterization_options method = options.method;
  method.progress_callback = progress;
  namespace P = SMP::parameters;
  const auto np = P::cut_parameterization_options(method,
                  P::face_lambda_map(face_lambda,
                  P::forbidden_seam_edge_map(forbidden,
                  P::face_discontinuity_map(v_field))));

  const auto start = std::chrono::steady_clock::now();
  summary.result = SMP::cut_and_parameterize(mesh, seams, uvmap, np);
  summary.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(!summary.result.ok())
    throw Failure(std::string("unwrapping failed: ") + SMP::error_message(summary.result.error) + " (" +
                  SMP::error_name(summary.result.error) + ")", SMP::error_name(summary.result.error));
  if(!summary.result.distortion_bound_met)
    summary.warnings.push_back("E_d " + std::to_string(summary.result.distortion) + " is above --max-distortion " +
                               std::to_string(options.method.distortion_bound) +
                               ": no seam cost tried reached it (lowest E_d kept)");
  if(visibility_wanted) summary.seam_visibility = SMP::seam_visibility(mesh, seams, visibility);
  summary.flipped_faces = SMP::number_of_flipped_faces(mesh, uvmap);
  summary.border_crossings = summary.result.border_crossings; // counted by the library on the map written
  summary.overlap_area = SMP::uv_overlap_area(mesh, uvmap);
  summary.uv_in_unit_square = true;
  for(face_descriptor f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const auto& uv = get(uvmap, h);
      if(!(uv.x() >= 0. && uv.x() <= 1. && uv.y() >= 0. && uv.y() <= 1.)) summary.uv_in_unit_square = false;
    }
}

} // namespace uv_unwrap

#endif
