// The polygon soup of a file, as CGAL reads it, every index checked (see mesh_input.h).
#include "detail.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <unordered_map>

namespace mesh_input {
namespace detail {

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
void read_soup(const std::string& filename, std::vector<File_point>& points, std::vector<Polygon>& polygons,
               std::vector<std::string>& notes)
{
  std::uintmax_t size = 0;
  check_file(filename, size);
  const std::string ext = lower_extension(filename);
  std::string normalized; // the text CGAL reads instead of the file, if not empty
  if(ext == "off") check_off_structure(filename, size, normalized, notes);
  else if(ext == "ply") check_ply_structure(filename, size, normalized, notes);
  else if(ext == "obj") check_obj_structure(filename, normalized, notes);
  else if(ext != "stl")
    cannot_read(filename, "unsupported file extension '" + ext.substr(0, 20) + "' (expected .obj, .off, .ply or .stl)");

  std::vector<Checked_polygon> soup;
  polygon_size_limit() = std::size_t(size);
  bool ok = false;
  try
  {
    if(normalized.empty())
      ok = CGAL::IO::read_polygon_soup(filename, points, soup, CGAL::parameters::verbose(false));
    else
    {
      polygon_size_limit() = normalized.size();
      std::istringstream text(normalized);
      if(ext == "off") ok = CGAL::IO::read_OFF(text, points, soup, CGAL::parameters::verbose(false));
      else if(ext == "ply") ok = CGAL::IO::read_PLY(text, points, soup, CGAL::parameters::verbose(false));
      else ok = CGAL::IO::read_OBJ(text, points, soup, CGAL::parameters::verbose(false));
    }
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
std::string describe_soup_problem(const std::vector<Polygon>& polygons, std::size_t number_of_points)
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

} // namespace detail
} // namespace mesh_input
