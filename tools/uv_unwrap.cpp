// uv_unwrap: command-line front end of cut_and_parameterize(). Reads a
// mesh (tools/mesh_input.h: validation, repair and triangulation, with
// warnings), cuts it and computes a UV map, writes an OBJ with texture
// coordinates and, on request, a JSON file of statistics and pictures
// (tools/preview). By default the result is a texture atlas: charts free of
// overlap, packed into the unit square with a padding in texels.
#include "blas_threads.h"
#include "json_text.h"
#include "mesh_input.h"

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Surface_mesh_parameterization/IO/write_OBJ_with_uvs.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include "preview/preview.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

using Kernel = mesh_input::Kernel;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = mesh_input::Mesh;
using halfedge_descriptor = Mesh::Halfedge_index;
using edge_descriptor = Mesh::Edge_index;
using face_descriptor = Mesh::Face_index;

// Any failure the user should read about: main prints it as one line.
// `status` goes to the statistics (ERROR_USAGE for command-line mistakes).
struct Failure : std::runtime_error
{
  explicit Failure(const std::string& message, std::string status_ = "ERROR_USAGE")
    : std::runtime_error(message), status(std::move(status_)) {}
  std::string status;
};

struct Options
{
  std::string input;          // empty: the built-in default mesh
  std::string output;         // empty: <input stem>_uv.obj in the current directory
  std::string stats;
  std::string svg, png, v_field; // pictures, written by tools/preview
  Preview_camera camera;         // of the PNG; y up unless --up
  double lambda = 1.;
  double epsilon_start = 0.1;
  double epsilon_end = 0.01;
  int iterations = 3;
  int passes = 1;
  // atlas
  bool allow_overlaps = false;   // global_injectivity(false)
  bool world_units = false;
  int texture_size = 1024;
  double padding = 2.;           // texels
  double box_aspect_ratio = 1.;  // width / height of the bounding box
  double box_stiffness = -1.;    // < 0: gentle (5) for the default square, tight (300) with --box
  bool box_given = false;
  double box_distortion_budget = SMP::gentle_bounding_box_distortion_budget;
  bool quiet = false;
};

const char* const usage_text =
  "usage: uv_unwrap [INPUT] [options]\n"
  "\n"
  "Cuts a mesh (OBJ, OFF, PLY or STL) along seams chosen jointly with a\n"
  "low-distortion UV map (Ambrosio-Tortorelli method) and writes the result as\n"
  "an OBJ with texture coordinates. Without INPUT, runs on a built-in mesh.\n"
  "Polygons are triangulated and non-manifold input is repaired, with a\n"
  "warning on stderr; unusable input is an error (exit status 1).\n"
  "\n"
  "options:\n"
  "  -o, --output FILE       output OBJ (default: <input name>_uv.obj in the current directory)\n"
  "  --stats FILE            write statistics as JSON\n"
  "  --lambda X              seam cost, relative to the mean edge length (default 1)\n"
  "  --epsilon-start X       first epsilon, relative to the mean edge length (default 0.1)\n"
  "  --epsilon-end X         epsilon is halved while above this value (default 0.01)\n"
  "  --iterations N          alternations per epsilon (default 3)\n"
  "  --passes N              optimize-and-cut passes (default 1)\n"
  "  --allow-overlaps        let a chart overlap itself (no scaffold; charts still packed apart)\n"
  "  --world-units           keep UVs in 3D units (charts still packed) instead of [0,1]\n"
  "  --texture-size N        texture width and height in texels, unit of --padding (default 1024)\n"
  "  --padding TEXELS        gap between charts and to the square's sides, >= 0 (default 2)\n"
  "  --box W:H               pull each chart tightly into a W:H rectangle (e.g. 2:1); without\n"
  "                          it, a gentle pull into a square rounds charts off\n"
  "  --box-stiffness S       how hard the box pulls, >= 0 (default 5, or 300 with --box);\n"
  "                          given, the box is kept whatever it costs (the default box is\n"
  "                          weakened, then dropped, where it raises E_d by more than 0.045)\n"
  "  --no-box                no bounding box at all (same as --box-stiffness 0)\n"
  "  --svg FILE              write the UV layout, colored by distortion, as SVG\n"
  "  --png FILE              write a checkerboard-textured render of the mesh as PNG\n"
  "  --up AXIS               up axis of the mesh for --png: x, y, z, -z, ... (default y)\n"
  "  --v-field FILE.ply      write the discontinuity field v as a colored PLY\n"
  "  -q, --quiet             print nothing but warnings and errors\n"
  "  -h, --help              show this help\n";

