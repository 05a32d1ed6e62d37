#include "comparison.h"

#include "benchmark_run.h"
#include "mesh_list.h"
#include "reference_tables.h"
#include "table_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace cut_benchmark {

namespace {

// Targets, relative to the reference implementation's measured figures.
const double ED_TOLERANCE = 0.03;   // E_d <= ref E_d + 0.03
const double ES_FACTOR = 1.25;      // E_s <= 1.25 ref E_s + 0.05
const double ES_TOLERANCE = 0.05;
// The baseline's figures are written with 10 significant digits: the same
// seams read back may be longer by a rounding.
const double BASELINE_ROUNDING = 1e-9;
// The speed target: the reference's time / SPEED_TARGET or less.
const double SPEED_TARGET = 7.;

struct Row
{
  Mesh_entry mesh;
  Run_result run;
  const Reference_figures* measured = nullptr;
  const Reference_figures* paper = nullptr;
  const Reference_figures* baseline = nullptr;
  int ed_pass = -1, es_pass = -1;  // -1: no reference to compare with
  int baseline_pass = -1;          // -1: no baseline figures
  double frontier_seam = NaN;      // the baseline frontier's E_s at this run's E_d
  int frontier_pass = -1;          // -1: no frontier at this E_d
  double speedup = NaN;
};

/// vs_base: "yes" (E_d and E_s against the baseline's run), "front" (E_s
/// against the baseline's frontier at this E_d only), "NO", "-" (nothing to
/// compare with).
std::string vs_baseline_text(const Row& row)
{
  if(row.baseline_pass > 0) return "yes";
  if(row.frontier_pass > 0) return "front";
  return row.baseline_pass < 0 && row.frontier_pass < 0 ? "-" : "NO";
}

} // namespace

