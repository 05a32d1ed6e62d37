// check_all_meshes: runs uv_unwrap on every mesh file of some directories
// (CGAL's data set, the shared benchmark meshes) and checks that each run
// ends with a result, or with the documented error of an input that does
// not load (or of seams forbidden by the options): never a crash, a hang, a
// NaN, a flipped face, an overlap or a UV outside the unit square.
//
//   check_all_meshes --uv-unwrap PATH [options] DIR_OR_FILE... [-- UV_UNWRAP_OPTIONS...]
//
// Per mesh, each step in a child process with a time limit, so that a crash
// or a hang is reported instead of stopping the run:
//   1. probe (fork): the input path of uv_unwrap (tools/mesh_input.h) gives
//      the face count, or the input error uv_unwrap must report;
//   2. uv_unwrap (fork + exec) with -o OBJ --stats JSON;
//   3. verify (fork): re-reads the input through the same path and the OBJ:
//      same vertices (positions bit for bit) and faces (count, order,
//      corners), finite `vt`, positive signed UV area for every face, every
//      `vt` in [0,1]² (not with --world-units among the uv_unwrap options);
//   4. overlaps: "border_crossings" and "overlap_area" of the statistics
//      (measured by uv_unwrap on its output) must be 0 (not with
//      --allow-overlaps);
//   5. determinism: meshes up to --repeat-faces faces are unwrapped a second
//      time, and both OBJ files must be identical byte for byte.
// Prints one table row per mesh and a summary; exits with 1 if any mesh
// crashed, hung, produced a NaN, a flipped face (FLIP), crossing UV borders
// (OVERLAP) or a UV outside [0,1] (RANGE), or otherwise broke the contract
// (undocumented error, inconsistent output), 0 otherwise.
#include "child_process.h"
#include "mesh_input.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sys/types.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
namespace SMP = CGAL::Surface_mesh_parameterization;
using Clock = std::chrono::steady_clock;

struct Options
{
  std::string uv_unwrap;
  std::vector<std::string> inputs;
  std::vector<std::string> uv_unwrap_args;
  std::size_t max_faces = 0;      // 0: no limit
  std::size_t repeat_faces = 20000;
  double timeout = 300.;
  std::string work_dir;
  std::size_t shard = 0, shards = 1; // this run checks the meshes i with i % shards == shard
};

const char* const description =
  "Runs uv_unwrap on every .off, .obj, .ply and .stl file (directories are\n"
  "searched recursively) and checks each result: the documented error of an\n"
  "input that does not load (or of seams the options forbid), else a\n"
  "valid UV map (finite, flip-free, same vertices and faces as the input) that\n"
  "is a texture atlas: no crossing UV borders and no UV area covered twice\n"
  "(\"border_crossings\" and \"overlap_area\": 0 in the statistics; not\n"
  "checked with --allow-overlaps after --) and every UV in [0,1] (not\n"
  "checked with --world-units after --).\n"
  "Exits with 1 on any crash, hang, NaN, flipped face, overlap, UV outside\n"
  "[0,1] or broken contract. Arguments after -- are passed to uv_unwrap.";

// ---------------------------------------------------------------- children

using cut_tools::Child_result;
using cut_tools::run_forked;
using cut_tools::run_program;

std::string describe(const Child_result& r)
{
  switch(r.kind)
  {
    case Child_result::SIGNALED: return std::string("signal ") + std::to_string(r.code) + " (" + strsignal(r.code) + ")";
    case Child_result::TIMED_OUT: return "no result after " + std::to_string(int(r.seconds)) + " s";
    case Child_result::NOT_STARTED: return "could not start a process";
    default: return "exit status " + std::to_string(r.code);
  }
}

// ---------------------------------------------------------------- files

