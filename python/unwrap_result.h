// What unwrap() returns (python/uv_unwrap_module.cpp), in the numbering of
// its input arrays: the UVs per corner (OBJ style), the seams as vertex
// pairs and the chart of each face, from the mesh the library unwrapped,
// which may be a repaired copy of the input (tools/mesh_input.h).
#ifndef CUT_PARAM_PYTHON_UNWRAP_RESULT_H
#define CUT_PARAM_PYTHON_UNWRAP_RESULT_H

#include "mesh_input.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace uv_unwrap_python {

namespace py = pybind11;
using Mesh = mesh_input::Mesh;
using Point_3 = mesh_input::Point_3;
using Point_2 = mesh_input::Kernel::Point_2;
using face_descriptor = Mesh::Face_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using edge_descriptor = Mesh::Edge_index;
using vertex_descriptor = Mesh::Vertex_index;

struct Result
{
  py::array_t<double> uv;              // (k,2)
  py::array_t<std::int64_t> faces_uv;  // (m,3), -1 for a face the repair dropped
  py::array_t<std::int64_t> seams;     // (s,2), vertex pairs, a < b, sorted
  py::array_t<std::int64_t> face_charts; // (m,), -1 for a face the repair dropped
  py::dict stats;                      // uv_unwrap --stats
  std::vector<std::string> warnings;
  int page = -1;                       // unwrap_scene(): the atlas page of the mesh; unwrap(): -1
};

// The chart of each face: faces joined across edges that are neither seams
// nor borders, numbered in the order of their first face.
inline std::vector<long> face_charts(const Mesh& mesh, const Mesh::Property_map<edge_descriptor, bool>& seams)
{
  std::vector<long> chart(num_faces(mesh), -1);
  long next = 0;
  std::vector<face_descriptor> stack;
  for(face_descriptor start : faces(mesh))
  {
    if(chart[std::size_t(start)] >= 0) continue;
    chart[std::size_t(start)] = next;
    stack.push_back(start);
    while(!stack.empty())
    {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
      {
        if(seams[edge(h, mesh)] || is_border(opposite(h, mesh), mesh)) continue;
        const face_descriptor g = face(opposite(h, mesh), mesh);
        if(chart[std::size_t(g)] < 0)
        {
          chart[std::size_t(g)] = next;
          stack.push_back(g);
        }
      }
    }
    ++next;
  }
  return chart;
}

using Triple = std::array<std::tuple<double, double, double>, 3>;

inline std::tuple<double, double, double> key(const Point_3& p) { return {p.x(), p.y(), p.z()}; }

// The outputs in the input's numbering. Without repair, mesh vertex i is
// V[i] and mesh face j is F[j]; after a repair, faces are matched by their
// corners' positions and vertices by position (the first input vertex at
// each position).
inline void fill_result(const Mesh& mesh, const Mesh::Property_map<halfedge_descriptor, Point_2>& uvmap,
                 const Mesh::Property_map<edge_descriptor, bool>& seams, const std::vector<Point_3>& points,
                 const std::vector<std::array<std::size_t, 3>>& polygons, bool repaired, Result& result)
{
  const std::size_t m = polygons.size();
  std::vector<face_descriptor> mesh_face(m, Mesh::null_face());
  std::vector<long> input_vertex(num_vertices(mesh), -1);
  if(!repaired)
  {
    for(std::size_t j = 0; j < m; ++j) mesh_face[j] = face_descriptor(Mesh::size_type(j));
    for(vertex_descriptor v : vertices(mesh)) input_vertex[std::size_t(v)] = long(std::size_t(v));
  }
  else
  {
    std::map<std::tuple<double, double, double>, long> first_at;
    for(std::size_t i = points.size(); i-- > 0;) first_at[key(points[i])] = long(i);
    for(vertex_descriptor v : vertices(mesh))
      if(auto it = first_at.find(key(mesh.point(v))); it != first_at.end()) input_vertex[std::size_t(v)] = it->second;
    std::map<Triple, face_descriptor> face_at;
    for(face_descriptor f : faces(mesh))
    {
      Triple t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = key(mesh.point(v));
      std::sort(t.begin(), t.end());
      face_at.emplace(t, f);
    }
    for(std::size_t j = 0; j < m; ++j)
    {
      Triple t;
      for(int k = 0; k < 3; ++k) t[k] = key(points[polygons[j][k]]);
      std::sort(t.begin(), t.end());
      if(auto it = face_at.find(t); it != face_at.end()) mesh_face[j] = it->second;
    }
  }

  // one UV per distinct (input vertex, UV): corners across a non-seam edge share it
  std::map<std::tuple<std::size_t, double, double>, std::int64_t> uv_index;
  std::vector<double> uvs;
  result.faces_uv = py::array_t<std::int64_t>({py::ssize_t(m), py::ssize_t(3)});
  auto fuv = result.faces_uv.mutable_unchecked<2>();
  std::size_t dropped = 0;
  for(std::size_t j = 0; j < m; ++j)
  {
    const face_descriptor f = mesh_face[j];
    if(f == Mesh::null_face())
    {
      ++dropped;
      for(int k = 0; k < 3; ++k) fuv(j, k) = -1;
      continue;
    }
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t vi = polygons[j][k];
      Point_2 uv(std::nan(""), std::nan(""));
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
        if(mesh.point(target(h, mesh)) == points[vi]) uv = uvmap[h];
      const auto [it, added] = uv_index.emplace(std::make_tuple(vi, uv.x(), uv.y()), std::int64_t(uvs.size() / 2));
      if(added)
      {
        uvs.push_back(uv.x());
        uvs.push_back(uv.y());
      }
      fuv(j, k) = it->second;
    }
  }
  if(dropped > 0)
    result.warnings.push_back(std::to_string(dropped) + " faces of F were dropped by the repair (repeated vertices "
                              "or duplicates): their faces_uv and face_charts rows are -1");
  result.uv = py::array_t<double>({py::ssize_t(uvs.size() / 2), py::ssize_t(2)});
  std::copy(uvs.begin(), uvs.end(), result.uv.mutable_data());

  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for(edge_descriptor e : edges(mesh))
    if(seams[e])
    {
      long a = input_vertex[std::size_t(source(e, mesh))], b = input_vertex[std::size_t(target(e, mesh))];
      if(a < 0 || b < 0) continue;
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  result.seams = py::array_t<std::int64_t>({py::ssize_t(pairs.size()), py::ssize_t(2)});
  auto s = result.seams.mutable_unchecked<2>();
  for(std::size_t i = 0; i < pairs.size(); ++i)
  {
    s(i, 0) = pairs[i].first;
    s(i, 1) = pairs[i].second;
  }

  const std::vector<long> chart = face_charts(mesh, seams);
  result.face_charts = py::array_t<std::int64_t>(py::ssize_t(m));
  auto c = result.face_charts.mutable_unchecked<1>();
  for(std::size_t j = 0; j < m; ++j)
    c(j) = mesh_face[j] == Mesh::null_face() ? -1 : chart[std::size_t(mesh_face[j])];
}

} // namespace uv_unwrap_python

#endif
