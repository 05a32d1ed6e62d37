// Free orientations of the charts of a scene atlas: besides the turns by 90°
// of the placements, a chart may be turned by any angle before it is
// rasterized. The raster placement tests a chart by the extent of each of
// its rows (or, turned, columns), so a chart claims the texels between its
// leftmost and rightmost texel of every row; a star or a bent strip claims
// less at some angles than in its minimum-area frame. Each chart is given,
// among a few angles of the quarter turn, the one that claims the fewest
// texels; which sampling packs best varies from scene to scene, so the
// caller tries a few and keeps the largest scale.
#ifndef CGAL_SMP_CUT_INTERNAL_CHART_ORIENTATION_H
#define CGAL_SMP_CUT_INTERNAL_CHART_ORIENTATION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_raster.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace packing {

/// `shape` turned by `angle` (radians, counterclockwise), its lower corner
/// moved to the origin.
/// \post same triangles up to a rotation and a translation (area kept, no mirror); `size` their extent
inline Chart_shape turned_shape(const Chart_shape& shape, double angle)
{
  const double co = std::cos(angle), si = std::sin(angle);
  Chart_shape out;
  out.area = shape.area;
  Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  out.triangles.reserve(shape.triangles.size());
  for(const auto& t : shape.triangles)
  {
    std::array<Vector2, 3> q;
    for(int k = 0; k < 3; ++k)
    {
      q[k] = Vector2(co * t[k].x() - si * t[k].y(), si * t[k].x() + co * t[k].y());
      low = low.cwiseMin(q[k]);
      high = high.cwiseMax(q[k]);
    }
    out.triangles.push_back(q);
  }
  if(out.triangles.empty()) return shape;
  for(auto& t : out.triangles)
    for(Vector2& p : t) p -= low;
  out.size = high - low;
  return out;
}

/// Frame area the raster placement's fit test claims for `shape`: the sum
/// of its row extents, or of its column extents if smaller (a turn by 90°
/// makes columns rows), on a raster of tuning::chart_turn_raster_texels
/// texels along its longer side, in units of the frame.
inline double claimed_area(const Chart_shape& shape)
{
  const double longer = shape.size.maxCoeff();
  if(!(longer > 0.)) return 0.;
  const double texels = tuning::chart_turn_raster_texels / longer;
  const Chart_raster r = rasterize(shape, texels);
  double rows = 0., columns = 0.;
  for(int j = 0; j < r.h; ++j) rows += r.row_hi[j] - r.row_lo[j] + 1;
  for(int i = 0; i < r.w; ++i) columns += r.col_hi[i] - r.col_lo[i] + 1;
  return (std::min)(rows, columns) / (texels * texels);
}

/// `shape` (in its minimum-area frame) turned by the angle k π / (2 `samples`),
/// k in [0, samples), whose claimed_area() is the least; another angle than 0
/// only where it claims at most tuning::chart_turn_gain times what the
/// angles before it claimed at best.
/// \pre samples >= 1
inline Chart_shape least_claiming_turn(const Chart_shape& shape, int samples)
{
  const double quarter = 0.5 * 3.14159265358979323846;
  Chart_shape best = shape;
  double least = claimed_area(shape);
  for(int k = 1; k < samples; ++k)
  {
    Chart_shape t = turned_shape(shape, -quarter * k / samples);
    const double claimed = claimed_area(t);
    if(claimed < tuning::chart_turn_gain * least)
    {
      least = claimed;
      best = std::move(t);
    }
  }
  return best;
}

} // namespace packing
} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
