// Build speed of the project's own programs (tests, examples, tools,
// benchmark), not part of the library: the core of cut_and_parameterize()
// (internal::cut::run_plan(), which depends on the mesh type only,
// not on the property maps or named parameters) is compiled once per common
// mesh type, in cmake/shared_instances/*.cpp, instead of in every program
// that calls it. Included by cmake/precompiled_headers.h; a program copied
// out of the project compiles without it.
#ifndef CUT_PARAM_SHARED_INSTANCES_H
#define CUT_PARAM_SHARED_INSTANCES_H

// Eigen's 2x2 symmetric eigensolver (the major axis in Bounding_box_term
// and the packing split), compiled once (cmake/shared_instances/surface_mesh.cpp):
// inline members of the library's classes call it, so every program
// instantiated it whether it ran it or not, about 12 s of GCC's time per file
// (measured in CMakeLists.txt). Declared before the headers that use it.
#include <Eigen/Eigenvalues>
#define CUT_PARAM_EIGEN_INSTANCE(KEYWORD)                                                            \
  namespace Eigen {                                                                                  \
  KEYWORD template SelfAdjointEigenSolver<Matrix2d>& SelfAdjointEigenSolver<Matrix2d>::compute<Matrix2d>( \
    const EigenBase<Matrix2d>&, int);                                                                \
  }
CUT_PARAM_EIGEN_INSTANCE(extern)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>

// CUT_PARAM_FOR_EACH_SHARED_MESH(X) calls X(Mesh) for each shared mesh type:
// the tests' and examples' meshes, and the tools' (mesh_input::Mesh).
#define CUT_PARAM_FOR_EACH_SHARED_MESH(X)                                       \
  X(CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>)                \
  X(CGAL::Polyhedron_3<CGAL::Simple_cartesian<double>>)                         \
  X(CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>)

// The instance of one mesh type, declared here and defined (without
// `extern`) in cmake/shared_instances/ (a file per mesh type: they compile
// side by side), which must follow CUT_PARAM_FOR_EACH_SHARED_MESH.
// The plan (both paths of cut_and_parameterize(): with and without a
// distortion bound) and its Debug postcondition: left out, the bound search
// pulled the whole method into every program again (unwrap_surface_mesh.cpp
// took 45 s to compile in Release on 2 cores).
#define CUT_PARAM_SHARED_INSTANCE(KEYWORD, ...)                                                         \
  namespace CGAL { namespace Surface_mesh_parameterization { namespace internal { namespace cut {       \
  KEYWORD template Error_code run_plan<Indexed_surface<__VA_ARGS__>>(                                   \
    const Indexed_surface<__VA_ARGS__>&, const std::vector<double>&, const Cut_parameterization_options&, \
    Map_state&, Work_log&, Packing_result&, bool&);                                                     \
  KEYWORD template bool is_valid_atlas<Indexed_surface<__VA_ARGS__>, Map_state>(                        \
    const Indexed_surface<__VA_ARGS__>&, const Map_state&);                                             \
  }}}}
#define CUT_PARAM_DECLARE_SHARED_INSTANCE(...) CUT_PARAM_SHARED_INSTANCE(extern, __VA_ARGS__)
CUT_PARAM_FOR_EACH_SHARED_MESH(CUT_PARAM_DECLARE_SHARED_INSTANCE)

#endif
