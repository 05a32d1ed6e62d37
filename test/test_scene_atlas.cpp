// Scene atlas (pack_scene_atlas.h): flat meshes given UVs at different
// scales are packed at one texel density, on one page or split over pages;
// every UV in [0,1], 0 overlap across the meshes of a page (combined UVs),
// densities equal within 1%, errors leave the UVs unchanged.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/uv_coverage_raster.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>

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

} // namespace

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
