// One of the shared instances declared in cmake/shared_instances.h, each in a
// file of its own so that they compile side by side; these files are the
// sources of the target that owns the precompiled header, and every
// program that reuses that header links their objects.
#include "../shared_instances.h"

CUT_PARAM_SHARED_INSTANCE(, CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>)
CUT_PARAM_EIGEN_INSTANCE()
