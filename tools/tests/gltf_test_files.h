// What the glTF tests of uv_unwrap share: building a model's buffers,
// reading a written file back, its accessors, and the Khronos
// glTF-Validator's verdict on it (tools/tests/validate_gltf.js; the test
// program is compiled with CUT_PARAM_GLTF_VALIDATOR_SCRIPT, empty when the
// check is off, and CUT_PARAM_GLTF_VALIDATOR_DIR).
#ifndef CUT_PARAM_TOOLS_TESTS_GLTF_TEST_FILES_H
#define CUT_PARAM_TOOLS_TESTS_GLTF_TEST_FILES_H

#include "uv_unwrap_runs.h"

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace uv_unwrap_test {

/// Appends `bytes` to buffer 0 as a view and an accessor (with the bounds of
/// float data, which the validator wants for POSITION); returns the accessor.
inline int add_accessor(tinygltf::Model& m, const void* data, std::size_t bytes, int component, int type,
                        std::size_t count, int target)
{
  auto& buffer = m.buffers[0].data;
  while(buffer.size() % 4) buffer.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  m.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = int(m.bufferViews.size()) - 1;
  a.componentType = component;
  a.type = type;
  a.count = count;
  if(component == TINYGLTF_COMPONENT_TYPE_FLOAT)
  {
    const std::size_t n = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
    const float* x = static_cast<const float*>(data);
    a.minValues.assign(n, 1e300);
    a.maxValues.assign(n, -1e300);
    for(std::size_t i = 0; i < count; ++i)
      for(std::size_t c = 0; c < n; ++c)
      {
        a.minValues[c] = std::min(a.minValues[c], double(x[i * n + c]));
        a.maxValues[c] = std::max(a.maxValues[c], double(x[i * n + c]));
      }
  }
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

/// Appends the float attribute `values` (`type`: TINYGLTF_TYPE_VEC2 or
/// TINYGLTF_TYPE_VEC3) to `p` as `name`.
inline void add_float_attribute(tinygltf::Model& m, tinygltf::Primitive& p, const std::string& name,
                                const std::vector<float>& values, int type)
{
  const std::size_t n = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
  p.attributes[name] = add_accessor(m, values.data(), values.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                                    values.size() / n, TINYGLTF_TARGET_ARRAY_BUFFER);
}

/// A triangle-list primitive of float positions `pos` (x, y, z each) and
/// 16-bit indices `idx`.
inline tinygltf::Primitive triangle_primitive(tinygltf::Model& m, const std::vector<float>& pos,
                                              const std::vector<std::uint16_t>& idx)
{
  tinygltf::Primitive p;
  add_float_attribute(m, p, "POSITION", pos, TINYGLTF_TYPE_VEC3);
  p.indices = add_accessor(m, idx.data(), idx.size() * 2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                           TINYGLTF_TYPE_SCALAR, idx.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  p.mode = TINYGLTF_MODE_TRIANGLES;
  return p;
}

/// Appends two triangles per cell of a grid of `columns` × `rows` cells
/// whose (columns + 1) × (rows + 1) vertices are numbered row by row from `first`.
inline void add_grid_triangles(std::vector<std::uint16_t>& idx, int columns, int rows, int first = 0)
{
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i < columns; ++i)
    {
      const auto a = std::uint16_t(first + j * (columns + 1) + i), b = std::uint16_t(a + 1),
                 c = std::uint16_t(a + columns + 1), d = std::uint16_t(c + 1);
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
}

/// The model of a .gltf or .glb file (a failure if it does not load).
inline tinygltf::Model load_gltf(const std::filesystem::path& file)
{
  tinygltf::TinyGLTF loader;
  tinygltf::Model m;
  std::string err, warn;
  const bool ok = file.extension() == ".glb" ? loader.LoadBinaryFromFile(&m, &err, &warn, file.string())
                                             : loader.LoadASCIIFromFile(&m, &err, &warn, file.string());
  EXPECT_TRUE(ok) << file << ": " << err;
  return m;
}

/// Element i of a float accessor.
inline std::vector<float> accessor_floats(const tinygltf::Model& m, int accessor, std::size_t i)
{
  const tinygltf::Accessor& a = m.accessors[std::size_t(accessor)];
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
  const int n = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
  const std::size_t stride = v.byteStride ? v.byteStride : std::size_t(n) * 4;
  std::vector<float> out(static_cast<std::size_t>(n));
  std::memcpy(out.data(), m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset + i * stride,
              out.size() * 4);
  return out;
}

/// The indices of a primitive (16- or 32-bit).
inline std::vector<std::uint32_t> primitive_indices(const tinygltf::Model& m, const tinygltf::Primitive& p)
{
  const tinygltf::Accessor& a = m.accessors[std::size_t(p.indices)];
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
  const unsigned char* data = m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
  std::vector<std::uint32_t> out(a.count);
  for(std::size_t i = 0; i < a.count; ++i)
  {
    if(a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
    {
      std::uint16_t x;
      std::memcpy(&x, data + 2 * i, 2);
      out[i] = x;
    }
    else
      std::memcpy(&out[i], data + 4 * i, 4);
  }
  return out;
}

/// Checks `file` with the Khronos glTF-Validator: 0 errors and no warning
/// that tools/tests/validate_gltf.js refuses. Skipped (true) when the build
/// turns the check off; false when the validator cannot run.
inline bool expect_validator_accepts(const std::filesystem::path& file)
{
  const std::string script = CUT_PARAM_GLTF_VALIDATOR_SCRIPT, validator_dir = CUT_PARAM_GLTF_VALIDATOR_DIR;
  if(script.empty()) return true; // -DCUT_PARAM_GLTF_VALIDATOR=OFF
  const std::string validate =
    "GLTF_VALIDATOR_DIR=\"" + validator_dir + "\" node \"" + script + "\" \"" + file.string() + "\"";
  const int status = exit_status(validate);
  if(status == 2 || status == 127)
  {
    ADD_FAILURE() << validate << ": the validator cannot run; install it with scripts/install_gltf_validator.sh "
                  << validator_dir << " (Debian's nodejs and npm first), or configure with "
                  << "-DCUT_PARAM_GLTF_VALIDATOR=OFF";
    return false;
  }
  EXPECT_EQ(status, 0) << validate << ": errors, or warnings not allowed in tools/tests/validate_gltf.js";
  return status == 0;
}

} // namespace uv_unwrap_test

#endif
