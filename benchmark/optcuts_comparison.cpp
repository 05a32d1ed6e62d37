#include "optcuts_comparison.h"

#include "benchmark_run.h"
#include "mesh_list.h"
#include "reference_tables.h"
#include "table_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace cut_benchmark {

namespace {

// Targets against OptCuts at equal distortion.
const double SPEED_FACTOR = 5.;       // time <= OptCuts' time / 5
const std::size_t ES_TARGET_MESHES = 8; // E_s <= OptCuts' E_s on at least 8 meshes of the table

struct Row
{
  Mesh_entry mesh;
  const Optcuts_figures* optcuts = nullptr; // nullptr: not in the table (with --optcuts-bound only)
  double bound = NaN;
  Run_result run;
  int ed_pass = -1, es_pass = -1, time_pass = -1; // -1: nothing to compare with
  double es_ratio = NaN, speed_ratio = NaN;
};

// The rows to run: each mesh with its OptCuts figures and its bound; the
// meshes without a bound go to `left_out` with the reason.
std::vector<Row> rows_to_run(const Options& opt, const std::vector<Mesh_entry>& meshes,
                             const std::vector<Optcuts_figures>& table, std::vector<std::string>& left_out)
{
  std::vector<Row> rows;
  for(const auto& m : meshes)
  {
    Row row;
    row.mesh = m;
    const auto it = std::find_if(table.begin(), table.end(),
                                 [&](const Optcuts_figures& f) { return f.mesh == m.name; });
    if(it != table.end()) row.optcuts = &*it;
    row.bound = opt.optcuts_bound ? *opt.optcuts_bound : row.optcuts ? row.optcuts->reached.distortion : NaN;
    if(!row.optcuts && !opt.optcuts_bound)
      left_out.push_back(m.name + ": not in optcuts_equal_distortion.csv, so no bound (left out)");
    else if(!(row.bound >= 4.) || !std::isfinite(row.bound))
      left_out.push_back(m.name + ": OptCuts' E_d '" + fixed(row.bound, 4) + "' is no bound (>= 4; left out)");
    else
      rows.push_back(std::move(row));
  }
  return rows;
}

void compare(Row& row, bool compare_seams)
{
  const Run_result& r = row.run;
  row.ed_pass = r.ok && r.distortion <= row.bound;
  if(!row.optcuts) return;
  const Reference_figures& oc = row.optcuts->reached;
  if(!std::isnan(oc.time))
  {
    row.time_pass = r.ok && r.time <= oc.time / SPEED_FACTOR;
    if(r.ok && r.time > 0.) row.speed_ratio = oc.time / r.time;
  }
  if(compare_seams && !std::isnan(oc.seam_length))
  {
    row.es_pass = r.ok && r.seam_length <= oc.seam_length;
    if(r.ok && oc.seam_length > 0.) row.es_ratio = r.seam_length / oc.seam_length;
  }
}

// "all N" if every compared row passes, else "K/N (not: a, b)"; "-" if none compared.
std::string passes_text(const std::vector<Row>& rows, int Row::*pass)
{
  std::size_t compared = 0, passed = 0;
  std::string failed;
  for(const auto& row : rows)
  {
    if(row.*pass < 0) continue;
    ++compared;
    if(row.*pass) ++passed;
    else failed += (failed.empty() ? "" : ", ") + row.mesh.name;
  }
  if(!compared) return "-";
  if(passed == compared) return "all " + std::to_string(compared);
  return std::to_string(passed) + "/" + std::to_string(compared) + " (not: " + failed + ")";
}

// Geometric mean of a ratio over the rows that have it, with how many ("-" if none).
std::string geometric_mean_text(const std::vector<Row>& rows, double Row::*ratio, const std::string& unit)
{
  double log_sum = 0.;
  std::size_t n = 0;
  for(const auto& row : rows)
    if(row.*ratio > 0.) { log_sum += std::log(row.*ratio); ++n; }
  if(!n) return "-";
  return fixed(std::exp(log_sum / double(n)), 2) + unit + " over " + std::to_string(n) + " meshes";
}

void write_csv(std::ostream& csv, const Options& opt, const std::vector<Row>& rows)
{
  csv << "mesh,file,faces,bound,time_s,E_d,E_s,charts,flipped_faces,distortion_bound_met,"
         "optcuts_time_s,optcuts_E_d,optcuts_E_s,E_s_ratio,speed_ratio,E_d_pass,E_s_pass,time_pass,status\n";
  for(const auto& row : rows)
  {
    const auto& r = row.run;
    const Reference_figures* oc = row.optcuts ? &row.optcuts->reached : nullptr;
    csv << csv_field(row.mesh.name) << "," << csv_field(relative_file(row.mesh, opt.mesh_dir)) << ","
        << (r.faces ? std::to_string(r.faces) : "") << "," << full(row.bound) << ","
        << (r.ran ? full(r.time) : "") << ","
        << (r.ok ? full(r.distortion) : "") << ","
        << (r.ok ? full(r.seam_length) : "") << ","
        << (r.ok ? std::to_string(r.charts) : "") << ","
        << (r.ok ? std::to_string(r.flipped) : "") << ","
        << (r.ok ? std::to_string(int(r.bound_met)) : "") << ","
        << (oc ? full(oc->time) : "") << "," << (oc ? full(oc->distortion) : "") << ","
        << (oc ? full(oc->seam_length) : "") << ","
        << full(row.es_ratio) << "," << full(row.speed_ratio) << ","
        << pass_csv(row.ed_pass) << "," << pass_csv(row.es_pass) << "," << pass_csv(row.time_pass) << ","
        << csv_field(r.status) << "\n";
  }
}

} // namespace

