// The mesh type the benchmark runs cut_and_parameterize() on.
#ifndef CUT_PARAM_BENCHMARK_BENCHMARK_MESH_H
#define CUT_PARAM_BENCHMARK_BENCHMARK_MESH_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

namespace cut_benchmark {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

} // namespace cut_benchmark

#endif
