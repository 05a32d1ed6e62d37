// The output contract of cut_and_parameterize(), as one predicate that debug
// builds assert at the end of every run and tests check: every UV finite, no
// flipped face, every chart a topological disk, every seam really opens.
#ifndef CGAL_SMP_CUT_INTERNAL_ATLAS_VALIDITY_H
#define CGAL_SMP_CUT_INTERNAL_ATLAS_VALIDITY_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>

#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// True if every connected component of the chart mesh is a topological
/// disk: one boundary loop and Euler characteristic V - E + F = 1.
inline bool charts_are_disks(const Chart_mesh& chart)
{
  int n = 0;
  const std::vector<int> chart_of_face = chart_of_faces(chart, n);
  std::vector<long> euler(n, 0), loops(n, 0);
  std::vector<int> chart_of_vertex(chart.number_of_vertices, -1);
  std::unordered_set<std::uint64_t> edges;
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
  {
    const int c = chart_of_face[f];
    ++euler[c];
    for(int k = 0; k < 3; ++k)
    {
      const int a = chart.faces[f][k], b = chart.faces[f][(k+1)%3];
      if(chart_of_vertex[a] < 0) { chart_of_vertex[a] = c; ++euler[c]; }
      if(edges.insert(directed_edge_key((std::min)(a, b), (std::max)(a, b))).second) --euler[c];
    }
  }
  for(const std::vector<int>& loop : boundary_loops(chart)) ++loops[chart_of_vertex[loop.front()]];
  for(int c = 0; c < n; ++c)
    if(euler[c] != 1 || loops[c] != 1) return false;
  return true;
}

/// True if the atlas in `state` fulfils the contract of cut_and_parameterize().
template <typename Surface, typename State>
bool is_valid_atlas(const Surface& surface, const State& state)
{
  const Chart_mesh& chart = state.chart;
  if(chart.number_of_faces() != surface.number_of_faces()) return false;
  if(!state.x.allFinite() || number_of_flipped_faces(chart, state.x) > 0) return false;
  // an inner cut edge must separate the corners on its two sides at one end at least
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int tw = surface.twin[fe];
    if(tw < 0 || !state.is_cut[surface.edge_of[fe]]) continue;
    const int f = fe / 3, k = fe % 3, g = tw / 3, l = tw % 3;
    if(chart.faces[f][k] == chart.faces[g][(l+1)%3] && chart.faces[f][(k+1)%3] == chart.faces[g][l]) return false;
  }
  return charts_are_disks(chart);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
