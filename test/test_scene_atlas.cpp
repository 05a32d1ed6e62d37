// Scene atlas (pack_scene_atlas.h): flat meshes given UVs at different
// scales are packed at one texel density, on one page or split over pages;
// every UV in [0,1], 0 overlap across the meshes of a page (combined UVs),
// densities equal within 1%, errors leave the UVs unchanged. Free angles
// (atlas/chart_orientation.h): a turn is a rotation (no mirror, area kept),
// an X claims fewer texels turned by 45°, a rectangle is never turned, and a
// scene of X-shaped meshes packs valid, each chart moved by a similarity,
// the same bits on every run.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_orientation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/uv_coverage_raster.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>

#include <map>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = CGAL::Surface_mesh_parameterization::parameters;
using namespace cut_test;

namespace {

using halfedge_descriptor = boost::graph_traits<Surface_mesh>::halfedge_descriptor;
using edge_descriptor = boost::graph_traits<Surface_mesh>::edge_descriptor;
using UV_map = Surface_mesh::Property_map<halfedge_descriptor, Point_2>;
using Seams = CGAL::Constant_property_map<edge_descriptor, bool>;

/// Flat meshes (grids and disks) of different sizes whose UVs are their
/// xy coordinates times a different factor each (so the input densities differ).
struct Scene
{
  std::vector<Surface_mesh> meshes;
  std::vector<UV_map> uv;
  explicit Scene(int count)
  {
    meshes.reserve(count);
    for(int m = 0; m < count; ++m)
    {
      const double size = 0.5 + 0.25 * (m % 5);
      meshes.push_back(make_mesh<Surface_mesh>(m % 2 ? grid_soup(6, 4, size, 0.6 * size) : flat_disk_soup(3, 12, size)));
      Surface_mesh& mesh = meshes.back();
      uv.push_back(mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0., 0.)).first);
      for(halfedge_descriptor h : halfedges(mesh))
      {
        const Point_3& p = mesh.point(target(h, mesh));
        uv.back()[h] = Point_2((1. + m) * p.x(), (1. + m) * p.y());
      }
    }
  }
  std::vector<SMP::Scene_atlas_mesh<Surface_mesh, Seams, UV_map>> atlas_meshes() const
  {
    std::vector<SMP::Scene_atlas_mesh<Surface_mesh, Seams, UV_map>> r;
    for(std::size_t m = 0; m < meshes.size(); ++m) r.push_back(SMP::make_scene_atlas_mesh(meshes[m], Seams(false), uv[m]));
    return r;
  }
  double uv_area(std::size_t m) const
  {
    double a = 0.;
    for(auto f : faces(meshes[m]))
    {
      const halfedge_descriptor h = halfedge(f, meshes[m]);
      const Point_2 &p = uv[m][h], &q = uv[m][next(h, meshes[m])], &r = uv[m][prev(h, meshes[m])];
      a += 0.5 * std::abs((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
    }
    return a;
  }
  double area_3d(std::size_t m) const
  {
    double a = 0.;
    for(auto f : faces(meshes[m]))
    {
      const halfedge_descriptor h = halfedge(f, meshes[m]);
      a += std::sqrt(CGAL::squared_area(meshes[m].point(source(h, meshes[m])), meshes[m].point(target(h, meshes[m])),
                                        meshes[m].point(target(next(h, meshes[m]), meshes[m]))));
    }
    return a;
  }
};

/// Checks UVs in [0,1], densities equal to result.texels_per_unit within
/// 1%, and no overlap between the triangles of all meshes of each page.
void check_scene(const Scene& scene, const SMP::Scene_atlas_result& r, int texture_size)
{
  ASSERT_EQ(r.error, SMP::OK);
  ASSERT_EQ(r.page.size(), scene.meshes.size());
  for(int page = 0; page < r.number_of_pages; ++page)
  {
    std::vector<std::array<std::array<double, 2>, 3>> triangles;
    int outside = 0;
    for(std::size_t m = 0; m < scene.meshes.size(); ++m)
    {
      if(r.page[m] != page) continue;
      for(auto f : faces(scene.meshes[m]))
      {
        std::array<std::array<double, 2>, 3> t;
        int k = 0;
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, scene.meshes[m]), scene.meshes[m]))
        {
          const Point_2& p = scene.uv[m][h];
          outside += !(p.x() >= 0. && p.x() <= 1. && p.y() >= 0. && p.y() <= 1.);
          t[k++] = {p.x(), p.y()};
        }
        triangles.push_back(t);
      }
      const double density = texture_size * std::sqrt(scene.uv_area(m) / scene.area_3d(m));
      EXPECT_NEAR(density / r.texels_per_unit, 1., 0.01) << "mesh " << m;
    }
    EXPECT_EQ(outside, 0);
    EXPECT_FALSE(triangles.empty()) << "page " << page << " is empty";
    EXPECT_EQ(SMP::internal::cut::overlap_area_of_triangles(triangles, 1024), 0.) << "page " << page;
  }
}

