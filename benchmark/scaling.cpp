#include "scaling.h"

#include "benchmark_mesh.h"
#include "median.h"
#include "midpoint_subdivision.h"
#include "table_output.h"

#include "child_process.h" // tools/

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/config.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

#include <sys/resource.h>

namespace cut_benchmark {

namespace SMP = CGAL::Surface_mesh_parameterization;
using cut_tools::Child_result;
using cut_tools::run_forked;

namespace {

// The maximum resident set size of this process so far, in KiB.
long peak_resident_kib()
{
  rusage usage{};
  if(getrusage(RUSAGE_SELF, &usage) != 0) return -1;
  return usage.ru_maxrss; // KiB on Linux
}

const char* const BASE_MESH = "optcuts/bimba_i_f10000.obj"; // in the mesh folder
const int SUBDIVISIONS = 3;                                 // 1-to-4 rounds: up to 64x its faces
const char* const CGAL_MESH = "meshes/refined_elephant.off"; // in CGAL's data set

struct Scaling_mesh
{
  std::string name;      // as printed
  std::string source;    // where it comes from, as printed (relative to its folder)
  fs::path file;         // what the child reads
  int subdivisions = 0;  // rounds of 1-to-4 midpoint subdivision after reading
  std::size_t faces = 0; // after them
};

/// What a child sends back, as raw bytes through the pipe.
struct Run_measure
{
  bool read = false;      // the mesh was read (and subdivided)
  int error = 0;          // SMP::Error_code of the run
  std::size_t faces = 0;
  SMP::Cut_and_parameterize_timings timings;
  std::size_t newton_iterations = 0, factorizations = 0, charts = 0;
  double distortion = 0., seam_length = 0.;
  long start_kib = 0;     // resident at the child's start (what it shares with the parent)
  long peak_kib = 0;      // maximum resident set size at its end
};
static_assert(std::is_trivially_copyable<Run_measure>::value, "sent as bytes");

struct Scaling_row
{
  Scaling_mesh mesh;
  std::vector<Run_measure> runs; // the runs that finished
  std::string status;            // "ok", an error name, "TIME_LIMIT", "CRASHED", ...
  bool ok = false;
  bool over_limit = false;
  SMP::Cut_and_parameterize_timings time; // medians over `runs`
  double peak_mb = 0., start_mb = 0.;     // medians over `runs`
  std::string note;
};

bool is_file(const fs::path& p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

bool read_mesh(const fs::path& file, Mesh& mesh)
{
  try
  {
    return CGAL::IO::read_polygon_mesh(file.string(), mesh, CGAL::parameters::verbose(false)) &&
           mesh.number_of_faces() > 0;
  }
  catch(const std::exception&)
  {
    return false;
  }
}

} // namespace

/// A file of CGAL's data set: through CGAL_DATA_DIR (CGAL::data_file_path())
/// when it is set, else in the data/ folder that the build extracts next to
/// bin/. Empty if not found.
fs::path cgal_data_file(const std::string& name)
{
  if(const char* dir = std::getenv("CGAL_DATA_DIR"))
    if(*dir)
    {
      const fs::path p = CGAL::data_file_path(name);
      return is_file(p) ? p : fs::path();
    }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec); // Linux
  if(ec) return {};
  const fs::path p = exe.parent_path().parent_path() / "data" / name;
  return is_file(p) ? p : fs::path();
}

namespace {

/// The meshes of the run, smallest first within each source (`elephant`:
/// CGAL's mesh, empty if not found); what cannot be run is reported in `notes`.
std::vector<Scaling_mesh> scaling_meshes(const Options& opt, const fs::path& elephant,
                                         std::vector<std::string>& notes)
{
  std::vector<Scaling_mesh> list;
  const fs::path base = opt.mesh_dir / BASE_MESH;
  Mesh mesh;
  if(!is_file(base))
    notes.push_back(std::string(BASE_MESH) + ": no such file in " + opt.mesh_dir.lexically_normal().string() +
                    " (left out, with its subdivisions)");
  else if(!read_mesh(base, mesh))
    notes.push_back(base.string() + ": cannot read (left out, with its subdivisions)");
  else
  {
    const std::string stem = base.stem().string();
    for(int k = 0; k <= SUBDIVISIONS; ++k)
      list.push_back({k == 0 ? stem : stem + " s" + std::to_string(k), BASE_MESH, base, k,
                      mesh.number_of_faces() << (2 * k)});
  }
  mesh.clear();

  Mesh other;
  if(elephant.empty())
    notes.push_back(std::string(CGAL_MESH) + ": not found in CGAL's data set (set CGAL_DATA_DIR to its data/ "
                    "folder; the build extracts it into <build>/data): left out");
  else if(!read_mesh(elephant, other))
    notes.push_back(elephant.string() + ": cannot read (left out)");
  else
    list.push_back({fs::path(CGAL_MESH).stem().string(), CGAL_MESH, elephant, 0, other.number_of_faces()});
  return list;
}

/// The child's work: reads and subdivides the mesh, runs the method with its
/// default named parameters (but --multiresolution-faces).
std::string measure_run(const Scaling_mesh& m, const Options& opt)
{
  Run_measure out;
  out.start_kib = peak_resident_kib();
  Mesh mesh;
  if(read_mesh(m.file, mesh))
  {
    for(int k = 0; k < m.subdivisions; ++k) mesh = midpoint_subdivision(mesh);
    out.read = true;
    out.faces = mesh.number_of_faces();
    auto seam = mesh.add_property_map<Mesh::Edge_index, bool>("e:benchmark_seam", false).first;
    auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:benchmark_uv").first;
    // the library's defaults but for --multiresolution-faces and --inner-solver (the only method options here)
    const SMP::Cut_and_parameterize_result r =
      SMP::cut_and_parameterize(mesh, seam, uv, SMP::parameters::cut_parameterization_options(opt.method));
    out.error = int(r.error);
    out.timings = r.timings;
    out.newton_iterations = r.newton_iterations;
    out.factorizations = r.number_of_factorizations;
    out.charts = r.number_of_charts;
    out.distortion = r.distortion;
    out.seam_length = r.seam_length;
  }
  out.peak_kib = peak_resident_kib();
  return std::string(reinterpret_cast<const char*>(&out), sizeof out);
}

std::string seconds_text(double s)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

double mib(double kib) { return kib / 1024.; }

/// Medians of the times and memory of the runs; a note if their results differ.
void summarize(Scaling_row& row)
{
  const Run_measure& first = row.runs.front();
  row.ok = first.error == int(SMP::OK);
  if(row.status.empty()) row.status = SMP::error_name(SMP::Error_code(first.error));
  auto median_of = [&](const std::function<double(const Run_measure&)>& field) {
    std::vector<double> v;
    for(const Run_measure& m : row.runs) v.push_back(field(m));
    return median(v);
  };
  SMP::Cut_and_parameterize_timings& t = row.time;
  t.initialization = median_of([](const Run_measure& m) { return m.timings.initialization; });
  t.u_steps = median_of([](const Run_measure& m) { return m.timings.u_steps; });
  t.v_steps = median_of([](const Run_measure& m) { return m.timings.v_steps; });
  t.cut_extraction = median_of([](const Run_measure& m) { return m.timings.cut_extraction; });
  t.final_solve = median_of([](const Run_measure& m) { return m.timings.final_solve; });
  t.packing = median_of([](const Run_measure& m) { return m.timings.packing; });
  t.total = median_of([](const Run_measure& m) { return m.timings.total; });
  row.peak_mb = median_of([](const Run_measure& m) { return mib(double(m.peak_kib)); });
  row.start_mb = median_of([](const Run_measure& m) { return mib(double(m.start_kib)); });
  for(const Run_measure& m : row.runs)
    if(m.error != first.error || m.newton_iterations != first.newton_iterations ||
       m.factorizations != first.factorizations || m.charts != first.charts ||
       m.distortion != first.distortion || m.seam_length != first.seam_length)
      row.note = "results vary across runs (first run shown)";
  if(first.faces != row.mesh.faces)
    row.note = "the child counted " + std::to_string(first.faces) + " faces";
}

Scaling_row run_mesh(const Scaling_mesh& m, const Options& opt, std::size_t index, std::size_t count)
{
  Scaling_row row;
  row.mesh = m;
  const int runs = m.faces <= SCALING_REPEAT_MAX_FACES ? opt.repeat_count() : 1;
  for(int r = 0; r < runs; ++r)
  {
    std::cerr << "[" << index + 1 << "/" << count << "] " << m.name << " (" << m.faces << " faces), run "
              << r + 1 << "/" << runs << " ... " << std::flush;
    const Child_result c = run_forked([&] { return measure_run(m, opt); }, opt.time_limit);
    if(c.kind == Child_result::TIMED_OUT)
    {
      row.over_limit = true;
      row.status = "TIME_LIMIT";
      std::cerr << "over " << seconds_text(opt.time_limit) << " s, killed\n";
      break;
    }
    if(c.kind == Child_result::NOT_STARTED) row.status = "NOT_STARTED";
    else if(c.kind == Child_result::SIGNALED)
    {
      row.status = "CRASHED";
      row.note = std::string("killed by signal ") + std::to_string(c.code) +
                 (c.code == SIGKILL ? " (out of memory?)" : "");
    }
    else if(c.code != 0 || c.output.size() != sizeof(Run_measure))
    {
      row.status = "EXCEPTION";
      row.note = c.code == 3 && !c.output.empty() ? c.output : "the child exited with status " + std::to_string(c.code);
    }
    if(!row.status.empty()) { std::cerr << row.status << "\n"; break; }
    Run_measure measure;
    std::memcpy(&measure, c.output.data(), sizeof measure);
    if(!measure.read)
    {
      row.status = "READ_FAILED";
      std::cerr << row.status << "\n";
      break;
    }
    row.runs.push_back(measure);
    std::cerr << SMP::error_name(SMP::Error_code(measure.error)) << " (" << time_text(measure.timings.total)
              << " s, " << fixed(mib(double(measure.peak_kib)), 1) << " MB)\n";
    if(measure.error != int(SMP::OK)) break; // a failing mesh fails again
  }
  if(row.over_limit) row.runs.clear();
  if(!row.runs.empty()) summarize(row);
  return row;
}

std::vector<std::string> cells_of(const Scaling_row& row, double time_limit)
{
  const bool ran = !row.runs.empty();
  const Run_measure* first = ran ? &row.runs.front() : nullptr;
  auto time = [&](double t) { return ran ? time_text(t) : std::string("-"); };
  auto count = [&](std::size_t n) { return row.ok ? std::to_string(n) : std::string("-"); };
  return {row.mesh.name,
          std::to_string(row.mesh.faces),
          std::to_string(row.runs.size()),
          row.over_limit ? "over " + seconds_text(time_limit) + " s" : time(row.time.total),
          time(row.time.initialization),
          time(row.time.u_steps),
          time(row.time.v_steps),
          time(row.time.cut_extraction),
          time(row.time.final_solve),
          time(row.time.packing),
          count(first ? first->newton_iterations : 0),
          count(first ? first->factorizations : 0),
          ran ? fixed(row.peak_mb, 1) : "-",
          row.ok ? fixed(first->distortion, 4) : "-",
          row.ok ? fixed(first->seam_length, 4) : "-",
          count(first ? first->charts : 0),
          row.status};
}

std::string cholesky_name()
{
  using Solver = SMP::internal::cut::Sparse_cholesky;
  std::string name = "Eigen simplicial LDLT (AMD)";
#ifdef CGAL_SMP_CUT_USE_METIS
  name += ", LLT (METIS) from " + std::to_string(Solver::metis_threshold) + " unknowns";
#endif
#ifdef CGAL_SMP_CUT_USE_CHOLMOD
  name += ", CHOLMOD supernodal from " + std::to_string(Solver::cholmod_threshold()) + " unknowns";
#endif
  return name;
}

const char* tbb_name()
{
#ifdef CGAL_LINKED_WITH_TBB
  return "on";
#else
  return "off";
#endif
}

bool write_json(const Options& opt, const std::vector<Scaling_row>& rows)
{
  using nlohmann::ordered_json;
  const auto number = [](double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(); };
  ordered_json j;
  j["benchmark"] = "scaling";
  j["hardware_concurrency"] = std::thread::hardware_concurrency();
  j["tbb"] = std::strcmp(tbb_name(), "on") == 0;
  j["cholesky"] = cholesky_name();
  j["time_limit_s"] = number(opt.time_limit);
  j["repeat"] = opt.repeat_count();
  j["repeat_max_faces"] = SCALING_REPEAT_MAX_FACES;
  j["max_faces"] = opt.max_faces ? ordered_json(*opt.max_faces) : ordered_json();
  j["rows"] = ordered_json::array();
  for(const Scaling_row& row : rows)
  {
    const bool ran = !row.runs.empty();
    const Run_measure* first = ran ? &row.runs.front() : nullptr;
    // null where nothing was measured
    const auto time = [&](double t) { return ran ? number(t) : ordered_json(); };
    const auto count = [&](std::size_t n) { return row.ok ? ordered_json(n) : ordered_json(); };
    ordered_json r;
    r["mesh"] = row.mesh.name;
    r["source"] = row.mesh.source;
    r["subdivisions"] = row.mesh.subdivisions;
    r["faces"] = row.mesh.faces;
    r["runs"] = row.runs.size();
    r["status"] = row.status;
    r["over_time_limit"] = row.over_limit;
    r["total_s"] = time(row.time.total);
    r["initialization_s"] = time(row.time.initialization);
    r["u_steps_s"] = time(row.time.u_steps);
    r["v_steps_s"] = time(row.time.v_steps);
    r["cut_extraction_s"] = time(row.time.cut_extraction);
    r["final_solve_s"] = time(row.time.final_solve);
    r["packing_s"] = time(row.time.packing);
    r["newton_iterations"] = count(first ? first->newton_iterations : 0);
    r["factorizations"] = count(first ? first->factorizations : 0);
    r["peak_memory_mb"] = ran ? number(row.peak_mb) : ordered_json();
    r["E_d"] = row.ok ? number(first->distortion) : ordered_json();
    r["E_s"] = row.ok ? number(first->seam_length) : ordered_json();
    r["charts"] = count(first ? first->charts : 0);
    j["rows"].push_back(r);
  }
  std::ofstream out(opt.json_file);
  out << j.dump(2) << '\n';
  out.close();
  return bool(out);
}

} // namespace

int run_scaling(const Options& opt)
{
  std::vector<std::string> notes;
  const fs::path elephant = cgal_data_file(CGAL_MESH);
  std::vector<std::string> left_out;
  std::vector<Scaling_mesh> kept;
  for(const Scaling_mesh& m : scaling_meshes(opt, elephant, notes))
  {
    if(opt.max_faces && m.faces > *opt.max_faces) left_out.push_back(m.name);
    else kept.push_back(m);
  }
  if(kept.empty())
  {
    for(const std::string& n : notes) std::cerr << "note: " << n << "\n";
    std::cerr << "error: no mesh to run" << (left_out.empty() ? "" : " (--max-faces left them all out)") << "\n";
    return 2;
  }

  std::vector<Scaling_row> rows;
  for(std::size_t i = 0; i < kept.size(); ++i) rows.push_back(run_mesh(kept[i], opt, i, kept.size()));

  const std::vector<Column> columns = {
    {"mesh", true}, {"faces"}, {"runs"}, {"total_s"}, {"init_s"}, {"u_steps_s"}, {"v_steps_s"}, {"cut_s"},
    {"final_s"}, {"packing_s"}, {"newton"}, {"factorizations"}, {"peak_MB"}, {"E_d"}, {"E_s"}, {"charts"},
    {"status", true}};
  std::vector<std::vector<std::string>> cells;
  for(const Scaling_row& row : rows) cells.push_back(cells_of(row, opt.time_limit));

  const int repeat = opt.repeat_count();
  std::cout << "cut_and_parameterize scaling benchmark\n"
            << "  meshes:     " << opt.mesh_dir.lexically_normal().string() << "; CGAL data: "
            << (elephant.empty() ? std::string("not found") : elephant.lexically_normal().string())
            << "\n"
            << "  machine:    " << std::thread::hardware_concurrency()
            << " hardware threads (std::thread::hardware_concurrency); TBB " << tbb_name() << "; sparse Cholesky: "
            << cholesky_name() << "\n"
            << "  parameters: cut_and_parameterize() defaults"
            << (opt.given_option("multiresolution_faces") ? ", multiresolution_faces " + std::to_string(opt.method.multiresolution_faces) : std::string())
            << "\n"
            << "  runs:       each in a child process, killed after " << seconds_text(opt.time_limit)
            << " s; each figure the median of " << repeat << " run" << (repeat > 1 ? "s" : "") << " up to "
            << SCALING_REPEAT_MAX_FACES << " faces, of 1 run above\n\n";
  print_table(std::cout, columns, cells);

  double start_mb = 0.;
  for(const Scaling_row& row : rows)
    if(!row.runs.empty()) start_mb = std::max(start_mb, row.start_mb);
  std::cout << "\nsN: " << fs::path(BASE_MESH).stem().string()
            << " after N rounds of 1-to-4 midpoint subdivision (same surface, 4^N times the faces)\n"
            << "times: wall seconds of cut_and_parameterize() (Cut_and_parameterize_result::timings): "
               "init = indexing, initial cut, chart mesh, Tutte map; u_steps = Newton minimizations of the "
               "alternation; v_steps = discontinuity-field solves; cut = cut paths and cutting; final = final "
               "solve (injective re-solve included); packing; the rest of total_s is argument checks, outputs "
               "and statistics\n"
            << "factorizations: numeric Cholesky factorizations of the Newton Hessians\n"
            << "peak_MB: maximum resident set size of the child process that read (and subdivided) the mesh "
               "and ran the method (getrusage ru_maxrss), " << fixed(start_mb, 1)
            << " MB of which it had at its start\n";
  for(const Scaling_row& row : rows)
    if(!row.note.empty()) std::cout << "note: " << row.mesh.name << ": " << row.note << "\n";
  for(const std::string& n : notes) std::cout << "note: " << n << "\n";
  if(!left_out.empty())
  {
    std::cout << "note: --max-faces " << *opt.max_faces << " left out:";
    for(const std::string& name : left_out) std::cout << " " << name;
    std::cout << "\n";
  }

  if(!opt.json_file.empty())
  {
    if(!write_json(opt, rows)) { std::cerr << "error: cannot write " << opt.json_file << "\n"; return 1; }
    std::cerr << "wrote " << opt.json_file << "\n";
  }
  return 0;
}

} // namespace cut_benchmark
