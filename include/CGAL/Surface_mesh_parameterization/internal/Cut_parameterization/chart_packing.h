// Places the charts of a UV map side by side without overlap: each chart's
// bounding box goes on a shelf (rows of a width chosen for a square-ish
// atlas), tallest first. A simple, correct layout, not a tight packing.
#ifndef CGAL_SMP_CUT_INTERNAL_CHART_PACKING_H
#define CGAL_SMP_CUT_INTERNAL_CHART_PACKING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Chart_mesh.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

inline void pack_charts(const Chart_mesh& mesh, UV_vector& x)
{
  int n = 0;
  const std::vector<int> chart_of_face = chart_of_faces(mesh, n);
  if(n <= 1) return;
  std::vector<int> chart_of_vertex(mesh.number_of_vertices, -1);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int v : mesh.faces[f]) chart_of_vertex[v] = chart_of_face[f];
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Vector2> low(n, Vector2(inf, inf)), high(n, Vector2(-inf, -inf));
  for(int v = 0; v < mesh.number_of_vertices; ++v)
  {
    const int c = chart_of_vertex[v];
    if(c < 0) continue;
    const Vector2 p = x.segment<2>(2 * v);
    low[c] = low[c].cwiseMin(p);
    high[c] = high[c].cwiseMax(p);
  }
  double area = 0., largest = 0.;
  for(int c = 0; c < n; ++c)
  {
    const Vector2 size = high[c] - low[c];
    area += size.x() * size.y();
    largest = (std::max)(largest, size.maxCoeff());
  }
  const double gap = 0.02 * largest;
  const double row_width = (std::max)(largest, 1.2 * std::sqrt(area));
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return high[a].y() - low[a].y() > high[b].y() - low[b].y(); });
  std::vector<Vector2> offset(n);
  double cursor_x = 0., cursor_y = 0., row_height = 0.;
  for(int c : order)
  {
    const Vector2 size = high[c] - low[c];
    if(cursor_x > 0. && cursor_x + size.x() > row_width)
    {
      cursor_x = 0.;
      cursor_y += row_height + gap;
      row_height = 0.;
    }
    offset[c] = Vector2(cursor_x, cursor_y) - low[c];
    cursor_x += size.x() + gap;
    row_height = (std::max)(row_height, size.y());
  }
  for(int v = 0; v < mesh.number_of_vertices; ++v)
    if(chart_of_vertex[v] >= 0) x.segment<2>(2 * v) += offset[chart_of_vertex[v]];
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
