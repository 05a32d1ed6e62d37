// The input path's entry point: validation and repair (see mesh_input.h).
#include "detail.h"

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>
#include <CGAL/boost/graph/helpers.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace mesh_input {

namespace {

std::string format_point(const File_point& p)
{
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

// The soup repair: `points` and `polygons` (not a polygon mesh: `problem`
// says why; `name`: the input, quoted, for messages) repaired, oriented and built into `mesh`, whose non-manifold
// vertices are then duplicated; `file_points` are the points of the file, for
// report.point_vertex. Throws Input_error where nothing can be built.
void repair_as_soup(const std::string& name, const std::vector<Point_3>& file_points, std::vector<Point_3>& points,
                    std::vector<detail::Polygon>& polygons, const std::string& problem, Mesh& mesh,
                    Input_report& report)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  mesh.clear();
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  if(polygons.empty())
    detail::fail("ERROR_EMPTY_MESH", name + ": no valid face left after repairing (" + problem + ")");
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    detail::fail("ERROR_NON_MANIFOLD", name + " is not manifold (" + problem + ") and could not be repaired");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const std::size_t duplicated = PMP::duplicate_non_manifold_vertices(mesh);
  std::map<Point_3, long> vertex_at;
  for(Mesh::Vertex_index v : vertices(mesh)) vertex_at.emplace(mesh.point(v), long(std::size_t(v)));
  report.point_vertex.assign(file_points.size(), -1);
  for(std::size_t i = 0; i < file_points.size(); ++i)
    if(auto it = vertex_at.find(file_points[i]); it != vertex_at.end()) report.point_vertex[i] = it->second;
  report.face_origin.clear();
  report.repaired = true;
  report.warnings.push_back(
    "not a manifold, consistently oriented mesh (" + problem + "): repaired as a polygon soup (" +
    std::to_string(report.file_vertices) + " vertices, " + std::to_string(report.file_faces) +
    " faces -> " + std::to_string(num_vertices(mesh)) + " vertices, " + std::to_string(num_faces(mesh)) +
    " faces; coincident vertices merged" +
    (duplicated ? ", " + std::to_string(duplicated) + " non-manifold vertices duplicated" : std::string()) +
    "); vertex and face indices below refer to the repaired mesh");
}

// An edge of `mesh` whose two vertices are joined by another edge too (a
// triangulated polygon whose diagonal was already an edge: in the soup, an
// edge of 3 or 4 faces), or a null edge.
Mesh::Edge_index first_parallel_edge(const Mesh& mesh)
{
  std::map<std::pair<std::size_t, std::size_t>, Mesh::Edge_index> seen;
  for(Mesh::Edge_index e : mesh.edges())
  {
    std::size_t a = std::size_t(mesh.vertex(e, 0)), b = std::size_t(mesh.vertex(e, 1));
    if(a > b) std::swap(a, b);
    if(!seen.emplace(std::make_pair(a, b), e).second) return e;
  }
  return Mesh::null_edge();
}

} // namespace


