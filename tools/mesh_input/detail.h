// Internal to the input path (tools/mesh_input/*.cpp): the helpers and
// steps its files share; each file includes the CGAL headers it uses. The interface is tools/mesh_input.h.
#ifndef UV_TOOLS_MESH_INPUT_DETAIL_H
#define UV_TOOLS_MESH_INPUT_DETAIL_H

#include "../mesh_input.h"

#include <cstddef>
#include <cstdint>
#include <string>
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

using Polygon = std::vector<std::size_t>;

// file_structure.cpp: the structure of a file of `file_size` bytes, checked
// before CGAL's readers see it (throw Input_error). Where the file needs a
// fix that CGAL's reader lacks (OFF counts glued to the keyword, PLY element
// lines with extra values, OBJ line continuations and `l` lines),
// `normalized` gets the fixed text, which CGAL then reads instead of the
// file, and `notes` a line saying what was done; `normalized` stays empty
// otherwise.
void check_off_structure(const std::string& filename, std::uintmax_t file_size, std::string& normalized,
                         std::vector<std::string>& notes);
void check_ply_structure(const std::string& filename, std::uintmax_t file_size, std::string& normalized,
                         std::vector<std::string>& notes);
void check_obj_structure(const std::string& filename, std::string& normalized, std::vector<std::string>& notes);

// read_soup.cpp: the soup of the file; `notes`: what the reading fixed (see above).
void read_soup(const std::string& filename, std::vector<File_point>& points, std::vector<Polygon>& polygons,
               std::vector<std::string>& notes);
std::string describe_soup_problem(const std::vector<Polygon>& polygons, std::size_t number_of_points);

// triangulation.cpp
bool triangulate_face(Mesh::Face_index f, Mesh& mesh);

} // namespace detail
} // namespace mesh_input

#endif
