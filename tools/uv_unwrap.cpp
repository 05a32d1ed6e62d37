// uv_unwrap: command-line front end of cut_and_parameterize(). Reads a
// mesh (tools/mesh_input.h: validation, repair and triangulation, with
// warnings), cuts it and computes a UV map, writes an OBJ with texture
// coordinates and, on request, a JSON file of statistics and pictures
// (tools/preview). By default the result is a texture atlas: charts free of
// overlap, packed into the unit square with a padding in texels.
#include "blas_setup.h"
#include "malloc_settings.h"
#include "gltf_io.h"
#include "mesh_input.h"
#include "mesh_output.h"
#include "output_formats.h"
#include "scene_atlas_run.h"
#include "uv_unwrap_scene.h"
#include "seam_constraints.h"
#include "gltf_split_normals.h"
#include "split_normals.h"
#include "unwrap_run.h"
#include "uv_unwrap_options.h"

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/face_visibility.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include "preview/preview.h"
#include "preview/preview_of_mesh.h"
#include "printable_text.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <time.h> // clock_gettime (POSIX)
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

// Ctrl-C (SIGINT) or SIGTERM: the unwrapping in progress stops at its next
// progress report (ERROR_CANCELED), nothing more is written, the outputs of
// the input in progress are removed, and uv_unwrap exits with
// exit_status_interrupted. A second signal a second or more after the first
// ends the process at once; one sooner is the same request repeated
// (coreutils' timeout signals the process, then its process group).
volatile std::sig_atomic_t interrupted = 0;
timespec first_interrupt{};
constexpr int exit_status_interrupted = 130; // 128 + SIGINT, as shells report it
void on_interrupt(int signal_number)
{
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now); // async-signal-safe
  if(!interrupted)
  {
    first_interrupt = now;
    interrupted = 1;
    return;
  }
  const double since_first =
    double(now.tv_sec - first_interrupt.tv_sec) + 1e-9 * double(now.tv_nsec - first_interrupt.tv_nsec);
  if(since_first < 1.0) return;
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

using Kernel = mesh_input::Kernel;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = mesh_input::Mesh;
using halfedge_descriptor = Mesh::Halfedge_index;
using edge_descriptor = Mesh::Edge_index;
using face_descriptor = Mesh::Face_index;

using uv_unwrap::Failure;
using uv_unwrap::Options;
using cut_tools::printable_text;
using uv_unwrap::Run_summary;
using uv_unwrap::Scene;
using uv_unwrap::statistics_text;

// ---------------------------------------------------------------- input

// A spherical cap reaching 165 degrees from its pole: a disk curved enough
// that it cannot be flattened without seams, used when no data mesh exists.
void make_spherical_cap(Mesh& mesh)
{
  const int rings = 16, segments = 48;
  const double max_polar_angle = 0.92 * M_PI; // about 165 degrees
  std::vector<std::vector<Mesh::Vertex_index>> ring(rings);
  const auto pole = mesh.add_vertex(Point_3(0., 0., 1.));
  for(int k = 0; k < rings; ++k)
  {
    const double theta = max_polar_angle * (k + 1) / rings;
    for(int j = 0; j < segments; ++j)
    {
      const double phi = 2. * M_PI * j / segments;
      ring[k].push_back(mesh.add_vertex(Point_3(std::sin(theta) * std::cos(phi),
                                                std::sin(theta) * std::sin(phi), std::cos(theta))));
    }
  }
  for(int j = 0; j < segments; ++j)
  {
    const int j1 = (j + 1) % segments;
    mesh.add_face(pole, ring[0][j], ring[0][j1]);
    for(int k = 0; k + 1 < rings; ++k)
    {
      mesh.add_face(ring[k][j], ring[k + 1][j], ring[k + 1][j1]);
      mesh.add_face(ring[k][j], ring[k + 1][j1], ring[k][j1]);
    }
  }
}

fs::path executable_directory(const char* argv0)
{
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec); // Linux; argv[0] elsewhere
  if(ec) exe = fs::absolute(argv0, ec);
  return ec ? fs::path() : exe.parent_path();
}

// The default input: a disk-like mesh of CGAL's data set, looked up through
// CGAL_DATA_DIR, then in the copy the setup scripts extract next to the
// build's bin/ folder. Empty if neither exists.
std::string find_default_mesh(const char* argv0)
{
  const char* const name = "meshes/mushroom.off";
  std::vector<fs::path> candidates;
  if(const char* dir = std::getenv("CGAL_DATA_DIR"))
    if(*dir) candidates.push_back(fs::path(dir) / name);
  const fs::path exe_dir = executable_directory(argv0);
  if(!exe_dir.empty()) candidates.push_back(exe_dir.parent_path() / "data" / name);
  for(const fs::path& p : candidates)
  {
    std::error_code ec;
    if(fs::is_regular_file(p, ec)) return p.string();
  }
  return {};
}

