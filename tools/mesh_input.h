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
#ifndef UV_TOOLS_MESH_INPUT_H
#define UV_TOOLS_MESH_INPUT_H

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
inline const std::vector<std::string>& input_error_statuses()
{
  static const std::vector<std::string> names = {"ERROR_CANNOT_READ", "ERROR_EMPTY_MESH",
    "ERROR_NON_FINITE_COORDINATE", "ERROR_NON_MANIFOLD", "ERROR_NON_TRIANGULAR_MESH"};
  return names;
}

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

inline std::string lower_extension(const std::string& filename)
{
  std::string ext = std::filesystem::path(filename).extension().string();
  if(!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

inline std::string format_point(const File_point& p)
{
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

// ------------------------------------------------------------ OFF structure

// Element counts larger than this cannot be genuine: every element takes at
// least one byte of the file. (CGAL's readers reserve memory for the counts
// of a header before reading any element.)
inline void check_count(const std::string& filename, const std::string& what, long long count,
                        std::uintmax_t file_size)
{
  if(count < 0)
    cannot_read(filename, "its header announces a negative number of " + what + " (" +
                          std::to_string(count) + ")");
  if(std::uintmax_t(count) > file_size || count > (1LL << 30))
    cannot_read(filename, "its header announces " + std::to_string(count) + " " + what +
                          " in a file of " + std::to_string(file_size) + " bytes");
}

// True if `token` is, as a whole, a number that is not finite ("nan",
// "inf", "1e999", ...): such a vertex is reported as non-finite rather than
// as unreadable (CGAL's readers reject some of these spellings).
inline bool is_non_finite_token(const std::string& token)
{
  if(token.empty()) return false;
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !std::isfinite(x);
}

[[noreturn]] inline void non_finite_vertex(const std::string& filename, long long v, const std::string& token)
{
  fail("ERROR_NON_FINITE_COORDINATE", quoted(filename) + ": vertex " + std::to_string(v) +
                                      " has a non-finite coordinate '" + token.substr(0, 30) + "'");
}

// A token of an OFF face line must be a non-negative integer (CGAL reads it
// as a double and casts it to an unsigned integer).
inline bool is_index_value(double x, double bound)
{
  return std::isfinite(x) && x >= 0. && x < bound && x == std::floor(x);
}

// Colors as CGAL's OFF scanner converts them (File_scanner_OFF::scan_color):
// integers are cast to unsigned char, other values are scaled by 255 first.
// Only values that survive the cast are accepted.
inline bool is_valid_off_color(const double* rgb)
{
  bool integers = true;
  for(int k = 0; k < 3; ++k)
  {
    if(!std::isfinite(rgb[k])) return false;
    integers = integers && std::floor(rgb[k]) == rgb[k];
  }
  for(int k = 0; k < 3; ++k)
  {
    const double x = integers ? rgb[k] : rgb[k] * 255.;
    if(!(x >= 0. && x < 256.)) return false;
  }
  return true;
}

// Walks an OFF file the way CGAL's File_scanner_OFF does (same header
// grammar, one line per vertex and per face in ASCII) and refuses what that
// reader does not handle safely: texture coordinates (STOFF) and n-dimensional
// files (nOFF), colors in binary files, short lines or out-of-range values in
// colored files, invalid face sizes and vertex indices, and counts the file
// cannot hold.
inline void check_off_structure(const std::string& filename, std::uintmax_t file_size)
{
  std::ifstream in(filename, std::ios::binary);
  char c = 0;
  while((in >> c) && c == '#') in >> CGAL::skip_until_EOL;
  if(!in) cannot_read(filename, "no OFF header");
  std::string keyword(1, c);
  while(keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) keyword += c;
  // [ST][C][N][4][n]OFF
  std::size_t j = 0;
  bool textures = false, colors = false, normals = false, homogeneous = false, dimensional = false;
  if(keyword.compare(j, 2, "ST") == 0) { textures = true; j += 2; }
  if(j < keyword.size() && keyword[j] == 'C') { colors = true; ++j; }
  if(j < keyword.size() && keyword[j] == 'N') { normals = true; ++j; }
  if(j < keyword.size() && keyword[j] == '4') { homogeneous = true; ++j; }
  if(j < keyword.size() && keyword[j] == 'n') { dimensional = true; ++j; }
  if(keyword.substr(j) != "OFF")
    cannot_read(filename, "not an OFF file (header '" + keyword.substr(0, 20) + "')");
  if(textures) cannot_read(filename, "OFF files with texture coordinates (" + keyword + ") are not supported");
  if(dimensional) cannot_read(filename, "n-dimensional OFF files (" + keyword + ") are not supported");

  in >> CGAL::skip_comment_OFF;
  c = 0;
  if(!(in >> c)) cannot_read(filename, "its OFF header has no element counts");
  long long vertices = 0, faces = 0, edges = 0;
  const bool binary = !std::isdigit(static_cast<unsigned char>(c));
  if(binary)
  {
    std::string word(1, c);
    while(word.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) word += c;
    if(word != "BINARY") cannot_read(filename, "its OFF header has no valid element counts");
    if(colors) cannot_read(filename, "binary OFF files with colors are not supported");
    if(c != '\n') in >> CGAL::skip_until_EOL;
    auto read_int32 = [&]() -> long long {
      unsigned char b[4];
      if(!in.read(reinterpret_cast<char*>(b), 4)) cannot_read(filename, "truncated binary OFF header");
      const std::uint32_t u = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                              (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]);
      return (long long)std::int32_t(u);
    };
    vertices = read_int32();
    faces = read_int32();
    edges = read_int32();
  }
  else
  {
    in.putback(c);
    if(!(in >> vertices >> faces >> edges)) cannot_read(filename, "its OFF header has no valid element counts");
  }
  check_count(filename, "vertices", vertices, file_size);
  check_count(filename, "faces", faces, file_size);
  check_count(filename, "edges", edges, file_size);
  if(binary) return; // face sizes are bounded by Checked_polygon, indices checked by CGAL

  std::string line, token;
  std::vector<double> entries;
  // (a truncated file is refused here: CGAL's scanner would go on reading
  // colors of lines it could not read)
  auto read_entries = [&](const std::string& what, long long i, long long count) {
    in >> CGAL::skip_comment_OFF;
    if(!std::getline(in, line))
      cannot_read(filename, "the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                            " " + what);
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    entries.clear();
    double d = 0.;
    while(words >> CGAL::IO::iformat(d)) entries.push_back(d);
  };
  // CGAL's scanner remembers that an element had colors and then reads
  // colors for every later one: they must all have them.
  bool colors_seen = false;
  auto check_colors = [&](std::size_t first, const std::string& where) {
    const std::size_t n = entries.size() - first;
    if(n == 0 && !colors_seen) return;
    if(n != 3 && n != 4)
      cannot_read(filename, where + " has " + std::to_string(n) + " color values (expected 3 or 4" +
                            (colors_seen ? ", as earlier elements have colors)" : " or none)"));
    if(!is_valid_off_color(&entries[first])) cannot_read(filename, where + " has an invalid color");
    colors_seen = true;
  };

  const std::size_t h = homogeneous ? 1 : 0;
  const std::size_t vertex_values = (3 + h) * (normals ? 2 : 1);
  for(long long i = 0; i < vertices; ++i)
  {
    read_entries("vertices", i, vertices);
    std::istringstream words(line);
    for(int k = 0; k < 3 && words >> token; ++k)
      if(is_non_finite_token(token)) non_finite_vertex(filename, i, token);
    if(!colors) continue;
    const std::string where = "vertex " + std::to_string(i);
    if(entries.size() < vertex_values)
      cannot_read(filename, where + " has " + std::to_string(entries.size()) + " values, expected at least " +
                            std::to_string(vertex_values));
    check_colors(vertex_values, where);
  }
  colors_seen = false;
  for(long long f = 0; f < faces; ++f)
  {
    read_entries("faces", f, faces);
    const std::string where = "face " + std::to_string(f);
    if(entries.empty()) cannot_read(filename, where + " has no vertex count");
    if(!is_index_value(entries[0], double(entries.size())))
      cannot_read(filename, where + " (line '" + line.substr(0, 40) + "') has an invalid vertex count");
    const std::size_t n = std::size_t(entries[0]);
    for(std::size_t k = 1; k <= n; ++k)
      if(!is_index_value(entries[k], double(vertices)))
      {
        std::ostringstream value;
        value << entries[k];
        cannot_read(filename, where + " refers to vertex " + value.str() + ", but the file has " +
                              std::to_string(vertices) + " vertices");
      }
    if(colors) check_colors(n + 1, where);
  }
}

// ------------------------------------------------------------ PLY structure

struct Ply_property
{
  std::string name;
  bool list = false;
  int count_size = 0; // bytes of the list count type
  int size = 0;       // bytes of the scalar / list item type
  bool count_signed = false, is_float = false;
};

struct Ply_element
{
  std::string name;
  long long count = 0;
  std::vector<Ply_property> properties;
};

// Byte size of a PLY scalar type, 0 if unknown.
inline int ply_type_size(const std::string& type, bool& is_signed, bool& is_float)
{
  is_signed = false;
  is_float = false;
  if(type == "char" || type == "int8") { is_signed = true; return 1; }
  if(type == "uchar" || type == "uint8") return 1;
  if(type == "short" || type == "int16") { is_signed = true; return 2; }
  if(type == "ushort" || type == "uint16") return 2;
  if(type == "int" || type == "int32") { is_signed = true; return 4; }
  if(type == "uint" || type == "uint32") return 4;
  if(type == "float" || type == "float32") { is_signed = true; is_float = true; return 4; }
  if(type == "double" || type == "float64") { is_signed = true; is_float = true; return 8; }
  return 0;
}

// A token CGAL's ASCII PLY reader consumes whole: an integer for integer
// types; for floating types, only characters its number parser takes (it
// would split other tokens and shift every later value).
inline bool is_ply_ascii_token(const std::string& token, bool is_float)
{
  if(token.empty()) return false;
  if(is_float)
  {
    for(char ch : token)
      if(!std::isdigit(static_cast<unsigned char>(ch)) && ch != '.' && ch != 'e' && ch != 'E' &&
         ch != '+' && ch != '-')
        return false;
    double x = 0.;
    return std::sscanf(token.c_str(), "%lf", &x) == 1;
  }
  std::size_t k = (token[0] == '-' || token[0] == '+') ? 1 : 0;
  if(k == token.size() || token.size() - k > 18) return false;
  for(; k < token.size(); ++k)
    if(!std::isdigit(static_cast<unsigned char>(token[k]))) return false;
  return true;
}

// Name of a "property list <count type> <item type> <name>" line.
inline std::string item_name_of(const std::string& line)
{
  std::istringstream words(line);
  std::string word, name;
  for(int k = 0; k < 5 && words >> word; ++k) name = word;
  return name;
}

// Parses the header the way CGAL's PLY_reader does, then walks every
// element: list sizes must be non-negative integers that fit in the data
// left, and the data must not end early.
inline void check_ply_structure(const std::string& filename, std::uintmax_t file_size)
{
  std::ifstream in(filename, std::ios::binary);
  std::string line;
  int format = -1; // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  bool header_done = false;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::string keyword;
    if(number == 1)
    {
      if(!(words >> keyword) || keyword != "ply") cannot_read(filename, "not a PLY file");
      continue;
    }
    if(number == 2)
    {
      std::string tag, name;
      words >> tag >> name;
      if(name == "ascii") format = 0;
      else if(name == "binary_little_endian") format = 1;
      else if(name == "binary_big_endian") format = 2;
      else cannot_read(filename, "unknown PLY format '" + name.substr(0, 30) + "'");
      continue;
    }
    if(!(words >> keyword)) cannot_read(filename, "empty line " + std::to_string(number) + " in the PLY header");
    if(keyword == "end_header") { header_done = true; break; }
    if(keyword == "element")
    {
      Ply_element e;
      std::string count;
      if(!(words >> e.name >> count) || !is_ply_ascii_token(count, false) || count[0] == '+')
        cannot_read(filename, "invalid element line " + std::to_string(number) + " in the PLY header");
      e.count = std::stoll(count);
      check_count(filename, "'" + e.name.substr(0, 30) + "' elements", e.count, file_size);
      elements.push_back(e);
    }
    else if(keyword == "property")
    {
      if(elements.empty())
        cannot_read(filename, "PLY property before any element (line " + std::to_string(number) + ")");
      std::string type, name;
      if(!(words >> type >> name))
        cannot_read(filename, "invalid property line " + std::to_string(number) + " in the PLY header");
      Ply_property p;
      bool is_signed = false, is_float = false;
      if(type == "list")
      {
        std::string item_type;
        if(!(words >> item_type))
          cannot_read(filename, "invalid property line " + std::to_string(number) + " in the PLY header");
        p.list = true;
        p.count_size = ply_type_size(name, p.count_signed, is_float);
        if(p.count_size == 0 || is_float)
          cannot_read(filename, "PLY list '" + item_type.substr(0, 30) + "' has an unsupported size type '" +
                                name.substr(0, 30) + "' (expected an integer type)");
        type = item_type;
      }
      p.size = ply_type_size(type, is_signed, p.is_float);
      if(p.size == 0)
        cannot_read(filename, "unknown PLY property type '" + type.substr(0, 30) + "' (line " +
                              std::to_string(number) + ")");
      p.name = p.list ? item_name_of(line) : name;
      // CGAL reads these with a fixed type and asserts (or, without
      // assertions, dereferences a null pointer) on any other one.
      const std::string& element = elements.back().name;
      const std::string where = "PLY property '" + p.name.substr(0, 30) + "' of '" + element.substr(0, 30) + "'";
      if((element == "vertex" || element == "vertices") && (p.name == "x" || p.name == "y" || p.name == "z") &&
         (p.list || !p.is_float))
        cannot_read(filename, where + " must be a float or a double");
      if(element == "halfedge" && (p.name == "source" || p.name == "target") &&
         (p.list || p.is_float || is_signed || p.size != 4))
        cannot_read(filename, where + " must be a uint");
      elements.back().properties.push_back(p);
    }
    // comment, obj_info, ...: ignored, as CGAL does
  }
  if(!header_done) cannot_read(filename, "the PLY header has no end_header line");
  if(format < 0) cannot_read(filename, "the PLY header has no format line");

  auto truncated = [&](const Ply_element& e, long long item) {
    cannot_read(filename, "PLY data ends inside '" + e.name.substr(0, 30) + "' element " + std::to_string(item));
  };
  auto bad_list = [&](const Ply_element& e, long long item, const std::string& size) {
    cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                          " has a list of invalid size " + size.substr(0, 30));
  };

  if(format == 0)
  {
    std::string token;
    for(const Ply_element& e : elements)
      for(long long item = 0; item < e.count; ++item)
        for(const Ply_property& p : e.properties)
        {
          if(!(in >> token)) truncated(e, item);
          if(!p.list)
          {
            if(p.is_float && is_non_finite_token(token) && (e.name == "vertex" || e.name == "vertices"))
              non_finite_vertex(filename, item, token);
            if(!is_ply_ascii_token(token, p.is_float))
              cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                                    " has an invalid value '" + token.substr(0, 30) + "'");
            continue;
          }
          if(!is_ply_ascii_token(token, false)) bad_list(e, item, token);
          const long long n = std::stoll(token);
          const long long max = (1LL << (8 * p.count_size - (p.count_signed ? 1 : 0))) - 1;
          if(n < 0 || n > max || std::uintmax_t(n) > file_size) bad_list(e, item, token);
          for(long long k = 0; k < n; ++k)
          {
            if(!(in >> token)) truncated(e, item);
            if(!is_ply_ascii_token(token, p.is_float))
              cannot_read(filename, "'" + e.name.substr(0, 30) + "' element " + std::to_string(item) +
                                    " has an invalid list value '" + token.substr(0, 30) + "'");
          }
        }
    return;
  }

  const std::streamoff data_start = in.tellg();
  if(data_start < 0) cannot_read(filename, "unreadable PLY data");
  std::uintmax_t position = std::uintmax_t(data_start);
  std::vector<unsigned char> bytes(8);
  for(const Ply_element& e : elements)
    for(long long item = 0; item < e.count; ++item)
      for(const Ply_property& p : e.properties)
      {
        if(!p.list)
        {
          if(position + std::uintmax_t(p.size) > file_size) truncated(e, item);
          position += std::uintmax_t(p.size);
          continue;
        }
        if(position + std::uintmax_t(p.count_size) > file_size) truncated(e, item);
        in.seekg(std::streamoff(position));
        if(!in.read(reinterpret_cast<char*>(bytes.data()), p.count_size)) truncated(e, item);
        position += std::uintmax_t(p.count_size);
        std::uint64_t u = 0;
        for(int k = 0; k < p.count_size; ++k)
        {
          const int b = format == 1 ? p.count_size - 1 - k : k; // most significant first
          u = (u << 8) | bytes[std::size_t(b)];
        }
        long long n = (long long)u;
        if(p.count_signed && (u >> (8 * p.count_size - 1)) != 0) n = -1;
        if(n < 0) bad_list(e, item, "-");
        const std::uintmax_t need = std::uintmax_t(n) * std::uintmax_t(p.size);
        if(need > file_size - position) bad_list(e, item, std::to_string(n));
        position += need;
      }
}

