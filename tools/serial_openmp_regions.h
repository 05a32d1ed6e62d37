// OpenMP regions of one thread run without a team in the programs of the
// project (serial_openmp_regions.cpp, linked into each of them; the
// reasons there, the measures in the manual, "Linear solvers").
#ifndef CUT_PARAM_TOOLS_SERIAL_OPENMP_REGIONS_H
#define CUT_PARAM_TOOLS_SERIAL_OPENMP_REGIONS_H

// GOMP_parallel can be put first in the symbol lookup on ELF systems with GCC's runtime
#if defined(__GNUC__) && defined(__ELF__) && defined(__linux__)
#define CUT_PARAM_SERIAL_OPENMP_REGIONS 1
#else
#define CUT_PARAM_SERIAL_OPENMP_REGIONS 0
#endif

namespace cut_tools {

/// The number of OpenMP regions this process ran on their calling thread
/// without a team (one thread asked, or no active level left); always 0
/// where CUT_PARAM_SERIAL_OPENMP_REGIONS is 0.
unsigned long openmp_regions_run_serially();

} // namespace cut_tools

#endif
