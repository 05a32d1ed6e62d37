// The statistics of one uv_unwrap run (its --stats file and --jsonl lines,
// documented in the README), shared with the fuzz target so that every
// message the input path can produce goes through the JSON writer.
#ifndef UV_TOOLS_RUN_STATISTICS_H
#define UV_TOOLS_RUN_STATISTICS_H

#include "printable_text.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace cut_tools {

/// One input's run: what was read, what came out, or why not.
struct Run_summary
{
  std::string input;
  std::string output;                 // empty until written
  std::string status = "ok";          // "ok", ERROR_USAGE, an input error or a library error name
  std::string error;                  // one-line message when status is not "ok"
  std::vector<std::string> warnings;  // input repairs and remarks
  std::size_t vertices = 0, faces = 0, flipped_faces = 0;
  std::size_t border_crossings = 0;   // recounted on the output
  bool uv_in_unit_square = false;     // every corner UV of the output in [0,1]²
  CGAL::Surface_mesh_parameterization::Cut_and_parameterize_result result;
  double time_seconds = 0.;
  double seam_visibility = std::nan(""); // with --hide-seams or --report-visibility
  double visibility_seconds = 0.;
};

/// The statistics of one run as JSON. Numbers that are not finite become
/// null (JSON has no NaN); file names, messages and warnings go through
/// printable_text() (a file name or a message quoting a file may hold bytes
/// that are not UTF-8, which nlohmann-json refuses), so building and dumping
/// the object never throws on text.
inline nlohmann::ordered_json statistics(const Run_summary& s)
{
  const CGAL::Surface_mesh_parameterization::Cut_and_parameterize_timings& t = s.result.timings;
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(); };
  auto text = [](const std::string& x) { return nlohmann::ordered_json(printable_text(x)); };
  nlohmann::ordered_json j;
  j["input"] = text(s.input);
  j["output"] = s.output.empty() ? nlohmann::ordered_json() : text(s.output);
  j["status"] = text(s.status);
  j["error"] = s.status == "ok" ? nlohmann::ordered_json() : text(s.error);
  j["warnings"] = nlohmann::ordered_json::array();
  for(const std::string& w : s.warnings) j["warnings"].push_back(printable_text(w));
  j["vertices"] = s.vertices;
  j["faces"] = s.faces;
  j["degenerate_faces"] = s.result.number_of_degenerate_faces;
  j["charts"] = s.result.number_of_charts;
  j["seam_edges"] = s.result.number_of_seam_edges;
  j["seam_length"] = number(s.result.seam_length);
  j["distortion"] = number(s.result.distortion);
  j["distortion_bound_met"] = s.result.distortion_bound_met;
  j["initial_distortion"] = number(s.result.initial_distortion);
  j["flipped_faces"] = s.flipped_faces;
  j["border_crossings"] = s.border_crossings;
  j["uv_coverage"] = number(s.result.uv_coverage);
  j["uv_scale"] = number(s.result.uv_scale);
  j["uv_in_unit_square"] = s.uv_in_unit_square;
  j["time_seconds"] = number(s.time_seconds);
  j["seam_visibility"] = number(s.seam_visibility);
  j["visibility_seconds"] = number(s.visibility_seconds);
  j["newton_iterations"] = s.result.newton_iterations;
  j["factorizations"] = s.result.number_of_factorizations;
  j["timings"] = {{"initialization", number(t.initialization)}, {"u_steps", number(t.u_steps)},
                  {"v_steps", number(t.v_steps)}, {"cut_extraction", number(t.cut_extraction)},
                  {"final_solve", number(t.final_solve)}, {"packing", number(t.packing)},
                  {"total", number(t.total)}};
  if(s.status != "ok") // nothing was measured: no figure rather than zeros
    for(auto& [key, value] : j.items())
      if(value.is_number() || value.is_boolean() || value.is_object())
        if(key != "vertices" && key != "faces") value = nullptr;
  return j;
}

/// The statistics as text: one line (`indent` < 0, for JSON Lines) or
/// indented. Invalid UTF-8 that got past printable_text() is replaced
/// (U+FFFD) rather than thrown on.
inline std::string statistics_text(const Run_summary& s, int indent = -1)
{
  return statistics(s).dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

/// Writes the indented statistics to `filename`; false if it cannot be written.
inline bool write_statistics(const std::string& filename, const Run_summary& s)
{
  std::ofstream out(filename);
  out << statistics_text(s, 2) << '\n';
  out.close();
  return bool(out);
}

} // namespace cut_tools

#endif