// ------------------------------------------------------------ OBJ structure

// Line keywords CGAL's OBJ reader accepts (it refuses the whole file on any
// other one).
inline bool is_known_obj_keyword(const std::string& s)
{
  static const char* const known[] = {"v", "vt", "vn", "f", "vp", "bevel", "lod", "ctech", "c_interp",
    "usemap", "usemtl", "stech", "d_interp", "mtllib", "shadow_obj", "trace_obj", "o", "g", "s", "p",
    "cstype", "deg", "step", "bmat", "con", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2", "curv2d_2", "bsp", "bzp", "cdc",
    "cdp", "res"};
  if(!s.empty() && s[0] == '#') return true;
  for(const char* k : known)
    if(s == k) return true;
  return false;
}

// Names what CGAL's OBJ reader would refuse, before it does: a
// non-finite coordinate, an unknown statement, no face at all.
inline void check_obj_structure(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::string line, keyword, token;
  long long vertex = 0, faces = 0;
  for(long long number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    if(!(words >> keyword)) continue;
    if(keyword == "v")
    {
      for(int k = 0; k < 3 && words >> token; ++k)
        if(is_non_finite_token(token)) non_finite_vertex(filename, vertex, token);
      ++vertex;
    }
    else if(keyword == "f") ++faces;
    else if(!is_known_obj_keyword(keyword))
      cannot_read(filename, "line " + std::to_string(number) + ": unsupported OBJ statement '" +
                            keyword.substr(0, 30) + "'");
  }
  if(faces == 0) fail("ERROR_EMPTY_MESH", quoted(filename) + " has no faces");
}

