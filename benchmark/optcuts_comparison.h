// The benchmark's --optcuts mode: cut_and_parameterize() against OptCuts at
// equal distortion. For every mesh of optcuts_equal_distortion.csv (OptCuts
// run under a distortion bound, with the time, E_d and E_s it reached), the
// method runs with distortion_bound(B), B the E_d OptCuts reached
// (--optcuts-bound B: the same B for every mesh), and the table gives faces,
// B, time (median of --repeat runs), E_d, E_s, charts, flipped faces and
// distortion_bound_met, OptCuts' figures, the ratios E_s / OptCuts' E_s and
// OptCuts' time / time, and whether the targets
//     E_d <= B,    E_s <= OptCuts' E_s (not with --optcuts-bound),
//     time <= OptCuts' time / 5
// are met.
#ifndef CUT_PARAM_BENCHMARK_OPTCUTS_COMPARISON_H
#define CUT_PARAM_BENCHMARK_OPTCUTS_COMPARISON_H

#include "options.h"

namespace cut_benchmark {

/// Prints the table and the summary (and writes --csv); returns the exit status.
int run_optcuts_comparison(const Options& opt);

} // namespace cut_benchmark

#endif
