// Charts cut for packing (atlas/packing_split.h, split_charts_for_packing):
// U-shaped flat charts that fill 0.28 of their bounding rectangle are cut
// into pieces that each fill at least the threshold (or are too small to
// cut), every piece moved by a similarity of its input UVs (edge-length
// ratios constant, no flip), the new seams interior edges, no overlap on the
// page, and a scene of such charts covers more of its page than uncut; in
// cut_and_parameterize(), the pieces keep the map (the same E_d, each a
// similarity of the map without the option), the seams and charts reported
// grow, and the atlas passes every check of the result.
#include "cut_result_checks.h"
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/packing_split.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/geometry/uv_coverage_raster.h>
#include <CGAL/Surface_mesh_parameterization/pack_scene_atlas.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = CGAL::Surface_mesh_parameterization::parameters;
using namespace cut_test;

namespace {

using halfedge_descriptor = boost::graph_traits<Surface_mesh>::halfedge_descriptor;
using edge_descriptor = boost::graph_traits<Surface_mesh>::edge_descriptor;
using face_descriptor = boost::graph_traits<Surface_mesh>::face_descriptor;
using UV_map = Surface_mesh::Property_map<halfedge_descriptor, Point_2>;
using Seam_map = Surface_mesh::Property_map<edge_descriptor, bool>;

/// A flat U of 20 × 20 cells of side `cell`: arms and bottom two cells wide
/// (112 of the 400 cells: it fills 0.28 of its square).
Soup u_soup(double cell)
{
  Soup soup = grid_soup(20, 20, 20. * cell, 20. * cell);
  std::vector<std::vector<std::size_t>> kept;
  for(const auto& f : soup.faces)
  {
    double x = 0., y = 0.;
    for(std::size_t v : f) { x += soup.points[v][0] / 3.; y += soup.points[v][1] / 3.; }
    if(!(x > 2. * cell && x < 18. * cell && y > 2. * cell)) kept.push_back(f);
  }
  soup.faces = kept;
  return soup.remove_unused_points();
}

/// Faces joined across edges that are neither seams nor borders: per face, its piece.
std::vector<int> pieces_of(const Surface_mesh& mesh, const Seam_map& seam, int& count)
{
  std::vector<int> piece(num_faces(mesh), -1);
  count = 0;
  for(face_descriptor f0 : faces(mesh))
  {
    if(piece[f0.idx()] >= 0) continue;
    std::vector<face_descriptor> stack{f0};
    piece[f0.idx()] = count;
    while(!stack.empty())
    {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const face_descriptor g = face(opposite(h, mesh), mesh);
        if(g == boost::graph_traits<Surface_mesh>::null_face() || seam[edge(h, mesh)] || piece[g.idx()] >= 0) continue;
        piece[g.idx()] = count;
        stack.push_back(g);
      }
    }
    ++count;
  }
  return piece;
}

/// Per piece, the ratio (UV length at `b`) / (UV length at `a`) of every edge
/// of its faces is one constant, and no face of `b` is flipped.
void expect_similarity_per_piece(const Surface_mesh& mesh, const std::vector<int>& piece, int pieces,
                                 const std::vector<Point_2>& a, const UV_map& b)
{
  std::vector<double> low(std::size_t(pieces), 1e300), high(std::size_t(pieces), 0.);
  for(face_descriptor f : faces(mesh))
  {
    const halfedge_descriptor h0 = halfedge(f, mesh);
    EXPECT_EQ(CGAL::orientation(b[h0], b[next(h0, mesh)], b[prev(h0, mesh)]), CGAL::LEFT_TURN) << "no flip";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(h0, mesh))
    {
      const double ratio = std::sqrt(CGAL::squared_distance(b[h], b[prev(h, mesh)])) /
                           std::sqrt(CGAL::squared_distance(a[h.idx()], a[prev(h, mesh).idx()]));
      low[std::size_t(piece[f.idx()])] = (std::min)(low[std::size_t(piece[f.idx()])], ratio);
      high[std::size_t(piece[f.idx()])] = (std::max)(high[std::size_t(piece[f.idx()])], ratio);
    }
  }
  for(int p = 0; p < pieces; ++p) EXPECT_LT(high[std::size_t(p)] / low[std::size_t(p)] - 1., 1e-9) << "piece " << p;
}