// ------------------------------------------------------------ reading

// The polygon type given to CGAL's readers: refuses a size the file cannot
// hold (CGAL's OFF reader resizes each polygon to the size the file says).
inline std::size_t& polygon_size_limit()
{
  static std::size_t limit = 0;
  return limit;
}

struct Polygon_too_large {};

struct Checked_polygon : std::vector<std::size_t>
{
  void resize(std::size_t n)
  {
    if(n > polygon_size_limit()) throw Polygon_too_large();
    std::vector<std::size_t>::resize(n);
  }
};

using Polygon = std::vector<std::size_t>;

inline void check_file(const std::string& filename, std::uintmax_t& size)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!fs::exists(filename, ec)) fail("ERROR_CANNOT_READ", "cannot open " + quoted(filename) + ": no such file");
  if(!fs::is_regular_file(filename, ec)) cannot_read(filename, "not a regular file");
  if(!std::ifstream(filename)) fail("ERROR_CANNOT_READ", "cannot open " + quoted(filename) + ": permission denied");
  size = fs::file_size(filename, ec);
  if(ec) cannot_read(filename, ec.message());
  if(size == 0) fail("ERROR_EMPTY_MESH", quoted(filename) + " is empty (0 bytes)");
}

// Polygon soup of the file, as CGAL reads it, with every index checked.
inline void read_soup(const std::string& filename, std::vector<File_point>& points, std::vector<Polygon>& polygons)
{
  std::uintmax_t size = 0;
  check_file(filename, size);
  const std::string ext = lower_extension(filename);
  if(ext == "off") check_off_structure(filename, size);
  else if(ext == "ply") check_ply_structure(filename, size);
  else if(ext == "obj") check_obj_structure(filename);
  else if(ext != "stl")
    cannot_read(filename, "unsupported file extension '" + ext.substr(0, 20) + "' (expected .obj, .off, .ply or .stl)");

  std::vector<Checked_polygon> soup;
  polygon_size_limit() = std::size_t(size);
  bool ok = false;
  try
  {
    ok = CGAL::IO::read_polygon_soup(filename, points, soup, CGAL::parameters::verbose(false));
  }
  catch(const Polygon_too_large&)
  {
    cannot_read(filename, "a face announces more vertices than the file can hold");
  }
  catch(const std::bad_alloc&)
  {
    cannot_read(filename, "out of memory while reading");
  }
  catch(const std::length_error&)
  {
    cannot_read(filename, "an element count is too large");
  }
  if(!ok) cannot_read(filename, "not a valid " + ext + " file");
  polygons.assign(soup.begin(), soup.end());

  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        cannot_read(filename, "face " + std::to_string(f) + " refers to vertex " +
                              std::to_string(static_cast<long long>(v)) + ", but the file has " +
                              std::to_string(points.size()) + " vertices");
}

