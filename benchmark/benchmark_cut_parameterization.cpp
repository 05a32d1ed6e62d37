// Benchmark of cut_and_parameterize() against the reference implementation
// (the paper's published code, measured on this machine type) and the
// paper's Table 1.
//
// For every mesh: faces, wall time of the algorithm alone (median of
// --repeat runs), Newton iterations, charts, flipped faces and UV border
// crossings (both recounted on the output), the atlas' coverage of its
// square (the library's figure), E_d and E_s; then the reference's figures, Table 1's figures, and
// whether the targets
//     E_d <= ref E_d + 0.03      and      E_s <= 1.25 ref E_s + 0.05
// are met, with the speed ratio ref_time / our_time.
//
// Run with --help for the options.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace SMP = CGAL::Surface_mesh_parameterization;

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

namespace {

const double NaN = std::numeric_limits<double>::quiet_NaN();

// Targets, relative to the reference implementation's measured figures.
const double ED_TOLERANCE = 0.03;   // E_d <= ref E_d + 0.03
const double ES_FACTOR = 1.25;      // E_s <= 1.25 ref E_s + 0.05
const double ES_TOLERANCE = 0.05;
const std::size_t QUICK_MAX_FACES = 5000;

// ---------------------------------------------------------------------------
// Command line

struct Options
{
  fs::path mesh_dir;
  fs::path reference_dir;
  std::vector<std::string> meshes;     // empty: the default list
  std::optional<double> lambda;
  std::optional<int> passes;
  double box = 0.;                     // bounding_box_aspect_ratio (0: off)
  int repeat = 1;
  std::string csv_file;
  bool quick = false;
};

fs::path project_root()
{
#ifdef CUT_PARAM_BENCHMARK_PROJECT_ROOT
  return fs::path(CUT_PARAM_BENCHMARK_PROJECT_ROOT);
#else
  return fs::path(".");
#endif
}

void print_usage(const char* program, std::ostream& os)
{
  os << "Usage: " << program << " [options]\n"
     << "Runs cut_and_parameterize() on a list of meshes and compares with the reference\n"
     << "implementation's measured figures and the paper's Table 1.\n\n"
     << "Options:\n"
     << "  --meshes a,b,c      mesh names (file stems, e.g. cat,venus; or paths relative to\n"
     << "                      the mesh folder, e.g. optcuts/cat.obj). Default: every mesh named\n"
     << "                      in the reference tables that exists in the mesh folder\n"
     << "  --mesh-dir DIR      mesh folder (holding uvat/ and optcuts/); default\n"
     << "                      ../shared/meshes relative to the project root\n"
     << "  --reference-dir DIR folder of uvat_reference_measured.csv and paper_table1.csv;\n"
     << "                      default ../shared/reference relative to the project root\n"
     << "  --lambda X          seam cost lambda (library default if not given)\n"
     << "  --passes N          number of passes (library default if not given)\n"
     << "  --box W:H           bounding-box term of aspect ratio W/H (default: off)\n"
     << "  --repeat N          runs per mesh; the time reported is their median (default 1)\n"
     << "  --csv FILE          also write the table as CSV\n"
     << "  --quick             only meshes with fewer than " << QUICK_MAX_FACES << " faces\n"
     << "  --help              this text\n";
}

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream is(s);
  while(std::getline(is, item, sep)) out.push_back(item);
  if(!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

std::string trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  if(b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool parse_double(const std::string& s, double& out)
{
  const std::string t = trim(s);
  if(t.empty()) return false;
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return end && *end == '\0';
}

bool parse_int(const std::string& s, int& out)
{
  const std::string t = trim(s);
  if(t.empty()) return false;
  char* end = nullptr;
  const long v = std::strtol(t.c_str(), &end, 10);
  if(!end || *end != '\0' || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    return false;
  out = int(v);
  return true;
}

// Returns 0 to run, 1 to exit with success (--help), 2 on a usage error.
int parse_options(int argc, char** argv, Options& opt)
{
  opt.mesh_dir = project_root() / ".." / "shared" / "meshes";
  opt.reference_dir = project_root() / ".." / "shared" / "reference";
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& out) {
      if(i + 1 >= argc) { std::cerr << "error: " << arg << " needs a value\n"; return false; }
      out = argv[++i];
      return true;
    };
    std::string v;
    if(arg == "--help" || arg == "-h") { print_usage(argv[0], std::cout); return 1; }
    else if(arg == "--quick") opt.quick = true;
    else if(arg == "--meshes")
    {
      if(!value(v)) return 2;
      for(const auto& name : split(v, ','))
        if(!trim(name).empty()) opt.meshes.push_back(trim(name));
      if(opt.meshes.empty()) { std::cerr << "error: --meshes: empty list\n"; return 2; }
    }
    else if(arg == "--mesh-dir") { if(!value(v)) return 2; opt.mesh_dir = v; }
    else if(arg == "--reference-dir") { if(!value(v)) return 2; opt.reference_dir = v; }
    else if(arg == "--csv") { if(!value(v)) return 2; opt.csv_file = v; }
    else if(arg == "--lambda")
    {
      double x;
      if(!value(v)) return 2;
      if(!parse_double(v, x) || !(x > 0.) || !std::isfinite(x))
      { std::cerr << "error: --lambda: expected a positive number, got '" << v << "'\n"; return 2; }
      opt.lambda = x;
    }
    else if(arg == "--box")
    {
      double w, h;
      if(!value(v)) return 2;
      const std::size_t colon = v.find(':');
      if(colon == std::string::npos || !parse_double(v.substr(0, colon), w) || !parse_double(v.substr(colon + 1), h) ||
         !(w > 0.) || !(h > 0.) || !std::isfinite(w / h))
      { std::cerr << "error: --box: expected W:H, two positive numbers, got '" << v << "'\n"; return 2; }
      opt.box = w / h;
    }
    else if(arg == "--passes")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 0)
      { std::cerr << "error: --passes: expected a non-negative integer, got '" << v << "'\n"; return 2; }
      opt.passes = n;
    }
    else if(arg == "--repeat")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 1)
      { std::cerr << "error: --repeat: expected a positive integer, got '" << v << "'\n"; return 2; }
      opt.repeat = n;
    }
    else
    {
      std::cerr << "error: unknown option '" << arg << "'\n";
      print_usage(argv[0], std::cerr);
      return 2;
    }
  }
  return 0;
}

