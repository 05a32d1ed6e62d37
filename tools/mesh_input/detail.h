// Internal to the input path (tools/mesh_input/*.cpp): the helpers and
// steps its files share. The interface is tools/mesh_input.h.
#ifndef UV_TOOLS_MESH_INPUT_DETAIL_H
#define UV_TOOLS_MESH_INPUT_DETAIL_H

#include "../mesh_input.h"

// triangulate_faces() on a self-intersecting polygon would print a
// performance hint of CGAL's constrained triangulation on stderr.
#ifndef CGAL_NO_CDT_2_WARNING
#define CGAL_NO_CDT_2_WARNING
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/IO/OFF/File_header_extended_OFF.h>
#include <CGAL/IO/io.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mesh_input {
namespace detail {

inline std::string quoted(const std::string& filename) { return "'" + filename + "'"; }

[[noreturn]] inline void fail(const std::string& status, const std::string& message)
{
  throw Input_error(status, message);
}

[[noreturn]] inline void cannot_read(const std::string& filename, const std::string& why)
{
  fail("ERROR_CANNOT_READ", "cannot read " + quoted(filename) + ": " + why);
}

inline std::string format_point(const File_point& p)
{
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

using Polygon = std::vector<std::size_t>;

// file_structure.cpp: the structure of a file of `file_size` bytes, checked
// before CGAL's readers see it (throw Input_error).
void check_off_structure(const std::string& filename, std::uintmax_t file_size);
void check_ply_structure(const std::string& filename, std::uintmax_t file_size);
void check_obj_structure(const std::string& filename);

// read_soup.cpp
void read_soup(const std::string& filename, std::vector<File_point>& points, std::vector<Polygon>& polygons);
std::string describe_soup_problem(const std::vector<Polygon>& polygons, std::size_t number_of_points);

// triangulation.cpp
bool triangulate_face(Mesh::Face_index f, Mesh& mesh);

} // namespace detail
} // namespace mesh_input

#endif
