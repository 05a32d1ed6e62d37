// The reference figures the benchmark compares with: the reference
// implementation measured on this machine type (uvat_reference_measured.csv)
// and the paper's Table 1 (paper_table1.csv), keyed by mesh name (file stem);
// for --optcuts, OptCuts under a distortion bound (optcuts_equal_distortion.csv).
#ifndef CUT_PARAM_BENCHMARK_REFERENCE_TABLES_H
#define CUT_PARAM_BENCHMARK_REFERENCE_TABLES_H

#include "frontier.h"

#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace cut_benchmark {

namespace fs = std::filesystem;

/// A figure that is missing.
const double NaN = std::numeric_limits<double>::quiet_NaN();

using Csv_row = std::map<std::string, std::string>;

/// Reads a CSV file with a header line; blank lines and lines starting with '#'
/// are skipped. Fields may be double-quoted. Returns false if the file cannot
/// be opened.
bool read_csv(const fs::path& file, std::vector<Csv_row>& rows);

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

/// File name without a mesh extension ("optcuts/cat.obj" -> "cat"); names such
/// as "cone2.0_f1500" keep their dots.
std::string stem_of(const std::string& name);

/// Both tables of `dir`; a table that cannot be read is reported on std::cerr
/// and left empty.
References read_references(const fs::path& dir);

/// A row of optcuts_equal_distortion.csv: OptCuts run with its distortion
/// bound set to `bound` (the reference implementation's E_d on the mesh), and
/// what it reached (its time, E_d and E_s).
struct Optcuts_figures
{
  std::string mesh;     // file stem
  double bound = NaN;
  Reference_figures reached;
};

/// Figures of an earlier run of this benchmark, by mesh name: the CSV that
/// --csv wrote (columns mesh, time_s, E_d, E_s). False if the file cannot be
/// read.
bool read_baseline(const fs::path& file, std::map<std::string, Reference_figures>& baseline);

/// The baseline's frontier by mesh name: (E_d, E_s) of the rows of a CSV with
/// columns mesh, E_d, E_s (one row per run, e.g. one per seam cost λ). False
/// if the file cannot be read.
bool read_frontier(const fs::path& file, std::map<std::string, std::vector<Frontier_point>>& frontier);

/// The rows of `dir`/optcuts_equal_distortion.csv, in the file's order; empty
/// (reported on std::cerr) if the file cannot be read.
std::vector<Optcuts_figures> read_optcuts_figures(const fs::path& dir);

} // namespace cut_benchmark

#endif
