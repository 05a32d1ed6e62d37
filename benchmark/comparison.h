// The benchmark's default mode: cut_and_parameterize() on the benchmark
// meshes, compared with the reference implementation's measured figures and
// the paper's Table 1.
//
// For every mesh: faces, wall time of the algorithm alone (median of
// --repeat runs), Newton iterations, charts, flipped faces and UV border
// crossings (both recounted on the output), the atlas' coverage of its
// square (the library's figure), E_d and E_s; then the reference's figures, Table 1's figures, and
// whether the targets
//     E_d <= ref E_d + 0.03      and      E_s <= 1.25 ref E_s + 0.05
// are met, with the speed ratio ref_time / our_time.
#ifndef CUT_PARAM_BENCHMARK_COMPARISON_H
#define CUT_PARAM_BENCHMARK_COMPARISON_H

#include "options.h"

namespace cut_benchmark {

/// Prints the table and the summary (and writes --csv); returns the exit status.
int run_comparison(const Options& opt);

} // namespace cut_benchmark

#endif