// Reads, validates and repairs (tools/mesh_input.h); warnings go to stderr
// and to the statistics.
void read_mesh(const std::string& filename, Mesh& mesh, std::vector<std::string>& warnings,
               mesh_input::Input_report& report)
{
  try
  {
    mesh_input::read_input_mesh(filename, mesh, report);
  }
  catch(const mesh_input::Input_error& e)
  {
    throw Failure(e.what(), e.status);
  }
  for(const std::string& w : report.warnings)
  {
    std::cerr << "uv_unwrap: warning: " << printable_text(w) << std::endl;
    warnings.push_back(w);
  }
}

// ---------------------------------------------------------------- output

void write_stats(const std::string& filename, const Run_summary& s)
{
  std::ofstream out(filename);
  out << statistics_text(s, 2) << '\n';
  out.close();
  if(!out)
    throw Failure("cannot write '" + filename + "'", "ERROR_CANNOT_WRITE");
}

template <typename SeamMap, typename UVMap, typename VMap>
void write_pictures(const Options& options, const Mesh& mesh, const SeamMap& seams, const UVMap& uvmap,
                    const VMap& v, const Run_summary& summary, const std::string& name)
{
  if(options.svg.empty() && options.png.empty() && options.v_field.empty() && options.v_png.empty()) return;

  // The preview library takes plain arrays; a freshly read Surface_mesh has
  // contiguous indices.
  Preview_mesh preview;
  append_to_preview(preview, mesh, uvmap, seams);
  for(auto f : faces(mesh))
  {
    preview.face_distortion.push_back(
      SMP::face_distortion(f, mesh, uvmap, SMP::parameters::uv_scale(summary.result.uv_scale)));
    preview.face_v.push_back(v[f]);
  }

  if(!options.svg.empty())
  {
    Preview_caption caption;
    caption.distortion = summary.result.distortion;
    caption.seam_length = summary.result.seam_length;
    caption.seconds = summary.time_seconds;
    caption.faces = summary.faces;
    caption.charts = summary.result.number_of_charts;
    caption.coverage = summary.result.uv_coverage;
    caption.border_crossings = static_cast<long long>(summary.border_crossings);
    caption.name = name;
    if(!write_uv_svg(options.svg, preview, caption))
      throw Failure("cannot write '" + options.svg + "'", "ERROR_CANNOT_WRITE");
  }
  if(!options.png.empty())
  {
    if(!write_checker_png(options.png, preview, 1024, 768, true, options.camera))
      throw Failure("cannot write '" + options.png + "'", "ERROR_CANNOT_WRITE");
  }
  if(!options.v_field.empty() && !write_v_field_ply(options.v_field, preview))
    throw Failure("cannot write '" + options.v_field + "'", "ERROR_CANNOT_WRITE");
  if(!options.v_png.empty() && !write_v_field_png(options.v_png, preview, 1024, 768, true, options.camera))
    throw Failure("cannot write '" + options.v_png + "'", "ERROR_CANNOT_WRITE");
}

// ---------------------------------------------------------------- run

} // namespace

// The writers of tools/output_formats.h's rows.
struct output_formats::Written
{
  const std::string& input;
  const mesh_input::Input_report* report;  // the mesh's; null for a glTF input
  const Mesh* mesh;                        // null for a glTF input
  const Mesh::Property_map<halfedge_descriptor, Point_2>* uvmap;
  std::vector<std::string>& warnings;
  gltf_io::Document* doc;                  // the glTF input's, UVs set; null for a mesh
};

// An OBJ read without repair keeps the input's other lines (tools/mesh_output.h);
// other inputs get the library's plain OBJ writer.
void output_formats::write_obj(const std::string& output, Written& w)
{
  bool written = false;
  if(mesh_input::lower_extension(w.input) == "obj" && !w.report->face_origin.empty())
  {
    std::string problem;
    written = mesh_output::write_obj_keeping_input(w.input, output, *w.mesh, *w.uvmap, w.report->face_origin, problem);
    if(!written)
    {
      const std::string warning = "the input's normals, groups and materials are not kept: " + problem;
      std::cerr << "uv_unwrap: warning: " << printable_text(warning) << std::endl;
      w.warnings.push_back(warning);
    }
  }
  else if(mesh_input::lower_extension(w.input) == "obj")
  {
    const std::string warning = "the input was repaired: the output has the repaired mesh's numbering, without the "
                                "input's normals, groups and materials";
    std::cerr << "uv_unwrap: warning: " << printable_text(warning) << std::endl;
    w.warnings.push_back(warning);
  }
  if(!written) written = SMP::write_OBJ_with_uvs(output, *w.mesh, *w.uvmap);
  if(!written) throw Failure("cannot write '" + output + "'", "ERROR_CANNOT_WRITE");
}

