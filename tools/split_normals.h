// Split normals as seams, for uv_unwrap --hard-edge-angle: an OBJ file whose
// faces give their corners normals (`f v//vn`, `f v/vt/vn`) says which
// edges are hard: those where the two faces give a shared vertex different
// normals. Those edges are flagged as seams, beside the library's own rule
// (a dihedral angle above the one given), as a lightmap needs: the
// lighting jumps there. The file is read again for its `vn` and face lines
// (CGAL's reader keeps positions only); its faces are matched to the mesh's
// through Input_report::face_origin, so a file that needed repair is left
// out with a warning.
#ifndef CUT_PARAM_TOOLS_SPLIT_NORMALS_H
#define CUT_PARAM_TOOLS_SPLIT_NORMALS_H

#include "mesh_input.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace split_normals {

using Mesh = mesh_input::Mesh;

/// Per polygon of an OBJ file, in the file's order: per corner, its position
/// index (0-based) and its normal (NaN when the corner names none).
struct Obj_corner_normals
{
  std::vector<std::vector<std::size_t>> positions;
  std::vector<std::vector<std::array<double, 3>>> normals;
};

/// Reads the `v`, `vn` and `f` lines of `filename` (indices 1-based, or
/// negative: relative to the last one read). False if it cannot be opened.
inline bool read_obj_corner_normals(const std::string& filename, Obj_corner_normals& out)
{
  std::ifstream in(filename);
  if(!in) return false;
  const double nan = std::nan("");
  std::vector<std::array<double, 3>> vn;
  long positions = 0;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if(keyword == "v") ++positions;
    else if(keyword == "vn")
    {
      std::array<double, 3> n{nan, nan, nan};
      tokens >> n[0] >> n[1] >> n[2];
      vn.push_back(n);
    }
    else if(keyword == "f")
    {
      out.positions.emplace_back();
      out.normals.emplace_back();
      std::string corner;
      while(tokens >> corner)
      {
        const long v = std::strtol(corner.c_str(), nullptr, 10);
        out.positions.back().push_back(std::size_t(v < 0 ? positions + v : v - 1));
        std::array<double, 3> n{nan, nan, nan};
        const std::size_t slash = corner.find('/'), second = slash == std::string::npos ? slash : corner.find('/', slash + 1);
        if(second != std::string::npos && second + 1 < corner.size())
        {
          const long k = std::strtol(corner.c_str() + second + 1, nullptr, 10);
          const long i = k < 0 ? long(vn.size()) + k : k - 1;
          if(i >= 0 && i < long(vn.size())) n = vn[std::size_t(i)];
        }
        out.normals.back().push_back(n);
      }
    }
  }
  return true;
}

/// The normal polygon `p` gives its corner at position `v` (NaN if none).
inline std::array<double, 3> corner_normal(const Obj_corner_normals& obj, std::size_t p, std::size_t v)
{
  for(std::size_t k = 0; k < obj.positions[p].size(); ++k)
    if(obj.positions[p][k] == v) return obj.normals[p][k];
  const double nan = std::nan("");
  return {nan, nan, nan};
}

/// Two normals given and more than 0.01 degree apart (exporters round their digits).
inline bool differ(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if(!(na > 0.) || !(nb > 0.)) return false; // missing (NaN) or zero: no split said
  const double cosine = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (na * nb);
  return cosine < std::cos(0.01 * M_PI / 180.);
}

/// Flags in `seams` the interior edges of `mesh` (read from the OBJ file
/// `filename`, with `report`) where the normals of the two faces differ at
/// either end, except those flagged in `forbidden` (the user's word wins, as
/// in the library's rule). Returns the number flagged; `warning` gets a line when the
/// file's faces cannot be matched (after a repair).
template <typename SeamMap, typename ForbiddenMap>
std::size_t flag_split_normal_edges(const std::string& filename, const Mesh& mesh,
                                    const mesh_input::Input_report& report, SeamMap seams,
                                    const ForbiddenMap& forbidden, std::string& warning)
{
  if(report.face_origin.empty())
  {
    warning = "'" + filename + "' was repaired on reading: its split normals cannot be matched to the mesh and "
              "are not taken as seams (the dihedral angle still is)";
    return 0;
  }
  Obj_corner_normals obj;
  if(!read_obj_corner_normals(filename, obj)) return 0;
  std::size_t flagged = 0;
  for(Mesh::Edge_index e : edges(mesh))
  {
    if(is_border(e, mesh)) continue;
    const Mesh::Halfedge_index h = halfedge(e, mesh);
    const std::size_t p = report.face_origin.at(std::size_t(face(h, mesh)));
    const std::size_t q = report.face_origin.at(std::size_t(face(opposite(h, mesh), mesh)));
    if(p == q || p >= obj.positions.size() || q >= obj.positions.size()) continue; // a polygon's own diagonal
    bool split = false;
    for(Mesh::Vertex_index v : {source(h, mesh), target(h, mesh)}) // vertex i of the mesh is point i of the file
      split = split || differ(corner_normal(obj, p, std::size_t(v)), corner_normal(obj, q, std::size_t(v)));
    if(split && !get(seams, e) && !get(forbidden, e))
    {
      put(seams, e, true);
      ++flagged;
    }
  }
  return flagged;
}

} // namespace split_normals

#endif
