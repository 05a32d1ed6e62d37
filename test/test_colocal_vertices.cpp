// weld_colocal_vertices: a mesh exported with split normals (every sharp
// edge's vertices duplicated, so that the surface comes in pieces) is
// unwrapped into the charts of the welded mesh, with a valid atlas written on
// the file's own vertices; without welding each piece is a chart.
// Generated from a cube always, from CGAL's fandisk.off when the data set is
// there (CGAL_DATA_DIR).
#include "cut_result_checks.h"

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <map>
#include <set>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

using Split_mesh = Surface_mesh;
using Split_face = boost::graph_traits<Split_mesh>::face_descriptor;
using Split_halfedge = boost::graph_traits<Split_mesh>::halfedge_descriptor;

Kernel::Vector_3 unit_normal(const Split_mesh& mesh, Split_face f)
{
  const Split_halfedge h = halfedge(f, mesh);
  const Point_3& a = mesh.point(source(h, mesh));
  const Point_3& b = mesh.point(target(h, mesh));
  const Point_3& c = mesh.point(target(next(h, mesh), mesh));
  const Kernel::Vector_3 n = CGAL::cross_product(b - a, c - a);
  return n / std::sqrt(n.squared_length());
}

/// The mesh as an exporter with split normals writes it: the corners of a
/// vertex are one point only across edges whose faces' normals are within
/// `angle_degrees`; faces in the mesh's order. `pieces`: connected pieces.
Soup split_normals_soup(const Split_mesh& mesh, double angle_degrees, std::size_t& pieces)
{
  const double cos_limit = std::cos(angle_degrees * CGAL_PI / 180.);
  // corner (face, vertex) -> index; union across smooth edges
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> corner;
  std::vector<std::size_t> parent;
  auto id = [&](Split_face f, Split_mesh::Vertex_index v) {
    const auto inserted = corner.emplace(std::make_pair(std::size_t(f), std::size_t(v)), parent.size());
    if(inserted.second) parent.push_back(parent.size());
    return inserted.first->second;
  };
  std::function<std::size_t(std::size_t)> find = [&](std::size_t a) { return parent[a] == a ? a : parent[a] = find(parent[a]); };
  std::vector<std::size_t> face_piece(num_faces(mesh));
  for(std::size_t f = 0; f < face_piece.size(); ++f) face_piece[f] = f;
  std::function<std::size_t(std::size_t)> find_piece = [&](std::size_t a) {
    return face_piece[a] == a ? a : face_piece[a] = find_piece(face_piece[a]);
  };
  for(Split_face f : faces(mesh))
    for(Split_halfedge h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) id(f, target(h, mesh));
  for(auto e : edges(mesh))
  {
    const Split_halfedge h = halfedge(e, mesh);
    if(is_border_edge(h, mesh)) continue;
    const Split_face f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    if(unit_normal(mesh, f) * unit_normal(mesh, g) < cos_limit) continue; // sharp
    for(auto v : {source(h, mesh), target(h, mesh)}) parent[find(id(f, v))] = find(id(g, v));
    face_piece[find_piece(std::size_t(f))] = find_piece(std::size_t(g));
  }
  Soup soup;
  std::map<std::size_t, std::size_t> point_of_class;
  for(Split_face f : faces(mesh))
  {
    std::vector<std::size_t> polygon;
    for(Split_halfedge h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const std::size_t c = find(id(f, target(h, mesh)));
      auto it = point_of_class.find(c);
      if(it == point_of_class.end())
      {
        const Point_3& p = mesh.point(target(h, mesh));
        it = point_of_class.emplace(c, soup.add_point(p.x(), p.y(), p.z())).first;
      }
      polygon.push_back(it->second);
    }
    soup.faces.push_back(polygon);
  }
  std::set<std::size_t> roots;
  for(std::size_t f = 0; f < face_piece.size(); ++f) roots.insert(find_piece(f));
  pieces = roots.size();
  return soup;
}

/// Charts of the split mesh as its UVs draw them: faces joined across two
/// colocal edges whose corners have the same UVs on both sides.
std::size_t charts_drawn_by_uvs(const Split_mesh& mesh, const Cut_run<Split_mesh>& run)
{
  std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, std::vector<Split_halfedge>> at;
  auto position = [&](Split_mesh::Vertex_index v) {
    const Point_3& p = mesh.point(v);
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  };
  for(Split_face f : faces(mesh))
    for(Split_halfedge h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      auto a = position(source(h, mesh)), b = position(target(h, mesh));
      at[a < b ? std::make_pair(a, b) : std::make_pair(b, a)].push_back(h);
    }
  std::vector<std::size_t> parent(num_faces(mesh));
  for(std::size_t f = 0; f < parent.size(); ++f) parent[f] = f;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t a) { return parent[a] == a ? a : parent[a] = find(parent[a]); };
  auto uv_at_source = [&](Split_halfedge h) { return run.uv_storage.at(prev(h, mesh)); };
  for(const auto& entry : at)
  {
    if(entry.second.size() != 2) continue;
    const Split_halfedge h = entry.second[0], k = entry.second[1];
    // h runs a -> b, k runs b -> a: corner a of h's face and corner a of k's face (k's target)
    if(run.uv_storage.at(h) == uv_at_source(k) && uv_at_source(h) == run.uv_storage.at(k))
      parent[find(std::size_t(face(h, mesh)))] = find(std::size_t(face(k, mesh)));
  }
  std::set<std::size_t> roots;
  for(std::size_t f = 0; f < parent.size(); ++f) roots.insert(find(f));
  return roots.size();
}

