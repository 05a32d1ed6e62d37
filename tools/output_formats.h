// uv_unwrap's output formats, one row each. The format chosen from --format
// or an extension, the --format check and help, the error messages listing
// the formats, the glTF-input rule and the dispatch to the writer all read
// this table, so a format is added by adding its row and its writer.
#pragma once

#include <string>
#include <string_view>

namespace output_formats {

// What a writer is handed; uv_unwrap.cpp defines it (the unwrapped mesh, its
// UVs and its input, or the glTF document with its UVs set).
struct Written;

// Writes `w` to `output`; throws the tool's Failure (or gltf_io::Gltf_error) when it cannot.
using Writer = void (*)(const std::string& output, Written& w);

// Defined in uv_unwrap.cpp.
void write_obj(const std::string& output, Written& w);
void write_ply(const std::string& output, Written& w);
void write_gltf(const std::string& output, Written& w);

struct Output_format
{
  std::string_view name;   // --format value; the file extension is "." + name
  std::string_view keeps;  // what the written file keeps of the input (README.md, "Outputs")
  bool needs_gltf_input;   // written from the glTF document read; the only formats of a glTF input
  Writer write;
};

// The first row is the format of inputs that have none (OFF, STL).
inline constexpr Output_format table[] = {
  {"obj", "an OBJ input's lines but vt and f (normals, groups, materials), when read without repair", false,
   write_obj},
  {"ply", "positions and faces in order; each face's UVs as a texcoord list", false, write_ply},
  {"gltf", "the glTF scene: nodes, materials, every vertex attribute; UVs in TEXCOORD_<uv-set>", true, write_gltf},
  {"glb", "the glTF scene: nodes, materials, every vertex attribute; UVs in TEXCOORD_<uv-set>", true, write_gltf},
};

// The row named `name` (a --format value, or an extension without its dot, lower case); nullptr if none.
inline const Output_format* find(std::string_view name)
{
  for(const Output_format& f : table)
    if(f.name == name) return &f;
  return nullptr;
}

enum class Inputs { any, mesh, gltf };  // rows listed: all, those written from a mesh, those of a glTF input

// The rows' names, each after `dot` (".": as extensions), e.g. "obj, ply, gltf or glb".
inline std::string list(const std::string& dot = "", Inputs inputs = Inputs::any)
{
  std::string names, last;
  for(const Output_format& f : table)
  {
    if(inputs != Inputs::any && f.needs_gltf_input != (inputs == Inputs::gltf)) continue;
    if(!last.empty()) names += (names.empty() ? "" : ", ") + last;
    last = dot + std::string(f.name);
  }
  return names.empty() ? last : names + " or " + last;
}

} // namespace output_formats
