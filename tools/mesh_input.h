// mesh_input.h: the input path of the tools (uv_unwrap, check_all_meshes,
// the fuzz target): reads a mesh file (OFF, OBJ, PLY, STL) as a polygon
// soup, validates it, repairs what can be repaired and builds a
// Surface_mesh ready for cut_and_parameterize().
//
//   mesh_input::Mesh mesh;
//   mesh_input::Input_report report;
//   mesh_input::read_input_mesh("in.off", mesh, report); // throws Input_error
//   for(const std::string& w : report.warnings) ...
//
// What is checked, in this order (each failure throws Input_error, whose
// message is one line naming the problem and where, and whose `status` is
// the identifier written to uv_unwrap's statistics):
//   - the file exists, is a non-empty regular file with a supported
//     extension                                        -> ERROR_CANNOT_READ
//   - its structure (OFF and PLY headers, element counts, face lists) is
//     sound before CGAL's readers see it: they trust counts and casts, so a
//     corrupt file could make them allocate without bound, loop, or convert
//     out-of-range numbers                              -> ERROR_CANNOT_READ
//   - CGAL reads it; every face index names a vertex   -> ERROR_CANNOT_READ
//     (what CGAL's readers do not read is fixed first, with a warning: OFF
//     counts glued to the keyword, "OFF8 6 12"; ASCII PLY element lines
//     ending with values the header does not list, as VCG/MeshLab writes
//     faces, cut there; OBJ lines continued with a trailing backslash,
//     joined; OBJ polylines and points, `l` and `p`, ignored)
//   - every coordinate is finite                       -> ERROR_NON_FINITE_COORDINATE
//   - there is at least one face                       -> ERROR_EMPTY_MESH
// and what is repaired (each adds a warning to the report):
//   - a soup that is not a manifold, consistently oriented polygon mesh
//     (non-manifold edge or vertex, face using a vertex twice, face with
//     fewer than 3 vertices, inconsistent orientation): repaired with
//     repair_polygon_soup(), orient_polygon_soup() and
//     duplicate_non_manifold_vertices(). The repair merges coincident
//     points and drops isolated ones, so vertex and face indices change.
//     If that fails                                    -> ERROR_NON_MANIFOLD
//   - faces with more than 3 vertices: triangulated (triangulate_faces(),
//     then an ear split for the faces it refuses, e.g. zero-area polygons).
//     Each polygon keeps its index (as its first triangle); the other
//     triangles are appended after the last face.
// and what is only reported (warnings):
//   - isolated vertices (in no face): they keep their index and position
//     but get no UV;
//   - degenerate faces (zero area, needles), by the same rule as the
//     library, which clamps their rest shape.
//
// A mesh that needs none of these repairs comes out with the vertices and
// faces of the file, in the file's order.
//
// The code is compiled once, into the static library uv_tools_mesh_input
// (tools/CMakeLists.txt), from tools/mesh_input/: file_structure.cpp (the
// structure checks of OFF, PLY and OBJ files), read_soup.cpp (the soup as
// CGAL reads it), triangulation.cpp (faces with more than 3 vertices) and
// read_input_mesh.cpp (validation and repair: the entry point).
#ifndef UV_TOOLS_MESH_INPUT_H
#define UV_TOOLS_MESH_INPUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesh_input {

// Filtered predicates (exact signs) keep triangulate_faces() robust on
// nearly degenerate polygons; coordinates are plain doubles all the same.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
// Points as the readers see them: plain doubles, so that a NaN read from a
// binary file is only compared as a double (an exact comparison of Epick
// points would convert it to an exact number, which GMP cannot).
using File_point = CGAL::Simple_cartesian<double>::Point_3;

/// A file the tools refuse. `status` is an identifier such as
/// "ERROR_CANNOT_READ" (the library's names where one fits); what() is a
/// one-line message.
struct Input_error : std::runtime_error
{
  Input_error(std::string status_, const std::string& message)
    : std::runtime_error(message), status(std::move(status_)) {}
  std::string status;
};

/// Every status read_input_mesh() can throw.
const std::vector<std::string>& input_error_statuses();

/// What read_input_mesh() found and did besides failing.
struct Input_report
{
  std::vector<std::string> warnings;     ///< one line each, for stderr and the stats
  std::size_t file_vertices = 0;         ///< points of the file
  std::size_t file_faces = 0;            ///< polygons of the file
  bool repaired = false;                 ///< went through the soup repair
  std::size_t triangulated_faces = 0;    ///< polygons with more than 3 vertices
  std::size_t isolated_vertices = 0;     ///< vertices in no face (no UV)
  std::size_t degenerate_faces = 0;      ///< zero-area or needle faces
  /// Per face of the mesh (by index): the polygon of the file it comes
  /// from. Empty when `repaired` (the repair reorders faces and vertices);
  /// otherwise vertex i of the mesh is point i of the file.
  std::vector<std::size_t> face_origin;
  /// Per point of the file (by index): the mesh vertex at its position
  /// (the point itself without repair; after a repair, the first vertex at
  /// the same coordinates), or -1 if it is in no face of the repaired mesh.
  /// Lets selections given in the file's numbering (tools/seam_constraints.h)
  /// find their vertices.
  std::vector<long> point_vertex;
};

/// The extension of `filename` in lower case, without its dot ("" if none).
std::string lower_extension(const std::string& filename);

/// Reads, validates and repairs `filename` into `mesh` (cleared first).
/// Throws Input_error; fills `report` (warnings included) otherwise.
void read_input_mesh(const std::string& filename, Mesh& mesh, Input_report& report);

/// The same validation and repair, on a polygon soup given in memory (the
/// Python module's arrays): `points` and `polygons` (indices into `points`,
/// each checked to be in range by the caller); `name` starts the messages
/// (e.g. "'mesh.off'"). Throws Input_error; fills `report` otherwise.
void mesh_from_polygon_soup(const std::vector<File_point>& points, std::vector<std::vector<std::size_t>> polygons,
                            const std::string& name, Mesh& mesh, Input_report& report);

/// After mesh_from_polygon_soup() on a soup of triangles (`points`,
/// `triangles`, as given to it), with its `report`: for corner k of triangle
/// t, `corners[t][k]` is a halfedge of `mesh` (of a face, pointing to the
/// vertex at that corner) whose UV that corner gets. Without repair, face t
/// of the mesh is triangle t. After the soup repair, a triangle is found
/// again by the positions of its corners: a triangle that the repair merged
/// with a duplicate gets that duplicate's face; one it dropped (two corners
/// at the same position) gets, at each corner, a face at that position
/// (a null halfedge where no face is). For the formats that keep their own
/// triangles (glTF).
void triangle_corner_halfedges(const std::vector<File_point>& points,
                               const std::vector<std::vector<std::size_t>>& triangles, const Mesh& mesh,
                               const Input_report& report, std::vector<std::array<Mesh::Halfedge_index, 3>>& corners);

} // namespace mesh_input

#endif