int run_comparison(const Options& opt)
{
  const References refs = read_references(opt.reference_dir);
  std::map<std::string, Reference_figures> baseline;
  if(!opt.baseline_file.empty() && !read_baseline(opt.baseline_file, baseline))
  {
    std::cerr << "error: cannot read the baseline " << opt.baseline_file.string() << " (--baseline \"\" for none)\n";
    return 2;
  }
  std::map<std::string, std::vector<Frontier_point>> frontier;
  if(!opt.frontier_file.empty() && !read_frontier(opt.frontier_file, frontier))
  {
    std::cerr << "error: cannot read the baseline frontier " << opt.frontier_file.string()
              << " (--baseline-frontier \"\" for none)\n";
    return 2;
  }
  std::vector<std::string> missing;
  const std::vector<Mesh_entry> meshes = mesh_list(opt, refs, missing);
  if(meshes.empty())
  {
    std::cerr << "error: no mesh to run (mesh folder: " << opt.mesh_dir.string() << ")\n";
    return 2;
  }

  const auto np = method_parameters(opt, SMP::Cut_parameterization_options().distortion_bound); // no bound
  std::vector<Row> rows;
  for(const auto& m : meshes)
  {
    Row row;
    row.mesh = m;
    row.run = benchmark_mesh_logged(rows.size() + 1, meshes.size(), m, opt, np);
    rows.push_back(std::move(row));
  }

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
    auto bt = baseline.find(row.mesh.name);
    if(bt != baseline.end() && !std::isnan(bt->second.distortion) && !std::isnan(bt->second.seam_length))
    {
      row.baseline = &bt->second;
      row.baseline_pass = row.run.ok && row.run.distortion <= row.baseline->distortion + BASELINE_ED_TOLERANCE
                          && row.run.seam_length <= row.baseline->seam_length * (1. + BASELINE_ROUNDING);
    }
    auto ft = frontier.find(row.mesh.name);
    if(row.run.ok && ft != frontier.end())
    {
      row.frontier_seam = frontier_seam_length(ft->second, row.run.distortion);
      if(!std::isnan(row.frontier_seam))
        row.frontier_pass = row.run.seam_length <= row.frontier_seam * (1. + BASELINE_ROUNDING);
    }
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
    {"mesh", true}, {"faces"}, {"time_s"}, {"newton"}, {"fact_u+rest"}, {"solves_u+rest"}, {"fact_v"}, {"charts"}, {"flips"}, {"crossings"}, {"coverage"},
    {"E_d"}, {"E_s"},
    {"ref_t"}, {"ref_E_d"}, {"ref_E_s"}, {"T1_t"}, {"T1_E_d"}, {"T1_E_s"},
    {"E_d_ok"}, {"E_s_ok"}, {"speedup"}, {"base_E_d"}, {"base_E_s"}, {"front_E_s"}, {"vs_base"}, {"status", true}};
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
      r.ok ? std::to_string(r.u_factorizations) + "+" + std::to_string(r.factorizations - r.u_factorizations) : "-",
      r.ok ? std::to_string(r.u_solves) + "+" + std::to_string(r.solves - r.u_solves) : "-",
      r.ok ? std::to_string(r.v_factorizations) : "-",
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
      row.baseline ? fixed(row.baseline->distortion, 4) : "-",
      row.baseline ? fixed(row.baseline->seam_length, 4) : "-",
      std::isnan(row.frontier_seam) ? "-" : fixed(row.frontier_seam, 4),
      vs_baseline_text(row),
      r.status});
  }

  std::cout << "cut_and_parameterize benchmark\n"
            << "  meshes:     " << opt.mesh_dir.lexically_normal().string() << "\n"
            << "  references: " << opt.reference_dir.lexically_normal().string() << "\n"
            << "  parameters: " << parameters_text(opt)
            << (opt.quick ? "; --quick (faces < 5000)" : "") << "\n\n";
  print_table(std::cout, columns, cells);

  // Summary.
  std::size_t compared = 0, passed = 0, failed_runs = 0, with_flips = 0, with_crossings = 0;
  double log_sum = 0.;
  std::size_t n_speed = 0, fast_enough = 0, with_baseline = 0, as_good = 0, on_frontier_only = 0;
  for(const auto& row : rows)
  {
    if(!std::isnan(row.speedup) && row.speedup >= SPEED_TARGET) ++fast_enough;
    if(row.baseline_pass >= 0 || row.frontier_pass >= 0) ++with_baseline;
    if(row.baseline_pass > 0 || row.frontier_pass > 0) ++as_good;
    if(row.baseline_pass <= 0 && row.frontier_pass > 0) ++on_frontier_only;
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
            << "newton: inner-solver iterations; fact_u+rest, solves_u+rest: Cholesky factorizations and solves with\n"
            << "  them, in the alternation's u-steps + in the rest (final solves, split and zip trials); fact_v: v-steps\n"
            << "base_*: the baseline run (" << (opt.baseline_file.empty() ? std::string("none") : opt.baseline_file.lexically_normal().string())
            << "); vs_base: yes if E_d <= base_E_d + " << BASELINE_ED_TOLERANCE << " and E_s <= base_E_s, "
            << "front if E_s <= front_E_s only\n"
            << "front_E_s: the baseline's E_s at this E_d, on its frontier over seam costs ("
            << (opt.frontier_file.empty() ? std::string("none") : opt.frontier_file.lexically_normal().string())
            << "; - below its least E_d)\n"
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
  if(n_speed) std::cout << fixed(std::exp(log_sum / double(n_speed)), 2) << "x over " << n_speed << " meshes";
  else std::cout << "-";
  std::cout << "; speedup " << fixed(SPEED_TARGET, 0) << "x or more: " << fast_enough << "/" << n_speed;
  if(with_baseline)
    std::cout << "; at least as good as the baseline: " << as_good << "/" << with_baseline << " ("
              << on_frontier_only << " at equal E_d only)";
  std::cout << "\n";

  // CSV.
  if(!opt.csv_file.empty())
  {
    std::ofstream csv(opt.csv_file);
    if(!csv) { std::cerr << "error: cannot write " << opt.csv_file << "\n"; return 1; }
    csv << "mesh,file,faces,time_s,newton_iterations,charts,flipped_faces,crossings,coverage,E_d,E_s,"
           "ref_time_s,ref_E_d,ref_E_s,paper_time_s,paper_E_d,paper_E_s,"
           "E_d_pass,E_s_pass,speedup,baseline_E_d,baseline_E_s,baseline_pass,frontier_E_s,frontier_pass,status,"
           "factorizations,solves,u_step_factorizations,u_step_solves,v_step_factorizations\n";
    for(const auto& row : rows)
    {
      const auto& r = row.run;
      const auto* m = row.measured;
      const auto* p = row.paper;
      csv << csv_field(row.mesh.name) << "," << csv_field(relative_file(row.mesh, opt.mesh_dir)) << ","
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
          << full(row.speedup) << ","
          << (row.baseline ? full(row.baseline->distortion) : "") << ","
          << (row.baseline ? full(row.baseline->seam_length) : "") << ","
          << pass_csv(row.baseline_pass) << "," << full(row.frontier_seam) << ","
          << pass_csv(row.frontier_pass) << "," << csv_field(r.status) << ","
          << (r.ok ? std::to_string(r.factorizations) : "") << "," << (r.ok ? std::to_string(r.solves) : "") << ","
          << (r.ok ? std::to_string(r.u_factorizations) : "") << "," << (r.ok ? std::to_string(r.u_solves) : "") << ","
          << (r.ok ? std::to_string(r.v_factorizations) : "") << "\n";
    }
    std::cerr << "wrote " << opt.csv_file << "\n";
  }
  return 0;
}

} // namespace cut_benchmark