std::string read_file(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

bool is_mesh_file(const fs::path& p)
{
  std::string ext = p.extension().string();
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

// ---------------------------------------------------------------- checks

// Statuses uv_unwrap may end with on purpose: the input path's and the library's.
bool is_documented_status(const std::string& status)
{
  const auto& input = mesh_input::input_error_statuses();
  if(std::find(input.begin(), input.end(), status) != input.end()) return true;
  for(int code = 0; code <= int(SMP::ERROR_CANCELED); ++code)
    if(status == SMP::error_name(SMP::Error_code(code)) && status != "ok" && status != "ERROR_CANCELED")
      return true;
  return false;
}

// Probe: the input path alone. "OK faces vertices" or "ERR status message".
std::string probe(const std::string& file)
{
  mesh_input::Mesh mesh;
  mesh_input::Input_report report;
  try
  {
    mesh_input::read_input_mesh(file, mesh, report);
  }
  catch(const mesh_input::Input_error& e)
  {
    return "ERR " + e.status + " " + e.what();
  }
  return "OK " + std::to_string(num_faces(mesh)) + " " + std::to_string(num_vertices(mesh));
}

// Verify: the OBJ against the mesh the input path gives. "OK" or "FAIL kind: reason"
// with kind NAN, FLIP, RANGE (a vt outside [0,1]², checked if `unit_square`) or OUTPUT.
std::string verify(const std::string& input, const std::string& obj_file, bool unit_square)
{
  mesh_input::Mesh mesh;
  mesh_input::Input_report report;
  mesh_input::read_input_mesh(input, mesh, report);

  std::ifstream in(obj_file);
  if(!in) return "FAIL OUTPUT: no OBJ written";
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<double, 2>> vt;
  std::vector<std::vector<std::pair<long, long>>> f;
  std::string line, word;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    if(!(s >> word)) continue;
    if(word == "v")
    {
      std::array<double, 3> p{};
      std::string x, y, z;
      if(!(s >> x >> y >> z)) return "FAIL OUTPUT: bad v line '" + line + "'";
      p = {std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr), std::strtod(z.c_str(), nullptr)};
      v.push_back(p);
    }
    else if(word == "vt")
    {
      std::string a, b;
      if(!(s >> a >> b)) return "FAIL OUTPUT: bad vt line '" + line + "'";
      vt.push_back({std::strtod(a.c_str(), nullptr), std::strtod(b.c_str(), nullptr)});
    }
    else if(word == "f")
    {
      std::vector<std::pair<long, long>> corners;
      while(s >> word)
      {
        const std::size_t slash = word.find('/');
        if(slash == std::string::npos) return "FAIL OUTPUT: face corner without vt: '" + line + "'";
        corners.emplace_back(std::atol(word.c_str()), std::atol(word.c_str() + slash + 1));
      }
      f.push_back(corners);
    }
  }

  if(v.size() != num_vertices(mesh))
    return "FAIL OUTPUT: " + std::to_string(v.size()) + " vertices written, input has " +
           std::to_string(num_vertices(mesh));
  if(f.size() != num_faces(mesh))
    return "FAIL OUTPUT: " + std::to_string(f.size()) + " faces written, input has " +
           std::to_string(num_faces(mesh));
  std::size_t i = 0;
  for(auto vd : vertices(mesh))
  {
    const auto& p = mesh.point(vd);
    if(v[i][0] != p.x() || v[i][1] != p.y() || v[i][2] != p.z())
      return "FAIL OUTPUT: vertex " + std::to_string(i) + " moved";
    ++i;
  }
  std::size_t nan_vt = 0;
  for(const auto& t : vt)
    if(!std::isfinite(t[0]) || !std::isfinite(t[1])) ++nan_vt;
  if(nan_vt > 0) return "FAIL NAN: " + std::to_string(nan_vt) + " non-finite vt";
  if(unit_square)
  {
    // exact: the OBJ's decimal digits cannot round a value of [0,1] out of it
    std::size_t outside = 0, first_outside = 0;
    for(std::size_t t = 0; t < vt.size(); ++t)
      if(!(vt[t][0] >= 0. && vt[t][0] <= 1. && vt[t][1] >= 0. && vt[t][1] <= 1.) && outside++ == 0)
        first_outside = t;
    if(outside > 0)
    {
      std::ostringstream why;
      why << "FAIL RANGE: " << outside << " vt outside [0,1] (first: vt " << first_outside + 1 << " = "
          << vt[first_outside][0] << " " << vt[first_outside][1] << ")";
      return why.str();
    }
  }

  // The faces in the order uv_unwrap writes them: the mesh's, except for an
  // OBJ read without repair, whose output keeps the file's face order (the
  // triangles of a polygon in its place; tools/mesh_output.h).
  std::vector<mesh_input::Mesh::Face_index> order(faces(mesh).begin(), faces(mesh).end());
  if(mesh_input::lower_extension(input) == "obj" && !report.face_origin.empty())
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
      return report.face_origin[std::size_t(a)] < report.face_origin[std::size_t(b)];
    });
  std::size_t k = 0, flipped = 0, first_flipped = 0;
  for(auto fd : order)
  {
    const auto& corners = f[k];
    if(corners.size() != 3) return "FAIL OUTPUT: face " + std::to_string(k) + " is not a triangle";
    auto h = mesh.halfedge(fd);
    std::array<std::array<double, 2>, 3> uv;
    for(int c = 0; c < 3; ++c, h = mesh.next(h))
    {
      if(corners[c].first != long(mesh.target(h).idx()) + 1)
        return "FAIL OUTPUT: face " + std::to_string(k) + " differs from the input's";
      if(corners[c].second < 1 || std::size_t(corners[c].second) > vt.size())
        return "FAIL OUTPUT: face " + std::to_string(k) + " has an invalid vt index";
      uv[c] = vt[std::size_t(corners[c].second) - 1];
    }
    // the library's test of a flip, on the corners in the same order
    const double area2 = (uv[1][0] - uv[0][0]) * (uv[2][1] - uv[0][1]) - (uv[1][1] - uv[0][1]) * (uv[2][0] - uv[0][0]);
    if(!(area2 > 0.) && flipped++ == 0) first_flipped = k;
    ++k;
  }
  if(flipped > 0)
    return "FAIL FLIP: " + std::to_string(flipped) + " UV faces with non-positive area (first: face " +
           std::to_string(first_flipped) + ")";
  return "OK";
}

