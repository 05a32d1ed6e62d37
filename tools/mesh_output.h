// mesh_output.h: the output files of uv_unwrap, a mesh with its UV map.
//
//   - write_obj_keeping_input(): an OBJ that is the input OBJ with texture
//     coordinates added. Every line but `vt` and `f` is copied as it is
//     (vertices, normals, `o`/`g` names, `mtllib`/`usemtl`, smoothing groups,
//     comments), in its place; each `f` line becomes the faces it was turned
//     into (one, or the triangles of a polygon), in the file's order, each
//     corner keeping its normal index and getting a texture coordinate.
//   - write_ply_with_texcoords(): a PLY whose faces carry their corners' UVs
//     as a `texcoord` list (u0 v0 u1 v1 u2 v2), the form PLY readers such as
//     MeshLab and Blender take.
// The plain OBJ writer of the library (write_OBJ_with_uvs()) covers the other
// inputs.
#ifndef CUT_PARAM_TOOLS_MESH_OUTPUT_H
#define CUT_PARAM_TOOLS_MESH_OUTPUT_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace mesh_output {

namespace detail {

// One corner of an OBJ `f` line: 0-based vertex and normal indices (normal
// -1 when the corner has none), negative (relative) indices resolved.
struct Obj_corner
{
  long long vertex = -1, normal = -1;
};

inline bool resolve_obj_index(const std::string& text, long long count, long long& index)
{
  if(text.empty()) return false;
  char* end = nullptr;
  const long long i = std::strtoll(text.c_str(), &end, 10);
  if(*end != '\0' || i == 0) return false;
  index = i > 0 ? i - 1 : count + i;
  return index >= 0;
}

// The corners of an `f` line ("f v v/t v/t/n v//n ..."), given how many
// `v` and `vn` lines came before it. False if a corner cannot be read.
inline bool parse_obj_face(const std::string& line, long long vertices, long long normals,
                           std::vector<Obj_corner>& corners)
{
  corners.clear();
  std::istringstream words(line);
  std::string token;
  words >> token; // "f"
  while(words >> token)
  {
    Obj_corner c;
    const std::size_t slash = token.find('/');
    if(!resolve_obj_index(token.substr(0, slash), vertices, c.vertex)) return false;
    if(slash != std::string::npos)
    {
      const std::size_t slash2 = token.find('/', slash + 1);
      if(slash2 != std::string::npos && slash2 + 1 < token.size() &&
         !resolve_obj_index(token.substr(slash2 + 1), normals, c.normal))
        return false;
    }
    corners.push_back(c);
  }
  return corners.size() >= 3;
}

inline std::string keyword_of(const std::string& line)
{
  std::istringstream words(line);
  std::string keyword;
  words >> keyword;
  return keyword;
}

} // namespace detail