void triangle_corner_halfedges(const std::vector<File_point>& points,
                               const std::vector<std::vector<std::size_t>>& triangles, const Mesh& mesh,
                               const Input_report& report, std::vector<std::array<Mesh::Halfedge_index, 3>>& corners)
{
  corners.assign(triangles.size(), {Mesh::null_halfedge(), Mesh::null_halfedge(), Mesh::null_halfedge()});
  if(!report.repaired)
  {
    for(std::size_t t = 0; t < triangles.size() && t < num_faces(mesh); ++t)
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(Mesh::Face_index(Mesh::size_type(t))), mesh))
        for(std::size_t k = 0; k < 3 && k < triangles[t].size(); ++k)
          if(long(std::size_t(mesh.target(h))) == report.point_vertex[triangles[t][k]]) corners[t][k] = h;
    return;
  }
  // each face by its corners' positions (sorted), and a face halfedge at each position
  using Key = std::array<Point_3, 3>;
  std::multimap<Key, Mesh::Face_index> face_at;
  std::map<Point_3, Mesh::Halfedge_index> halfedge_at;
  for(Mesh::Face_index f : faces(mesh))
  {
    Key key;
    std::size_t k = 0;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    {
      if(k < 3) key[k] = mesh.point(mesh.target(h));
      ++k;
      halfedge_at.emplace(mesh.point(mesh.target(h)), h);
    }
    if(k != 3) continue;
    std::sort(key.begin(), key.end());
    face_at.emplace(key, f);
  }
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    if(triangles[t].size() != 3) continue;
    Key p;
    for(std::size_t k = 0; k < 3; ++k)
    {
      const File_point& q = points[triangles[t][k]];
      p[k] = Point_3(q.x(), q.y(), q.z());
    }
    Key key = p;
    std::sort(key.begin(), key.end());
    // the face at these positions, in the triangle's orientation if there is one
    Mesh::Face_index face;
    const auto range = face_at.equal_range(key);
    for(auto it = range.first; it != range.second; ++it)
    {
      const Mesh::Halfedge_index h = mesh.halfedge(it->second);
      if(face == Mesh::null_face()) face = it->second;
      for(std::size_t k = 0; k < 3; ++k)
        if(mesh.point(mesh.target(h)) == p[k] && mesh.point(mesh.target(mesh.next(h))) == p[(k + 1) % 3])
          face = it->second;
    }
    for(std::size_t k = 0; k < 3; ++k)
    {
      if(face != Mesh::null_face())
      {
        for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(face), mesh))
          if(mesh.point(mesh.target(h)) == p[k]) corners[t][k] = h;
      }
      else if(const auto it = halfedge_at.find(p[k]); it != halfedge_at.end())
        corners[t][k] = it->second;
    }
  }
}

const std::vector<std::string>& input_error_statuses()
{
  static const std::vector<std::string> names = {"ERROR_CANNOT_READ", "ERROR_EMPTY_MESH",
    "ERROR_NON_FINITE_COORDINATE", "ERROR_NON_MANIFOLD", "ERROR_NON_TRIANGULAR_MESH"};
  return names;
}