// ---------------------------------------------------------------- table

struct Row
{
  std::string mesh, faces = "-", status, time = "-", distortion = "-", seam = "-", charts = "-", warnings = "-";
};

std::string fixed(double number, int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << number;
  return out.str();
}

// A number of uv_unwrap's statistics: "-" if absent, "null" if null.
std::string fixed(const nlohmann::json& stats, const char* key, int digits)
{
  if(!stats.contains(key)) return "-";
  const nlohmann::json& value = stats[key];
  return value.is_number() ? fixed(value.get<double>(), digits) : std::string("null");
}

// The statistics uv_unwrap wrote (an empty object if none or unreadable).
nlohmann::json read_statistics(const std::string& filename)
{
  std::ifstream in(filename);
  nlohmann::json stats = nlohmann::json::parse(in, nullptr, false);
  return stats.is_object() ? stats : nlohmann::json::object();
}

void print_row(const Row& r)
{
  std::cout << std::left << std::setw(34) << r.mesh.substr(0, 33) << std::right << std::setw(8) << r.faces
            << std::setw(8) << r.time << std::setw(9) << r.distortion << std::setw(8) << r.seam
            << std::setw(7) << r.charts << std::setw(5) << r.warnings << "  " << r.status << std::endl;
}

bool parse_arguments(int argc, char** argv, Options& options)
{
  // everything after "--" belongs to uv_unwrap
  int own = argc;
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "--") { own = i; break; }
  if(own < argc) options.uv_unwrap_args.assign(argv + own + 1, argv + argc);

  CLI::App app(description, "check_all_meshes");
  app.add_option("--uv-unwrap", options.uv_unwrap, "the uv_unwrap executable")->type_name("PATH")->required();
  app.add_option("--max-faces", options.max_faces, "skip meshes with more than N faces (default 0: no limit)")
    ->type_name("N");
  app.add_option("--timeout", options.timeout, "time limit per run of uv_unwrap, in seconds (default 300)")
    ->type_name("S")->check(CLI::PositiveNumber);
  app.add_option("--repeat-faces", options.repeat_faces,
                 "unwrap meshes with at most N faces twice and compare the\n"
                 "outputs byte for byte (default 20000; 0: never)")->type_name("N");
  app.add_option("--work-dir", options.work_dir, "scratch directory (default: a new one in the temp directory)")
    ->type_name("DIR");
  app.add_option_function<std::string>("--shard",
      [&options](const std::string& v) {
        const std::size_t slash = v.find('/');
        options.shard = std::stoul(v.substr(0, slash));
        options.shards = std::stoul(v.substr(slash + 1));
      },
      "check only the meshes K, K+N, K+2N, ... (0 <= K < N) of the\n"
      "sorted list, so that N runs share the work (default 0/1)")
    ->type_name("K/N")
    ->check(CLI::Validator(
        [](std::string& v) -> std::string {
          const std::size_t slash = v.find('/');
          const bool digits = slash != std::string::npos && slash > 0 && slash + 1 < v.size() &&
                              v.find_first_not_of("0123456789/") == std::string::npos &&
                              v.find('/', slash + 1) == std::string::npos && v.size() < 16;
          if(!digits || std::stoul(v.substr(slash + 1)) < 1 ||
             std::stoul(v.substr(0, slash)) >= std::stoul(v.substr(slash + 1)))
            return "invalid value '" + v + "' (expected K/N with 0 <= K < N)";
          return {};
        },
        ""));
  app.add_option("INPUT", options.inputs, "mesh files and directories")->type_name("DIR_OR_FILE")->required();
  try
  {
    app.parse(own, argv);
  }
  catch(const CLI::CallForHelp& e)
  {
    app.exit(e);
    return false;
  }
  catch(const CLI::ParseError& e)
  {
    throw std::runtime_error(e.what());
  }
  return true;
}

