// Faces with more than 3 vertices split into triangles (see mesh_input.h).
#include "detail.h"

// triangulate_faces() on a self-intersecting polygon would print a
// performance hint of CGAL's constrained triangulation on stderr.
#ifndef CGAL_NO_CDT_2_WARNING
#define CGAL_NO_CDT_2_WARNING
#endif

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace mesh_input {
namespace detail {

// Splits face f into triangles by cutting ears at its first corner; works
// for any polygon, whatever its geometry (degenerate triangles are then
// clamped by the library).
inline void ear_split(Mesh::Face_index f, Mesh& mesh)
{
  Mesh::Halfedge_index h = mesh.halfedge(f);
  while(mesh.next(mesh.next(mesh.next(h))) != h)
    CGAL::Euler::split_face(h, mesh.next(mesh.next(h)), mesh);
}

// Largest polygon handed to triangulate_faces() (the crossing test below is
// quadratic); larger ones are split at their first corner.
constexpr int max_polygon_for_cdt = 1000;

// True unless the polygon is clearly simple seen along `normal` (the
// projection triangulate_faces() triangulates in): false if two corners
// coincide, two edges cross or touch, or a corner lies on the line of an edge
// it is not on, by the predicates of that triangulation. On such polygons it
// fails: coinciding first and last corners make it insert a constraint from
// a vertex to itself (a CGAL precondition; without it, undefined behavior);
// crossing edges make it construct an intersection point, which can fail (a
// CGAL assertion); collinear edges meet its coordinate comparisons, which are
// inexact in this projection while its orientation test is exact, and can
// break the same precondition.
inline bool has_crossing_edges(const std::vector<Point_3>& p, const Kernel::Vector_3& normal)
{
  const CGAL::Projection_traits_3<Kernel> traits(normal);
  const auto orientation = traits.orientation_2_object();
  const auto compare_x = traits.compare_x_2_object();
  const auto compare_y = traits.compare_y_2_object();
  const std::size_t n = p.size();
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(compare_x(p[i], p[j]) == CGAL::EQUAL && compare_y(p[i], p[j]) == CGAL::EQUAL) return true;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 2; j < n; ++j)
    {
      if(i == 0 && j == n - 1) continue; // adjacent
      const Point_3 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
      const int o1 = int(orientation(a, b, c)), o2 = int(orientation(a, b, d));
      const int o3 = int(orientation(c, d, a)), o4 = int(orientation(c, d, b));
      if(o1 * o2 <= 0 && o3 * o4 <= 0) return true; // crossing, touching or collinear
    }
  return false;
}

// Largest polygon triangulated by ear clipping (cubic in the worst case).
constexpr int max_polygon_for_ear_clipping = 200;

// Ear clipping of the polygon seen along `normal`, with the exact
// orientation predicate only: an ear is a strictly convex corner whose
// triangle holds no other remaining corner, inside or on its border. For
// the polygons triangulate_faces() is not given (collinear or touching
// edges, which simple polygons can have); false if no ear is left before
// the end (the polygon is not simple in this projection).
inline bool ear_clipping_diagonals(const std::vector<Point_3>& p, const Kernel::Vector_3& normal,
                                   std::vector<std::pair<int, int>>& diagonals)
{
  const int n = int(p.size());
  if(n > max_polygon_for_ear_clipping) return false;
  const CGAL::Projection_traits_3<Kernel> traits(normal);
  const auto orientation = traits.orientation_2_object();
  for(const int turn : {int(CGAL::LEFT_TURN), int(CGAL::RIGHT_TURN)}) // the polygon's orientation
  {
    std::vector<int> left(std::size_t(n), 0);
    for(int i = 0; i < n; ++i) left[std::size_t(i)] = i;
    diagonals.clear();
    while(left.size() > 3)
    {
      const std::size_t m = left.size();
      bool clipped = false;
      for(std::size_t k = 0; k < m && !clipped; ++k)
      {
        const int a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
        if(int(orientation(p[std::size_t(a)], p[std::size_t(b)], p[std::size_t(c)])) != turn) continue;
        bool empty = true;
        for(std::size_t j = 0; j < m && empty; ++j)
        {
          const int q = left[j];
          if(q == a || q == b || q == c) continue;
          const Point_3& x = p[std::size_t(q)];
          empty = !(int(orientation(p[std::size_t(a)], p[std::size_t(b)], x)) * turn >= 0 &&
                    int(orientation(p[std::size_t(b)], p[std::size_t(c)], x)) * turn >= 0 &&
                    int(orientation(p[std::size_t(c)], p[std::size_t(a)], x)) * turn >= 0);
        }
        if(!empty) continue;
        diagonals.emplace_back((std::min)(a, c), (std::max)(a, c));
        left.erase(left.begin() + std::ptrdiff_t(k));
        clipped = true;
      }
      if(!clipped) break;
    }
    if(left.size() == 3)
    {
      std::sort(diagonals.begin(), diagonals.end());
      return true;
    }
  }
  return false;
}

// The diagonals (pairs of corner indices) with which
// PMP::triangulate_faces() splits the polygon `corners`, computed on a
// mesh of that polygon alone and checked: false unless the result is a
// valid triangulation of the polygon with its own corners. (On a
// self-overlapping polygon, triangulate_faces() can leave a polygon edge
// out of every triangle and return an invalid mesh.) Polygons it cannot
// handle safely are not given to it: too large, with coordinates so large
// that its normal overflows (a NaN reaching an exact predicate aborts) or
// without a normal (false), or with crossing, touching or collinear edges
// (ear clipping instead).
inline bool triangulation_diagonals(const std::vector<Point_3>& corners, std::vector<std::pair<int, int>>& diagonals)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const int n = int(corners.size());
  if(n > max_polygon_for_cdt) return false;
  for(const Point_3& p : corners)
    if(!(std::abs(p.x()) < 1e100 && std::abs(p.y()) < 1e100 && std::abs(p.z()) < 1e100)) return false;
  Mesh polygon;
  std::vector<Mesh::Vertex_index> v;
  for(const Point_3& p : corners) v.push_back(polygon.add_vertex(p));
  const Mesh::Face_index face = polygon.add_face(v);
  if(face == Mesh::null_face()) return false;
  // the normal triangulate_faces() projects along (a zero one makes it fail)
  const Kernel::Vector_3 normal = PMP::compute_face_normal(face, polygon);
  if(!std::isfinite(normal.x()) || !std::isfinite(normal.y()) || !std::isfinite(normal.z()) ||
     normal == CGAL::NULL_VECTOR)
    return false;
  if(n > 4 && has_crossing_edges(corners, normal)) return ear_clipping_diagonals(corners, normal, diagonals);
  if(!PMP::triangulate_faces(polygon)) return false;
  if(!polygon.is_valid(false) || int(polygon.number_of_vertices()) != n ||
     int(polygon.number_of_faces()) != n - 2 || !CGAL::is_triangle_mesh(polygon))
    return false;
  for(int k = 0; k < n; ++k)
  {
    const auto h = CGAL::halfedge(v[std::size_t(k)], v[std::size_t((k + 1) % n)], polygon);
    if(!h.second || CGAL::is_border(h.first, polygon) || !CGAL::is_border(polygon.opposite(h.first), polygon))
      return false;
  }
  diagonals.clear();
  for(Mesh::Edge_index e : polygon.edges())
  {
    const auto h = polygon.halfedge(e);
    if(CGAL::is_border(h, polygon) || CGAL::is_border(polygon.opposite(h), polygon)) continue;
    const int a = int(polygon.source(h).idx()), b = int(polygon.target(h).idx());
    diagonals.emplace_back((std::min)(a, b), (std::max)(a, b));
  }
  // in a canonical order: the pieces, hence face order and corners, depend
  // only on the triangulation, not on the order of its edges
  std::sort(diagonals.begin(), diagonals.end());
  return int(diagonals.size()) == n - 3;
}

