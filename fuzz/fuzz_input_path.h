// The input path exercised by the fuzz target (fuzz_input.cpp) and replayed
// on the saved regression inputs by replay_regressions.cpp (any compiler):
//
//   bytes -> temporary file (extension from the first byte: off, obj, ply,
//   stl; the other bytes are the file) -> mesh_input::read_input_mesh()
//   (validation, repair, triangulation: the code uv_unwrap runs) -> if the
//   mesh has at most max_faces faces, cut_and_parameterize() with small
//   settings -> invariants.
//
// A violated invariant calls abort(), which libFuzzer reports as a crash:
//   - read_input_mesh() either throws Input_error with a documented status,
//     or returns a non-empty triangle mesh with finite coordinates;
//   - cut_and_parameterize() then never returns a code the input path rules
//     out (empty, non-triangle, non-finite), nor an unknown one;
//   - when it returns OK: every corner UV is finite, no UV triangle has a
//     non-positive signed area, and the OBJ writer writes every vertex and
//     face;
//   - the statistics writer of uv_unwrap (unwrap_run.h) turns every
//     outcome into JSON that parses back, whatever bytes the file, its
//     messages and its name hold (the input's first bytes serve as a file
//     name), with the error and warnings as printable_text() makes them.
#ifndef UV_TOOLS_FUZZ_INPUT_PATH_H
#define UV_TOOLS_FUZZ_INPUT_PATH_H