/// Eight U meshes of different sizes, their UVs their xy.
struct U_scene
{
  std::vector<Surface_mesh> meshes;
  std::vector<UV_map> uv;
  std::vector<Seam_map> seam;
  std::vector<std::vector<Point_2>> input; // per mesh, per halfedge index
  U_scene()
  {
    meshes.reserve(8);
    for(int m = 0; m < 8; ++m)
    {
      meshes.push_back(make_mesh<Surface_mesh>(u_soup(0.1 + 0.01 * m)));
      Surface_mesh& mesh = meshes.back();
      uv.push_back(mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0., 0.)).first);
      seam.push_back(mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first);
      input.emplace_back(num_halfedges(mesh));
      for(halfedge_descriptor h : halfedges(mesh))
      {
        const Point_3& p = mesh.point(target(h, mesh));
        uv.back()[h] = input.back()[h.idx()] = Point_2(p.x(), p.y());
      }
    }
  }
  SMP::Scene_atlas_result pack(bool split)
  {
    std::vector<SMP::Scene_atlas_mesh<Surface_mesh, Seam_map, UV_map>> atlas;
    for(std::size_t m = 0; m < meshes.size(); ++m) atlas.push_back(SMP::make_scene_atlas_mesh(meshes[m], seam[m], uv[m]));
    return split ? SMP::pack_scene_atlas(atlas, P::texture_size(256, P::split_charts_for_packing(0.5)))
                 : SMP::pack_scene_atlas(atlas, P::texture_size(256));
  }
  double coverage() const
  {
    double area = 0.;
    for(std::size_t m = 0; m < meshes.size(); ++m) area += SMP::uv_area(meshes[m], uv[m]);
    return area;
  }
};

} // namespace

TEST(Packing_split, a_u_is_cut_into_pieces_that_fill_their_rectangles)
{
  namespace pk = SMP::internal::cut::packing;
  U_scene scene;
  const SMP::Scene_atlas_result uncut = scene.pack(false);
  ASSERT_EQ(uncut.error, SMP::OK);
  EXPECT_EQ(uncut.number_of_charts, 8u);
  const double uncut_coverage = scene.coverage();
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
    for(halfedge_descriptor h : halfedges(scene.meshes[m])) scene.uv[m][h] = scene.input[m][h.idx()];

  const SMP::Scene_atlas_result r = scene.pack(true);
  ASSERT_EQ(r.error, SMP::OK);
  ASSERT_EQ(r.number_of_pages, 1);
  std::size_t added = 0;
  std::vector<std::array<std::array<double, 2>, 3>> triangles;
  for(std::size_t m = 0; m < scene.meshes.size(); ++m)
  {
    const Surface_mesh& mesh = scene.meshes[m];
    int pieces = 0;
    const std::vector<int> piece = pieces_of(mesh, scene.seam[m], pieces);
    EXPECT_GE(pieces, 3) << "mesh " << m << ": the bottom and the two arms apart";
    EXPECT_EQ(std::size_t(pieces), 1 + r.added_charts[m]);
    added += r.added_charts[m];
    double seam_length = 0.;
    for(edge_descriptor e : edges(mesh))
      if(scene.seam[m][e])
      {
        EXPECT_FALSE(is_border(e, mesh)) << "a seam is an interior edge";
        seam_length += edge_length_3(mesh, e);
      }
    double area = 0.;
    for(face_descriptor f : faces(mesh))
    {
      const halfedge_descriptor h = halfedge(f, mesh);
      area += std::sqrt(CGAL::squared_area(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                           mesh.point(target(next(h, mesh), mesh))));
    }
    EXPECT_GT(seam_length, 0.);
    EXPECT_NEAR(seam_length / std::sqrt(area / M_PI), r.added_seam_length[m], 1e-9 * r.added_seam_length[m])
      << "E_s added, in the unit of seam_length";
    // each piece fills at least the threshold, or is too small to be cut
    std::vector<std::vector<int>> faces_of(static_cast<std::size_t>(pieces));
    for(face_descriptor f : faces(mesh)) faces_of[std::size_t(piece[f.idx()])].push_back(int(f.idx()));
    std::vector<SMP::internal::cut::Vector2> input_corners;
    for(face_descriptor f : faces(mesh))
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        input_corners.emplace_back(scene.input[m][h.idx()].x(), scene.input[m][h.idx()].y());
    for(const std::vector<int>& p : faces_of)
      EXPECT_TRUE(pk::rectangle_fill(p, input_corners) >= 0.5 ||
                  int(p.size()) < 2 * SMP::internal::cut::tuning::packing_split_min_faces)
        << "mesh " << m << ": a piece of " << p.size() << " faces fills " << pk::rectangle_fill(p, input_corners);
    expect_similarity_per_piece(mesh, piece, pieces, scene.input[m], scene.uv[m]);
    for(face_descriptor f : faces(mesh))
    {
      std::array<std::array<double, 2>, 3> t;
      int k = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const Point_2& q = scene.uv[m][h];
        EXPECT_TRUE(q.x() >= 0. && q.x() <= 1. && q.y() >= 0. && q.y() <= 1.);
        t[k++] = {q.x(), q.y()};
      }
      triangles.push_back(t);
    }
  }
  EXPECT_EQ(r.number_of_charts, 8u + added);
  EXPECT_EQ(SMP::internal::cut::overlap_area_of_triangles(triangles, 1024), 0.) << "no texel covered twice";
  EXPECT_GT(scene.coverage(), 1.2 * uncut_coverage) << "the pieces fill the page better than the U's";
}

