// Seam constraints from files, for uv_unwrap: edges in the selection-file
// format of CGAL's Polyhedron demo and Surface_mesh_parameterization examples
// (`*.selection.txt`: a line of selected vertices, a line of selected faces,
// a line of selected edges as pairs of 0-based vertex indices), read as
// forced seams (--seams) or forbidden edges (--forbid) and written back
// (--save-seams); and a per-face λ factor from a PLY property
// (--lambda-from-ply-property). Indices are those of the input file; the
// mesh read from it (tools/mesh_input.h) maps them to its vertices.
#ifndef CUT_PARAM_TOOLS_SEAM_CONSTRAINTS_H
#define CUT_PARAM_TOOLS_SEAM_CONSTRAINTS_H

#include "mesh_input.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace seam_constraints {

using Mesh = mesh_input::Mesh;
using Edge_pairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// A file that cannot be read or does not fit the mesh (one line of text).
struct Constraint_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The edges of a selection file: its third line (the first two, selected
/// vertices and faces, are ignored). Throws Constraint_error on a missing
/// file, a token that is not an index or an odd count.
inline Edge_pairs read_selection_edges(const std::string& filename)
{
  std::ifstream in(filename);
  if(!in) throw Constraint_error("cannot read '" + filename + "'");
  std::string line;
  for(int skip = 0; skip < 2; ++skip)
    if(!std::getline(in, line))
      throw Constraint_error("'" + filename + "' is not a selection file: it needs a line of vertices, a line of "
                             "faces and a line of edges (the first two may be empty)");
  std::getline(in, line);
  std::istringstream tokens(line);
  std::vector<std::size_t> indices;
  std::string token;
  while(tokens >> token)
  {
    std::size_t used = 0;
    unsigned long long value = 0;
    try
    {
      value = std::stoull(token, &used);
    }
    catch(const std::exception&)
    {
      used = 0;
    }
    if(used != token.size() || token[0] == '-')
      throw Constraint_error("'" + filename + "', line 3: '" + token.substr(0, 20) + "' is not a vertex index");
    indices.push_back(std::size_t(value));
  }
  if(indices.size() % 2 != 0)
    throw Constraint_error("'" + filename + "', line 3: an odd number of vertex indices (edges are pairs)");
  Edge_pairs edges;
  for(std::size_t i = 0; i < indices.size(); i += 2) edges.emplace_back(indices[i], indices[i + 1]);
  return edges;
}

/// Writes `edges` as a selection file (no vertex, no face selected).
inline bool write_selection_edges(const std::string& filename, const Edge_pairs& edges)
{
  std::ofstream out(filename);
  out << "\n\n";
  for(std::size_t i = 0; i < edges.size(); ++i) out << (i ? " " : "") << edges[i].first << ' ' << edges[i].second;
  out << '\n';
  return bool(out);
}

/// Flags in `map` the mesh edges of `pairs` (indices of the input file's
/// points, see `Input_report::point_vertex`). Throws Constraint_error if an
/// index is out of range or two vertices are not joined by an edge.
template <typename EdgeMap>
void flag_edges(const Mesh& mesh, const mesh_input::Input_report& report, const Edge_pairs& pairs,
                const std::string& filename, EdgeMap map)
{
  auto vertex_of = [&](std::size_t i) {
    if(i >= report.point_vertex.size() || report.point_vertex[i] < 0)
      throw Constraint_error("'" + filename + "': vertex " + std::to_string(i) + " is not a vertex of the mesh (" +
                             std::to_string(report.point_vertex.size()) + " vertices in the file)");
    return Mesh::Vertex_index(Mesh::size_type(report.point_vertex[i]));
  };
  for(const auto& [a, b] : pairs)
  {
    const auto [h, found] = CGAL::halfedge(vertex_of(a), vertex_of(b), mesh);
    if(!found)
      throw Constraint_error("'" + filename + "': vertices " + std::to_string(a) + " and " + std::to_string(b) +
                             " are not joined by an edge");
    put(map, CGAL::edge(h, mesh), true);
  }
}

/// The edges flagged in `map`, as pairs of the input file's point indices
/// (the first point at each vertex).
template <typename EdgeMap>
Edge_pairs flagged_edges(const Mesh& mesh, const mesh_input::Input_report& report, EdgeMap map)
{
  std::vector<long> point_of(num_vertices(mesh), -1);
  for(std::size_t i = report.point_vertex.size(); i-- > 0;) // first point wins
    if(report.point_vertex[i] >= 0) point_of[std::size_t(report.point_vertex[i])] = long(i);
  Edge_pairs pairs;
  for(auto e : edges(mesh))
    if(get(map, e))
    {
      const long a = point_of[std::size_t(source(e, mesh))], b = point_of[std::size_t(target(e, mesh))];
      if(a >= 0 && b >= 0) pairs.emplace_back(std::size_t(a), std::size_t(b));
    }
  return pairs;
}

namespace detail {

// A property of the PLY file as read by CGAL (any numeric PLY type), as doubles.
template <typename Index>
bool numeric_property(const Mesh& ply, const std::string& name, std::size_t count, std::vector<double>& values)
{
  bool found = false;
  auto try_type = [&](auto type_tag) {
    using T = decltype(type_tag);
    if(found) return;
    auto [map, exists] = ply.property_map<Index, T>(name);
    if(!exists) return;
    found = true;
    values.resize(count);
    for(std::size_t i = 0; i < count; ++i) values[i] = double(map[Index(Mesh::size_type(i))]);
  };
  try_type(std::int8_t()); try_type(std::uint8_t()); try_type(std::int16_t()); try_type(std::uint16_t());
  try_type(std::int32_t()); try_type(std::uint32_t()); try_type(float()); try_type(double());
  return found;
}

template <typename Index>
bool gray_levels(const Mesh& ply, const std::string& name, std::size_t count, std::vector<double>& values)
{
  auto [map, exists] = ply.property_map<Index, CGAL::IO::Color>(name);
  if(!exists) return false;
  values.resize(count);
  for(std::size_t i = 0; i < count; ++i)
  {
    const CGAL::IO::Color& c = map[Index(Mesh::size_type(i))];
    values[i] = (double(c.red()) + double(c.green()) + double(c.blue())) / (3. * 255.);
  }
  return true;
}

} // namespace detail

/// λ factors per face of `mesh` (by index) from the PLY file it was read
/// from: the face property `name`, else the vertex property `name` (a face
/// takes the mean of its corners), taken as factors (each > 0); or, for
/// `name` "color", the face colors, else the vertex colors, whose gray level
/// g in [0,1] gives the factor 10^(2g - 1): black (0.1) draws seams, white
/// (10) keeps them away. The input must have loaded without repair (its
/// numbering is the file's). Throws Constraint_error otherwise, or if the
/// property is missing or a factor is not positive.
inline std::vector<double> face_lambda_from_ply(const std::string& filename, const Mesh& mesh,
                                                const mesh_input::Input_report& report, const std::string& name)
{
  if(mesh_input::lower_extension(filename) != "ply")
    throw Constraint_error("--lambda-from-ply-property needs a .ply input, not '" + filename + "'");
  if(report.face_origin.empty())
    throw Constraint_error("'" + filename + "' was repaired on reading, so its faces and vertices were renumbered: "
                           "its properties cannot be matched (give a manifold, consistently oriented mesh)");
  Mesh ply;
  {
    std::ifstream in(filename, std::ios::binary);
    std::string comments;
    if(!in || !CGAL::IO::read_PLY(in, ply, comments))
      throw Constraint_error("cannot read the properties of '" + filename + "'");
  }
  const bool colors = name == "color";
  std::vector<double> at_face, at_vertex;
  const bool on_faces = colors ? detail::gray_levels<Mesh::Face_index>(ply, "f:color", num_faces(ply), at_face)
                               : detail::numeric_property<Mesh::Face_index>(ply, "f:" + name, num_faces(ply), at_face);
  const bool on_vertices =
    !on_faces && (colors ? detail::gray_levels<Mesh::Vertex_index>(ply, "v:color", num_vertices(ply), at_vertex)
                         : detail::numeric_property<Mesh::Vertex_index>(ply, "v:" + name, num_vertices(ply), at_vertex));
  if(!on_faces && !on_vertices)
    throw Constraint_error("'" + filename + "' has no face or vertex property '" + name + "'" +
                           (colors ? std::string(" (red, green, blue)") : std::string()));

  std::vector<double> lambda(num_faces(mesh), 1.);
  for(Mesh::Face_index f : faces(mesh))
  {
    double value = 0.;
    if(on_faces)
    {
      const std::size_t origin = report.face_origin.at(std::size_t(f));
      if(origin >= at_face.size()) throw Constraint_error("'" + filename + "': face count differs on reading");
      value = at_face[origin];
    }
    else
    {
      int corners = 0;
      for(Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      {
        if(std::size_t(v) >= at_vertex.size()) throw Constraint_error("'" + filename + "': vertex count differs");
        value += at_vertex[std::size_t(v)];
        ++corners;
      }
      value /= corners;
    }
    const double factor = colors ? std::pow(10., 2. * value - 1.) : value;
    if(!(factor > 0.) || !std::isfinite(factor))
      throw Constraint_error("'" + filename + "': property '" + name + "' is " + std::to_string(value) +
                             " at face " + std::to_string(std::size_t(f)) + " (λ factors must be > 0)");
    lambda[std::size_t(f)] = factor;
  }
  return lambda;
}

} // namespace seam_constraints

#endif
