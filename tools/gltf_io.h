// gltf_io.h: glTF 2.0 (.gltf, .glb) in and out for uv_unwrap, through
// Debian's libtinygltf-dev.
//
//   gltf_io::Document doc;
//   gltf_io::load("in.glb", doc);                      // throws Gltf_error
//   for(gltf_io::Primitive_ref p : gltf_io::triangle_primitives(doc))
//   {
//     gltf_io::Triangles t = gltf_io::read_triangles(doc, p);   // positions, welded
//     ... unwrap t, giving a UV per corner ...
//     gltf_io::set_corner_uvs(doc, p, t, corner_uvs, uv_set);
//   }
//   gltf_io::save(doc, "out.glb");
//
// Everything but the unwrapped primitives' vertex data is kept: nodes and
// their transforms, materials, textures and images (not decoded: image URIs
// are rewritten relative to the output), animations, skins, extensions. An
// unwrapped primitive gets new vertex attributes in which a vertex of the
// input is split only where the UV map has a seam through it (vertices
// already split in the input, e.g. along hard normals, stay split); every
// attribute (POSITION, NORMAL, TANGENT, COLOR_n, JOINTS_n, WEIGHTS_n, other
// TEXCOORD_n, morph targets) is carried to the new vertices; indices become
// 32-bit, and strips and fans lists of triangles. The new data is appended
// to the first buffer (the GLB's binary chunk); the old accessors stay in
// the file, unused by that primitive.
#ifndef CUT_PARAM_TOOLS_GLTF_IO_H
#define CUT_PARAM_TOOLS_GLTF_IO_H

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace gltf_io {

/// A file that cannot be read or written; what() is one line.
struct Gltf_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Document
{
  tinygltf::Model model;
  std::string input_directory;      // where relative URIs of the input point to
  std::vector<std::string> warnings;
};

struct Primitive_ref
{
  int mesh = 0, primitive = 0;
};

/// One primitive's triangles over welded positions: vertices at the same
/// position are merged (unless that would make the mesh non-manifold), so
/// that splits of the input along normals or old UVs are no cuts.
struct Triangles
{
  std::vector<std::array<double, 3>> points;         // welded
  std::vector<std::array<std::uint32_t, 3>> faces;   // into points
  std::vector<std::array<std::uint32_t, 3>> corners; // the input's vertex at each corner
};

namespace detail {

inline std::size_t component_size(int type)
{
  switch(type)
  {
    case TINYGLTF_COMPONENT_TYPE_BYTE: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
  }
}

// The bytes of element i of an accessor (not sparse), checked against its buffer.
class Accessor_view
{
public:
  Accessor_view(const tinygltf::Model& model, int index)
  {
    if(index < 0 || std::size_t(index) >= model.accessors.size()) throw Gltf_error("invalid accessor index");
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    if(a.sparse.isSparse) throw Gltf_error("sparse accessors are not supported");
    if(a.bufferView < 0 || std::size_t(a.bufferView) >= model.bufferViews.size())
      throw Gltf_error("accessor " + std::to_string(index) + " has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
    if(view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
      throw Gltf_error("invalid buffer index");
    const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
    const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    element_size_ = component_size(a.componentType) * std::size_t(components > 0 ? components : 0);
    if(element_size_ == 0) throw Gltf_error("accessor " + std::to_string(index) + " has an unknown type");
    stride_ = view.byteStride ? view.byteStride : element_size_;
    count_ = a.count;
    begin_ = data.data() + view.byteOffset + a.byteOffset;
    const std::size_t needed = count_ == 0 ? 0 : (count_ - 1) * stride_ + element_size_;
    if(view.byteOffset + a.byteOffset + needed > data.size() || a.byteOffset + needed > view.byteLength)
      throw Gltf_error("accessor " + std::to_string(index) + " reaches past its buffer");
    component_type_ = a.componentType;
    components_ = components;
  }
  std::size_t count() const { return count_; }
  std::size_t element_size() const { return element_size_; }
  const unsigned char* element(std::size_t i) const { return begin_ + i * stride_; }
  int components() const { return components_; }
  // component c of element i as a double (float data) or an index (integer data)
  double real(std::size_t i, int c) const
  {
    const unsigned char* p = element(i) + std::size_t(c) * component_size(component_type_);
    switch(component_type_)
    {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float x; std::memcpy(&x, p, 4); return x; }
      case TINYGLTF_COMPONENT_TYPE_DOUBLE: { double x; std::memcpy(&x, p, 8); return x; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: return double(std::int8_t(*p));
      case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t x; std::memcpy(&x, p, 2); return double(x); }
      default: return double(integer(i, c));
    }
  }
  std::uint64_t integer(std::size_t i, int c) const
  {
    const unsigned char* p = element(i) + std::size_t(c) * component_size(component_type_);
    switch(component_type_)
    {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t x; std::memcpy(&x, p, 2); return x; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t x; std::memcpy(&x, p, 4); return x; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: return std::uint64_t(std::int64_t(std::int8_t(*p)));
      case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t x; std::memcpy(&x, p, 2); return std::uint64_t(std::int64_t(x)); }
      default: throw Gltf_error("integer data expected");
    }
  }

private:
  const unsigned char* begin_ = nullptr;
  std::size_t count_ = 0, element_size_ = 0, stride_ = 0;
  int component_type_ = 0, components_ = 0;
};

// Appends `bytes` (4-byte aligned) to buffer 0 as a new buffer view; returns its index.
inline int append_buffer_view(tinygltf::Model& model, const std::vector<unsigned char>& bytes, int target)
{
  if(model.buffers.empty()) model.buffers.emplace_back();
  std::vector<unsigned char>& data = model.buffers[0].data;
  while(data.size() % 4) data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = bytes.size();
  view.target = target;
  data.insert(data.end(), bytes.begin(), bytes.end());
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

// A copy of accessor `index` holding the elements `order` of it, in a new buffer view.
inline int remapped_accessor(tinygltf::Model& model, int index, const std::vector<std::uint32_t>& order)
{
  const Accessor_view in(model, index);
  std::vector<unsigned char> bytes(order.size() * in.element_size());
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    if(order[i] >= in.count()) throw Gltf_error("a vertex index is past an attribute's end");
    std::memcpy(bytes.data() + i * in.element_size(), in.element(order[i]), in.element_size());
  }
  tinygltf::Accessor a = model.accessors[std::size_t(index)]; // type and normalization kept
  if(!a.minValues.empty() || !a.maxValues.empty()) // the bounds of the elements kept
  {
    a.minValues.assign(std::size_t(in.components()), 0.);
    a.maxValues.assign(std::size_t(in.components()), 0.);
    for(int c = 0; c < in.components(); ++c)
      for(std::size_t i = 0; i < order.size(); ++i)
      {
        const double x = in.real(order[i], c);
        if(i == 0 || x < a.minValues[std::size_t(c)]) a.minValues[std::size_t(c)] = x;
        if(i == 0 || x > a.maxValues[std::size_t(c)]) a.maxValues[std::size_t(c)] = x;
      }
  }
  a.bufferView = append_buffer_view(model, bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
  a.byteOffset = 0;
  a.count = order.size();
  a.name.clear();
  model.accessors.push_back(a);
  return int(model.accessors.size()) - 1;
}

} // namespace detail

/// Reads a .gltf or .glb file (buffers loaded, images left undecoded).
inline void load(const std::string& filename, Document& doc)
{
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*,
                           int, void*) { return true; }, nullptr);
  std::string err, warn;
  const bool binary = std::filesystem::path(filename).extension() == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&doc.model, &err, &warn, filename)
                         : loader.LoadASCIIFromFile(&doc.model, &err, &warn, filename);
  if(!warn.empty()) doc.warnings.push_back(warn);
  if(!ok)
  {
    for(char& c : err) if(c == '\n') c = ' ';
    throw Gltf_error("cannot read '" + filename + "': " + (err.empty() ? "not a glTF file" : err));
  }
  doc.input_directory = std::filesystem::path(filename).parent_path().string();
}