// True if a diagonal of `diagonals` (corner indices) joins two vertices
// that an edge of `mesh` joins already.
inline bool joins_joined_vertices(const std::vector<Mesh::Vertex_index>& corner, const Mesh& mesh,
                                  const std::vector<std::pair<int, int>>& diagonals)
{
  for(const auto& [a, b] : diagonals)
    if(CGAL::halfedge(corner[std::size_t(a)], corner[std::size_t(b)], mesh).second) return true;
  return false;
}

// Where a diagonal of the triangulation joins two vertices already joined
// by an edge of the mesh (two quads folded over a common diagonal, as in
// quad models with a vertex of two faces), splitting along it would make a
// second edge between them: an edge of four triangles. The fan from the
// first corner whose diagonals are all new replaces the triangulation then
// (for a quad: the other diagonal); if there is none, it stays (the input
// path then repairs the mesh as a soup).
inline void avoid_existing_edges(const std::vector<Mesh::Vertex_index>& corner, const Mesh& mesh,
                                 std::vector<std::pair<int, int>>& diagonals)
{
  if(!joins_joined_vertices(corner, mesh, diagonals)) return;
  const int n = int(corner.size());
  for(int k = 0; k < n; ++k)
  {
    std::vector<std::pair<int, int>> fan;
    for(int j = 2; j <= n - 2; ++j)
    {
      const int a = k, b = (k + j) % n;
      fan.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
    if(!joins_joined_vertices(corner, mesh, fan))
    {
      std::sort(fan.begin(), fan.end());
      diagonals = std::move(fan);
      return;
    }
  }
}

// Triangulates face f of `mesh` as PMP::triangulate_faces() would, by
// splitting it along the diagonals found on the polygon alone; falls back
// to ear_split() where that fails. Returns false on the fallback. Face f
// keeps its index; the other triangles are appended.
bool triangulate_face(Mesh::Face_index f, Mesh& mesh)
{
  std::vector<Mesh::Vertex_index> corner;
  std::vector<Point_3> points;
  for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
  {
    corner.push_back(mesh.target(h));
    points.push_back(mesh.point(mesh.target(h)));
  }
  std::vector<std::pair<int, int>> diagonals;
  if(!triangulation_diagonals(points, diagonals))
  {
    ear_split(f, mesh);
    return false;
  }
  avoid_existing_edges(corner, mesh, diagonals);
  // Diagonals of a triangulation do not cross: each one lies inside exactly
  // one of the pieces cut so far, between two non-adjacent corners of it.
  std::vector<Mesh::Face_index> pieces = {f};
  for(const auto& [a, b] : diagonals)
  {
    bool done = false;
    for(std::size_t i = 0; i < pieces.size() && !done; ++i)
    {
      Mesh::Halfedge_index ha, hb;
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(pieces[i]), mesh))
      {
        if(mesh.target(h) == corner[std::size_t(a)]) ha = h;
        if(mesh.target(h) == corner[std::size_t(b)]) hb = h;
      }
      if(ha == Mesh::null_halfedge() || hb == Mesh::null_halfedge() || mesh.next(ha) == hb || mesh.next(hb) == ha)
        continue;
      const Mesh::Halfedge_index cut = CGAL::Euler::split_face(ha, hb, mesh);
      pieces.push_back(mesh.face(mesh.opposite(cut)) == pieces[i] ? mesh.face(cut) : mesh.face(mesh.opposite(cut)));
      done = true;
    }
    if(!done) break;
  }
  bool all_triangles = true;
  for(Mesh::Face_index piece : pieces)
    if(CGAL::halfedges_around_face(mesh.halfedge(piece), mesh).size() != 3)
    {
      ear_split(piece, mesh);
      all_triangles = false;
    }
  return all_triangles;
}

} // namespace detail
} // namespace mesh_input
