// Benchmark of cut_and_parameterize().
//
// Default mode (comparison.h): the benchmark meshes against the reference
// implementation (the paper's published code, measured on this machine type)
// and the paper's Table 1.
// --optcuts (optcuts_comparison.h): the OptCuts meshes at equal distortion
// against OptCuts' time, E_d and E_s.
// --hard-surface (hard_surface.h): generated CAD-like meshes and CGAL's,
// Newton iterations per phase.
// --scaling (scaling.h): time, memory and where the time goes as the mesh
// grows, up to 640k faces.
// --packing (packing.h): the atlas packing alone on 1,000 and 10,000 charts.
//
// Run with --help for the options.

#include "comparison.h"
#include "hard_surface.h"
#include "optcuts_comparison.h"
#include "options.h"
#include "packing.h"
#include "scaling.h"

#include "blas_setup.h"      // tools/
#include "malloc_settings.h" // tools/

int main(int argc, char** argv)
{
  cut_tools::use_vector_blas_kernels(argv); // see blas_setup.h
  cut_benchmark::Options opt;
  if(const int r = cut_benchmark::parse_options(argc, argv, opt)) return r == 1 ? 0 : r;
  if(cut_tools::use_one_blas_thread()) cut_tools::stop_blas_worker_threads();
  cut_tools::keep_freed_memory();
  if(opt.packing) return cut_benchmark::run_packing(opt);
  if(opt.scaling) return cut_benchmark::run_scaling(opt);
  if(opt.hard_surface) return cut_benchmark::run_hard_surface(opt);
  return opt.optcuts ? cut_benchmark::run_optcuts_comparison(opt) : cut_benchmark::run_comparison(opt);
}
