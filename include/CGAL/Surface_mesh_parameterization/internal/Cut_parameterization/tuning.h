// Every threshold and tuning constant of the method, in one place: each with
// a one-line reason; the measurements behind the values are in the manual's
// page "Design and measurements" (doc/design/).
#ifndef CGAL_SMP_CUT_INTERNAL_TUNING_H
#define CGAL_SMP_CUT_INTERNAL_TUNING_H

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace tuning {

// ---- Linear algebra, energies and inner solvers (linalg/, mesh/, energy/, solver/)



// ---- end of the solver section



// ---- Cuts, seams, atlas and the plan (cuts/, seams/, atlas/, pipeline/)



// ---- end of the pipeline section

} // namespace tuning
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
