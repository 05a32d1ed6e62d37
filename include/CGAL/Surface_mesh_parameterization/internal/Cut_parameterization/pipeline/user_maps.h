// What cut_and_parameterize() reads from the user's property maps and
// writes to them and to its result: corner UVs (and those of border edges
// glued by welding), seams, forbidden edges, timings and statistics.
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CUT_PARAMETERIZATION_PIPELINE_USER_MAPS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CUT_PARAMETERIZATION_PIPELINE_USER_MAPS_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_result.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/border_crossings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/util/Scoped_timer.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {
namespace cut {

/// Writable face map that drops what it is given (no v output requested).
struct Ignored_face_map
{
  template <typename Key, typename Value>
  friend void put(const Ignored_face_map&, const Key&, const Value&) {}
};

/// UV of every corner at its halfedge; a border halfedge gets the UV of the
/// corner at its target in the face across.
template <typename TriangleMesh, typename HalfedgeUVMap>
void write_corner_uvs(const TriangleMesh& mesh, const Indexed_surface<TriangleMesh>& surface,
                      const Map_state& state, HalfedgeUVMap uvmap)
{
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
  auto uv = [&](int corner) {
    const int i = state.corner_uv[corner];
    return Point_2(state.x[2*i], state.x[2*i+1]);
  };
  for(std::size_t c = 0; c < state.corner_uv.size(); ++c)
    put(uvmap, surface.corner_halfedge[c / 3][c % 3], uv(int(c)));
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < 0)
      put(uvmap, opposite(surface.face_edge_halfedge(fe), mesh), uv(fe));
}

/// After welding (mesh/colocal_vertices.h): the input's border halfedges
/// across the face-edges `glued` get the UV of the corner at their target;
/// their edges, on the input's border, are never seams (a `Seam_mesh`'s
/// seams are interior edges).
template <typename TriangleMesh, typename Surface, typename HalfedgeUVMap, typename SeamEdgeMap>
void write_glued_outputs(const TriangleMesh& mesh, const Surface& surface, const std::vector<int>& glued,
                         const Map_state& state, HalfedgeUVMap uvmap, SeamEdgeMap seam_edge_map)
{
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
  for(int fe : glued)
  {
    const int i = state.corner_uv[std::size_t(fe)];
    const auto h = surface.face_edge_halfedge(fe);
    put(uvmap, opposite(h, mesh), Point_2(state.x[2*i], state.x[2*i+1]));
    put(seam_edge_map, edge(h, mesh), false);
  }
}

/// No `forbidden_seam_edge_map` given: nothing is forbidden.
template <typename Surface>
bool read_forbidden_edges(const Surface&, CGAL::internal_np::Param_not_found, Map_state&) { return true; }

/// Reads the forbidden edges into `state.rules.forbidden` (left empty if none is
/// flagged; flags on border edges are ignored). False if an edge is both a
/// given seam and forbidden.
template <typename Surface, typename ForbiddenEdgeMap>
bool read_forbidden_edges(const Surface& surface, const ForbiddenEdgeMap& forbidden_map, Map_state& state)
{
  std::vector<char> forbidden(surface.edges.size(), 0);
  bool any = false;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    if(get(forbidden_map, surface.edges[e])) { forbidden[e] = 1; any = true; }
  for(std::size_t fe = 0; fe < surface.twin.size(); ++fe)
    if(surface.twin[fe] < 0) forbidden[surface.edge_of[fe]] = 0;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    if(forbidden[e] && state.is_cut[e]) return false;
  if(any) state.rules.forbidden.swap(forbidden);
  return true;
}

/// Seams = cut edges that are not on the mesh's boundary.
template <typename Surface, typename SeamEdgeMap>
void write_seams(const Surface& surface, const Map_state& state, SeamEdgeMap seam_edge_map)
{
  std::vector<char> border(surface.edges.size(), 0);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] < 0) border[surface.edge_of[fe]] = 1;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    put(seam_edge_map, surface.edges[e], bool(state.is_cut[e] && !border[e]));
}

/// Copies the phases' times, and `total` from `start` to now.
inline void fill_timings(const Work_log& log, Steady_clock::time_point start, Cut_and_parameterize_result& result)
{
  Cut_and_parameterize_timings& t = result.timings;
  t.initialization = log.timings.initialization;
  t.u_steps = log.timings.u_steps;
  t.v_steps = log.timings.v_steps;
  t.cut_extraction = log.timings.cut_extraction;
  t.final_solve = log.timings.final_solve;
  t.packing = log.timings.packing;
  t.total = seconds_since(start);
}

template <typename Surface>
void fill_statistics(const Surface& surface, const Map_state& state, const Work_log& log, const Packing_result& packing,
                     Cut_and_parameterize_result& result)
{
  int charts = 0;
  chart_of_faces(state.chart, charts);
  result.number_of_charts = std::size_t(charts);
  double seam = 0.;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
    if(surface.twin[fe] > fe && state.is_cut[surface.edge_of[fe]])
    {
      seam += surface.edge_length(fe);
      ++result.number_of_seam_edges;
    }
  result.seam_length = seam / std::sqrt(state.chart.total_area() / M_PI);
  result.newton_iterations = log.work.iterations;
  result.number_of_factorizations = log.work.factorizations;
  result.number_of_solves = log.work.solves;
  result.alternation_newton_iterations = log.u_step_work.iterations;
  result.alternation_factorizations = log.u_step_work.factorizations;
  result.alternation_solves = log.u_step_work.solves;
  result.final_solve_newton_iterations = log.final_work.iterations;
  result.box_newton_iterations = log.box_work.iterations;
  result.relax_newton_iterations = log.relax_work.iterations;
  result.v_step_factorizations = log.v_step_factorizations;
  result.number_of_degenerate_faces = state.degenerate_faces;
  result.initial_distortion = state.initial_distortion;
  result.distortion = state.distortion;
  result.uv_coverage = packing.coverage;
  result.uv_scale = packing.scale;
  result.border_crossings = count_border_crossings(border_segments(state.chart), state.x);
}

} // namespace cut
} // namespace internal

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
