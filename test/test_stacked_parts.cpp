// Stacked parts of a scene atlas (pack_scene_atlas()'s instance_of and
// stacking_tolerance, find_stacked_meshes()): a scene of a box (6 charts,
// its hard edges cut) plus 10 rigidly moved copies of it and a grid packs
// exactly as the box and the grid alone (same charts, same density, same
// UVs), every copy with the box's UVs and seams; a mirror image and a
// copy deformed beyond the tolerance are packed on their own; wrong
// instances are refused; the same on Polyhedron_3 (any FaceGraph, maps of
// any kind).
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/uv_coverage_raster.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = CGAL::Surface_mesh_parameterization::parameters;
using cut_test::Soup;
using cut_test::Surface_mesh;

namespace {

using halfedge_descriptor = boost::graph_traits<Surface_mesh>::halfedge_descriptor;
using edge_descriptor = boost::graph_traits<Surface_mesh>::edge_descriptor;
using Stacked_uv_map = Surface_mesh::Property_map<halfedge_descriptor, cut_test::Point_2>;
using Stacked_seam_map = Surface_mesh::Property_map<edge_descriptor, bool>;
using Stacked_atlas_mesh = SMP::Scene_atlas_mesh<Surface_mesh, Stacked_seam_map, Stacked_uv_map>;

/// `s` turned by `angle` about the axis (1, 2, 2)/3 (a rotation, det +1), then moved by `shift`.
Soup rigidly_moved(Soup s, double angle, double shift)
{
  const double a[3] = {1. / 3., 2. / 3., 2. / 3.}, c = std::cos(angle), si = std::sin(angle);
  return s.transform([&](const Soup::Point& p) {
    const double dot = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
    const double cross[3] = {a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]};
    Soup::Point q;
    for(int i = 0; i < 3; ++i) q[i] = p[i] * c + cross[i] * si + a[i] * dot * (1. - c) + shift;
    return q;
  });
}

/// The meshes of a scene with their seams and UVs: mesh 0 a 1x2x3 box unwrapped
/// with its hard edges as seams, mesh 1 a flat grid (UV = xy), then the `extra`
/// soups with no UV and no seam (their faces and vertices numbered as the box's).
struct Stacked_scene
{
  std::vector<Surface_mesh> meshes;
  std::vector<Stacked_uv_map> uv;
  std::vector<Stacked_seam_map> seams;
  explicit Stacked_scene(const std::vector<Soup>& extra)
  {
    meshes.reserve(2 + extra.size());
    meshes.push_back(cut_test::make_mesh<Surface_mesh>(cut_test::box_soup(1., 2., 3.)));
    meshes.push_back(cut_test::make_mesh<Surface_mesh>(cut_test::grid_soup(6, 4, 2., 1.)));
    for(const Soup& s : extra) meshes.push_back(cut_test::make_mesh<Surface_mesh>(s));
    for(Surface_mesh& m : meshes)
    {
      uv.push_back(m.add_property_map<halfedge_descriptor, cut_test::Point_2>("h:uv", cut_test::Point_2(-5., -5.)).first);
      seams.push_back(m.add_property_map<edge_descriptor, bool>("e:seam", false).first);
    }
    const auto r = SMP::cut_and_parameterize(meshes[0], seams[0], uv[0], P::hard_edge_angle(30.));
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.number_of_charts, 6u);
    for(halfedge_descriptor h : halfedges(meshes[1]))
    {
      const auto& p = meshes[1].point(target(h, meshes[1]));
      uv[1][h] = cut_test::Point_2(p.x(), p.y());
    }
  }
  std::vector<Stacked_atlas_mesh> atlas_meshes() const
  {
    std::vector<Stacked_atlas_mesh> r;
    for(std::size_t m = 0; m < meshes.size(); ++m) r.push_back(SMP::make_scene_atlas_mesh(meshes[m], seams[m], uv[m]));
    return r;
  }
  /// Gives mesh `m` (of the box's connectivity) the box's unpacked UVs and seams, halfedge by halfedge.
  void copy_box_input(std::size_t m)
  {
    for(halfedge_descriptor h : halfedges(meshes[0])) uv[m][h] = uv[0][h];
    for(edge_descriptor e : edges(meshes[0])) seams[m][e] = seams[0][e];
  }
  std::size_t uv_differences(std::size_t a, std::size_t b) const
  {
    std::size_t d = 0;
    for(halfedge_descriptor h : halfedges(meshes[a])) d += !(uv[a][h] == uv[b][h]);
    for(edge_descriptor e : edges(meshes[a])) d += seams[a][e] != seams[b][e];
    return d;
  }
  /// Overlap area of the triangles of the meshes `which` (UVs of one page).
  double overlap(const std::vector<std::size_t>& which) const
  {
    std::vector<std::array<std::array<double, 2>, 3>> triangles;
    for(std::size_t m : which)
      for(auto f : faces(meshes[m]))
      {
        std::array<std::array<double, 2>, 3> t;
        int k = 0;
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, meshes[m]), meshes[m]))
          t[k++] = {uv[m][h].x(), uv[m][h].y()};
        triangles.push_back(t);
      }
    return SMP::internal::cut::overlap_area_of_triangles(triangles, 1024);
  }
};