TEST(Packing_split, the_option_off_or_a_full_chart_cuts_nothing)
{
  namespace ic = SMP::internal::cut;
  // a rectangle fills its rectangle: never cut, whatever the threshold
  const Surface_mesh grid = make_mesh<Surface_mesh>(grid_soup(12, 8, 3., 2.));
  ic::Indexed_surface<Surface_mesh> s;
  ASSERT_EQ(ic::index_surface(grid, ic::vertex_points(grid, CGAL::parameters::default_values()), s), ic::Indexing_status::OK);
  std::vector<ic::Vector2> uv;
  for(const auto& cv : s.corner_vertex)
    for(int v : cv) uv.emplace_back(s.points[std::size_t(v)].x(), s.points[std::size_t(v)].y());
  std::size_t added = 7;
  const std::vector<char> cut = ic::packing::packing_cuts(s, std::vector<char>(s.edges.size(), 0), {}, uv, 1., added);
  EXPECT_EQ(added, 0u);
  EXPECT_EQ(std::count(cut.begin(), cut.end(), 1), 0);
  // a threshold out of (0, 1] is refused
  U_scene scene;
  std::vector<SMP::Scene_atlas_mesh<Surface_mesh, Seam_map, UV_map>> atlas;
  atlas.push_back(SMP::make_scene_atlas_mesh(scene.meshes[0], scene.seam[0], scene.uv[0]));
  EXPECT_EQ(SMP::pack_scene_atlas(atlas, P::split_charts_for_packing(0.)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(SMP::pack_scene_atlas(atlas, P::split_charts_for_packing(1.5)).error, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(scene.uv[0][*halfedges(scene.meshes[0]).begin()], scene.input[0][0]) << "nothing written on error";
}

TEST(Packing_split, cut_and_parameterize_keeps_the_map_of_each_piece)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(u_soup(0.1));
  Cut_run<Surface_mesh> plain(mesh), cut(mesh);
  plain.run(P::number_of_passes(1));
  cut.run(P::number_of_passes(1, P::split_charts_for_packing(0.5)));
  ASSERT_TRUE(plain.result.ok() && cut.result.ok());
  check_cut_result(mesh, cut); // disks, seams interior, no flip, no overlap, statistics as the outputs say
  EXPECT_GT(cut.result.number_of_charts, plain.result.number_of_charts);
  EXPECT_GT(cut.result.seam_length, plain.result.seam_length);
  EXPECT_EQ(cut.result.distortion, plain.result.distortion) << "the same map, cut";
  // per chart of the cut run, its UVs a similarity of the plain run's
  Seam_map seams;
  Surface_mesh copy = mesh;
  seams = copy.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  UV_map uv = copy.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0., 0.)).first;
  std::vector<Point_2> before(num_halfedges(mesh));
  for(edge_descriptor e : edges(mesh)) seams[e] = cut.is_seam(e);
  for(halfedge_descriptor h : halfedges(mesh))
    if(!is_border(h, mesh))
    {
      before[h.idx()] = plain.uv(h);
      uv[h] = cut.uv(h);
    }
  int pieces = 0;
  const std::vector<int> piece = pieces_of(copy, seams, pieces);
  EXPECT_EQ(std::size_t(pieces), cut.result.number_of_charts);
  expect_similarity_per_piece(copy, piece, pieces, before, uv);
}
