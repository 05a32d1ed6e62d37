#include "options.h"

#include "options/cli_options.h"
#include "text_parsing.h"

#include <CLI/CLI.hpp>

#include <cmath>
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

/// An option of the default mode given with --hard-surface (reported).
static bool misplaced_hard_surface(const std::vector<CLI::Option*>& options)
{
  for(CLI::Option* o : options)
    if(o->count() > 0 && o->get_name() != "--csv")
    {
      std::cerr << "error: " << o->get_name() << " does not apply to --hard-surface\n";
      return true;
    }
  return false;
}

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
  // the method's options: rows of the option table, those of the comparisons in their group
  for(CLI::Option* o : cut_options::add_cli_options(app, opt.given,
                                                    {"lambda", "number_of_passes", "bounding_box_aspect_ratio",
                                                     "bounding_box_stiffness", "global_injectivity"},
                                                    comparison))
    comparisons.push_back(o);
  cut_options::add_cli_options(app, opt.given, {"multiresolution_faces", "inner_solver", "preset"});
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

  const std::string hard = "Hard-surface corpus (--hard-surface)";
  app.add_flag("--hard-surface", opt.hard_surface,
               "run the hard-surface corpus instead: generated CAD-like meshes\n"
               "(gears, plates with holes, brackets, cylinders) and CGAL's CAD-like\n"
               "meshes; Newton iterations per phase (--meshes, --csv, --repeat,\n"
               "--max-faces and the method's options apply)")->group(hard);
  app.add_option("--write-meshes", opt.write_meshes_dir,
                 "with --hard-surface: write each mesh of the corpus as\n"
                 "DIR/<name>.obj instead of running it (for\n"
                 "scripts/blender_smart_uv_comparison.sh)")
    ->type_name("DIR")->group(hard);
  app.add_flag("--packing", opt.packing, "time the atlas packing alone on 1,000 and 10,000 generated charts")
      ->group(scaling);
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
  cut_options::apply(opt.given, opt.method);
  const bool other_method = opt.given_option("number_of_passes") || opt.given_option("bounding_box_aspect_ratio") ||
                            opt.given_option("bounding_box_stiffness") || opt.given_option("global_injectivity") ||
                            opt.given_option("multiresolution_faces");
  if((other_method || opt.given_option("lambda")) && app.count("--baseline") == 0) opt.baseline_file.clear();
  if(other_method && app.count("--baseline-frontier") == 0) opt.frontier_file.clear();
  if(opt.packing) return 0; // no mesh, no option
  if(opt.optcuts && opt.scaling) { std::cerr << "error: --optcuts and --scaling are separate modes\n"; return 2; }
  if(opt.hard_surface && (opt.optcuts || opt.scaling))
  {
    std::cerr << "error: --hard-surface, --optcuts and --scaling are separate modes\n";
    return 2;
  }
  if(!opt.write_meshes_dir.empty() && !opt.hard_surface) { std::cerr << "error: --write-meshes needs --hard-surface\n"; return 2; }
  if(opt.hard_surface) return misplaced_hard_surface(comparison_only) ? 2 : 0;
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