/// The primitives made of triangles (mode TRIANGLES, TRIANGLE_STRIP or
/// TRIANGLE_FAN), in mesh order; strips and fans are read as their
/// triangles and written back as lists (set_corner_uvs()), with a note in
/// the warnings. The others (points, lines) are left as they are, with a
/// warning.
inline std::vector<Primitive_ref> triangle_primitives(Document& doc)
{
  std::vector<Primitive_ref> refs;
  for(std::size_t m = 0; m < doc.model.meshes.size(); ++m)
    for(std::size_t p = 0; p < doc.model.meshes[m].primitives.size(); ++p)
    {
      const tinygltf::Primitive& prim = doc.model.meshes[m].primitives[p];
      const bool strip = prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP, fan = prim.mode == TINYGLTF_MODE_TRIANGLE_FAN;
      if((prim.mode == TINYGLTF_MODE_TRIANGLES || strip || fan) && prim.attributes.count("POSITION"))
      {
        refs.push_back({int(m), int(p)});
        if(strip || fan)
          doc.warnings.push_back("mesh " + std::to_string(m) + ", primitive " + std::to_string(p) + ": a triangle " +
                                 (strip ? "strip (mode 5)" : "fan (mode 6)") +
                                 ", read as its triangles and written back as a list of triangles (mode 4)");
      }
      else
        doc.warnings.push_back("mesh " + std::to_string(m) + ", primitive " + std::to_string(p) +
                               ": not a list of triangles, left without new UVs");
    }
  return refs;
}