/// Writes `output`: the OBJ file `input` with the texture coordinates of
/// `uvmap` (halfedge -> UV of the corner at its target, as the library's
/// seam-mesh conventions have them) on every face.
///
/// Preconditions: `mesh` was read from `input` without repair, so that
/// vertex i is the file's i-th `v` and `face_origin[f]` is the index of the
/// `f` line face f comes from (mesh_input::Input_report::face_origin).
/// Returns false, with `problem` set, if the file does not match (it
/// changed, or has faces the reader skipped) or cannot be written.
template <typename TriangleMesh, typename UVMap>
bool write_obj_keeping_input(const std::string& input, const std::string& output, const TriangleMesh& mesh,
                             const UVMap& uvmap, const std::vector<std::size_t>& face_origin,
                             std::string& problem)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

  std::ifstream in(input, std::ios::binary);
  std::vector<std::string> lines;
  bool continued = false; // a line ending with a backslash goes on with the next (not a comment), as the reader has it
  for(std::string line; std::getline(in, line);)
  {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    if(continued) lines.back() += line;
    else lines.push_back(line);
    const std::size_t last = line.find_last_not_of(" \t");
    continued = last != std::string::npos && line[last] == '\\' && detail::keyword_of(lines.back())[0] != '#';
    if(continued) lines.back().replace(lines.back().size() - (line.size() - last), std::string::npos, " ");
  }
  if(!in.eof()) { problem = "cannot read '" + input + "' again"; return false; }

  // the faces of each `f` line, in the mesh's order
  std::size_t polygons = 0;
  for(const std::string& line : lines)
    if(detail::keyword_of(line) == "f") ++polygons;
  std::vector<std::vector<face_descriptor>> faces_of(polygons);
  if(face_origin.size() != num_faces(mesh)) { problem = "face origins do not match the mesh"; return false; }
  for(face_descriptor f : faces(mesh))
  {
    const std::size_t origin = face_origin[std::size_t(f)];
    if(origin >= polygons) { problem = "the file has fewer faces than were read"; return false; }
    faces_of[origin].push_back(f);
  }

  // One `vt` per distinct (vertex, UV) pair, numbered in face order.
  std::map<std::pair<std::size_t, std::pair<double, double>>, std::size_t> uv_index;
  std::vector<std::pair<double, double>> uvs;
  auto index_of = [&](halfedge_descriptor h) {
    const auto& p = get(uvmap, h);
    const std::pair<double, double> uv(p.x(), p.y());
    const auto inserted = uv_index.emplace(std::make_pair(std::size_t(target(h, mesh)), uv), uvs.size());
    if(inserted.second) uvs.push_back(uv);
    return inserted.first->second;
  };
  for(const auto& list : faces_of)
    for(face_descriptor f : list)
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) index_of(h);

  std::ofstream out(output);
  out.precision(17);
  long long vertices = 0, normals = 0;
  std::size_t polygon = 0;
  bool uvs_written = false;
  std::vector<detail::Obj_corner> corners;
  char number[64];
  for(const std::string& line : lines)
  {
    const std::string keyword = detail::keyword_of(line);
    if(keyword == "vt") continue; // replaced by the new texture coordinates
    if(keyword != "f")
    {
      if(keyword == "v") ++vertices;
      else if(keyword == "vn") ++normals;
      out << line << '\n';
      continue;
    }
    if(!uvs_written)
    {
      for(const auto& uv : uvs)
      {
        std::snprintf(number, sizeof number, "%.17g %.17g", uv.first, uv.second);
        out << "vt " << number << '\n';
      }
      uvs_written = true;
    }
    if(!detail::parse_obj_face(line, vertices, normals, corners))
    {
      problem = "cannot read the face line '" + line.substr(0, 60) + "' again";
      return false;
    }
    for(face_descriptor f : faces_of[polygon])
    {
      out << 'f';
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const long long v = static_cast<long long>(std::size_t(target(h, mesh)));
        long long normal = -1;
        bool found = false;
        for(const detail::Obj_corner& c : corners)
          if(c.vertex == v) { normal = c.normal; found = true; break; }
        if(!found)
        {
          problem = "face line " + std::to_string(polygon) + " does not hold vertex " + std::to_string(v + 1);
          return false;
        }
        out << ' ' << v + 1 << '/' << index_of(h) + 1;
        if(normal >= 0) out << '/' << normal + 1;
      }
      out << '\n';
    }
    ++polygon;
  }
  out.close();
  if(!out) { problem = "cannot write '" + output + "'"; return false; }
  return true;
}

/// Writes `mesh` as an ASCII PLY: vertex positions, and per face its vertex
/// indices and a `texcoord` list of 6 floats, the UVs of `uvmap` at its
/// three corners (halfedge -> UV of the corner at its target). Vertices are
/// numbered in the mesh's order (a mesh read from a file keeps the file's
/// numbering unless it was repaired). Returns false if it cannot be written.
/// Precondition: `mesh` is a triangle mesh with contiguous indices.
template <typename TriangleMesh, typename UVMap>
bool write_ply_with_texcoords(const std::string& output, const TriangleMesh& mesh, const UVMap& uvmap)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::ofstream out(output);
  out << "ply\nformat ascii 1.0\ncomment UV map by uv_unwrap\n"
      << "element vertex " << num_vertices(mesh) << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << num_faces(mesh) << "\n"
      << "property list uchar int vertex_indices\n"
      << "property list uchar float texcoord\n"
      << "end_header\n";
  char number[80];
  for(auto v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    std::snprintf(number, sizeof number, "%.17g %.17g %.17g", double(p.x()), double(p.y()), double(p.z()));
    out << number << '\n';
  }
  for(auto f : faces(mesh))
  {
    std::ostringstream indices, uvs;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      indices << ' ' << std::size_t(target(h, mesh));
      const auto& uv = get(uvmap, h);
      std::snprintf(number, sizeof number, " %.9g %.9g", double(uv.x()), double(uv.y()));
      uvs << number;
    }
    out << "3" << indices.str() << " 6" << uvs.str() << '\n';
  }
  out.close();
  return bool(out);
}

} // namespace mesh_output

#endif
