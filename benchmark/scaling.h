// The benchmark's scaling run (--scaling): how time and memory grow with the
// mesh, and where the time goes.
//
// Meshes: optcuts/bimba_i_f10000.obj of the mesh folder, the same refined by
// 1, 2 and 3 rounds of 1-to-4 midpoint subdivision (4, 16, 64 times its
// faces: the surface is unchanged, only finer), and CGAL's
// meshes/refined_elephant.off. cut_and_parameterize() runs with its default
// named parameters, each run in a child process of its own (tools/child_process.h)
// that reads (and subdivides) the mesh, runs the method and sends back the
// result's timings, counts and measures and its own peak memory. For every
// mesh, one row: faces, total time and its phases
// (Cut_and_parameterize_timings), Newton iterations, Cholesky
// factorizations, peak memory, E_d, E_s, charts; each figure the median of
// --repeat runs up to SCALING_REPEAT_MAX_FACES faces, of one run above.
#ifndef CUT_PARAM_BENCHMARK_SCALING_H
#define CUT_PARAM_BENCHMARK_SCALING_H

#include "options.h"

#include <string>

namespace cut_benchmark {

/// A file of CGAL's data set: through CGAL_DATA_DIR (CGAL::data_file_path())
/// when it is set, else in the data/ folder that the build extracts next to
/// bin/. Empty if not found.
fs::path cgal_data_file(const std::string& name);

/// Prints the table (and writes --json); returns the exit status.
int run_scaling(const Options& opt);

} // namespace cut_benchmark

#endif
