// The benchmark's packing run (--packing): the atlas packing alone
// (chart_packing.h) on 1,000 and 10,000 generated charts (rectangles, L
// shapes, triangles and disks of random sizes and angles), by rectangles
// only and with the shape packing: time and coverage per row. The target:
// 10,000 charts in at most 2 s.
#ifndef CUT_PARAM_BENCHMARK_PACKING_H
#define CUT_PARAM_BENCHMARK_PACKING_H

#include "options.h"

namespace cut_benchmark {

/// Prints the table; returns the exit status.
int run_packing(const Options& opt);

} // namespace cut_benchmark

#endif