// Describes the first reason why the soup is not a manifold, consistently
// oriented polygon mesh (empty if none is found).
inline std::string describe_soup_problem(const std::vector<Polygon>& polygons, std::size_t number_of_points)
{
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    if(polygons[f].size() < 3)
      return "face " + std::to_string(f) + " has " + std::to_string(polygons[f].size()) + " vertices";
    std::vector<std::size_t> sorted = polygons[f];
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if(twice != sorted.end())
      return "face " + std::to_string(f) + " uses vertex " + std::to_string(*twice) + " twice";
  }
  // undirected edge -> faces (in order), and how often each direction occurs
  struct Edge_use { std::vector<std::size_t> faces; int forward = 0, backward = 0; };
  std::map<std::pair<std::size_t, std::size_t>, Edge_use> edges;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = 0; k < polygons[f].size(); ++k)
    {
      const std::size_t a = polygons[f][k], b = polygons[f][(k + 1) % polygons[f].size()];
      Edge_use& use = edges[std::make_pair((std::min)(a, b), (std::max)(a, b))];
      use.faces.push_back(f);
      (a < b ? use.forward : use.backward) += 1;
    }
  for(const auto& [edge, use] : edges)
    if(use.faces.size() > 2)
      return "edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) + ") is shared by " +
             std::to_string(use.faces.size()) + " faces, the first " + std::to_string(use.faces[0]) +
             " and " + std::to_string(use.faces[1]);
  for(const auto& [edge, use] : edges)
    if(use.forward > 1 || use.backward > 1)
      return "faces " + std::to_string(use.faces[0]) + " and " + std::to_string(use.faces[1]) +
             " run through edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
             ") in the same direction (opposite orientations or a duplicate face)";
  // Non-manifold vertex: its faces form several fans (joined through the
  // edges at the vertex).
  std::vector<std::vector<std::size_t>> faces_at(number_of_points);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f]) faces_at[v].push_back(f);
  std::unordered_map<std::size_t, std::size_t> parent;
  for(std::size_t v = 0; v < number_of_points; ++v)
  {
    if(faces_at[v].size() < 2) continue;
    parent.clear();
    for(std::size_t f : faces_at[v]) parent[f] = f;
    auto find = [&](std::size_t f) {
      while(parent[f] != f) f = parent[f] = parent[parent[f]];
      return f;
    };
    for(std::size_t f : faces_at[v])
    {
      const Polygon& p = polygons[f];
      for(std::size_t k = 0; k < p.size(); ++k)
      {
        if(p[k] != v) continue;
        for(std::size_t w : {p[(k + 1) % p.size()], p[(k + p.size() - 1) % p.size()]})
        {
          const auto it = edges.find(std::make_pair((std::min)(v, w), (std::max)(v, w)));
          for(std::size_t g : it->second.faces) parent[find(g)] = find(f);
        }
      }
    }
    std::size_t fans = 0;
    for(std::size_t f : faces_at[v]) fans += (find(f) == f);
    if(fans > 1)
      return "vertex " + std::to_string(v) + " joins " + std::to_string(fans) + " separate fans of faces";
  }
  return {};
}

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