double parse_number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0.;
  try { value = std::stod(text, &used); } catch(const std::exception&) { used = 0; }
  if(used == 0 || used != text.size() || !std::isfinite(value))
    throw Failure("invalid value '" + text + "' for " + option + " (expected a number)");
  return value;
}

int parse_count(const std::string& option, const std::string& text)
{
  const double value = parse_number(option, text);
  if(value != std::floor(value) || value < 1. || value > 1e6)
    throw Failure("invalid value '" + text + "' for " + option + " (expected a positive integer)");
  return int(value);
}

// "W:H", both positive numbers: the aspect ratio W / H.
double parse_aspect_ratio(const std::string& option, const std::string& text)
{
  const std::size_t colon = text.find(':');
  const std::string expected = " (expected W:H, two positive numbers, e.g. 2:1)";
  if(colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
    throw Failure("invalid value '" + text + "' for " + option + expected);
  double w = 0., h = 0.;
  try
  {
    w = parse_number(option, text.substr(0, colon));
    h = parse_number(option, text.substr(colon + 1));
  }
  catch(const Failure&)
  {
    throw Failure("invalid value '" + text + "' for " + option + expected);
  }
  if(!(w > 0.) || !(h > 0.) || !std::isfinite(w / h) || !(w / h > 0.))
    throw Failure("invalid value '" + text + "' for " + option + expected);
  return w / h;
}

// Returns false when the program should stop successfully (--help).
bool parse_arguments(int argc, char** argv, Options& options)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    std::string arg = args[i], value;
    bool has_inline_value = false;
    // Accept both "--name value" and "--name=value".
    if(arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos)
    {
      value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      has_inline_value = true;
    }
    auto next_value = [&]() -> std::string {
      if(has_inline_value) return value;
      if(i + 1 >= args.size()) throw Failure("option " + arg + " needs a value");
      return args[++i];
    };

    if(arg == "-h" || arg == "--help") { std::cout << usage_text; return false; }
    else if(arg == "-q" || arg == "--quiet") options.quiet = true;
    else if(arg == "-o" || arg == "--output") options.output = next_value();
    else if(arg == "--stats") options.stats = next_value();
    else if(arg == "--lambda") options.lambda = parse_number(arg, next_value());
    else if(arg == "--epsilon-start") options.epsilon_start = parse_number(arg, next_value());
    else if(arg == "--epsilon-end") options.epsilon_end = parse_number(arg, next_value());
    else if(arg == "--iterations") options.iterations = parse_count(arg, next_value());
    else if(arg == "--passes") options.passes = parse_count(arg, next_value());
    else if(arg == "--allow-overlaps") options.allow_overlaps = true;
    else if(arg == "--world-units") options.world_units = true;
    else if(arg == "--texture-size") options.texture_size = parse_count(arg, next_value());
    else if(arg == "--padding")
    {
      const std::string text = next_value();
      options.padding = parse_number(arg, text);
      if(!(options.padding >= 0.))
        throw Failure("invalid value '" + text + "' for --padding (expected a number >= 0, in texels)");
    }
    else if(arg == "--box")
    {
      options.box_aspect_ratio = parse_aspect_ratio(arg, next_value());
      options.box_given = true;
    }
    else if(arg == "--box-stiffness")
    {
      const std::string text = next_value();
      options.box_stiffness = parse_number(arg, text);
      if(!(options.box_stiffness >= 0.) || !std::isfinite(options.box_stiffness))
        throw Failure("invalid value '" + text + "' for --box-stiffness (expected a number >= 0)");
    }
    else if(arg == "--no-box") options.box_stiffness = 0.;
    else if(arg == "--svg") options.svg = next_value();
    else if(arg == "--png") options.png = next_value();
    else if(arg == "--up")
    {
      const std::string axis = next_value();
      if(!preview_camera_for_up_axis(axis, options.camera))
        throw Failure("invalid value '" + axis + "' for --up (expected x, y, z, -x, -y or -z)");
    }
    else if(arg == "--v-field") options.v_field = next_value();
    else if(arg.size() > 1 && arg[0] == '-')
      throw Failure("unknown option '" + arg + "' (see --help)");
    else if(!options.input.empty())
      throw Failure("more than one input file given ('" + options.input + "' and '" + arg + "')");
    else
      options.input = arg;
  }
  // as in the library: a box asked for is kept whatever it costs, the default one within a budget
  if(options.box_given || options.box_stiffness >= 0.)
    options.box_distortion_budget = std::numeric_limits<double>::infinity();
  if(options.box_stiffness < 0.)
    options.box_stiffness = options.box_given ? SMP::tight_bounding_box_stiffness
                                              : SMP::gentle_bounding_box_stiffness;
  if(!(options.lambda > 0.)) throw Failure("--lambda must be positive");
  if(!(options.epsilon_start > 0.) || !(options.epsilon_end > 0.))
    throw Failure("--epsilon-start and --epsilon-end must be positive");
  if(options.epsilon_end > options.epsilon_start)
    throw Failure("--epsilon-end must not exceed --epsilon-start");
  return true;
}

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
void read_mesh(const std::string& filename, Mesh& mesh, std::vector<std::string>& warnings)
{
  mesh_input::Input_report report;
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
    std::cerr << "uv_unwrap: warning: " << w << std::endl;
    warnings.push_back(w);
  }
}

