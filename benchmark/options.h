// Command line of the benchmark: the comparison with the reference tables
// (default mode), the comparison with OptCuts (--optcuts) and the scaling run
// (--scaling).
#ifndef CUT_PARAM_BENCHMARK_OPTIONS_H
#define CUT_PARAM_BENCHMARK_OPTIONS_H

#include "options/option_table.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cut_benchmark {

namespace fs = std::filesystem;

/// --quick: only meshes with fewer faces.
const std::size_t QUICK_MAX_FACES = 5000;
/// --scaling: meshes up to this many faces are run --repeat times, bigger ones once.
const std::size_t SCALING_REPEAT_MAX_FACES = 40000;
/// The default mode's baseline: the library's defaults measured on this
/// machine type at the project's commit 8ae88e6, relative to the project root.
const char* const DEFAULT_BASELINE = "benchmark/baseline_8ae88e6.csv";
/// The baseline's frontier: the same commit run with other seam costs λ
/// (mesh, lambda, E_d, E_s), relative to the project root.
const char* const DEFAULT_BASELINE_FRONTIER = "benchmark/baseline_8ae88e6_frontier.csv";
/// A run is at least as good as its baseline if E_d <= base E_d + this and
/// E_s <= base E_s, or if E_s is at most the baseline frontier's at its E_d.
const double BASELINE_ED_TOLERANCE = 0.02;
/// --scaling: default time limit of one run, in seconds.
const double SCALING_DEFAULT_TIME_LIMIT = 1800.;

struct Options
{
  fs::path mesh_dir;
  fs::path reference_dir;
  std::vector<std::string> meshes;     // empty: the default list
  // the method's options, flags from the option table (tools/options/option_table.h):
  // --lambda, --passes, --box, --box-stiffness, --allow-overlaps,
  // --multiresolution-faces, --inner-solver; one slot per row (nullopt: not given)
  cut_options::Given_options given;
  // them as the library's options: those not given left as the library leaves them
  CGAL::Surface_mesh_parameterization::Cut_parameterization_options method = cut_options::front_end_options();
  /// The option of this field of Cut_parameterization_options was given.
  bool given_option(const char* name) const
  {
    const std::size_t i = cut_options::option_index(name);
    return i < given.size() && given[i].has_value();
  }
  std::optional<int> repeat;           // empty: the mode's default (repeat())
  std::string csv_file;
  bool quick = false;
  // default mode: the figures of an earlier run to compare with (empty: none)
  fs::path baseline_file;
  // default mode: the baseline's runs with other seam costs (empty: none)
  fs::path frontier_file;

  // --optcuts
  bool optcuts = false;
  std::optional<double> optcuts_bound; // empty: each mesh under the E_d OptCuts reached

  // --hard-surface
  bool hard_surface = false;
  fs::path write_meshes_dir;           // empty: the corpus is not written
  // --packing
  bool packing = false;

  // --scaling
  bool scaling = false;
  std::optional<std::size_t> max_faces; // empty: no limit
  double time_limit = SCALING_DEFAULT_TIME_LIMIT;
  std::string json_file;

  /// Runs per mesh: --repeat, else 1 (3 with --scaling).
  int repeat_count() const { return repeat.value_or(scaling ? 3 : 1); }
};

/// The project's root as seen when the benchmark was configured ("." if unknown).
fs::path project_root();

/// Returns 0 to run, 1 to exit with success (--help), 2 on a usage error
/// (reported on std::cerr).
int parse_options(int argc, char** argv, Options& opt);

} // namespace cut_benchmark

#endif
