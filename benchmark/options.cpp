#include "options.h"

#include "text_parsing.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <map>
#include <iostream>
#include <sstream>

namespace cut_benchmark {

fs::path project_root()
{
#ifdef CUT_PARAM_BENCHMARK_PROJECT_ROOT
  return fs::path(CUT_PARAM_BENCHMARK_PROJECT_ROOT);
#else
  return fs::path(".");
#endif
}

namespace {

// "W:H", both positive numbers: the aspect ratio W / H.
bool parse_aspect_ratio(const std::string& text, double& ratio)
{
  const std::size_t colon = text.find(':');
  double w = 0., h = 0.;
  if(colon == std::string::npos || !parse_double(text.substr(0, colon), w) ||
     !parse_double(text.substr(colon + 1), h) || !(w > 0.) || !(h > 0.))
    return false;
  ratio = w / h;
  return std::isfinite(ratio) && ratio > 0.;
}

const char* const description =
  "Runs cut_and_parameterize() on a list of meshes and compares with the reference\n"
  "implementation's measured figures and the paper's Table 1.\n\n"
  "OptCuts comparison (--optcuts): each mesh of optcuts_equal_distortion.csv under\n"
  "distortion_bound(B), B the E_d OptCuts reached on it (or --optcuts-bound B for all);\n"
  "time, E_d and E_s against OptCuts' (targets: E_d <= B, E_s <= OptCuts' E_s, time\n"
  "<= OptCuts' time / 5).\n\n"
  "Scaling run (--scaling): time, memory and where the time goes, as the mesh grows.\n"
  "Meshes: optcuts/bimba_i_f10000.obj of the mesh folder, refined by 1-to-4 midpoint\n"
  "subdivision to 4, 16 and 64 times its faces, and CGAL's meshes/refined_elephant.off\n"
  "(CGAL_DATA_DIR, else the data/ folder next to the build's bin/; left out if absent).\n"
  "Library defaults; each run in its own child process (peak memory: its maximum\n"
  "resident set size). Per mesh: total time and its phases, Newton iterations,\n"
  "Cholesky factorizations, peak memory, E_d, E_s, charts.";

} // namespace

int parse_options(int argc, char** argv, Options& opt)
{
  opt.mesh_dir = project_root() / ".." / "shared" / "meshes";
  opt.reference_dir = project_root() / ".." / "shared" / "reference";
  opt.baseline_file = project_root() / DEFAULT_BASELINE;
  opt.frontier_file = project_root() / DEFAULT_BASELINE_FRONTIER;
  CLI::App app(description, "benchmark_cut_parameterization");
  app.get_formatter()->column_width(30);
  const auto positive = CLI::PositiveNumber & CLI::Validator(
    [](std::string& v) { double x; return parse_double(v, x) && std::isfinite(x) ? std::string() : "not finite"; }, "");

  // options of the comparisons (default mode and --optcuts), of the default
  // mode alone, and of the scaling run
  const std::string comparison = "Comparisons (default mode and --optcuts)",
                    optcuts = "OptCuts comparison (--optcuts)", scaling = "Scaling run (--scaling)";
  std::vector<CLI::Option*> comparisons, comparison_only, scaling_only;
  std::string meshes;
  comparisons.push_back(
    app.add_option("--meshes", meshes,
                   "mesh names (file stems, e.g. cat,venus; or paths relative to\n"
                   "the mesh folder, e.g. optcuts/cat.obj). Default: every mesh named\n"
                   "in the reference tables that exists in the mesh folder")
      ->type_name("A,B,C")->group(comparison));
  app.add_option("--mesh-dir", opt.mesh_dir, "mesh folder (holding uvat/ and optcuts/); default\n"
                                             "../shared/meshes relative to the project root")
    ->type_name("DIR");
  comparisons.push_back(
    app.add_option("--reference-dir", opt.reference_dir,
                   "folder of uvat_reference_measured.csv, paper_table1.csv and\n"
                   "optcuts_equal_distortion.csv; default ../shared/reference\n"
                   "relative to the project root")
      ->type_name("DIR")->group(comparison));
  comparisons.push_back(app.add_option("--lambda", opt.lambda, "seam cost lambda (library default if not given)")
                          ->type_name("X")->check(positive)->group(comparison));
  comparisons.push_back(app.add_option("--passes", opt.passes, "number of passes (library default if not given)")
                          ->type_name("N")->check(CLI::NonNegativeNumber)->group(comparison));
  comparisons.push_back(
    app.add_option_function<std::string>("--box", [&opt](const std::string& v) {
        double ratio = 1.;
        parse_aspect_ratio(v, ratio);
        opt.box = ratio;
      }, "tight bounding box of aspect ratio W/H (default: the library's\ngentle square)")
      ->type_name("W:H")
      ->check(CLI::Validator([](std::string& v) {
          double ratio;
          return parse_aspect_ratio(v, ratio) ? std::string() : "expected W:H, two positive numbers, got '" + v + "'";
        }, ""))
      ->group(comparison));
  comparisons.push_back(
    app.add_option("--box-stiffness", opt.box_stiffness,
                   "how hard the box pulls, >= 0 (0: no box; library default if not given)")
      ->type_name("S")->check(CLI::NonNegativeNumber)->group(comparison));
  app.add_option("--multiresolution-faces", opt.multiresolution_faces,
                 "cuts decided on a copy simplified to N faces for meshes\n"
                 "of more than 2N (0: full resolution; library default if not given)")
    ->type_name("N")->check(CLI::NonNegativeNumber);
  app.add_option("--inner-solver", opt.inner_solver,
                 "inner solver of the UV minimizations: newton (default) or quasi-newton\n"
                 "(the Hessian factorized at a few iterates, L-BFGS between them)")
    ->transform(CLI::CheckedTransformer(std::map<std::string, CGAL::Surface_mesh_parameterization::Inner_solver>{
        {"newton", CGAL::Surface_mesh_parameterization::Inner_solver::NEWTON},
        {"quasi-newton", CGAL::Surface_mesh_parameterization::Inner_solver::PROXY_QUASI_NEWTON}}))
    ->type_name("NAME");
  comparisons.push_back(
    app.add_flag("--allow-overlaps", opt.allow_overlaps,
                 "global_injectivity(false): no border barrier (with --box-stiffness 0, the\n"
                 "map as it was before the atlas work, only packed)")->group(comparison));
  app.add_option("--repeat", opt.repeat,
                 "runs per mesh; the time reported is their median (default 1;\n"
                 "with --scaling 3, for meshes up to " + std::to_string(SCALING_REPEAT_MAX_FACES) + " faces)")
    ->type_name("N")->check(CLI::PositiveNumber);
  comparisons.push_back(app.add_option("--csv", opt.csv_file, "also write the table as CSV")
                          ->type_name("FILE")->group(comparison));
  comparison_only.push_back(
    app.add_option("--baseline", opt.baseline_file,
                   "CSV of an earlier run (what --csv writes) to compare each mesh\n"
                   "with: at least as good if E_d <= its E_d + 0.02 and E_s <= its E_s;\n"
                   "default " + std::string(DEFAULT_BASELINE) + " (library defaults at the\n"
                   "project's commit 8ae88e6); \"\" for none (default mode only)")
      ->type_name("FILE")->group(comparison));
  comparison_only.push_back(
    app.add_option("--baseline-frontier", opt.frontier_file,
                   "CSV of the baseline run with other seam costs (columns mesh, E_d,\n"
                   "E_s; a row per run): a mesh is also at least as good as the baseline\n"
                   "if its E_s is at most the frontier's at its E_d (lower envelope, linear\n"
                   "between runs); default " + std::string(DEFAULT_BASELINE_FRONTIER) + ";\n"
                   "\"\" for none (default mode only)")
      ->type_name("FILE")->group(comparison));
  comparison_only.push_back(
    app.add_flag("--quick", opt.quick, "only meshes with fewer than " + std::to_string(QUICK_MAX_FACES) + " faces\n"
                 "(default mode only)")
      ->group(comparison));

  app.add_flag("--optcuts", opt.optcuts, "compare with OptCuts under a distortion bound instead")->group(optcuts);
  app.add_option("--optcuts-bound", opt.optcuts_bound,
                 "every mesh under this bound B >= 4 instead of the E_d OptCuts\n"
                 "reached (E_s not compared; implies --optcuts)")
    ->type_name("B")
    ->check(CLI::Validator([](std::string& v) {
        double x;
        return parse_double(v, x) && std::isfinite(x) && x >= 4.
                 ? std::string() : "a distortion bound is a finite number >= 4, got '" + v + "'";
      }, ""))
    ->group(optcuts);

  app.add_flag("--scaling", opt.scaling, "run the scaling benchmark instead of the comparison")->group(scaling);
  scaling_only.push_back(app.add_option("--max-faces", opt.max_faces,
                                        "leave out meshes of more than N faces (default: none left out)")
                           ->type_name("N")->check(CLI::PositiveNumber)->group(scaling));
  std::ostringstream limit;
  limit << SCALING_DEFAULT_TIME_LIMIT;
  scaling_only.push_back(app.add_option("--time-limit", opt.time_limit,
                                        "seconds a run may take before it is killed (default " + limit.str() + ")")
                           ->type_name("S")->check(positive)->group(scaling));
  scaling_only.push_back(app.add_option("--json", opt.json_file, "also write the table as JSON")
                           ->type_name("FILE")->group(scaling));

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::CallForHelp& e)
  {
    app.exit(e);
    return 1;
  }
  catch(const CLI::ParseError& e)
  {
    std::cerr << "error: " << e.what() << " (see --help)\n";
    return 2;
  }
  for(const auto& name : split(meshes, ','))
    if(!trim(name).empty()) opt.meshes.push_back(trim(name));
  if(app.count("--meshes") && opt.meshes.empty()) { std::cerr << "error: --meshes: empty list\n"; return 2; }
  if(opt.optcuts_bound) opt.optcuts = true;
  // the default baseline holds the library's defaults: with other method
  // parameters, no comparison unless a baseline is named
  // (the frontier covers other seam costs λ: only the other parameters clear it)
  const bool other_method = opt.passes || opt.box || opt.box_stiffness || opt.allow_overlaps || opt.multiresolution_faces;
  if((other_method || opt.lambda) && app.count("--baseline") == 0) opt.baseline_file.clear();
  if(other_method && app.count("--baseline-frontier") == 0) opt.frontier_file.clear();
  if(opt.optcuts && opt.scaling) { std::cerr << "error: --optcuts and --scaling are separate modes\n"; return 2; }
  // an option of another mode than the one run
  auto misplaced = [](const std::vector<CLI::Option*>& options, const std::string& why) {
    for(CLI::Option* o : options)
      if(o->count() > 0) { std::cerr << "error: " << o->get_name() << why << "\n"; return true; }
    return false;
  };
  if(opt.scaling)
    return misplaced(comparisons, " does not apply to --scaling")
           || misplaced(comparison_only, " does not apply to --scaling") ? 2 : 0;
  if(misplaced(scaling_only, " needs --scaling")) return 2;
  return opt.optcuts && misplaced(comparison_only, " does not apply to --optcuts") ? 2 : 0;
}

} // namespace cut_benchmark