int run(const Options& options)
{
  std::vector<std::pair<std::string, fs::path>> meshes; // (name shown, path)
  for(const std::string& input : options.inputs)
  {
    const fs::path root(input);
    if(fs::is_directory(root))
    {
      std::vector<fs::path> found;
      for(const auto& entry : fs::recursive_directory_iterator(root))
        if(entry.is_regular_file() && is_mesh_file(entry.path())) found.push_back(entry.path());
      std::sort(found.begin(), found.end());
      for(const fs::path& p : found)
        meshes.emplace_back((root.filename().empty() ? root.parent_path().filename() : root.filename()).string() +
                              "/" + fs::relative(p, root).string(), p);
    }
    else if(fs::is_regular_file(root))
      meshes.emplace_back(root.filename().string(), root);
    else
      throw std::runtime_error("no such file or directory: " + input);
  }
  if(options.shards > 1)
  {
    std::vector<std::pair<std::string, fs::path>> mine;
    for(std::size_t i = options.shard; i < meshes.size(); i += options.shards) mine.push_back(meshes[i]);
    meshes.swap(mine);
  }

  fs::path work = options.work_dir.empty()
                    ? fs::temp_directory_path() / ("check_all_meshes_" + std::to_string(getpid()))
                    : fs::path(options.work_dir);
  fs::create_directories(work);
  const std::string obj = (work / "out.obj").string(), obj2 = (work / "out2.obj").string(),
                    json = (work / "out.json").string(), log = (work / "log.txt").string();
  const std::string exe = fs::absolute(options.uv_unwrap).string();
  if(access(exe.c_str(), X_OK) != 0) throw std::runtime_error("cannot execute " + exe);
  // the atlas contracts, unless uv_unwrap is told to waive them
  auto passes_option = [&](const char* option) {
    return std::find(options.uv_unwrap_args.begin(), options.uv_unwrap_args.end(), option) !=
           options.uv_unwrap_args.end();
  };
  const bool check_overlaps = !passes_option("--allow-overlaps");
  const bool check_unit_square = !passes_option("--world-units");

  std::cout << "check_all_meshes: " << meshes.size() << " mesh files"
            << (options.shards > 1 ? " (shard " + std::to_string(options.shard) + "/" + std::to_string(options.shards) + ")"
                                   : std::string())
            << "; time limit " << options.timeout
            << " s per run; "
            << (options.max_faces ? "skipping meshes above " + std::to_string(options.max_faces) + " faces"
                                  : std::string("no face limit"))
            << "; determinism checked up to " << options.repeat_faces << " faces"
            << "; overlaps " << (check_overlaps ? "checked" : "not checked (--allow-overlaps)")
            << "; UVs in [0,1] " << (check_unit_square ? "checked" : "not checked (--world-units)") << "\n\n";
  Row header{"mesh", "faces", "status", "time", "E_d", "E_s", "charts", "warn"};
  print_row(header);
  std::cout << std::string(100, '-') << std::endl;

  std::map<std::string, int> counts;         // ok, skipped, rejected: X, crash, hang, nan, flip, fail
  std::vector<std::string> problems;         // failing meshes with the reason
  double total_time = 0.;
  int deterministic = 0;                     // ok meshes unwrapped twice, identical outputs
  const auto started = Clock::now();

  for(const auto& [name, path] : meshes)
  {
    Row row;
    row.mesh = name;
    const std::string file = path.string();
    auto problem = [&](const std::string& kind, const std::string& why) {
      ++counts[kind];
      row.status = kind + ": " + why;
      problems.push_back(name + ": " + row.status);
    };

    // 1. probe
    const Child_result p = run_forked([&] { return probe(file); }, options.timeout);
    std::string probe_status;
    if(p.kind != Child_result::EXITED || p.code != 0)
    {
      problem(p.kind == Child_result::TIMED_OUT ? "HANG" : "CRASH", "reading the input: " + describe(p));
      print_row(row);
      continue;
    }
    std::istringstream ps(p.output);
    std::string head;
    ps >> head;
    std::size_t faces = 0;
    if(head == "OK")
    {
      ps >> faces;
      row.faces = std::to_string(faces);
      if(options.max_faces > 0 && faces > options.max_faces)
      {
        ++counts["skipped"];
        row.status = "skipped (more than " + std::to_string(options.max_faces) + " faces)";
        print_row(row);
        continue;
      }
    }
    else
      ps >> probe_status;

    // 2. uv_unwrap
    std::error_code ec;
    fs::remove(obj, ec);
    fs::remove(json, ec);
    std::vector<std::string> args = {exe, file, "-q", "-o", obj, "--stats", json};
    args.insert(args.end(), options.uv_unwrap_args.begin(), options.uv_unwrap_args.end());
    const Child_result u = run_program(args, log, options.timeout);
    row.time = fixed(u.seconds, 1);
    total_time += u.seconds;
    const nlohmann::json stats = read_statistics(json);
    const std::string status = stats.value("status", std::string());
    if(status == "ok")
    {
      row.distortion = fixed(stats, "distortion", 3);
      row.seam = fixed(stats, "seam_length", 2);
      row.charts = stats.contains("charts") ? stats["charts"].dump() : "-";
      row.warnings = stats.contains("warnings") ? std::to_string(stats["warnings"].size()) : "-";
    }
    std::string last_line = read_file(log);
    while(!last_line.empty() && last_line.back() == '\n') last_line.pop_back();
    last_line = last_line.substr(last_line.rfind('\n') == std::string::npos ? 0 : last_line.rfind('\n') + 1);

    if(u.kind == Child_result::TIMED_OUT) { problem("HANG", "uv_unwrap: " + describe(u)); print_row(row); continue; }
    if(u.kind == Child_result::SIGNALED) { problem("CRASH", "uv_unwrap: " + describe(u)); print_row(row); continue; }
    if(u.kind != Child_result::EXITED) { problem("FAIL", describe(u)); print_row(row); continue; }
    if(u.code != 0)
    {
      if(u.code != 1) problem("FAIL", "uv_unwrap: " + describe(u) + ": " + last_line);
      else if(status.empty()) problem("FAIL", "error without statistics: " + last_line);
      else if(!is_documented_status(status)) problem("FAIL", "undocumented status " + status + ": " + last_line);
      else if(!probe_status.empty() && status != probe_status)
        problem("FAIL", "uv_unwrap says " + status + ", the input path " + probe_status);
      // an input that loads has a UV map: the method's errors are failures
      // (CGAL's boeing.off failed with ERROR_CANNOT_SOLVE_LINEAR_SYSTEM and
      // was counted as rejected), but for seams forbidden by the options
      else if(probe_status.empty() && status != "ERROR_FORBIDDEN_EDGES_BLOCK_CUT")
        problem("FAIL", "an input that loads failed to unwrap: " + status + ": " + last_line);
      else
      {
        ++counts["rejected: " + status];
        // the message without its "uv_unwrap: error: " prefix and file name
        std::string why = last_line.substr(std::min(last_line.size(), std::string("uv_unwrap: error: ").size()));
        const std::size_t quote = why.find(file + "'");
        if(quote != std::string::npos) why = why.substr(quote + file.size() + 1);
        while(!why.empty() && (why[0] == ':' || why[0] == ' ')) why.erase(0, 1);
        row.status = "rejected: " + status + " (" + why.substr(0, 70) + ")";
      }
      print_row(row);
      continue;
    }
    if(!probe_status.empty()) { problem("FAIL", "uv_unwrap accepted an input the probe rejects (" + probe_status + ")"); print_row(row); continue; }
    if(status != "ok") { problem("FAIL", "exit status 0 with status '" + status + "'"); print_row(row); continue; }

    // 3. verify
    const Child_result v = run_forked([&] { return verify(file, obj, check_unit_square); }, options.timeout);
    if(v.kind != Child_result::EXITED || v.code != 0)
    {
      problem(v.kind == Child_result::TIMED_OUT ? "HANG" : "CRASH", "verifying: " + describe(v) + " " + v.output);
      print_row(row);
      continue;
    }
    if(v.output.rfind("FAIL ", 0) == 0)
    {
      const std::string rest = v.output.substr(5);
      const std::string kind = rest.substr(0, rest.find(':'));
      problem(kind, rest.substr(rest.find(':') + 2));
      print_row(row);
      continue;
    }

    // 4. overlaps: uv_unwrap's recount on its output
    if(check_overlaps)
    {
      const std::string crossings = stats.contains("border_crossings") ? stats["border_crossings"].dump() : "";
      if(crossings.empty())
      {
        problem("OUTPUT", "no border_crossings in the statistics");
        print_row(row);
        continue;
      }
      if(crossings != "0")
      {
        problem("OVERLAP", crossings + " pairs of UV border segments cross (charts overlap)");
        print_row(row);
        continue;
      }
      // charts stacked or nested cross no border: the covered area counts them
      const nlohmann::json overlap = stats.contains("overlap_area") ? stats["overlap_area"] : nlohmann::json();
      if(!overlap.is_number() || overlap.get<double>() != 0.)
      {
        problem("OVERLAP", "UV area covered more than once: " + overlap.dump());
        print_row(row);
        continue;
      }
    }

    // 5. determinism
    if(faces <= options.repeat_faces)
    {
      std::vector<std::string> again = args;
      again[4] = obj2;
      again[6] = (work / "out2.json").string();
      const Child_result w = run_program(again, log, options.timeout);
      if(w.kind != Child_result::EXITED || w.code != 0)
      {
        problem(w.kind == Child_result::TIMED_OUT ? "HANG" : "FAIL", "second run: " + describe(w));
        print_row(row);
        continue;
      }
      if(read_file(obj) != read_file(obj2))
      {
        problem("FAIL", "two runs wrote different OBJ files (not deterministic)");
        print_row(row);
        continue;
      }
      ++deterministic;
    }
    ++counts["ok"];
    row.status = "ok";
    print_row(row);
  }

  const double wall = std::chrono::duration<double>(Clock::now() - started).count();
  std::cout << std::string(100, '-') << "\n"
            << "summary: " << meshes.size() << " mesh files, " << std::fixed << std::setprecision(0) << wall
            << " s in total (" << total_time << " s in uv_unwrap)\n";
  for(const auto& [kind, n] : counts)
    std::cout << "  " << std::left << std::setw(44) << kind << std::right << std::setw(5) << n << "\n";
  std::cout << "  (" << deterministic << " of the ok meshes unwrapped twice: identical OBJ files)\n";
  if(!problems.empty())
  {
    std::cout << "\nproblems:\n";
    for(const std::string& p : problems) std::cout << "  " << p << "\n";
  }
  std::cout << std::endl;

  std::error_code ignored;
  if(options.work_dir.empty()) fs::remove_all(work, ignored);
  return problems.empty() ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    if(!parse_arguments(argc, argv, options)) return 0;
    return run(options);
  }
  catch(const std::exception& e)
  {
    std::cerr << "check_all_meshes: error: " << e.what() << std::endl;
    return 2;
  }
}