void output_formats::write_ply(const std::string& output, Written& w)
{
  if(!mesh_output::write_ply_with_texcoords(output, *w.mesh, *w.uvmap))
    throw Failure("cannot write '" + output + "'", "ERROR_CANNOT_WRITE");
}

void output_formats::write_gltf(const std::string& output, Written& w)
{
  if(!w.doc) throw Failure("glTF output needs a glTF input (for other inputs: " + list(".", Inputs::mesh) + ")");
  gltf_io::save(*w.doc, output);
}

namespace {

// A glTF input: its extension is that of a format written from the glTF document.
bool is_gltf(const std::string& input)
{
  const output_formats::Output_format* f = output_formats::find(mesh_input::lower_extension(input));
  return f && f->needs_gltf_input;
}

// The output format of `input`'s run (a row of tools/output_formats.h): --format, else -o's
// extension, else the input's (the first row, OBJ, for OFF and STL, which have no texture coordinates).
const output_formats::Output_format& output_format(const Options& options, const std::string& input)
{
  if(!options.output_format.empty())
    if(const output_formats::Output_format* f = output_formats::find(options.output_format)) return *f;
  const std::string from = !options.output.empty() ? options.output : input;
  std::string extension = fs::path(from).extension().string();
  for(char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if(!extension.empty())
    if(const output_formats::Output_format* f = output_formats::find(extension.substr(1))) return *f;
  if(options.output.empty()) return output_formats::table[0];
  throw Failure("cannot tell the format of '" + options.output + "' (give " + output_formats::list(".") +
                ", or --format)");
}

// The output file of a run on `stem`: -o, else <stem>_uv.<format> in --output-dir.
std::string output_file(const Options& options, const std::string& stem, const output_formats::Output_format& format)
{
  if(!options.output.empty()) return options.output;
  const fs::path dir = options.output_dir.empty() ? fs::path() : fs::path(options.output_dir);
  return (dir / (stem + "_uv." + std::string(format.name))).string();
}

// The file a mesh was read from, for the constraints given in its numbering.
struct Mesh_source
{
  std::string filename;
  const mesh_input::Input_report* report = nullptr;
};

// --seams, --forbid and --lambda-from-ply-property (tools/seam_constraints.h).
template <typename SeamMap, typename ForbiddenMap, typename LambdaMap>
void read_constraints(const Options& options, const Mesh& mesh, const Mesh_source* source, SeamMap seams,
                      ForbiddenMap forbidden, LambdaMap face_lambda)
{
  const bool split_normals = options.method.hard_edge_angle && source != nullptr && source->report != nullptr &&
                             mesh_input::lower_extension(source->filename) == "obj"; // hard edges: the file's too
  if(options.seams_file.empty() && options.forbid_file.empty() && options.lambda_property.empty() && !split_normals)
    return;
  if(source == nullptr || source->report == nullptr)
    throw Failure("--seams, --forbid and --lambda-from-ply-property need a mesh file (OBJ, OFF, PLY or STL)");
  try
  {
    const mesh_input::Input_report& report = *source->report;
    if(!options.seams_file.empty())
      seam_constraints::flag_edges(mesh, report, seam_constraints::read_selection_edges(options.seams_file),
                                   options.seams_file, seams);
    if(!options.forbid_file.empty())
      seam_constraints::flag_edges(mesh, report, seam_constraints::read_selection_edges(options.forbid_file),
                                   options.forbid_file, forbidden);
    if(split_normals)
    {
      std::string warning;
      split_normals::flag_split_normal_edges(source->filename, mesh, report, seams, forbidden, warning);
      if(!warning.empty()) std::cerr << "uv_unwrap: warning: " << printable_text(warning) << std::endl;
    }
    if(!options.lambda_property.empty())
    {
      const std::vector<double> factor =
        seam_constraints::face_lambda_from_ply(source->filename, mesh, report, options.lambda_property);
      for(face_descriptor f : faces(mesh)) face_lambda[f] *= factor[std::size_t(f)];
    }
  }
  catch(const seam_constraints::Constraint_error& e)
  {
    throw Failure(e.what(), "ERROR_WRONG_PARAMETER");
  }
}

// cut_and_parameterize() with the options (tools/unwrap_run.h), progress
// and warnings on stderr. `source`: the file the mesh comes from (null for
// glTF primitives and the built-in mesh), for the constraints given in its
// numbering.
template <typename SeamMap, typename UVMap, typename VMap>
void unwrap_mesh(const Options& options, Mesh& mesh, SeamMap seams, UVMap uvmap, VMap v_field, Run_summary& summary,
                 const Mesh_source* source = nullptr)
{
  // Progress goes to stderr so that stdout keeps the summary only.
  uv_unwrap::Progress progress = [quiet = options.quiet](const SMP::Cut_and_parameterize_progress& p) {
      if(interrupted) return false; // Ctrl-C: ERROR_CANCELED
      if(quiet) return true;
      const std::string phase = p.phase;
      if(phase == "visibility") // reported per block of faces: one line, at the start
      {
        if(p.alternation == 0) std::cerr << "  visibility: " << p.alternations_per_pass << " faces" << std::endl;
        return true;
      }
      std::cerr << "  " << phase << ":";
      if(phase == "alternate" || phase == "cut") std::cerr << " pass " << p.pass + 1 << ",";
      if(phase == "alternate")
        std::cerr << " alternation " << p.alternation << "/" << p.alternations_per_pass
                  << ", epsilon " << p.epsilon << ",";
      std::cerr << " E_d " << p.distortion << std::endl;
      return true;
    };
  const std::size_t warned = summary.warnings.size();
  uv_unwrap::unwrap_mesh(options, mesh, seams, uvmap, v_field, progress,
                         [&](auto forbidden, auto face_lambda) {
                           read_constraints(options, mesh, source, seams, forbidden, face_lambda);
                         },
                         summary);
  for(std::size_t i = warned; i < summary.warnings.size(); ++i)
    std::cerr << "uv_unwrap: warning: " << printable_text(summary.warnings[i]) << std::endl;
  if(interrupted) // after the library's last report
    throw Failure(std::string("unwrapping failed: ") + SMP::error_message(SMP::ERROR_CANCELED) + " (ERROR_CANCELED)",
                  "ERROR_CANCELED");
}

// A primitive whose triangles are no manifold mesh, welded or not (an edge of
// more than two faces, faces repeated or with a repeated corner): repaired as
// a polygon soup by the input path of mesh files (tools/mesh_input.h), the
// warnings prefixed with `name`; `corners`: the halfedge whose UV each corner
// of `t` gets (the output keeps the primitive's own triangles).
void repair_primitive(const std::string& name, const gltf_io::Triangles& t, Mesh& mesh,
                      std::vector<std::array<halfedge_descriptor, 3>>& corners, std::vector<std::string>& warnings)
{
  std::vector<mesh_input::File_point> points;
  for(const auto& p : t.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> triangles;
  for(const auto& f : t.faces) triangles.push_back({f[0], f[1], f[2]});
  mesh_input::Input_report report;
  try
  {
    mesh_input::mesh_from_polygon_soup(points, triangles, "the primitive", mesh, report);
  }
  catch(const mesh_input::Input_error& e)
  {
    throw Failure(e.what(), e.status);
  }
  mesh_input::triangle_corner_halfedges(points, triangles, mesh, report, corners);
  for(const std::string& w : report.warnings)
  {
    std::cerr << "uv_unwrap: warning: " << printable_text(name + ": " + w) << std::endl;
    warnings.push_back(name + ": " + w);
  }
}

// In a scene atlas, a rigid copy of a mesh unwrapped before takes that
// mesh's texels (given by the packing) instead of being unwrapped. Returns
// the index of that mesh's part, -1 if the mesh was unwrapped.
template <typename SeamMap, typename UVMap, typename VMap>
int unwrap_or_stack(const Options& options, Scene* scene, Mesh& mesh, SeamMap seams, UVMap uvmap, VMap v_field,
                     Run_summary& summary, const Mesh_source* source = nullptr)
{
  const int original = scene ? uv_unwrap::stacked_original(scene->parts, mesh, options.method.stacking_tolerance) : -1;
  if(original < 0)
  {
    unwrap_mesh(options, mesh, seams, uvmap, v_field, summary, source);
    return original;
  }
  uv_unwrap::take_stacked_result(scene->parts[std::size_t(original)], summary);
  if(!options.quiet)
    std::cout << "  stacked on " << printable_text(scene->parts[std::size_t(original)].name) << std::endl;
  return original;
}

// A glTF file: each triangle primitive unwrapped on its own (tools/gltf_io.h),
// into its own atlas; the statistics add up the primitives (E_d weighted by
// area, E_s from the summed seam length and area, as METHOD.md defines them).
void run_gltf(const Options& options, const std::string& input, const output_formats::Output_format& format,
              const std::string& output, Run_summary& summary, Scene* scene)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto doc_ptr = std::make_shared<gltf_io::Document>(); // shared with the scene's writer
  gltf_io::Document& doc = *doc_ptr;
  std::vector<gltf_io::Primitive_ref> primitives;
  try
  {
    gltf_io::load(input, doc);
    primitives = gltf_io::triangle_primitives(doc);
  }
  catch(const gltf_io::Gltf_error& e)
  {
    throw Failure(e.what(), "ERROR_CANNOT_READ");
  }
  if(primitives.empty()) throw Failure("'" + input + "' has no triangles", "ERROR_EMPTY_MESH");

  double area = 0., seam_length = 0., distortion = 0., initial = 0., coverage = 0., seen = 0.;
  SMP::Cut_and_parameterize_result& total = summary.result;
  total = SMP::Cut_and_parameterize_result();
  summary.uv_in_unit_square = true;
  for(const gltf_io::Primitive_ref& ref : primitives)
  {
    const std::string name = "mesh " + std::to_string(ref.mesh) + ", primitive " + std::to_string(ref.primitive);
    try
    {
      // welded positions first; as the file has it if that is no manifold
      const auto t_ptr = std::make_shared<gltf_io::Triangles>();
      gltf_io::Triangles& t = *t_ptr;
      std::vector<Point_3> points;
      std::vector<std::vector<std::size_t>> polygons;
      for(bool weld : {true, false})
      {
        t = gltf_io::read_triangles(doc, ref, weld);
        points.clear();
        polygons.clear();
        for(const auto& p : t.points) points.emplace_back(p[0], p[1], p[2]);
        bool repeated = false;
        for(const auto& f : t.faces)
        {
          polygons.push_back({f[0], f[1], f[2]});
          repeated = repeated || f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
        }
        if(!repeated && PMP::is_polygon_soup_a_polygon_mesh(polygons)) break;
        polygons.clear();
      }
      const auto mesh_ptr = std::make_shared<Mesh>();
      Mesh& mesh = *mesh_ptr;
      const auto corners_ptr = std::make_shared<std::vector<std::array<halfedge_descriptor, 3>>>();
      std::vector<std::array<halfedge_descriptor, 3>>& corner_halfedges = *corners_ptr; // after a repair: each corner's UV
      if(polygons.empty()) // repaired as the input path repairs mesh files (t: the file's vertices)
        repair_primitive(name, t, mesh, corner_halfedges, summary.warnings);
      else
        PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      auto seams = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
      auto uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
      auto v_field = mesh.add_property_map<face_descriptor, double>("f:v", 1.).first;
      if(options.method.hard_edge_angle && corner_halfedges.empty()) // hard edges: the split NORMALs too
        split_normals::flag_gltf_split_normal_edges(doc, ref, t, mesh, seams);
      Run_summary part;
      part.input = name;
      if(!options.quiet)
        std::cout << "uv_unwrap: " << printable_text(input) << ", " << printable_text(name) << ": " << num_vertices(mesh) << " vertices, "
                  << num_faces(mesh) << " faces" << std::endl;
      const int original = unwrap_or_stack(options, scene, mesh, seams, uvmap, v_field, part);

      // the UV of each corner: face i of the mesh is triangle i of the primitive
      // (with --atlas, once the scene is packed)
      auto write_uvs = [doc_ptr, ref, t_ptr, mesh_ptr, corners_ptr, uvmap, uv_set = options.uv_set] {
        const Mesh& m = *mesh_ptr;
        const gltf_io::Triangles& tri = *t_ptr;
        std::vector<std::array<double, 2>> uvs(3 * tri.faces.size());
        if(corners_ptr->empty())
        {
          for(face_descriptor f : faces(m))
            for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m), m))
              for(int k = 0; k < 3; ++k)
                if(std::size_t(target(h, m)) == tri.faces[std::size_t(f)][std::size_t(k)])
                  uvs[3 * std::size_t(f) + std::size_t(k)] = {uvmap[h].x(), uvmap[h].y()};
        }
        else
          for(std::size_t f = 0; f < corners_ptr->size(); ++f)
            for(std::size_t k = 0; k < 3; ++k)
              if(const halfedge_descriptor h = (*corners_ptr)[f][k]; h != Mesh::null_halfedge())
                uvs[3 * f + k] = {uvmap[h].x(), uvmap[h].y()};
        gltf_io::set_corner_uvs(*doc_ptr, ref, tri, uvs, uv_set);
      };
      if(scene)
        scene->parts.push_back(
          {scene->input, input + ", " + name, mesh_ptr, seams, uvmap, write_uvs, -1, original, part.result});
      else
        write_uvs();

      const double a = PMP::area(mesh);
      const SMP::Cut_and_parameterize_result& r = part.result;
      area += a;
      distortion += a * r.distortion;
      initial += a * r.initial_distortion;
      coverage += a * r.uv_coverage;
      seam_length += r.seam_length * std::sqrt(a / M_PI);
      if(!std::isnan(part.seam_visibility)) seen += part.seam_visibility * r.seam_length * std::sqrt(a / M_PI);
      summary.visibility_seconds += part.visibility_seconds;
      summary.vertices += num_vertices(mesh);
      summary.faces += num_faces(mesh);
      summary.flipped_faces += part.flipped_faces;
      summary.border_crossings += part.border_crossings;
      summary.overlap_area += part.overlap_area; // each primitive has an atlas of its own
      summary.uv_in_unit_square = summary.uv_in_unit_square && part.uv_in_unit_square;
      summary.time_seconds += part.time_seconds;
      total.number_of_charts += r.number_of_charts;
      total.distortion_bound_met = total.distortion_bound_met && r.distortion_bound_met;
      total.number_of_seam_edges += r.number_of_seam_edges;
      total.number_of_hard_edges += r.number_of_hard_edges;
      total.number_of_degenerate_faces += r.number_of_degenerate_faces;
      total.newton_iterations += r.newton_iterations;
      total.number_of_factorizations += r.number_of_factorizations;
      total.timings.initialization += r.timings.initialization;
      total.timings.u_steps += r.timings.u_steps;
      total.timings.v_steps += r.timings.v_steps;
      total.timings.cut_extraction += r.timings.cut_extraction;
      total.timings.final_solve += r.timings.final_solve;
      total.timings.packing += r.timings.packing;
      total.timings.total += r.timings.total;
      total.uv_scale = primitives.size() == 1 ? r.uv_scale : std::nan(""); // one per primitive
    }
    catch(const gltf_io::Gltf_error& e)
    {
      throw Failure(input + ", " + name + ": " + e.what(), "ERROR_CANNOT_READ");
    }
    catch(const Failure& e)
    {
      throw Failure(input + ", " + name + ": " + e.what(), e.status);
    }
  }
  total.distortion = distortion / area;
  total.initial_distortion = initial / area;
  total.uv_coverage = coverage / area;
  total.seam_length = seam_length / std::sqrt(area / M_PI);
  if(options.hide_seams > 0. || options.report_visibility)
    summary.seam_visibility = seam_length > 0. ? seen / seam_length : 0.;
  for(const std::string& w : doc.warnings)
  {
    std::cerr << "uv_unwrap: warning: " << printable_text(w) << std::endl;
    summary.warnings.push_back(w);
  }
  if(interrupted) throw Failure("interrupted", "ERROR_CANCELED");
  auto write = [doc_ptr, input, &format, output](Run_summary& s) {
    try
    {
      output_formats::Written written{input, nullptr, nullptr, nullptr, s.warnings, doc_ptr.get()};
      format.write(output, written);
    }
    catch(const gltf_io::Gltf_error& e)
    {
      throw Failure(e.what(), "ERROR_CANNOT_WRITE");
    }
    s.output = output;
  };
  if(scene) { scene->writers.push_back({scene->input, write}); return; }
  write(summary);
  if(!options.quiet)
    std::cout << "  " << primitives.size() << " primitives: charts " << total.number_of_charts << ", E_d "
              << total.distortion << ", E_s " << total.seam_length << ", flipped faces " << summary.flipped_faces
              << ", border crossings " << summary.border_crossings << ", overlap area " << summary.overlap_area
              << "\n  wrote " << output << std::endl;
}