#include "mesh_input.h"
#include "unwrap_run.h"

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace fuzz_input {

/// Larger meshes are read and validated but not unwrapped (time per input).
constexpr std::size_t max_faces = 300;

inline const char* extension_of(std::uint8_t first_byte)
{
  static const char* const extensions[] = {"off", "obj", "ply", "stl"};
  return extensions[first_byte % 4];
}

[[noreturn]] inline void violation(const std::string& what)
{
  std::fprintf(stderr, "fuzz_input: invariant violated: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// Unwraps a mesh accepted by the input path and checks the result.
inline CGAL::Surface_mesh_parameterization::Cut_and_parameterize_result unwrap_and_check(const mesh_input::Mesh& mesh)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using Mesh = mesh_input::Mesh;
  using Point_2 = mesh_input::Kernel::Point_2;
  Mesh m = mesh; // the property maps are added to a copy
  auto seams = m.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto uvmap = m.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  namespace P = SMP::parameters;
  const auto np = P::iterations_per_epsilon(1, P::number_of_passes(1, P::epsilon_start(0.1, P::epsilon_end(0.05))))
                    .number_of_iterations(20);
  const SMP::Cut_and_parameterize_result result = SMP::cut_and_parameterize(m, seams, uvmap, np);

  const std::string name = SMP::error_name(result.error);
  if(name == "ERROR_UNKNOWN") violation("unknown error code " + std::to_string(int(result.error)));
  if(result.error == SMP::ERROR_EMPTY_MESH || result.error == SMP::ERROR_NON_TRIANGULAR_MESH ||
     result.error == SMP::ERROR_NON_FINITE_COORDINATE || result.error == SMP::ERROR_NON_MANIFOLD)
    violation("the input path accepted a mesh the library rejects with " + name);
  if(!result.ok()) return result;

  for(Mesh::Face_index f : faces(m))
  {
    const Mesh::Halfedge_index h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const Point_2 u0 = uvmap[h0], u1 = uvmap[h1], u2 = uvmap[h2];
    for(const Point_2& u : {u0, u1, u2})
      if(!std::isfinite(u.x()) || !std::isfinite(u.y()))
        violation("non-finite UV in face " + std::to_string(std::size_t(f)));
    const double area2 = (u1.x() - u0.x()) * (u2.y() - u0.y()) - (u1.y() - u0.y()) * (u2.x() - u0.x());
    if(!(area2 > 0.)) violation("flipped or collapsed UV face " + std::to_string(std::size_t(f)));
  }
  if(!std::isfinite(result.distortion)) violation("non-finite distortion on success");

  std::ostringstream obj;
  if(!SMP::write_OBJ_with_uvs(obj, m, uvmap)) violation("write_OBJ_with_uvs failed");
  std::istringstream lines(obj.str());
  std::string line;
  std::size_t v = 0, f = 0;
  while(std::getline(lines, line))
  {
    if(line.rfind("v ", 0) == 0) ++v;
    if(line.rfind("f ", 0) == 0) ++f;
  }
  if(v != num_vertices(m) || f != num_faces(m)) violation("OBJ output lost vertices or faces");
  return result;
}

/// The statistics of `summary` dumped as uv_unwrap dumps them, parsed back
/// and compared with the summary's text fields.
inline void check_statistics(const uv_unwrap::Run_summary& summary)
{
  for(int indent : {-1, 2})
  {
    std::string text;
    try
    {
      text = uv_unwrap::statistics_text(summary, indent);
    }
    catch(const std::exception& e)
    {
      violation(std::string("the statistics writer threw: ") + e.what());
    }
    const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    if(parsed.is_discarded()) violation("the statistics are not valid JSON");
    if(indent < 0 && text.find('\n') != std::string::npos) violation("a JSON line holds a line break");
    if(parsed["input"] != cut_tools::printable_text(summary.input)) violation("the input name changed in JSON");
    if(summary.status != "ok" && parsed["error"] != cut_tools::printable_text(summary.error))
      violation("the error message changed in JSON");
    if(parsed["warnings"].size() != summary.warnings.size()) violation("warnings lost in JSON");
  }
}

/// Runs the input path on `data`; `scratch_dir` holds the temporary file.
inline void run(const std::uint8_t* data, std::size_t size, const std::string& scratch_dir)
{
  if(size == 0) return;
  const std::string filename =
    scratch_dir + "/fuzz_input_" + std::to_string(long(getpid())) + "." + extension_of(data[0]);
  {
    std::ofstream out(filename, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    if(!out) violation("cannot write the temporary file " + filename);
  }

  mesh_input::Mesh mesh;
  mesh_input::Input_report report;
  uv_unwrap::Run_summary summary;
  summary.input = std::string(reinterpret_cast<const char*>(data + 1), std::min<std::size_t>(size - 1, 64)) + "." +
                  extension_of(data[0]); // any bytes, as a file name may hold
  bool accepted = false;
  try
  {
    mesh_input::read_input_mesh(filename, mesh, report);
    accepted = true;
  }
  catch(const mesh_input::Input_error& e)
  {
    const auto& known = mesh_input::input_error_statuses();
    if(std::find(known.begin(), known.end(), e.status) == known.end())
      violation("undocumented input status " + e.status);
    if(std::string(e.what()).find('\n') != std::string::npos) violation("multi-line error message");
    summary.status = e.status;
    summary.error = e.what();
  }
  std::remove(filename.c_str());
  if(!accepted)
  {
    check_statistics(summary);
    return;
  }
  summary.warnings = report.warnings;
  summary.vertices = num_vertices(mesh);
  summary.faces = num_faces(mesh);

  if(num_faces(mesh) == 0) violation("accepted an empty mesh");
  if(!CGAL::is_triangle_mesh(mesh)) violation("accepted a mesh that is not a triangle mesh");
  if(!mesh.is_valid(false)) violation("accepted an invalid Surface_mesh");
  for(auto vd : vertices(mesh))
  {
    const auto& p = mesh.point(vd);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      violation("accepted a non-finite coordinate");
  }
  if(num_faces(mesh) <= max_faces)
  {
    summary.result = unwrap_and_check(mesh);
    if(!summary.result.ok())
    {
      summary.status = CGAL::Surface_mesh_parameterization::error_name(summary.result.error);
      summary.error = "the library returned " + summary.status;
    }
  }
  check_statistics(summary);
}

} // namespace fuzz_input

#endif