// ---------------------------------------------------------------------------
// Reference tables

using Csv_row = std::map<std::string, std::string>;

// Reads a CSV file with a header line; blank lines and lines starting with '#'
// are skipped. Fields may be double-quoted. Returns false if the file cannot
// be opened.
bool read_csv(const fs::path& file, std::vector<Csv_row>& rows)
{
  std::ifstream in(file);
  if(!in) return false;
  auto fields_of = [](const std::string& line) {
    std::vector<std::string> fields;
    std::string cur;
    bool quoted = false;
    for(std::size_t i = 0; i < line.size(); ++i)
    {
      const char c = line[i];
      if(quoted)
      {
        if(c == '"' && i + 1 < line.size() && line[i + 1] == '"') { cur += '"'; ++i; }
        else if(c == '"') quoted = false;
        else cur += c;
      }
      else if(c == '"') quoted = true;
      else if(c == ',') { fields.push_back(trim(cur)); cur.clear(); }
      else cur += c;
    }
    fields.push_back(trim(cur));
    return fields;
  };
  std::vector<std::string> header;
  std::string line;
  while(std::getline(in, line))
  {
    const std::string t = trim(line);
    if(t.empty() || t[0] == '#') continue;
    const auto fields = fields_of(t);
    if(header.empty()) { header = fields; continue; }
    Csv_row row;
    for(std::size_t i = 0; i < header.size(); ++i)
      row[header[i]] = i < fields.size() ? fields[i] : std::string();
    rows.push_back(std::move(row));
  }
  return true;
}

