// The map state of a run: which edges are cut, the chart mesh, its map and
// the field v (the work log is apart: work_log.h).
#ifndef CGAL_SMP_CUT_INTERNAL_MAP_STATE_H
#define CGAL_SMP_CUT_INTERNAL_MAP_STATE_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Cut_rules.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// The state of the cut mesh: which edges are cut, its chart mesh and UVs.
struct Map_state
{
  std::vector<char> is_cut;      // per surface edge
  Cut_rules rules;               // forbidden edges and the cost of cutting each edge
  Chart_mesh chart;
  std::vector<int> corner_uv;    // per surface corner
  UV_vector x;
  Eigen::VectorXd v;             // per face
  std::size_t degenerate_faces = 0; // faces whose rest shape was clamped
  double initial_distortion = 0.;
  double distortion = 0.;           // E_d of the final map, before packing scales it
  // chart, x and v hold the initial cut mesh after the alternation's first
  // u-step (prepare_first_u_step()): the first pass starts at its v-step
  bool first_u_step_done = false;
};

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