int run_optcuts_comparison(const Options& opt)
{
  const std::vector<Optcuts_figures> table = read_optcuts_figures(opt.reference_dir);
  std::vector<std::string> names;
  for(const auto& f : table) names.push_back(f.mesh);
  std::vector<std::string> missing, left_out;
  std::vector<Row> rows = rows_to_run(opt, mesh_list(opt, names, missing), table, left_out);
  for(const auto& note : left_out) std::cerr << "note: " << note << "\n";
  if(rows.empty())
  {
    std::cerr << "error: no mesh to run (mesh folder: " << opt.mesh_dir.string() << ")\n";
    return 2;
  }

  const bool equal_distortion = !opt.optcuts_bound;
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    Row& row = rows[i];
    row.run = benchmark_mesh_logged(i + 1, rows.size(), row.mesh, opt, method_parameters(opt, row.bound));
    compare(row, equal_distortion);
  }

  // Table.
  const std::vector<Column> columns = {
    {"mesh", true}, {"faces"}, {"B"}, {"time_s"}, {"E_d"}, {"E_s"}, {"charts"}, {"flips"}, {"bound_met"},
    {"OC_t"}, {"OC_E_d"}, {"OC_E_s"}, {"E_s/OC"}, {"OC_t/t"},
    {"E_d<=B"}, {"E_s<=OC"}, {"t<=OC/5"}, {"status", true}};
  std::vector<std::vector<std::string>> cells;
  for(const auto& row : rows)
  {
    const auto& r = row.run;
    const Reference_figures* oc = row.optcuts ? &row.optcuts->reached : nullptr;
    cells.push_back({
      row.mesh.name,
      r.faces ? std::to_string(r.faces) : "-",
      fixed(row.bound, 4),
      r.ran ? time_text(r.time) : "-",
      r.ok ? fixed(r.distortion, 4) : "-",
      r.ok ? fixed(r.seam_length, 4) : "-",
      r.ok ? std::to_string(r.charts) : "-",
      r.ok ? std::to_string(r.flipped) : "-",
      r.ok ? pass_text(r.bound_met) : "-",
      oc ? time_text(oc->time) : "-",
      oc ? fixed(oc->distortion, 4) : "-",
      oc ? fixed(oc->seam_length, 4) : "-",
      fixed(row.es_ratio, 3),
      std::isnan(row.speed_ratio) ? "-" : fixed(row.speed_ratio, 2) + "x",
      pass_text(row.ed_pass),
      pass_text(row.es_pass),
      pass_text(row.time_pass),
      r.status});
  }

  std::cout << "cut_and_parameterize vs OptCuts under a distortion bound\n"
            << "  meshes:     " << opt.mesh_dir.lexically_normal().string() << "\n"
            << "  OptCuts:    " << (opt.reference_dir / "optcuts_equal_distortion.csv").lexically_normal().string()
            << "\n  bound B:    "
            << (equal_distortion ? std::string("the E_d OptCuts reached on the mesh (equal distortion)")
                                 : fixed(*opt.optcuts_bound, 4) + " for every mesh (E_s not compared)")
            << "\n  parameters: " << parameters_text(opt) << "\n\n";
  print_table(std::cout, columns, cells);

  std::cout << "\nB: distortion_bound; bound_met: the result's distortion_bound_met; OC_*: OptCuts "
               "(optcuts_equal_distortion.csv: its own optimisation timer, its E_d and E_s);\n"
            << "E_s/OC = E_s / OC_E_s; OC_t/t = OC_t / time_s; targets: E_d <= B"
            << (equal_distortion ? ", E_s <= OC_E_s" : "") << ", time_s <= OC_t / " << SPEED_FACTOR << "\n";
  for(const auto& note : left_out) std::cout << "note: " << note << "\n";
  for(const auto& row : rows)
    if(!row.run.note.empty()) std::cout << "note: " << row.mesh.name << ": " << row.run.note << "\n";
  for(const auto& name : missing)
    std::cout << "note: " << name << ": no mesh file in " << opt.mesh_dir.lexically_normal().string()
              << (opt.meshes.empty() ? " (left out)" : "") << "\n";

  // Summary.
  std::cout << "\nSummary:";
  if(equal_distortion)
  {
    std::size_t es_passed = 0;
    for(const auto& row : rows) es_passed += row.es_pass > 0;
    std::cout << " E_s <= OptCuts' E_s on " << es_passed << "/" << rows.size() << " meshes (target: at least "
              << ES_TARGET_MESHES << " of the table's " << table.size() << "); geometric-mean E_s ratio "
              << geometric_mean_text(rows, &Row::es_ratio, "") << ";";
  }
  std::cout << " E_d <= B: " << passes_text(rows, &Row::ed_pass) << "; time <= OptCuts' time / " << SPEED_FACTOR
            << ": " << passes_text(rows, &Row::time_pass) << "; geometric-mean speed ratio "
            << geometric_mean_text(rows, &Row::speed_ratio, "x") << "\n";

  if(!opt.csv_file.empty())
  {
    std::ofstream csv(opt.csv_file);
    if(!csv) { std::cerr << "error: cannot write " << opt.csv_file << "\n"; return 1; }
    write_csv(csv, opt, rows);
    std::cerr << "wrote " << opt.csv_file << "\n";
  }
  return 0;
}

} // namespace cut_benchmark