// ---------------------------------------------------------------- output

using cut_tools::json_number;
using cut_tools::json_string;

struct Run_summary
{
  std::string input;
  std::string status = "ok";          // "ok", ERROR_USAGE, an input error or a library error name
  std::string error;                  // one-line message when status is not "ok"
  std::vector<std::string> warnings;  // input repairs and remarks
  std::size_t vertices = 0, faces = 0, flipped_faces = 0;
  std::size_t border_crossings = 0;   // recounted on the output
  bool uv_in_unit_square = false;     // every corner UV of the output in [0,1]²
  SMP::Cut_and_parameterize_result result;
  double time_seconds = 0.;
};

void write_stats(const std::string& filename, const Run_summary& s)
{
  const SMP::Cut_and_parameterize_timings& t = s.result.timings;
  std::ofstream out(filename);
  out << "{\n"
      << "  \"input\": " << json_string(s.input) << ",\n"
      << "  \"status\": " << json_string(s.status) << ",\n"
      << "  \"error\": " << (s.status == "ok" ? std::string("null") : json_string(s.error)) << ",\n"
      << "  \"warnings\": [";
  for(std::size_t i = 0; i < s.warnings.size(); ++i)
    out << (i ? ",\n    " : "\n    ") << json_string(s.warnings[i]);
  out << (s.warnings.empty() ? "" : "\n  ") << "],\n"
      << "  \"vertices\": " << s.vertices << ",\n"
      << "  \"faces\": " << s.faces << ",\n"
      << "  \"degenerate_faces\": " << s.result.number_of_degenerate_faces << ",\n"
      << "  \"charts\": " << s.result.number_of_charts << ",\n"
      << "  \"seam_edges\": " << s.result.number_of_seam_edges << ",\n"
      << "  \"seam_length\": " << json_number(s.result.seam_length) << ",\n"
      << "  \"distortion\": " << json_number(s.result.distortion) << ",\n"
      << "  \"initial_distortion\": " << json_number(s.result.initial_distortion) << ",\n"
      << "  \"flipped_faces\": " << s.flipped_faces << ",\n"
      << "  \"border_crossings\": " << s.border_crossings << ",\n"
      << "  \"uv_coverage\": " << json_number(s.result.uv_coverage) << ",\n"
      << "  \"uv_scale\": " << json_number(s.result.uv_scale) << ",\n"
      << "  \"uv_in_unit_square\": " << (s.uv_in_unit_square ? "true" : "false") << ",\n"
      << "  \"time_seconds\": " << json_number(s.time_seconds) << ",\n"
      << "  \"newton_iterations\": " << s.result.newton_iterations << ",\n"
      << "  \"factorizations\": " << s.result.number_of_factorizations << ",\n"
      << "  \"timings\": {\"initialization\": " << json_number(t.initialization)
      << ", \"u_steps\": " << json_number(t.u_steps) << ", \"v_steps\": " << json_number(t.v_steps)
      << ", \"cut_extraction\": " << json_number(t.cut_extraction)
      << ", \"final_solve\": " << json_number(t.final_solve) << ", \"packing\": " << json_number(t.packing)
      << ", \"total\": " << json_number(t.total) << "}\n"
      << "}\n";
  out.close();
  if(!out) throw Failure("cannot write '" + filename + "'", "ERROR_CANNOT_WRITE");
}

