// The benchmark's hard-surface corpus (--hard-surface): generated CAD-like
// meshes (hard_surface_meshes.h) and CGAL's CAD-like meshes, run with the
// library's defaults (or the options given), one table: faces, time, Newton
// iterations per phase (alternation, final solve, box, relaxations judging
// trials, the rest), factorizations, E_d, E_s, charts, flipped faces,
// border crossings, valid; the ten slowest listed again at the end.
#ifndef CUT_PARAM_BENCHMARK_HARD_SURFACE_H
#define CUT_PARAM_BENCHMARK_HARD_SURFACE_H

#include "options.h"

namespace cut_benchmark {

/// Prints the table (and writes --csv), or only writes the meshes (--write-meshes); returns the exit status.
int run_hard_surface(const Options& opt);

} // namespace cut_benchmark

#endif
