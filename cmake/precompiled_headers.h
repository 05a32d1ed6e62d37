// The headers that the project's own programs (tests, examples, tools,
// benchmark) all include, parsed once into a precompiled header by
// cut_param_precompiled_headers() in CMakeLists.txt. A build-speed aid only:
// every program still includes what it uses, and a program copied out of
// the project compiles without this file.
#include "shared_instances.h" // first: it declares instances the headers below use
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/make_seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