/// The atlas on the split mesh is valid whatever was glued: finite UVs in
/// the unit square, no flipped face, no crossing border, no overlap.
void expect_valid_atlas(const Split_mesh& mesh, const Cut_run<Split_mesh>& run)
{
  Cut_run<Split_mesh>& r = const_cast<Cut_run<Split_mesh>&>(run);
  EXPECT_EQ(SMP::number_of_flipped_faces(mesh, r.uvs()), std::size_t(0));
  EXPECT_EQ(SMP::number_of_border_crossings(mesh, r.uvs()), std::size_t(0));
  EXPECT_LT(SMP::uv_overlap_area(mesh, r.uvs()), 1e-12);
  // seams are interior edges (a Seam_mesh's), glued border edges included
  for(auto e : edges(mesh))
    if(run.is_seam(e)) EXPECT_FALSE(is_border(e, mesh)) << "a seam on the border of the split mesh";
  for(Split_face f : faces(mesh))
    for(Split_halfedge h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const Point_2& uv = run.uv_storage.at(h);
      EXPECT_TRUE(uv.x() >= 0. && uv.x() <= 1. && uv.y() >= 0. && uv.y() <= 1.);
    }
}

/// Unwraps `welded` and its split-normals copy (with and without welding)
/// and compares their charts. `np`: the options of every run.
template <typename NamedParameters>
void check_split_normals(const Split_mesh& welded, double angle_degrees, const NamedParameters& np, bool unwelded_run)
{
  std::size_t pieces = 0;
  const Soup soup = split_normals_soup(welded, angle_degrees, pieces);
  const Split_mesh split = make_mesh<Split_mesh>(soup);
  ASSERT_GT(num_vertices(split), num_vertices(welded)) << "no vertex was split";
  ASSERT_GT(pieces, std::size_t(1));

  Cut_run<Split_mesh> reference(welded);
  ASSERT_TRUE(reference.run(np).ok());
  EXPECT_EQ(reference.result.number_of_welded_vertices, std::size_t(0));

  Cut_run<Split_mesh> joined(split);
  ASSERT_TRUE(joined.run(SMP::parameters::weld_colocal_vertices(true, np)).ok());
  EXPECT_EQ(joined.result.number_of_welded_vertices, num_vertices(split) - num_vertices(welded));
  EXPECT_EQ(joined.result.number_of_charts, reference.result.number_of_charts);
  EXPECT_NEAR(joined.result.seam_length, reference.result.seam_length, 1e-6 * (1. + reference.result.seam_length));
  EXPECT_EQ(charts_drawn_by_uvs(split, joined), reference.result.number_of_charts);
  expect_valid_atlas(split, joined);

  if(!unwelded_run) return;
  Cut_run<Split_mesh> apart(split);
  ASSERT_TRUE(apart.run(np).ok()); // the library's default: no welding
  EXPECT_EQ(apart.result.number_of_welded_vertices, std::size_t(0));
  EXPECT_EQ(apart.result.number_of_charts, pieces); // each piece a chart (each is a disk here)
  EXPECT_EQ(charts_drawn_by_uvs(split, apart), pieces);
  expect_valid_atlas(split, apart);
}

} // namespace

TEST(ColocalVertices, cube_with_split_normals)
{
  const Split_mesh cube = make_mesh<Split_mesh>(box_soup(1., 2., 3.));
  check_split_normals(cube, 30., CGAL::parameters::default_values(), true);
}

TEST(ColocalVertices, pieces_touching_at_a_corner_stay_apart)
{
  // two triangles sharing only a point: welding would pinch it, so it is not welded
  Soup soup;
  soup.add_point(0., 0., 0.); soup.add_point(1., 0., 0.); soup.add_point(0., 1., 0.);
  soup.add_point(0., 0., 0.); soup.add_point(-1., 0., 0.); soup.add_point(0., -1., 0.);
  soup.add_triangle(0, 1, 2);
  soup.add_triangle(3, 4, 5);
  const Split_mesh mesh = make_mesh<Split_mesh>(soup);
  Cut_run<Split_mesh> run(mesh);
  ASSERT_TRUE(run.run(SMP::parameters::weld_colocal_vertices(true)).ok());
  EXPECT_EQ(run.result.number_of_welded_vertices, std::size_t(0));
  EXPECT_EQ(run.result.number_of_charts, std::size_t(2));
  expect_valid_atlas(mesh, run);
}

TEST(ColocalVertices, fandisk_with_split_normals)
{
  if(std::getenv("CGAL_DATA_DIR") == nullptr) GTEST_SKIP() << "CGAL_DATA_DIR not set";
  Split_mesh fandisk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(CGAL::data_file_path("meshes/fandisk.off"), fandisk));
  // the charts of the initial cut and the final solve only: seconds, not a whole alternation
  check_split_normals(fandisk, 30., SMP::parameters::number_of_passes(0), false);
}