void run(const char* argv0, const Options& options, const std::string& input, Run_summary& summary, Scene* scene)
{
  if(is_gltf(input))
  {
    summary.input = input;
    if(!options.save_seams_file.empty()) throw Failure("--save-seams needs a mesh file (OBJ, OFF, PLY or STL)");
    const std::string stem = fs::path(input).stem().string();
    const output_formats::Output_format& format = output_format(options, input);
    if(!format.needs_gltf_input)
      throw Failure("a glTF input gives a glTF output (" + output_formats::list(".", output_formats::Inputs::gltf) +
                    "), not " + std::string(format.name));
    run_gltf(options, input, format, output_file(options, stem, format), summary, scene);
    return;
  }
  const auto mesh_ptr = std::make_shared<Mesh>();                       // shared with the scene's writer
  const auto report_ptr = std::make_shared<mesh_input::Input_report>();
  Mesh& mesh = *mesh_ptr;
  mesh_input::Input_report& report = *report_ptr;
  std::string stem;
  if(!input.empty())
  {
    summary.input = input;
    read_mesh(input, mesh, summary.warnings, report);
    stem = fs::path(input).stem().string();
  }
  else if(std::string data_mesh = find_default_mesh(argv0); !data_mesh.empty())
  {
    summary.input = data_mesh;
    read_mesh(data_mesh, mesh, summary.warnings, report);
    stem = fs::path(data_mesh).stem().string();
  }
  else
  {
    make_spherical_cap(mesh);
    summary.input = "built-in spherical cap";
    stem = "spherical_cap";
    for(std::size_t v = 0; v < num_vertices(mesh); ++v) report.point_vertex.push_back(long(v));
  }
  const output_formats::Output_format& format = output_format(options, input);
  const std::string output = output_file(options, stem, format);
  summary.vertices = num_vertices(mesh);
  summary.faces = num_faces(mesh);
  if(!options.quiet)
    std::cout << "uv_unwrap: " << printable_text(summary.input) << ": " << summary.vertices << " vertices, "
              << summary.faces << " faces" << std::endl;

  auto seams = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  auto v_field = mesh.add_property_map<face_descriptor, double>("f:v", 1.).first;
  const Mesh_source source{summary.input, &report};
  const int original = unwrap_or_stack(options, scene, mesh, seams, uvmap, v_field, summary, &source);
  if(options.uv_set > 0)
  {
    const std::string warning = std::string(format.name) + " has one set of texture coordinates: the UVs of --uv-set " +
                                std::to_string(options.uv_set) + " are written as that set";
    std::cerr << "uv_unwrap: warning: " << printable_text(warning) << std::endl;
    summary.warnings.push_back(warning);
  }
  if(scene)
  {
    scene->parts.push_back({scene->input, summary.input, mesh_ptr, seams, uvmap, {}, -1, original, summary.result});
    scene->writers.push_back({scene->input, [mesh_ptr, report_ptr, uvmap, &format, output](Run_summary& s) {
      output_formats::Written written{s.input, report_ptr.get(), mesh_ptr.get(), &uvmap, s.warnings, nullptr};
      format.write(output, written);
      s.output = output;
    }});
    return;
  }

  // Isolated vertices are written as plain `v` lines that no face uses (the
  // writer numbers every vertex), so indices and positions stay those of the
  // input.
  output_formats::Written written{summary.input, &report, &mesh, &uvmap, summary.warnings, nullptr};
  format.write(output, written);
  summary.output = output;
  write_pictures(options, mesh, seams, uvmap, v_field, summary, stem);
  if(!options.save_seams_file.empty() &&
     !seam_constraints::write_selection_edges(options.save_seams_file,
                                              seam_constraints::flagged_edges(mesh, report, seams)))
    throw Failure("cannot write '" + options.save_seams_file + "'", "ERROR_CANNOT_WRITE");

  if(!options.quiet)
  {
    const auto& r = summary.result;
    std::cout << "  charts " << r.number_of_charts << ", seam edges " << r.number_of_seam_edges
              << ", seam length E_s " << r.seam_length << "\n"
              << "  distortion E_d " << r.distortion << " (initial " << r.initial_distortion
              << "), flipped faces " << summary.flipped_faces << "\n"
              << "  UV coverage " << 100. * r.uv_coverage << " %, border crossings " << summary.border_crossings
              << ", overlap area " << summary.overlap_area
              << ", UVs " << (summary.uv_in_unit_square ? "in" : "not in") << " the unit square\n"
              << "  " << summary.time_seconds << " s, " << r.newton_iterations << " Newton iterations\n"
              << (std::isnan(summary.seam_visibility) ? std::string()
                  : "  seam visibility " + std::to_string(summary.seam_visibility) + " (visibility " +
                    std::to_string(summary.visibility_seconds) + " s)\n")
              << "  wrote " << printable_text(output);
    for(const std::string* file : {&options.stats, &options.svg, &options.png, &options.v_field, &options.v_png,
                                   &options.save_seams_file})
      if(!file->empty()) std::cout << ", " << printable_text(*file);
    std::cout << std::endl;
  }
}


