// The last stage of every run: the charts of the solved cut mesh cut for
// packing where the options ask, packed, and the atlas checked before it is
// handed out.
#ifndef CGAL_SMP_CUT_INTERNAL_FINISH_ATLAS_H
#define CGAL_SMP_CUT_INTERNAL_FINISH_ATLAS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/packing_split.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/progress.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Packs the charts of the solved cut mesh in `state` (cut first for packing
/// where the options ask) and checks the result
/// (finite, no flipped face, no forbidden edge cut).
template <typename Surface>
Error_code finish_atlas(const Surface& surface, const Cut_parameterization_options& o, const Progress& progress,
                        Map_state& state, Work_log& log, Packing_result& packing)
{
  Scoped_timer packing_timer(log.timings.packing);
  if(o.split_charts_for_packing) packing::cut_charts_for_packing(surface, *o.split_charts_for_packing, state);
  packing = pack_charts(state.chart, state.x, Packing_settings{o.texture_size, o.padding, o.world_units});
  packing_timer.stop();
  // never hand out a silently wrong map (checked in every build type)
  if(!state.x.allFinite() || number_of_flipped_faces(state.chart, state.x) > 0) return ERROR_NO_1_TO_1_MAPPING;
  for(std::size_t e = 0; e < state.rules.forbidden.size(); ++e)
    if(state.rules.forbidden[e] && state.is_cut[e]) return ERROR_FORBIDDEN_EDGES_BLOCK_CUT;
  if(progress && !progress(progress_report("final", o.number_of_passes, 0, alternations_per_pass(o), o.epsilon_end,
                                           state.distortion)))
    return ERROR_CANCELED;
  return OK;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_CUT_INTERNAL_FINISH_ATLAS_H