template <typename SeamMap, typename UVMap, typename VMap>
void write_pictures(const Options& options, const Mesh& mesh, const SeamMap& seams, const UVMap& uvmap,
                    const VMap& v, const Run_summary& summary, const std::string& name)
{
  if(options.svg.empty() && options.png.empty() && options.v_field.empty()) return;

  // The preview library takes plain arrays; a freshly read Surface_mesh has
  // contiguous indices.
  Preview_mesh preview;
  for(auto vd : vertices(mesh))
  {
    const Point_3& p = mesh.point(vd);
    preview.points.push_back({p.x(), p.y(), p.z()});
  }
  for(auto f : faces(mesh))
  {
    std::array<int, 3> corners;
    std::array<std::array<double, 2>, 3> uvs;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      corners[k] = int(target(h, mesh).idx());
      uvs[k] = {uvmap[h].x(), uvmap[h].y()};
      ++k;
    }
    preview.faces.push_back(corners);
    preview.corner_uv.push_back(uvs);
    preview.face_distortion.push_back(
      SMP::face_distortion(f, mesh, uvmap, SMP::parameters::uv_scale(summary.result.uv_scale)));
    preview.face_v.push_back(v[f]);
  }
  for(auto e : edges(mesh))
    if(seams[e])
      preview.seam_edges.emplace_back(int(source(e, mesh).idx()), int(target(e, mesh).idx()));

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
}

// ---------------------------------------------------------------- run