// Unwraps one input (empty: the default mesh); every failure ends up in
// the summary's status and message.
Run_summary unwrap_one(const char* argv0, const Options& options, const std::string& input, Scene* scene = nullptr)
{
  Run_summary summary;
  summary.input = input;
  try
  {
    run(argv0, options, input, summary, scene);
    if(interrupted) // during the writing: none of this input's files stays
    {
      std::error_code ignored;
      for(const std::string* file : {static_cast<const std::string*>(&summary.output), &options.svg, &options.png, &options.v_field, &options.v_png,
                                     &options.save_seams_file})
        if(!file->empty()) fs::remove(*file, ignored);
      summary.output.clear();
      throw Failure("interrupted", "ERROR_CANCELED");
    }
  }
  catch(const Failure& e)
  {
    summary.status = e.status;
    summary.error = e.what();
  }
  catch(const std::bad_alloc&)
  {
    summary.status = "ERROR_OUT_OF_MEMORY";
    summary.error = "out of memory";
  }
  catch(const std::exception& e)
  {
    summary.status = "ERROR_INTERNAL";
    summary.error = e.what();
  }
  if(!options.stats.empty() && !scene) // with --atlas: once the atlas is written
  {
    try
    {
      write_stats(options.stats, summary);
    }
    catch(const Failure& e)
    {
      if(summary.status == "ok")
      {
        summary.status = e.status;
        summary.error = e.what();
      }
    }
  }
  return summary;
}

} // namespace