double number_in(const Csv_row& row, const std::string& column)
{
  const auto it = row.find(column);
  double x;
  if(it == row.end() || !parse_double(it->second, x)) return NaN;
  return x;
}

std::string text_in(const Csv_row& row, const std::string& column)
{
  const auto it = row.find(column);
  return it == row.end() ? std::string() : it->second;
}

struct Reference_figures
{
  double time = NaN, distortion = NaN, seam_length = NaN;
  std::string status;   // measured reference only
  std::string model;    // paper only: the model's name in Table 1
};

struct References
{
  std::vector<std::string> measured_order;        // mesh names as listed
  std::map<std::string, Reference_figures> measured; // by mesh name (file stem)
  std::vector<std::string> paper_files;           // mesh_file as listed (relative paths)
  std::map<std::string, Reference_figures> paper; // by file stem
  std::vector<std::string> paper_without_file;    // Table 1 models with no mesh file
};

// File name without a mesh extension ("optcuts/cat.obj" -> "cat"); names such
// as "cone2.0_f1500" keep their dots.
std::string stem_of(const std::string& name)
{
  std::string base = fs::path(name).filename().string();
  const auto dot = base.rfind('.');
  if(dot != std::string::npos)
  {
    std::string ext = base.substr(dot + 1);
    for(auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    for(const char* known : {"obj", "off", "ply", "stl", "vtp", "ts"})
      if(ext == known) return base.substr(0, dot);
  }
  return base;
}

References read_references(const fs::path& dir)
{
  References refs;
  std::vector<Csv_row> rows;
  const fs::path measured = dir / "uvat_reference_measured.csv";
  if(!read_csv(measured, rows))
    std::cerr << "warning: cannot read " << measured.string() << "\n";
  for(const auto& row : rows)
  {
    const std::string name = text_in(row, "mesh");
    if(name.empty()) continue;
    Reference_figures r;
    r.time = number_in(row, "median_time_s");
    r.distortion = number_in(row, "E_d");
    r.seam_length = number_in(row, "E_s");
    r.status = text_in(row, "status");
    if(!refs.measured.count(name)) refs.measured_order.push_back(name);
    refs.measured[name] = r;
  }

  rows.clear();
  const fs::path paper = dir / "paper_table1.csv";
  if(!read_csv(paper, rows))
    std::cerr << "warning: cannot read " << paper.string() << "\n";
  for(const auto& row : rows)
  {
    const std::string file = text_in(row, "mesh_file");
    const std::string model = text_in(row, "model");
    if(file.empty()) { refs.paper_without_file.push_back(model); continue; }
    Reference_figures r;
    r.time = number_in(row, "at_time_s");
    r.distortion = number_in(row, "at_distortion");
    r.seam_length = number_in(row, "at_cut_length");
    r.model = model;
    const std::string stem = stem_of(file);
    if(!refs.paper.count(stem)) refs.paper_files.push_back(file);
    refs.paper[stem] = r;
  }
  return refs;
}

// ---------------------------------------------------------------------------
// Mesh list

struct Mesh_entry
{
  std::string name;   // file stem
  fs::path file;      // empty if not found
};

bool is_file(const fs::path& p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// A name is looked up as given (relative to the mesh folder, or absolute),
// then as <name>.obj in uvat/, optcuts/ and the folder itself.
fs::path find_mesh(const fs::path& dir, const std::string& name)
{
  const fs::path given(name);
  if(stem_of(name) != given.filename().string()) // has a mesh extension
  {
    if(given.is_absolute() && is_file(given)) return given;
    if(is_file(dir / given)) return dir / given;
    if(is_file(given)) return given;
  }
  for(const char* sub : {"uvat", "optcuts", ""})
  {
    const fs::path p = dir / sub / (name + ".obj");
    if(is_file(p)) return p;
  }
  return {};
}

std::vector<Mesh_entry> mesh_list(const Options& opt, const References& refs,
                                  std::vector<std::string>& missing)
{
  std::vector<Mesh_entry> list;
  std::set<std::string> seen;
  auto add = [&](const std::string& name, bool keep_missing) {
    const fs::path file = find_mesh(opt.mesh_dir, name);
    const std::string stem = stem_of(name);
    if(seen.count(stem)) return;
    seen.insert(stem);
    if(file.empty())
    {
      missing.push_back(name);
      if(!keep_missing) return;
    }
    list.push_back({stem, file});
  };
  if(!opt.meshes.empty())
  {
    for(const auto& name : opt.meshes) add(name, true);
    return list;
  }
  for(const auto& name : refs.measured_order) add(name, false);
  for(const auto& file : refs.paper_files) add(file, false);
  return list;
}

// ---------------------------------------------------------------------------
// Running the method

struct Run_result
{
  std::string status;          // "ok", an error name, or a failure to read
  std::size_t faces = 0;
  bool ran = false;            // the algorithm was called
  bool ok = false;
  double time = NaN;           // median wall time of the algorithm (s)
  std::size_t newton = 0, charts = 0, flipped = 0, crossings = 0;
  double distortion = NaN, seam_length = NaN, coverage = NaN;
  std::string note;
};

double median(std::vector<double> v)
{
  if(v.empty()) return NaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool close(double a, double b, double rel = 1e-6)
{
  if(std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if(std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= rel * std::max(1., std::max(std::abs(a), std::abs(b)));
}

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
    else if(res.error != first.error || !close(res.distortion, first.distortion, 1e-9)
            || !close(res.seam_length, first.seam_length, 1e-9))
      varies = true;
    if(res.error != SMP::OK) break; // a failing mesh fails again; do not time it N times
  }

  out.time = median(times);
  out.status = SMP::error_name(first.error);
  out.ok = first.ok();
  if(varies) out.note = "results vary across runs (first run shown)";
  if(!out.ok) return;

  out.newton = first.newton_iterations;
  out.charts = first.number_of_charts;
  out.distortion = first.distortion;
  out.seam_length = first.seam_length;
  out.coverage = first.uv_coverage;
  // The maps hold the last run; with deterministic runs it is the first one.
  out.flipped = SMP::number_of_flipped_faces(mesh, uv);
  out.crossings = SMP::number_of_border_crossings(mesh, uv);
  if(!varies)
  {
    const double ed = SMP::distortion_energy(mesh, uv, SMP::parameters::uv_scale(first.uv_scale));
    const double es = SMP::seam_length(mesh, seam);
    if(!close(ed, first.distortion) || !close(es, first.seam_length))
    {
      std::ostringstream os;
      os.precision(6);
      os << "metrics on the output disagree with the result: E_d " << ed << ", E_s " << es;
      out.note = os.str();
    }
  }
}

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
    run_method(mesh, opt.repeat, np, out);
  }
  catch(const std::exception& e)
  {
    out.ok = false;
    out.status = "EXCEPTION";
    out.note = e.what();
  }
  return out;
}

// ---------------------------------------------------------------------------
// Output

struct Row
{
  Mesh_entry mesh;
  Run_result run;
  const Reference_figures* measured = nullptr;
  const Reference_figures* paper = nullptr;
  int ed_pass = -1, es_pass = -1;  // -1: no reference to compare with
  double speedup = NaN;
};

std::string fixed(double x, int digits)
{
  if(std::isnan(x)) return "-";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  // Huge values (a failed reference result) in scientific notation.
  if(std::abs(x) >= 1e6) std::snprintf(buf, sizeof buf, "%.3g", x);
  else std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// Seconds with 3 decimals; sub-millisecond times with 2 significant digits.
std::string time_text(double t)
{
  if(!(t < 0.001) || t <= 0.) return fixed(t, 3);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2g", t);
  return buf;
}

std::string full(double x)
{
  if(std::isnan(x)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string pass_text(int p) { return p < 0 ? "-" : (p ? "yes" : "NO"); }

struct Column
{
  std::string title;
  bool left = false;
};

void print_table(std::ostream& os, const std::vector<Column>& columns,
                 const std::vector<std::vector<std::string>>& cells)
{
  std::vector<std::size_t> width(columns.size());
  for(std::size_t c = 0; c < columns.size(); ++c)
  {
    width[c] = columns[c].title.size();
    for(const auto& row : cells) width[c] = std::max(width[c], row[c].size());
  }
  auto line = [&](const std::vector<std::string>& row) {
    std::string s;
    for(std::size_t c = 0; c < columns.size(); ++c)
    {
      const std::string pad(width[c] - row[c].size(), ' ');
      if(c) s += "  ";
      s += columns[c].left ? row[c] + pad : pad + row[c];
    }
    while(!s.empty() && s.back() == ' ') s.pop_back();
    os << s << "\n";
  };
  std::vector<std::string> titles;
  for(const auto& c : columns) titles.push_back(c.title);
  line(titles);
  std::size_t total = 0;
  for(auto w : width) total += w;
  os << std::string(total + 2 * (columns.size() - 1), '-') << "\n";
  for(const auto& row : cells) line(row);
}

std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for(char c : s) { if(c == '"') q += '"'; q += c; }
  return q + "\"";
}

} // namespace

int main(int argc, char** argv)
{
  Options opt;
  if(const int r = parse_options(argc, argv, opt)) return r == 1 ? 0 : r;

  const References refs = read_references(opt.reference_dir);
  std::vector<std::string> missing;
  const std::vector<Mesh_entry> meshes = mesh_list(opt, refs, missing);
  if(meshes.empty())
  {
    std::cerr << "error: no mesh to run (mesh folder: " << opt.mesh_dir.string() << ")\n";
    return 2;
  }

  auto run = [&](const auto& np) {
    std::vector<Row> rows;
    for(const auto& m : meshes)
    {
      std::cerr << "[" << rows.size() + 1 << "/" << meshes.size() << "] " << m.name << " ... " << std::flush;
      Row row;
      row.mesh = m;
      row.run = benchmark_mesh(m, opt, np);
      std::cerr << row.run.status;
      if(row.run.ran) std::cerr << " (" << time_text(row.run.time) << " s)";
      std::cerr << "\n";
      if(!row.run.note.empty()) std::cerr << "  note: " << row.run.note << "\n";
      rows.push_back(std::move(row));
    }
    return rows;
  };

  namespace P = SMP::parameters;
  std::vector<Row> rows;
  const SMP::internal::cut::Joint_settings defaults;
  rows = run(P::lambda(opt.lambda.value_or(defaults.lambda),
             P::number_of_passes(opt.passes.value_or(defaults.passes),
             P::bounding_box_aspect_ratio(opt.box))));

  // --quick: meshes left out for their size.
  std::vector<std::string> skipped_names;
  for(const auto& row : rows)
    if(row.run.status == "skipped") skipped_names.push_back(row.mesh.name);
  rows.erase(std::remove_if(rows.begin(), rows.end(),
                            [](const Row& row) { return row.run.status == "skipped"; }),
             rows.end());

  // Comparisons.
  for(auto& row : rows)
  {
    auto it = refs.measured.find(row.mesh.name);
    if(it != refs.measured.end()) row.measured = &it->second;
    auto jt = refs.paper.find(row.mesh.name);
    if(jt != refs.paper.end()) row.paper = &jt->second;
    if(row.measured)
    {
      const double ref_ed = row.measured->distortion, ref_es = row.measured->seam_length;
      if(!std::isnan(ref_ed))
        row.ed_pass = row.run.ok && row.run.distortion <= ref_ed + ED_TOLERANCE;
      if(!std::isnan(ref_es))
        row.es_pass = row.run.ok && row.run.seam_length <= ES_FACTOR * ref_es + ES_TOLERANCE;
      if(row.run.ok && row.run.time > 0. && row.measured->time > 0.)
        row.speedup = row.measured->time / row.run.time;
    }
  }

  // Table.
  const std::vector<Column> columns = {
    {"mesh", true}, {"faces"}, {"time_s"}, {"newton"}, {"charts"}, {"flips"}, {"crossings"}, {"coverage"},
    {"E_d"}, {"E_s"},
    {"ref_t"}, {"ref_E_d"}, {"ref_E_s"}, {"T1_t"}, {"T1_E_d"}, {"T1_E_s"},
    {"E_d_ok"}, {"E_s_ok"}, {"speedup"}, {"status", true}};
  std::vector<std::vector<std::string>> cells;
  for(const auto& row : rows)
  {
    const auto& r = row.run;
    const auto* m = row.measured;
    const auto* p = row.paper;
    cells.push_back({
      row.mesh.name,
      r.faces ? std::to_string(r.faces) : "-",
      r.ran ? time_text(r.time) : "-",
      r.ok ? std::to_string(r.newton) : "-",
      r.ok ? std::to_string(r.charts) : "-",
      r.ok ? std::to_string(r.flipped) : "-",
      r.ok ? std::to_string(r.crossings) : "-",
      r.ok ? fixed(r.coverage, 3) : "-",
      r.ok ? fixed(r.distortion, 4) : "-",
      r.ok ? fixed(r.seam_length, 4) : "-",
      m ? fixed(m->time, 3) : "-",
      m ? fixed(m->distortion, 4) : "-",
      m ? fixed(m->seam_length, 4) : "-",
      p ? fixed(p->time, 2) : "-",
      p ? fixed(p->distortion, 2) : "-",
      p ? fixed(p->seam_length, 2) : "-",
      pass_text(row.ed_pass),
      pass_text(row.es_pass),
      std::isnan(row.speedup) ? "-" : fixed(row.speedup, 2) + "x",
      r.status});
  }

  std::cout << "cut_and_parameterize benchmark\n"
            << "  meshes:     " << opt.mesh_dir.lexically_normal().string() << "\n"
            << "  references: " << opt.reference_dir.lexically_normal().string() << "\n"
            << "  parameters: lambda "
            << (opt.lambda ? fixed(*opt.lambda, 3) : std::string("default")) << ", passes "
            << (opt.passes ? std::to_string(*opt.passes) : std::string("default"))
            << (opt.box > 0. ? ", box aspect ratio " + fixed(opt.box, 3) : std::string())
            << "; time: median of " << opt.repeat << " run" << (opt.repeat > 1 ? "s" : "")
            << (opt.quick ? "; --quick (faces < 5000)" : "") << "\n\n";
  print_table(std::cout, columns, cells);

  // Summary.
  std::size_t compared = 0, passed = 0, failed_runs = 0, with_flips = 0, with_crossings = 0;
  double log_sum = 0.;
  std::size_t n_speed = 0;
  for(const auto& row : rows)
  {
    if(!row.run.ok) ++failed_runs;
    if(row.run.ok && row.run.flipped > 0) ++with_flips;
    if(row.run.ok && row.run.crossings > 0) ++with_crossings;
    if(row.ed_pass >= 0 && row.es_pass >= 0)
    {
      ++compared;
      if(row.ed_pass && row.es_pass) ++passed;
    }
    if(!std::isnan(row.speedup)) { log_sum += std::log(row.speedup); ++n_speed; }
  }
  std::cout << "\nE_d_ok: E_d <= ref_E_d + " << ED_TOLERANCE << "; E_s_ok: E_s <= " << ES_FACTOR
            << " ref_E_s + " << ES_TOLERANCE << "; speedup = ref_t / time_s\n"
            << "crossings: pairs of UV border segments that cross (overlaps; 0 for a valid atlas); "
               "coverage: UV area / area of the packing square\n"
            << "ref_*: reference implementation measured on this machine type "
               "(uvat_reference_measured.csv); T1_*: the paper's Table 1 (paper_table1.csv)\n";
  for(const auto& row : rows)
    if(row.measured && row.measured->status != "ok" && !row.measured->status.empty())
      std::cout << "note: " << row.mesh.name << ": reference status '" << row.measured->status << "'\n";
  for(const auto& row : rows)
    if(row.measured && row.measured->distortion > 100.)
      std::cout << "note: " << row.mesh.name << ": reference E_d " << fixed(row.measured->distortion, 4)
                << " is a failed result, so the E_d target is met trivially\n";
  for(const auto& row : rows)
    if(!row.run.note.empty()) std::cout << "note: " << row.mesh.name << ": " << row.run.note << "\n";
  for(const auto& name : missing)
    std::cout << "note: " << name << ": no mesh file in " << opt.mesh_dir.lexically_normal().string()
              << (opt.meshes.empty() ? " (left out)" : "") << "\n";
  if(!skipped_names.empty())
  {
    std::cout << "note: --quick left out (" << QUICK_MAX_FACES << " faces or more):";
    for(const auto& name : skipped_names) std::cout << " " << name;
    std::cout << "\n";
  }
  if(opt.meshes.empty())
    for(const auto& model : refs.paper_without_file)
      std::cout << "note: Table 1 model '" << model << "' has no mesh file (left out)\n";

  std::cout << "\nSummary: " << passed << "/" << compared << " meshes pass both targets";
  if(failed_runs) std::cout << " (" << failed_runs << " failed: error or unreadable mesh)";
  if(with_flips) std::cout << "; " << with_flips << " with flipped faces";
  if(with_crossings) std::cout << "; " << with_crossings << " with border crossings";
  if(!skipped_names.empty()) std::cout << "; " << skipped_names.size() << " skipped (--quick)";
  std::cout << "; geometric-mean speedup vs reference: ";
  if(n_speed) std::cout << fixed(std::exp(log_sum / double(n_speed)), 2) << "x over " << n_speed << " meshes\n";
  else std::cout << "-\n";

  // CSV.
  if(!opt.csv_file.empty())
  {
    std::ofstream csv(opt.csv_file);
    if(!csv) { std::cerr << "error: cannot write " << opt.csv_file << "\n"; return 1; }
    csv << "mesh,file,faces,time_s,newton_iterations,charts,flipped_faces,crossings,coverage,E_d,E_s,"
           "ref_time_s,ref_E_d,ref_E_s,paper_time_s,paper_E_d,paper_E_s,"
           "E_d_pass,E_s_pass,speedup,status\n";
    auto pass_csv = [](int p) { return p < 0 ? std::string() : std::to_string(p); };
    for(const auto& row : rows)
    {
      const auto& r = row.run;
      const auto* m = row.measured;
      const auto* p = row.paper;
      std::string file = row.mesh.file.empty() ? std::string()
                                               : row.mesh.file.lexically_relative(opt.mesh_dir).generic_string();
      csv << csv_field(row.mesh.name) << "," << csv_field(file) << ","
          << (r.faces ? std::to_string(r.faces) : "") << ","
          << (r.ran ? full(r.time) : "") << ","
          << (r.ok ? std::to_string(r.newton) : "") << ","
          << (r.ok ? std::to_string(r.charts) : "") << ","
          << (r.ok ? std::to_string(r.flipped) : "") << ","
          << (r.ok ? std::to_string(r.crossings) : "") << ","
          << (r.ok ? full(r.coverage) : "") << ","
          << (r.ok ? full(r.distortion) : "") << ","
          << (r.ok ? full(r.seam_length) : "") << ","
          << (m ? full(m->time) : "") << "," << (m ? full(m->distortion) : "") << ","
          << (m ? full(m->seam_length) : "") << ","
          << (p ? full(p->time) : "") << "," << (p ? full(p->distortion) : "") << ","
          << (p ? full(p->seam_length) : "") << ","
          << pass_csv(row.ed_pass) << "," << pass_csv(row.es_pass) << ","
          << full(row.speedup) << "," << csv_field(r.status) << "\n";
    }
    std::cerr << "wrote " << opt.csv_file << "\n";
  }
  return 0;
}