/// A plus sign of five unit squares (each two triangles, shared corners),
/// turned by `angle` about the origin: an X at 45°.
Soup plus_soup(double angle)
{
  Soup soup;
  const double co = std::cos(angle), si = std::sin(angle);
  std::map<std::pair<int, int>, std::size_t> index;
  auto corner = [&](int x, int y) {
    const auto it = index.find({x, y});
    if(it != index.end()) return it->second;
    const std::size_t v = soup.add_point(co * x - si * y, si * x + co * y, 0.);
    index[{x, y}] = v;
    return v;
  };
  for(const auto& [x, y] : std::vector<std::pair<int, int>>{{1, 1}, {0, 1}, {2, 1}, {1, 0}, {1, 2}})
  {
    const std::size_t a = corner(x, y), b = corner(x + 1, y), c = corner(x + 1, y + 1), d = corner(x, y + 1);
    soup.faces.push_back({a, b, c});
    soup.faces.push_back({a, c, d});
  }
  return soup;
}

/// A chart shape of the triangles of `soup` (its xy).
SMP::internal::cut::packing::Chart_shape shape_of(const Soup& soup)
{
  namespace ic = SMP::internal::cut;
  ic::packing::Chart_shape shape;
  ic::Vector2 low = ic::Vector2::Constant(1e300), high = -low;
  for(const Soup::Point& p : soup.points)
  {
    low = low.cwiseMin(ic::Vector2(p[0], p[1]));
    high = high.cwiseMax(ic::Vector2(p[0], p[1]));
  }
  for(const auto& f : soup.faces)
  {
    std::array<ic::Vector2, 3> t;
    for(int k = 0; k < 3; ++k) t[k] = ic::Vector2(soup.points[f[k]][0], soup.points[f[k]][1]) - low;
    shape.triangles.push_back(t);
    const ic::Vector2 e1 = t[1] - t[0], e2 = t[2] - t[0];
    shape.area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  shape.size = high - low;
  return shape;
}

} // namespace

TEST(Chart_orientation, a_turn_is_rigid_and_an_x_claims_less_turned_back)
{
  namespace pk = SMP::internal::cut::packing;
  const pk::Chart_shape x = shape_of(plus_soup(0.25 * M_PI)); // an X: its rows' extents claim its bays
  const pk::Chart_shape plus = shape_of(plus_soup(0.));
  EXPECT_GT(pk::claimed_area(x), 1.25 * x.area);
  EXPECT_NEAR(pk::claimed_area(plus), plus.area, 0.1 * plus.area); // rows of a plus are whole
  const pk::Chart_shape turned = pk::least_claiming_turn(x, 4); // 0, 22.5, 45, 67.5 degrees
  EXPECT_LT(pk::claimed_area(turned), 0.85 * pk::claimed_area(x));
  EXPECT_NEAR(pk::claimed_area(turned), pk::claimed_area(plus), 0.01 * plus.area);
  EXPECT_NEAR(turned.size.x(), 3., 1e-9); // the plus again: 3 x 3
  EXPECT_NEAR(turned.size.y(), 3., 1e-9);
  ASSERT_EQ(turned.triangles.size(), x.triangles.size());
  EXPECT_EQ(turned.area, x.area);
  for(std::size_t t = 0; t < x.triangles.size(); ++t)
  {
    const auto &a = x.triangles[t], &b = turned.triangles[t];
    auto cross = [](const std::array<SMP::internal::cut::Vector2, 3>& q) {
      const auto e1 = q[1] - q[0], e2 = q[2] - q[0];
      return e1.x() * e2.y() - e1.y() * e2.x(); };
    EXPECT_NEAR(cross(a), cross(b), 1e-12) << "no mirror, area kept";
    for(int k = 0; k < 3; ++k)
      EXPECT_NEAR((a[k] - a[(k + 1) % 3]).norm(), (b[k] - b[(k + 1) % 3]).norm(), 1e-12) << "rigid";
    for(const auto& p : b) EXPECT_TRUE(p.x() >= -1e-12 && p.y() >= -1e-12) << "lower corner at the origin";
  }
  // a rectangle's rows are whole at angle 0: never turned
  const pk::Chart_shape rectangle = shape_of(grid_soup(3, 2, 2., 1.));
  const pk::Chart_shape kept = pk::least_claiming_turn(rectangle, 5);
  EXPECT_EQ(kept.size, rectangle.size);
  EXPECT_EQ(kept.triangles, rectangle.triangles);
}

