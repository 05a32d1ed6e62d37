// Scene atlas layout: the charts of several meshes, all at one texel density
// (texels per unit of 3D length), on one or more square pages; every chart
// of a mesh on the same page. Charts are shape-packed (shape_packing.h), by
// the skyline and by the raster placement, and, for the largest density of
// few charts, by the raster placement with the charts turned to free angles
// (chart_orientation.h); the layout of larger density (or, at a given
// density, of fewer pages) is kept.
#ifndef CGAL_SMP_CUT_INTERNAL_SCENE_PACKING_H
#define CGAL_SMP_CUT_INTERNAL_SCENE_PACKING_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_orientation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/shape_packing.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// One chart of a scene: its triangles at 3D scale (UV area equal to its 3D
/// area up to the mesh's distortion), in the frame of its minimum-area
/// rectangle, and the mesh it belongs to.
struct Scene_chart
{
  packing::Chart_shape shape;
  int mesh = 0;
};

/// Where the charts of a scene went.
struct Scene_layout
{
  double texels_per_unit = 0.;                   ///< texels per unit of 3D length
  int pages = 0;                                 ///< number of pages used
  std::vector<int> page_of_mesh;                 ///< page of each mesh
  std::vector<packing::Chart_raster> rasters;    ///< per chart, at texels_per_unit
  std::vector<packing::Raster_placement> placed; ///< per chart, texel offset and turn on its page
};

