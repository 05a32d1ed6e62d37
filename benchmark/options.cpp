#include "options.h"

#include "text_parsing.h"

#include <cmath>
#include <iostream>

namespace cut_benchmark {

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
     << "       " << program << " --scaling [--max-faces N] [--time-limit S] [--repeat N] [--json FILE]\n"
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
     << "  --box W:H           tight bounding box of aspect ratio W/H (default: the library's\n"
     << "                      gentle square)\n"
     << "  --box-stiffness S   how hard the box pulls, >= 0 (0: no box; library default if not given)\n"
     << "  --multiresolution-faces N  cuts decided on a copy simplified to N faces for meshes\n"
     << "                      of more than 2N (0: full resolution; library default if not given)\n"
     << "  --allow-overlaps    global_injectivity(false): no scaffold (with --box-stiffness 0, the\n"
     << "                      map as it was before the atlas work, only packed)\n"
     << "  --repeat N          runs per mesh; the time reported is their median (default 1;\n"
     << "                      with --scaling 3, for meshes up to " << SCALING_REPEAT_MAX_FACES
     << " faces)\n"
     << "  --csv FILE          also write the table as CSV\n"
     << "  --quick             only meshes with fewer than " << QUICK_MAX_FACES << " faces\n"
     << "  --help              this text\n\n"
     << "Scaling run (--scaling): time, memory and where the time goes, as the mesh grows.\n"
     << "Meshes: optcuts/bimba_i_f10000.obj of the mesh folder, refined by 1-to-4 midpoint\n"
     << "subdivision to 4, 16 and 64 times its faces, and CGAL's meshes/refined_elephant.off\n"
     << "(CGAL_DATA_DIR, else the data/ folder next to the build's bin/; left out if absent).\n"
     << "Library defaults; each run in its own child process (peak memory: its maximum\n"
     << "resident set size). Per mesh: total time and its phases, Newton iterations,\n"
     << "Cholesky factorizations, peak memory, E_d, E_s, charts.\n"
     << "  --scaling           run the scaling benchmark instead of the comparison\n"
     << "  --max-faces N       leave out meshes of more than N faces (default: none left out)\n"
     << "  --time-limit S      seconds a run may take before it is killed (default "
     << SCALING_DEFAULT_TIME_LIMIT << ")\n"
     << "  --json FILE         also write the table as JSON\n"
     << "  (--mesh-dir and --repeat apply too; the other options do not)\n";
}

int parse_options(int argc, char** argv, Options& opt)
{
  opt.mesh_dir = project_root() / ".." / "shared" / "meshes";
  opt.reference_dir = project_root() / ".." / "shared" / "reference";
  std::vector<std::string> comparison_only, scaling_only; // options given
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
    else if(arg == "--quick") { opt.quick = true; comparison_only.push_back(arg); }
    else if(arg == "--meshes")
    {
      if(!value(v)) return 2;
      for(const auto& name : split(v, ','))
        if(!trim(name).empty()) opt.meshes.push_back(trim(name));
      if(opt.meshes.empty()) { std::cerr << "error: --meshes: empty list\n"; return 2; }
      comparison_only.push_back(arg);
    }
    else if(arg == "--mesh-dir") { if(!value(v)) return 2; opt.mesh_dir = v; }
    else if(arg == "--reference-dir")
    {
      if(!value(v)) return 2;
      opt.reference_dir = v;
      comparison_only.push_back(arg);
    }
    else if(arg == "--csv") { if(!value(v)) return 2; opt.csv_file = v; comparison_only.push_back(arg); }
    else if(arg == "--lambda")
    {
      double x;
      if(!value(v)) return 2;
      if(!parse_double(v, x) || !(x > 0.) || !std::isfinite(x))
      { std::cerr << "error: --lambda: expected a positive number, got '" << v << "'\n"; return 2; }
      opt.lambda = x;
      comparison_only.push_back(arg);
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
      comparison_only.push_back(arg);
    }
    else if(arg == "--box-stiffness")
    {
      double x;
      if(!value(v)) return 2;
      if(!parse_double(v, x) || !(x >= 0.) || !std::isfinite(x))
      { std::cerr << "error: --box-stiffness: expected a number >= 0, got '" << v << "'\n"; return 2; }
      opt.box_stiffness = x;
      comparison_only.push_back(arg);
    }
    else if(arg == "--passes")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 0)
      { std::cerr << "error: --passes: expected a non-negative integer, got '" << v << "'\n"; return 2; }
      opt.passes = n;
      comparison_only.push_back(arg);
    }
    else if(arg == "--multiresolution-faces")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 0)
      { std::cerr << "error: --multiresolution-faces: expected an integer >= 0, got '" << v << "'\n"; return 2; }
      opt.multiresolution_faces = n;
    }
    else if(arg == "--allow-overlaps")
    {
      opt.allow_overlaps = true;
      comparison_only.push_back(arg);
    }
    else if(arg == "--repeat")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 1)
      { std::cerr << "error: --repeat: expected a positive integer, got '" << v << "'\n"; return 2; }
      opt.repeat = n;
    }
    else if(arg == "--scaling") opt.scaling = true;
    else if(arg == "--max-faces")
    {
      int n;
      if(!value(v)) return 2;
      if(!parse_int(v, n) || n < 1)
      { std::cerr << "error: --max-faces: expected a positive integer, got '" << v << "'\n"; return 2; }
      opt.max_faces = std::size_t(n);
      scaling_only.push_back(arg);
    }
    else if(arg == "--time-limit")
    {
      double x;
      if(!value(v)) return 2;
      if(!parse_double(v, x) || !(x > 0.) || !std::isfinite(x))
      { std::cerr << "error: --time-limit: expected a positive number of seconds, got '" << v << "'\n"; return 2; }
      opt.time_limit = x;
      scaling_only.push_back(arg);
    }
    else if(arg == "--json") { if(!value(v)) return 2; opt.json_file = v; scaling_only.push_back(arg); }
    else
    {
      std::cerr << "error: unknown option '" << arg << "'\n";
      print_usage(argv[0], std::cerr);
      return 2;
    }
  }
  if(opt.scaling && !comparison_only.empty())
  {
    std::cerr << "error: " << comparison_only.front() << " does not apply to --scaling\n";
    return 2;
  }
  if(!opt.scaling && !scaling_only.empty())
  {
    std::cerr << "error: " << scaling_only.front() << " needs --scaling\n";
    return 2;
  }
  return 0;
}

} // namespace cut_benchmark