TEST(Scene_atlas, charts_at_free_angles_pack_valid_by_a_similarity_each)
{
  // X-shaped meshes (their UVs their xy): the free angles may turn them
  Scene scene(0);
  scene.meshes.reserve(6); // the UV maps are handles into the meshes: no reallocation
  for(int m = 0; m < 6; ++m)
  {
    scene.meshes.push_back(make_mesh<Surface_mesh>(plus_soup(0.25 * M_PI + 0.05 * m)));
    Surface_mesh& mesh = scene.meshes.back();
    scene.uv.push_back(mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0., 0.)).first);
    for(halfedge_descriptor h : halfedges(mesh))
      scene.uv.back()[h] = Point_2(mesh.point(target(h, mesh)).x(), mesh.point(target(h, mesh)).y());
  }
  std::vector<Point_2> input;
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
    for(halfedge_descriptor h : halfedges(scene.meshes[m])) input.push_back(scene.uv[m][h]);
  const SMP::Scene_atlas_result r = SMP::pack_scene_atlas(scene.atlas_meshes(), P::texture_size(128));
  check_scene(scene, r, 128);
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
  {
    const Surface_mesh& mesh = scene.meshes[m];
    double low = 1e300, high = 0.;
    for(halfedge_descriptor h : halfedges(mesh))
    {
      if(is_border(h, mesh)) continue;
      const Point_2 &a = scene.uv[m][h], &b = scene.uv[m][prev(h, mesh)];
      const double ratio = std::sqrt(CGAL::squared_distance(a, b)) /
                           std::sqrt(CGAL::squared_distance(mesh.point(target(h, mesh)), mesh.point(source(h, mesh))));
      low = (std::min)(low, ratio);
      high = (std::max)(high, ratio);
    }
    EXPECT_LT(high / low - 1., 1e-9) << "mesh " << m << ": a similarity";
    for(auto f : faces(mesh))
    {
      const halfedge_descriptor h = halfedge(f, mesh);
      EXPECT_EQ(CGAL::orientation(scene.uv[m][h], scene.uv[m][next(h, mesh)], scene.uv[m][prev(h, mesh)]),
                CGAL::LEFT_TURN) << "mesh " << m << ": no mirror";
    }
  }
  // the same bits again, from the same input
  std::vector<Point_2> first;
  std::size_t j = 0;
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
    for(halfedge_descriptor h : halfedges(scene.meshes[m]))
    {
      first.push_back(scene.uv[m][h]);
      scene.uv[m][h] = input[j++];
    }
  const SMP::Scene_atlas_result again = SMP::pack_scene_atlas(scene.atlas_meshes(), P::texture_size(128));
  EXPECT_EQ(again.texels_per_unit, r.texels_per_unit);
  std::size_t i = 0;
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
    for(halfedge_descriptor h : halfedges(scene.meshes[m])) EXPECT_EQ(scene.uv[m][h], first[i++]);
}

TEST(Scene_atlas, one_page_at_the_largest_density)
{
  Scene scene(7);
  const SMP::Scene_atlas_result r = SMP::pack_scene_atlas(scene.atlas_meshes(), P::texture_size(256));
  EXPECT_EQ(r.number_of_pages, 1);
  EXPECT_GT(r.texels_per_unit, 0.);
  check_scene(scene, r, 256);
}

TEST(Scene_atlas, charts_that_do_not_fit_one_page_are_split_over_pages)
{
  Scene scene(9);
  // 9 meshes of 0.15 to 7 square units (20 in all) at 35 texels per unit on 128-texel pages: >= 2 pages
  const SMP::Scene_atlas_result r =
    SMP::pack_scene_atlas(scene.atlas_meshes(), P::padding(3., P::texels_per_unit(35., P::texture_size(128))));
  EXPECT_GT(r.number_of_pages, 1);
  EXPECT_EQ(r.texels_per_unit, 35.);
  check_scene(scene, r, 128);
}

TEST(Scene_atlas, a_mesh_larger_than_a_page_is_an_error_and_nothing_is_written)
{
  Scene scene(3);
  const Point_2 before = scene.uv[1][*halfedges(scene.meshes[1]).begin()];
  const SMP::Scene_atlas_result r =
    SMP::pack_scene_atlas(scene.atlas_meshes(), P::texels_per_unit(1000., P::texture_size(64)));
  EXPECT_EQ(r.error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(scene.uv[1][*halfedges(scene.meshes[1]).begin()], before);
  EXPECT_EQ(SMP::pack_scene_atlas(scene.atlas_meshes(), P::padding(-1.)).error,
            SMP::ERROR_WRONG_PARAMETER);
}