/// The triangles of a primitive. `weld`: vertices at the same position are
/// one vertex (the caller tries again without if the result is no manifold).
inline Triangles read_triangles(const Document& doc, Primitive_ref ref, bool weld)
{
  const tinygltf::Primitive& prim = doc.model.meshes[std::size_t(ref.mesh)].primitives[std::size_t(ref.primitive)];
  const detail::Accessor_view positions(doc.model, prim.attributes.at("POSITION"));
  if(positions.components() != 3) throw Gltf_error("POSITION is not a 3D vector");
  std::vector<std::uint32_t> indices;
  if(prim.indices >= 0)
  {
    const detail::Accessor_view idx(doc.model, prim.indices);
    for(std::size_t i = 0; i < idx.count(); ++i)
    {
      const std::uint64_t v = idx.integer(i, 0);
      if(v >= positions.count()) throw Gltf_error("an index is past the vertex count");
      indices.push_back(std::uint32_t(v));
    }
  }
  else
    for(std::size_t i = 0; i < positions.count(); ++i) indices.push_back(std::uint32_t(i));
  if(prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP || prim.mode == TINYGLTF_MODE_TRIANGLE_FAN)
  {
    // the triangles of the glTF specification (3.7.2.1), strips alternating
    // their corners so that all keep the first one's winding; those with a
    // repeated index (the joins of strips) draw nothing and are left out
    std::vector<std::uint32_t> list;
    for(std::size_t i = 0; i + 2 < indices.size(); ++i)
    {
      const std::array<std::uint32_t, 3> c =
        prim.mode == TINYGLTF_MODE_TRIANGLE_FAN
          ? std::array<std::uint32_t, 3>{indices[i + 1], indices[i + 2], indices[0]}
          : std::array<std::uint32_t, 3>{indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]};
      if(c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) list.insert(list.end(), c.begin(), c.end());
    }
    indices = std::move(list);
    if(indices.empty()) throw Gltf_error("the triangle strip or fan has no triangle");
  }
  if(indices.size() % 3) throw Gltf_error("the index count is not a multiple of 3");

  Triangles t;
  std::map<std::array<double, 3>, std::uint32_t> welded;
  std::vector<std::uint32_t> point_of(positions.count());
  for(std::size_t v = 0; v < positions.count(); ++v)
  {
    const std::array<double, 3> p = {positions.real(v, 0), positions.real(v, 1), positions.real(v, 2)};
    if(weld)
    {
      const auto it = welded.emplace(p, std::uint32_t(t.points.size()));
      if(it.second) t.points.push_back(p);
      point_of[v] = it.first->second;
    }
    else
    {
      point_of[v] = std::uint32_t(t.points.size());
      t.points.push_back(p);
    }
  }
  for(std::size_t i = 0; i < indices.size(); i += 3)
  {
    t.corners.push_back({indices[i], indices[i + 1], indices[i + 2]});
    t.faces.push_back({point_of[indices[i]], point_of[indices[i + 1]], point_of[indices[i + 2]]});
  }
  return t;
}