std::vector<Soup> ten_box_copies()
{
  std::vector<Soup> copies;
  for(int i = 0; i < 10; ++i) copies.push_back(rigidly_moved(cut_test::box_soup(1., 2., 3.), 0.4 + 0.55 * i, 3. * i));
  return copies;
}

} // namespace

TEST(Stacked_parts, ten_copies_of_a_box_use_the_texels_of_one)
{
  Stacked_scene alone({});
  const SMP::Scene_atlas_result reference = SMP::pack_scene_atlas(alone.atlas_meshes(), P::texture_size(256));
  ASSERT_EQ(reference.error, SMP::OK);
  EXPECT_EQ(reference.number_of_charts, 7u); // the box's 6 sides and the grid
  EXPECT_EQ(alone.overlap({0, 1}), 0.);

  for(bool told : {false, true})
  {
    Stacked_scene scene(ten_box_copies());
    std::vector<int> instance_of(scene.meshes.size(), -1);
    for(std::size_t m = 2; m < scene.meshes.size(); ++m) instance_of[m] = 0;
    const SMP::Scene_atlas_result r =
      told ? SMP::pack_scene_atlas(scene.atlas_meshes(), P::instance_of(instance_of, P::texture_size(256)))
           : SMP::pack_scene_atlas(scene.atlas_meshes(), P::stacking_tolerance(1e-4, P::texture_size(256)));
    ASSERT_EQ(r.error, SMP::OK) << (told ? "instance_of" : "found");
    EXPECT_EQ(r.number_of_charts, reference.number_of_charts);
    EXPECT_EQ(r.texels_per_unit, reference.texels_per_unit); // the same charts packed: the same density
    EXPECT_EQ(r.number_of_pages, 1);
    EXPECT_EQ(r.stacked_on[0], 0);
    EXPECT_EQ(r.stacked_on[1], 1);
    for(std::size_t m = 2; m < scene.meshes.size(); ++m)
    {
      EXPECT_EQ(r.stacked_on[m], 0) << m;
      EXPECT_EQ(r.page[m], r.page[0]);
      EXPECT_EQ(scene.uv_differences(m, 0), 0u) << "copy " << m << ": its UVs and seams are the box's";
    }
    // the originals' UVs are those of the scene without the copies
    std::size_t moved_uvs = 0;
    for(std::size_t m = 0; m < 2; ++m)
      for(halfedge_descriptor h : halfedges(scene.meshes[m])) moved_uvs += !(scene.uv[m][h] == alone.uv[m][h]);
    EXPECT_EQ(moved_uvs, 0u);
    std::size_t seams = 0;
    for(edge_descriptor e : edges(scene.meshes[5])) seams += scene.seams[5][e];
    EXPECT_EQ(seams, 12u); // the copy's own seams: the box's 12 edges
  }
}

TEST(Stacked_parts, a_mirror_image_or_a_deformed_copy_is_not_stacked)
{
  Soup mirrored = cut_test::box_soup(1., 2., 3.);
  mirrored.transform([](const Soup::Point& p) { return Soup::Point{-p[0], p[1], p[2]}; });
  Soup deformed = rigidly_moved(cut_test::box_soup(1., 2., 3.), 1., 2.);
  deformed.points[7][2] += 0.01; // 0.0027 of the diagonal (3.74), beyond 1e-4
  Soup within = rigidly_moved(cut_test::box_soup(1., 2., 3.), 2., -1.);
  within.points[7][2] += 1e-5; // 2.7e-6 of the diagonal
  Stacked_scene scene({mirrored, deformed, within});
  scene.copy_box_input(2);
  scene.copy_box_input(3);
  const SMP::Scene_atlas_result r =
    SMP::pack_scene_atlas(scene.atlas_meshes(), P::stacking_tolerance(1e-4, P::texture_size(256)));
  ASSERT_EQ(r.error, SMP::OK);
  EXPECT_EQ(r.stacked_on, (std::vector<int>{0, 1, 2, 3, 0}));
  EXPECT_EQ(r.number_of_charts, 7u + 6u + 6u); // the mirror image and the deformed copy packed on their own
  EXPECT_EQ(scene.uv_differences(4, 0), 0u);
  EXPECT_EQ(scene.overlap({0, 1, 2, 3}), 0.);

  std::vector<const Surface_mesh*> pointers;
  for(const Surface_mesh& m : scene.meshes) pointers.push_back(&m);
  std::vector<int> found;
  ASSERT_EQ(SMP::find_stacked_meshes(pointers, found), SMP::OK);
  EXPECT_EQ(found, r.stacked_on);
  ASSERT_EQ(SMP::find_stacked_meshes(pointers, found, P::stacking_tolerance(0.01)), SMP::OK);
  EXPECT_EQ(found, (std::vector<int>{0, 1, 2, 0, 0})); // a looser tolerance takes the deformed copy, never the mirror
  EXPECT_EQ(SMP::find_stacked_meshes(pointers, found, P::stacking_tolerance(-1.)), SMP::ERROR_WRONG_PARAMETER);
}