// Triangulates face f of `mesh` as PMP::triangulate_faces() would, by
// splitting it along the diagonals found on the polygon alone; falls back
// to ear_split() where that fails. Returns false on the fallback. Face f
// keeps its index; the other triangles are appended.
inline bool triangulate_face(Mesh::Face_index f, Mesh& mesh)
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

/// Reads, validates and repairs `filename` into `mesh` (cleared first).
/// Throws Input_error; fills `report` (warnings included) otherwise.
inline void read_input_mesh(const std::string& filename, Mesh& mesh, Input_report& report)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  mesh.clear();
  report = Input_report();

  std::vector<Point_3> points;
  std::vector<detail::Polygon> polygons;
  {
    std::vector<File_point> file_points;
    detail::read_soup(filename, file_points, polygons);
    for(std::size_t v = 0; v < file_points.size(); ++v)
    {
      const File_point& p = file_points[v];
      if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        detail::fail("ERROR_NON_FINITE_COORDINATE", detail::quoted(filename) + ": vertex " + std::to_string(v) +
                                                    " has a non-finite coordinate " + detail::format_point(p));
    }
    points.reserve(file_points.size());
    for(const File_point& p : file_points) points.emplace_back(p.x(), p.y(), p.z());
  }
  report.file_vertices = points.size();
  report.file_faces = polygons.size();
  if(polygons.empty()) detail::fail("ERROR_EMPTY_MESH", detail::quoted(filename) + " has no faces");

  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    std::string problem = detail::describe_soup_problem(polygons, points.size());
    if(problem.empty()) problem = "not a polygon mesh";
    const std::vector<Point_3> file_points_kept = points; // the repair renumbers `points`
    PMP::repair_polygon_soup(points, polygons);
    PMP::orient_polygon_soup(points, polygons);
    if(polygons.empty())
      detail::fail("ERROR_EMPTY_MESH", detail::quoted(filename) + ": no valid face left after repairing (" +
                                       problem + ")");
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      detail::fail("ERROR_NON_MANIFOLD", detail::quoted(filename) + " is not manifold (" + problem +
                                         ") and could not be repaired");
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    const std::size_t duplicated = PMP::duplicate_non_manifold_vertices(mesh);
    std::map<Point_3, long> vertex_at;
    for(Mesh::Vertex_index v : vertices(mesh)) vertex_at.emplace(mesh.point(v), long(std::size_t(v)));
    report.point_vertex.assign(file_points_kept.size(), -1);
    for(std::size_t i = 0; i < file_points_kept.size(); ++i)
      if(auto it = vertex_at.find(file_points_kept[i]); it != vertex_at.end()) report.point_vertex[i] = it->second;
    report.repaired = true;
    report.warnings.push_back(
      "not a manifold, consistently oriented mesh (" + problem + "): repaired as a polygon soup (" +
      std::to_string(report.file_vertices) + " vertices, " + std::to_string(report.file_faces) +
      " faces -> " + std::to_string(num_vertices(mesh)) + " vertices, " + std::to_string(num_faces(mesh)) +
      " faces; coincident vertices merged" +
      (duplicated ? ", " + std::to_string(duplicated) + " non-manifold vertices duplicated" : std::string()) +
      "); vertex and face indices below refer to the repaired mesh");
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
      detail::fail("ERROR_NON_TRIANGULAR_MESH", detail::quoted(filename) + ": face " +
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

#endif