/// Gives primitive `ref` new vertex data: one vertex per distinct (input
/// vertex, UV) pair of its corners, every attribute carried over, the UVs
/// as TEXCOORD_<uv_set> (float VEC2, v down as glTF has it: v = 1 - UV.y),
/// new 32-bit indices. `uvs[3 * t + k]` is the UV of corner k of triangle t.
inline void set_corner_uvs(Document& doc, Primitive_ref ref, const Triangles& t,
                           const std::vector<std::array<double, 2>>& uvs, int uv_set)
{
  std::map<std::pair<std::uint32_t, std::array<double, 2>>, std::uint32_t> vertex_of;
  std::vector<std::uint32_t> order;              // new vertex -> input vertex
  std::vector<std::array<float, 2>> texcoords;   // per new vertex
  std::vector<std::uint32_t> indices;
  for(std::size_t f = 0; f < t.corners.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const std::array<double, 2>& uv = uvs[3 * f + std::size_t(k)];
      const auto it = vertex_of.emplace(std::make_pair(t.corners[f][std::size_t(k)], uv), std::uint32_t(order.size()));
      if(it.second)
      {
        order.push_back(t.corners[f][std::size_t(k)]);
        texcoords.push_back({float(uv[0]), float(1. - uv[1])});
      }
      indices.push_back(it.first->second);
    }

  tinygltf::Model& model = doc.model;
  tinygltf::Primitive& prim = model.meshes[std::size_t(ref.mesh)].primitives[std::size_t(ref.primitive)];
  const std::string uv_name = "TEXCOORD_" + std::to_string(uv_set);
  std::map<std::string, int> attributes;
  for(const auto& [name, accessor] : prim.attributes)
    if(name != uv_name) attributes[name] = detail::remapped_accessor(model, accessor, order);
  for(auto& target : prim.targets) // morph targets: per vertex too
    for(auto& [name, accessor] : target) accessor = detail::remapped_accessor(model, accessor, order);

  // glTF wants TEXCOORD_0 .. TEXCOORD_{n-1} without gaps
  for(int s = 0; s < uv_set; ++s)
    if(!attributes.count("TEXCOORD_" + std::to_string(s)))
      throw Gltf_error("--uv-set " + std::to_string(uv_set) + ": the primitive has no TEXCOORD_" + std::to_string(s));

  std::vector<unsigned char> bytes(texcoords.size() * 8);
  std::memcpy(bytes.data(), texcoords.data(), bytes.size());
  tinygltf::Accessor uv_accessor;
  uv_accessor.bufferView = detail::append_buffer_view(model, bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
  uv_accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  uv_accessor.type = TINYGLTF_TYPE_VEC2;
  uv_accessor.count = texcoords.size();
  uv_accessor.minValues = {1e300, 1e300};
  uv_accessor.maxValues = {-1e300, -1e300};
  for(const auto& uv : texcoords)
    for(int c = 0; c < 2; ++c)
    {
      uv_accessor.minValues[std::size_t(c)] = std::min(uv_accessor.minValues[std::size_t(c)], double(uv[std::size_t(c)]));
      uv_accessor.maxValues[std::size_t(c)] = std::max(uv_accessor.maxValues[std::size_t(c)], double(uv[std::size_t(c)]));
    }
  model.accessors.push_back(uv_accessor);
  attributes[uv_name] = int(model.accessors.size()) - 1;

  bytes.resize(indices.size() * 4);
  std::memcpy(bytes.data(), indices.data(), bytes.size());
  tinygltf::Accessor index_accessor;
  index_accessor.bufferView = detail::append_buffer_view(model, bytes, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  index_accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  index_accessor.type = TINYGLTF_TYPE_SCALAR;
  index_accessor.count = indices.size();
  model.accessors.push_back(index_accessor);

  prim.attributes = attributes;
  prim.indices = int(model.accessors.size()) - 1;
  prim.mode = TINYGLTF_MODE_TRIANGLES; // strips and fans become lists
}

/// Writes the document as .glb (binary) or .gltf (JSON with its buffers in
/// <output stem>.bin, or <stem>_<k>.bin, beside it). Relative image URIs are
/// rewritten to point, from the output's folder, to the input's images.
inline void save(Document& doc, const std::string& filename)
{
  namespace fs = std::filesystem;
  const fs::path out(filename);
  const bool binary = out.extension() == ".glb";
  const fs::path out_dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  for(tinygltf::Image& image : doc.model.images)
    if(!image.uri.empty() && image.uri.find(':') == std::string::npos && image.bufferView < 0)
    {
      std::error_code ec;
      const fs::path target = fs::absolute(fs::path(doc.input_directory) / image.uri, ec);
      const fs::path relative = fs::relative(target, fs::absolute(out_dir, ec), ec);
      if(!ec && !relative.empty()) image.uri = relative.generic_string();
    }
  for(std::size_t b = 0; b < doc.model.buffers.size(); ++b)
    if(!(binary && b == 0))
      doc.model.buffers[b].uri = out.stem().string() + (b ? "_" + std::to_string(b) : std::string()) + ".bin";
  if(binary && !doc.model.buffers.empty()) doc.model.buffers[0].uri.clear();

  tinygltf::TinyGLTF writer;
  // images are written as they were read: URI or buffer view, never re-encoded
  writer.SetImageWriter([](const std::string*, const std::string*, const tinygltf::Image* image, bool,
                           std::string* out_uri, void*) {
    *out_uri = image->uri;
    return true;
  }, nullptr);
  if(!writer.WriteGltfSceneToFile(&doc.model, filename, false, false, !binary, binary))
    throw Gltf_error("cannot write '" + filename + "'");
}

} // namespace gltf_io

#endif