std::string lower_extension(const std::string& filename)
{
  std::string ext = std::filesystem::path(filename).extension().string();
  if(!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// Reads, validates and repairs `filename` into `mesh` (cleared first).
/// Throws Input_error; fills `report` (warnings included) otherwise.
void read_input_mesh(const std::string& filename, Mesh& mesh, Input_report& report)
{
  std::vector<File_point> file_points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::string> notes; // what the reading fixed, first in the warnings
  detail::read_soup(filename, file_points, polygons, notes);
  mesh_from_polygon_soup(file_points, std::move(polygons), detail::quoted(filename), mesh, report);
  report.warnings.insert(report.warnings.begin(), notes.begin(), notes.end());
}

void mesh_from_polygon_soup(const std::vector<File_point>& file_points, std::vector<std::vector<std::size_t>> polygons,
                            const std::string& name, Mesh& mesh, Input_report& report)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  mesh.clear();
  report = Input_report();

  std::vector<Point_3> points;
  for(std::size_t v = 0; v < file_points.size(); ++v)
  {
    const File_point& p = file_points[v];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      detail::fail("ERROR_NON_FINITE_COORDINATE", name + ": vertex " + std::to_string(v) +
                                                  " has a non-finite coordinate " + format_point(p));
  }
  points.reserve(file_points.size());
  for(const File_point& p : file_points) points.emplace_back(p.x(), p.y(), p.z());
  report.file_vertices = points.size();
  report.file_faces = polygons.size();
  if(polygons.empty()) detail::fail("ERROR_EMPTY_MESH", name + " has no faces");

  const std::vector<Point_3> file_points_kept = points; // the repairs renumber `points`
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    std::string problem = detail::describe_soup_problem(polygons, points.size());
    if(problem.empty()) problem = "not a polygon mesh";
    repair_as_soup(name, file_points_kept, points, polygons, problem, mesh, report);
  }
  else
  {
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    report.point_vertex.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i) report.point_vertex[i] = long(i);
    report.face_origin.resize(num_faces(mesh));
    for(std::size_t f = 0; f < report.face_origin.size(); ++f) report.face_origin[f] = f;
  }

  // Triangulation of the faces with more than 3 vertices.
  std::size_t first_polygon = 0, first_degree = 0;
  std::vector<Mesh::Face_index> polygons_to_split;
  for(Mesh::Face_index f : faces(mesh))
  {
    const std::size_t degree = CGAL::halfedges_around_face(mesh.halfedge(f), mesh).size();
    if(degree == 3) continue;
    if(polygons_to_split.empty()) { first_polygon = std::size_t(f); first_degree = degree; }
    polygons_to_split.push_back(f);
  }
  if(!polygons_to_split.empty())
  {
    const std::size_t before = num_faces(mesh);
    std::size_t refused = 0;
    for(Mesh::Face_index f : polygons_to_split)
    {
      if(!detail::triangulate_face(f, mesh)) ++refused;
      if(!report.face_origin.empty()) // the new triangles come from the same polygon
        report.face_origin.resize(num_faces(mesh), report.face_origin[std::size_t(f)]);
    }
    if(!CGAL::is_triangle_mesh(mesh) || !mesh.is_valid(false))
      detail::fail("ERROR_NON_TRIANGULAR_MESH", name + ": face " +
                                                std::to_string(first_polygon) + " could not be triangulated");
    report.triangulated_faces = polygons_to_split.size();
    report.warnings.push_back(
      std::to_string(polygons_to_split.size()) + " faces are not triangles (first: face " +
      std::to_string(first_polygon) + ", " + std::to_string(first_degree) + " vertices): triangulated (" +
      std::to_string(before) + " -> " + std::to_string(num_faces(mesh)) + " faces" +
      (refused ? "; " + std::to_string(refused) + " degenerate or self-intersecting polygons split at their first corner"
               : std::string()) +
      ")");
  }

  // A polygon split along a diagonal that was already an edge (two quads
  // folded over their common diagonal) leaves two edges between the same
  // vertices: an edge of 3 or 4 triangles, which the unwrapping cannot take.
  // The triangulated mesh then goes through the soup repair, which splits it.
  if(const Mesh::Edge_index e = first_parallel_edge(mesh); e != Mesh::null_edge())
  {
    const std::string problem = "after triangulation, edge (" + std::to_string(std::size_t(mesh.vertex(e, 0))) + ", " +
                                std::to_string(std::size_t(mesh.vertex(e, 1))) + ") is shared by more than 2 faces";
    std::vector<Point_3> soup_points;
    std::vector<detail::Polygon> soup_polygons;
    PMP::polygon_mesh_to_polygon_soup(mesh, soup_points, soup_polygons);
    repair_as_soup(name, file_points_kept, soup_points, soup_polygons, problem, mesh, report);
  }

  std::size_t first_isolated = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    if(mesh.is_isolated(v) && report.isolated_vertices++ == 0) first_isolated = std::size_t(v);
  if(report.isolated_vertices > 0)
    report.warnings.push_back(std::to_string(report.isolated_vertices) + " isolated vertices (first: vertex " +
                              std::to_string(first_isolated) + ") are in no face: they get no UV");

  std::size_t first_degenerate = 0;
  for(Mesh::Face_index f : faces(mesh))
    if(CGAL::Surface_mesh_parameterization::is_degenerate_face(f, mesh) && report.degenerate_faces++ == 0) first_degenerate = std::size_t(f);
  if(report.degenerate_faces > 0)
    report.warnings.push_back(std::to_string(report.degenerate_faces) +
                              " degenerate faces (zero area or needle; first: face " +
                              std::to_string(first_degenerate) + "): their shape is clamped");
}

} // namespace mesh_input