TEST(Stacked_parts, wrong_instances_are_refused_and_nothing_is_written)
{
  Stacked_scene scene({rigidly_moved(cut_test::box_soup(1., 2., 3.), 1., 1.)});
  const cut_test::Point_2 before = scene.uv[0][*halfedges(scene.meshes[0]).begin()];
  for(const std::vector<int>& instance_of :
      {std::vector<int>{-1, 0, -1},  // the grid is no box
       std::vector<int>{2, -1, 0},   // a cycle
       std::vector<int>{-1, -1, 7},  // out of range
       std::vector<int>{-1, -1}})    // the wrong size
    EXPECT_EQ(SMP::pack_scene_atlas(scene.atlas_meshes(), P::instance_of(instance_of)).error,
              SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(SMP::pack_scene_atlas(scene.atlas_meshes(), P::stacking_tolerance(-1.)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(scene.uv[0][*halfedges(scene.meshes[0]).begin()], before);
}

template <typename Mesh>
class Stacked_parts_typed : public ::testing::Test {};
TYPED_TEST_SUITE(Stacked_parts_typed, cut_test::Mesh_types);

TYPED_TEST(Stacked_parts_typed, copies_found_get_the_uvs_and_seams_of_their_original_corner_by_corner)
{
  std::vector<TypeParam> meshes;
  meshes.reserve(4);
  meshes.push_back(cut_test::make_mesh<TypeParam>(cut_test::box_soup(1., 2., 3.)));
  for(int i = 1; i < 4; ++i) meshes.push_back(cut_test::make_mesh<TypeParam>(rigidly_moved(cut_test::box_soup(1., 2., 3.), i, 5. * i)));
  std::vector<cut_test::Cut_run<TypeParam>> runs;
  runs.reserve(meshes.size());
  for(const TypeParam& m : meshes) runs.emplace_back(m);
  ASSERT_TRUE(runs[0].run(P::hard_edge_angle(30.)).ok());
  using Run = cut_test::Cut_run<TypeParam>;
  using Scene_mesh = SMP::Scene_atlas_mesh<TypeParam, decltype(std::declval<Run&>().seams()),
                                           decltype(std::declval<Run&>().uvs())>;
  std::vector<Scene_mesh> scene;
  std::vector<const TypeParam*> pointers;
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    scene.push_back(SMP::make_scene_atlas_mesh(meshes[m], runs[m].seams(), runs[m].uvs()));
    pointers.push_back(&meshes[m]);
  }
  std::vector<int> stacked_on;
  ASSERT_EQ(SMP::find_stacked_meshes(pointers, stacked_on), SMP::OK);
  EXPECT_EQ(stacked_on, (std::vector<int>{0, 0, 0, 0}));
  const SMP::Scene_atlas_result r = SMP::pack_scene_atlas(scene, P::instance_of(stacked_on, P::texture_size(128)));
  ASSERT_EQ(r.error, SMP::OK);
  EXPECT_EQ(r.number_of_charts, 6u);
  for(std::size_t m = 1; m < meshes.size(); ++m)
  {
    std::size_t differences = 0, corners = 0;
    auto f0 = faces(meshes[0]).begin();
    for(auto f : faces(meshes[m]))
    {
      auto h0 = halfedge(*f0++, meshes[0]);
      for(auto h : CGAL::halfedges_around_face(halfedge(f, meshes[m]), meshes[m]))
      {
        differences += !(runs[m].uv(h) == runs[0].uv(h0)) + (runs[m].is_seam(edge(h, meshes[m])) !=
                                                             runs[0].is_seam(edge(h0, meshes[0])));
        ++corners;
        h0 = next(h0, meshes[0]);
      }
    }
    EXPECT_EQ(corners, 36u);
    EXPECT_EQ(differences, 0u) << "copy " << m;
  }
}