int main(int argc, char** argv)
{
  cut_tools::use_vector_blas_kernels(argv); // see blas_setup.h
  if(cut_tools::use_one_blas_thread()) cut_tools::stop_blas_worker_threads();
  cut_tools::keep_freed_memory();   // see malloc_settings.h
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  Options options;
  try
  {
    if(!uv_unwrap::parse_arguments(argc, argv, options)) return EXIT_SUCCESS;
    if(!options.output_dir.empty())
    {
      std::error_code ec;
      fs::create_directories(options.output_dir, ec);
      if(ec) throw Failure("cannot create the directory '" + options.output_dir + "': " + ec.message(),
                           "ERROR_CANNOT_WRITE");
    }
  }
  catch(const Failure& e)
  {
    std::cerr << "uv_unwrap: error: " << printable_text(e.what()) << std::endl;
    return EXIT_FAILURE;
  }

  // JSON Lines, flushed after each input so that a long batch can be followed.
  std::ofstream jsonl_file;
  std::ostream* jsonl = nullptr;
  if(options.jsonl == "-") jsonl = &std::cout;
  else if(!options.jsonl.empty())
  {
    jsonl_file.open(options.jsonl);
    if(!jsonl_file)
    {
      std::cerr << "uv_unwrap: error: cannot write '" << printable_text(options.jsonl) << "'" << std::endl;
      return EXIT_FAILURE;
    }
    jsonl = &jsonl_file;
  }
  if(jsonl == &std::cout) options.quiet = true; // stdout holds the JSON lines only

  // Each input on its own: a failure is reported and the next one runs.
  // Two inputs of the same name would write the same output: the second fails.
  std::vector<std::string> inputs = options.inputs;
  if(inputs.empty()) inputs.push_back(std::string()); // the default mesh
  std::set<std::string> outputs;
  int failures = 0;
  if(options.atlas)
  {
    for(const std::string& input : inputs)
      if(inputs.size() > 1 && !outputs.insert(fs::path(input).stem().string()).second)
      {
        std::cerr << "uv_unwrap: error: two inputs named '" << printable_text(fs::path(input).stem().string())
                  << "' would write the same output" << std::endl;
        return EXIT_FAILURE;
      }
    try
    {
      failures = uv_unwrap::run_scene(
        options, inputs, jsonl,
        [&](const std::string& input, Scene* scene) { return unwrap_one(argv[0], options, input, scene); },
        interrupted);
    }
    catch(const Failure& e)
    {
      std::cerr << "uv_unwrap: error: " << printable_text(e.what()) << std::endl;
      ++failures;
    }
    if(interrupted) return exit_status_interrupted;
    return std::min(failures, 100);
  }
  for(const std::string& input : inputs)
  {
    Run_summary summary;
    const std::string stem = fs::path(input).stem().string();
    if(inputs.size() > 1 && !outputs.insert(stem).second)
    {
      summary.input = input;
      summary.status = "ERROR_USAGE";
      summary.error = "another input of the same name ('" + stem + "') was written to the same output";
    }
    else
      summary = unwrap_one(argv[0], options, input);
    if(summary.status != "ok")
    {
      ++failures;
      const bool named = inputs.size() == 1 || summary.error.find(summary.input) != std::string::npos;
      std::cerr << "uv_unwrap: error: " << printable_text((named ? std::string() : summary.input + ": ") + summary.error)
                << std::endl;
    }
    if(jsonl) *jsonl << statistics_text(summary) << std::endl;
    if(interrupted) break; // the inputs left are not started
  }
  if(jsonl && !*jsonl)
  {
    std::cerr << "uv_unwrap: error: cannot write '" << printable_text(options.jsonl) << "'" << std::endl;
    ++failures;
  }
  if(inputs.size() > 1 && !options.quiet)
    std::cout << "uv_unwrap: " << inputs.size() - failures << " of " << inputs.size() << " inputs unwrapped"
              << std::endl;
  if(interrupted) return exit_status_interrupted;
  return std::min(failures, 100);
}