void run(const char* argv0, Options& options, Run_summary& summary)
{
  Mesh mesh;
  std::string stem;
  if(!options.input.empty())
  {
    summary.input = options.input;
    read_mesh(options.input, mesh, summary.warnings);
    stem = fs::path(options.input).stem().string();
  }
  else if(std::string data_mesh = find_default_mesh(argv0); !data_mesh.empty())
  {
    summary.input = data_mesh;
    read_mesh(data_mesh, mesh, summary.warnings);
    stem = fs::path(data_mesh).stem().string();
  }
  else
  {
    make_spherical_cap(mesh);
    summary.input = "built-in spherical cap";
    stem = "spherical_cap";
  }
  if(options.output.empty()) options.output = stem + "_uv.obj";
  summary.vertices = num_vertices(mesh);
  summary.faces = num_faces(mesh);
  if(!options.quiet)
    std::cout << "uv_unwrap: " << summary.input << ": " << summary.vertices << " vertices, "
              << summary.faces << " faces" << std::endl;

  auto seams = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  auto uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  auto v_field = mesh.add_property_map<face_descriptor, double>("f:v", 1.).first;

  // Progress goes to stderr so that stdout keeps the summary only.
  std::function<bool(const SMP::Cut_and_parameterize_progress&)> progress =
    [](const SMP::Cut_and_parameterize_progress& p) {
      const std::string phase = p.phase;
      std::cerr << "  " << phase << ":";
      if(phase == "alternate" || phase == "cut") std::cerr << " pass " << p.pass + 1 << ",";
      if(phase == "alternate")
        std::cerr << " alternation " << p.alternation << "/" << p.alternations_per_pass
                  << ", epsilon " << p.epsilon << ",";
      std::cerr << " E_d " << p.distortion << std::endl;
      return true;
    };

  namespace P = SMP::parameters;
  const auto np = P::lambda(options.lambda,
                  P::epsilon_start(options.epsilon_start,
                  P::epsilon_end(options.epsilon_end,
                  P::iterations_per_epsilon(options.iterations,
                  P::number_of_passes(options.passes,
                  P::global_injectivity(!options.allow_overlaps,
                  P::world_units(options.world_units,
                  P::texture_size(options.texture_size,
                  P::padding(options.padding,
                  P::bounding_box_aspect_ratio(options.box_aspect_ratio,
                  P::bounding_box_stiffness(options.box_stiffness,
                  P::bounding_box_distortion_budget(options.box_distortion_budget,
                  P::face_discontinuity_map(v_field,
                  P::progress_callback(options.quiet ? decltype(progress)() : progress))))))))))))));

  const auto start = std::chrono::steady_clock::now();
  summary.result = SMP::cut_and_parameterize(mesh, seams, uvmap, np);
  summary.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(!summary.result.ok())
    throw Failure(std::string("unwrapping failed: ") + SMP::error_message(summary.result.error) + " (" +
                  SMP::error_name(summary.result.error) + ")", SMP::error_name(summary.result.error));
  summary.flipped_faces = SMP::number_of_flipped_faces(mesh, uvmap);
  summary.border_crossings = SMP::number_of_border_crossings(mesh, uvmap);
  summary.uv_in_unit_square = true;
  for(face_descriptor f : faces(mesh))
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const Point_2& uv = uvmap[h];
      if(!(uv.x() >= 0. && uv.x() <= 1. && uv.y() >= 0. && uv.y() <= 1.)) summary.uv_in_unit_square = false;
    }

  // Isolated vertices are written as plain `v` lines that no face uses (the
  // writer numbers every vertex), so indices and positions stay those of the
  // input.
  if(!SMP::write_OBJ_with_uvs(options.output, mesh, uvmap))
    throw Failure("cannot write '" + options.output + "'", "ERROR_CANNOT_WRITE");
  write_pictures(options, mesh, seams, uvmap, v_field, summary, stem);

  if(!options.quiet)
  {
    const auto& r = summary.result;
    std::cout << "  charts " << r.number_of_charts << ", seam edges " << r.number_of_seam_edges
              << ", seam length E_s " << r.seam_length << "\n"
              << "  distortion E_d " << r.distortion << " (initial " << r.initial_distortion
              << "), flipped faces " << summary.flipped_faces << "\n"
              << "  UV coverage " << 100. * r.uv_coverage << " %, border crossings " << summary.border_crossings
              << ", UVs " << (summary.uv_in_unit_square ? "in" : "not in") << " the unit square\n"
              << "  " << summary.time_seconds << " s, " << r.newton_iterations << " Newton iterations\n"
              << "  wrote " << options.output;
    for(const std::string* file : {&options.stats, &options.svg, &options.png, &options.v_field})
      if(!file->empty()) std::cout << ", " << *file;
    std::cout << std::endl;
  }
}

} // namespace

int main(int argc, char** argv)
{
  cut_tools::use_one_blas_thread(); // see blas_threads.h
  Options options;
  try
  {
    if(!parse_arguments(argc, argv, options)) return EXIT_SUCCESS;
  }
  catch(const Failure& e)
  {
    std::cerr << "uv_unwrap: error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  // Every failure from here on is one line on stderr, exit status 1, and
  // the statistics (when asked for) with its status and message.
  Run_summary summary;
  try
  {
    run(argv[0], options, summary);
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
  if(!options.stats.empty())
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
  if(summary.status == "ok") return EXIT_SUCCESS;
  std::cerr << "uv_unwrap: error: " << summary.error << std::endl;
  return EXIT_FAILURE;
}