/// Turns the triangles `corners` (UV, any scale) of one chart into a Chart_shape
/// scaled by `scale` and turned to its minimum-area rectangle, lower corner at the origin.
inline packing::Chart_shape chart_shape(const std::vector<std::array<Vector2, 3>>& corners, double scale)
{
  packing::Chart_shape shape;
  std::vector<Vector2> points;
  for(const auto& t : corners) points.insert(points.end(), t.begin(), t.end());
  const Vector2 origin = points.empty() ? Vector2::Zero() : points.front();
  for(Vector2& p : points) p = scale * (p - origin);
  const double angle = packing::best_angle(packing::convex_hull(points), false);
  const double co = std::cos(angle), si = std::sin(angle);
  Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for(Vector2& p : points)
  {
    p = Vector2(co * p.x() + si * p.y(), -si * p.x() + co * p.y()); // rotation by -angle
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  shape.size = points.empty() ? Vector2::Zero() : Vector2(high - low);
  for(std::size_t t = 0; t < corners.size(); ++t)
  {
    const std::array<Vector2, 3> q{points[3 * t] - low, points[3 * t + 1] - low, points[3 * t + 2] - low};
    shape.triangles.push_back(q);
    const Vector2 e1 = q[1] - q[0], e2 = q[2] - q[0];
    shape.area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  return shape;
}

/// Drops the charts `which` (largest first) on `skyline` (a Skyline or a Raster_page); false if one does not fit.
template <typename Placer>
bool drop_charts(const std::vector<Scene_chart>& charts, std::vector<int> which, Placer& skyline, Scene_layout& layout)
{
  auto key = [&](int c) { return std::make_pair(charts[c].shape.size.maxCoeff(), charts[c].shape.size.minCoeff()); };
  std::stable_sort(which.begin(), which.end(), [&](int a, int b) { return key(a) > key(b); });
  for(int c : which)
    if(!skyline.drop(layout.rasters[c], layout.placed[c])) return false;
  return true;
}

/// Puts the meshes' charts (rasters in `layout`) on pages of `Placer`s:
/// each mesh, largest total area first, on the first page that holds all its
/// charts. False if a mesh does not fit an empty page.
template <typename Placer>
bool paginate(const std::vector<Scene_chart>& charts, int number_of_meshes, int n, int pad, Scene_layout& layout)
{
  layout.placed.assign(charts.size(), packing::Raster_placement());
  std::vector<std::vector<int>> charts_of_mesh(number_of_meshes);
  std::vector<double> mesh_area(number_of_meshes, 0.);
  for(std::size_t c = 0; c < charts.size(); ++c)
  {
    charts_of_mesh[charts[c].mesh].push_back(int(c));
    mesh_area[charts[c].mesh] += charts[c].shape.area;
  }
  std::vector<int> meshes(number_of_meshes);
  std::iota(meshes.begin(), meshes.end(), 0);
  std::stable_sort(meshes.begin(), meshes.end(), [&](int a, int b) { return mesh_area[a] > mesh_area[b]; });
  std::vector<Placer> pages;
  for(int m : meshes)
  {
    if(charts_of_mesh[m].empty()) continue;
    bool placed = false;
    for(std::size_t p = 0; p <= pages.size() && !placed; ++p)
    {
      Placer trial = p < pages.size() ? pages[p] : Placer(n, pad);
      if(!drop_charts(charts, charts_of_mesh[m], trial, layout)) continue;
      if(p < pages.size()) pages[p] = trial;
      else pages.push_back(trial);
      layout.page_of_mesh[m] = int(p);
      placed = true;
    }
    if(!placed) return false; // not even an empty page holds it
  }
  layout.pages = int(pages.size());
  return true;
}

/// Lays out the charts of `number_of_meshes` meshes on pages of
/// `texture_size` texels per side with `padding` texels (rounded up) between
/// charts and to the sides. `texels_per_unit` > 0: that density, meshes on
/// as many pages as needed (each mesh first-fit, largest total area first,
/// on the first page that holds all its charts); else the largest density
/// at which every chart fits one page, where up to
/// tuning::raster_orders_max_charts charts (and padding up to
/// tuning::raster_orders_max_padding texels) may also be turned to free
/// angles (least_claiming_turn(), each sampling of tuning::chart_turn_samples
/// tried, kept only for a larger density). False if a mesh does not fit one
/// page (or nothing fits).
/// \post on success the layout is of the shapes left in `charts` (each
///   turned by some angle about its frame where free angles won)
inline bool layout_scene(std::vector<Scene_chart>& charts, int number_of_meshes, int texture_size,
                         double padding, double texels_per_unit, Scene_layout& layout)
{
  const int n = texture_size;
  const int pad = std::isfinite(padding) ? int(std::ceil((std::max)(0., padding))) : 0;
  if(charts.empty() || n <= 2 * pad + 2 || !(texels_per_unit >= 0.) || !std::isfinite(texels_per_unit)) return false;
  layout = Scene_layout();
  layout.page_of_mesh.assign(number_of_meshes, 0);
  std::vector<packing::Chart_shape> shapes;
  double area = 0.;
  for(const Scene_chart& c : charts) { shapes.push_back(c.shape); area += c.shape.area; }
  if(!(area > 0.)) return false;
  if(texels_per_unit == 0.) // the largest density on one page
  {
    const double high = (n - 2. * pad) / std::sqrt(area);
    layout.texels_per_unit = packing::largest_shape_scale(shapes, n, pad, 0., high, layout.rasters, layout.placed);
    if(int(charts.size()) <= tuning::raster_placement_max_charts)
    {
      Scene_layout by_bits = layout;
      by_bits.texels_per_unit =
        packing::largest_raster_scale(shapes, n, pad, layout.texels_per_unit, high, by_bits.rasters, by_bits.placed);
      if(by_bits.texels_per_unit > layout.texels_per_unit) layout = by_bits; // found only above the skyline's
    }
    if(int(charts.size()) <= tuning::raster_orders_max_charts && pad <= tuning::raster_orders_max_padding)
    {
      std::vector<packing::Chart_shape> best_turned;
      for(int samples : tuning::chart_turn_samples)
      {
        std::vector<packing::Chart_shape> turned;
        for(const packing::Chart_shape& s : shapes) turned.push_back(packing::least_claiming_turn(s, samples));
        Scene_layout by_angles = layout;
        by_angles.texels_per_unit = packing::largest_raster_scale(turned, n, pad, layout.texels_per_unit, high,
                                                                  by_angles.rasters, by_angles.placed);
        if(by_angles.texels_per_unit > layout.texels_per_unit) // found only above the best so far
        {
          layout = by_angles;
          best_turned.swap(turned);
        }
      }
      for(std::size_t c = 0; c < best_turned.size(); ++c) charts[c].shape = best_turned[c];
    }
    layout.pages = 1;
    return layout.texels_per_unit > 0.;
  }
  layout.texels_per_unit = texels_per_unit;
  for(const packing::Chart_shape& s : shapes) layout.rasters.push_back(packing::rasterize(s, texels_per_unit));
  if(!paginate<packing::Skyline>(charts, number_of_meshes, n, pad, layout)) return false;
  if(int(charts.size()) <= tuning::raster_placement_max_charts && layout.pages > 1)
  {
    Scene_layout by_bits = layout;
    if(paginate<packing::Raster_page>(charts, number_of_meshes, n, pad, by_bits) && by_bits.pages < layout.pages)
      layout = by_bits;
  }
  return true;
}

/// UV (in the unit square of its page) of point `p` of chart `c`'s frame.
inline Vector2 scene_uv(const Scene_layout& layout, int texture_size, int c, const Vector2& p)
{
  const Vector2 uv = packing::place_point(p, layout.texels_per_unit, layout.rasters[c], layout.placed[c]) /
                     double(texture_size);
  return uv.cwiseMax(Vector2::Zero()).cwiseMin(Vector2::Ones()); // rounding only
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
