// uv_unwrap on a glTF file with two primitives (tools/gltf_io.h): the output
// keeps the node transform, the materials, and every vertex's position and
// normal; it has the same triangles, a TEXCOORD_0 whose accessor counts and
// bounds match its data, UVs in [0,1] without flipped triangles, and
// vertices split only where a seam passes. The Khronos glTF-Validator must
// report no error and no warning but the allowed ones on the .gltf and .glb
// outputs (tools/tests/validate_gltf.js, run with node; the npm package in
// CUT_PARAM_GLTF_VALIDATOR_DIR, installed there by
// scripts/install_gltf_validator.sh): that test fails when the validator
// cannot run, and is skipped when the build turns it off
// (-DCUT_PARAM_GLTF_VALIDATOR=OFF). Every output format that --help lists
// (tools/output_formats.h) is written, by -o's extension and by --format, and
// reads back with texture coordinates. With --hard-edge-angle, a
// primitive's split NORMALs are seams (tools/gltf_split_normals.h).
//   UV_UNWRAP=<uv_unwrap executable> test_gltf_round_trip
#include "tests/gltf_test_files.h"

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <filesystem>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
std::string uv_unwrap_program;
using namespace uv_unwrap_test;

// A bumpy n x n grid at height z0, normals +z, 16-bit indices.
tinygltf::Primitive grid(tinygltf::Model& m, int n, float z0, int material)
{
  std::vector<float> pos, nrm;
  std::vector<std::uint16_t> idx;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const float x = float(i) / n, y = float(j) / n;
      pos.insert(pos.end(), {x, y, z0 + 0.3f * std::sin(3.f * x) * std::cos(2.f * y)});
      nrm.insert(nrm.end(), {0.f, 0.f, 1.f});
    }
  add_grid_triangles(idx, n, n);
  tinygltf::Primitive p = triangle_primitive(m, pos, idx);
  add_float_attribute(m, p, "NORMAL", nrm, TINYGLTF_TYPE_VEC3);
  p.material = material;
  return p;
}

tinygltf::Model two_primitives()
{
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.buffers.emplace_back();
  tinygltf::Mesh mesh;
  mesh.name = "two";
  mesh.primitives.push_back(grid(m, 10, 0.f, 0));
  mesh.primitives.push_back(grid(m, 6, 1.f, 1));
  m.meshes.push_back(mesh);
  for(const char* name : {"red", "blue"})
  {
    tinygltf::Material material;
    material.name = name;
    m.materials.push_back(material);
  }
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "grids";
  node.translation = {1., 2., 3.};
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  return m;
}

class Gltf_round_trip : public ::testing::TestWithParam<std::string>
{
protected:
  fs::path dir;
  std::string input, output;
  tinygltf::Model in;

  // Writes the two grids to a .gltf and unwraps it to a .gltf or .glb (the parameter).
  void unwrap(const std::string& name)
  {
    ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
    dir = fs::temp_directory_path() / ("cut_param_gltf_" + name + "_" + GetParam());
    fs::remove_all(dir);
    fs::create_directories(dir);
    input = (dir / "two.gltf").string();
    output = (dir / ("two_uv." + GetParam())).string();
    in = two_primitives();
    tinygltf::TinyGLTF writer;
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&in, input, false, true, true, false));
    in = load_gltf(input);
    const std::string command = "\"" + uv_unwrap_program + "\" \"" + input + "\" -o \"" + output + "\" -q";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  void TearDown() override
  {
    if(!dir.empty()) fs::remove_all(dir);
  }
};

TEST_P(Gltf_round_trip, keeps_the_scene_and_adds_valid_uvs)
{
  ASSERT_NO_FATAL_FAILURE(unwrap("scene"));
  const tinygltf::Model out = load_gltf(output);

  // the scene: node, transform, materials, primitives and their materials
  ASSERT_EQ(out.nodes.size(), 1u);
  EXPECT_EQ(out.nodes[0].translation, in.nodes[0].translation);
  EXPECT_EQ(out.nodes[0].name, "grids");
  ASSERT_EQ(out.materials.size(), 2u);
  EXPECT_EQ(out.materials[0].name, "red");
  EXPECT_EQ(out.materials[1].name, "blue");
  ASSERT_EQ(out.meshes.size(), 1u);
  ASSERT_EQ(out.meshes[0].primitives.size(), 2u);

  for(std::size_t k = 0; k < 2; ++k)
  {
    SCOPED_TRACE("primitive " + std::to_string(k));
    const tinygltf::Primitive& pi = in.meshes[0].primitives[k];
    const tinygltf::Primitive& po = out.meshes[0].primitives[k];
    EXPECT_EQ(po.material, pi.material);
    ASSERT_TRUE(po.attributes.count("TEXCOORD_0"));
    const int pos = po.attributes.at("POSITION"), nrm = po.attributes.at("NORMAL"), uv = po.attributes.at("TEXCOORD_0");
    const std::size_t n = out.accessors[std::size_t(pos)].count;
    EXPECT_EQ(out.accessors[std::size_t(nrm)].count, n);
    EXPECT_EQ(out.accessors[std::size_t(uv)].count, n);

    // triangles: the same ones, corner by corner, by position and normal
    const std::vector<std::uint32_t> ii = primitive_indices(in, pi), io = primitive_indices(out, po);
    ASSERT_EQ(io.size(), ii.size());
    for(std::size_t c = 0; c < io.size(); ++c)
    {
      ASSERT_LT(io[c], n);
      EXPECT_EQ(accessor_floats(out, pos, io[c]), accessor_floats(in, pi.attributes.at("POSITION"), ii[c]));
      EXPECT_EQ(accessor_floats(out, nrm, io[c]), accessor_floats(in, pi.attributes.at("NORMAL"), ii[c]));
    }

    // accessor bounds match the data (the validator's rule for POSITION)
    for(int accessor : {pos, uv})
    {
      const tinygltf::Accessor& a = out.accessors[std::size_t(accessor)];
      ASSERT_FALSE(a.minValues.empty());
      std::vector<double> lo(a.minValues.size(), 1e300), hi(a.minValues.size(), -1e300);
      for(std::size_t v = 0; v < a.count; ++v)
      {
        const std::vector<float> x = accessor_floats(out, accessor, v);
        for(std::size_t c = 0; c < x.size(); ++c)
        {
          lo[c] = std::min(lo[c], double(x[c]));
          hi[c] = std::max(hi[c], double(x[c]));
        }
      }
      EXPECT_EQ(lo, a.minValues);
      EXPECT_EQ(hi, a.maxValues);
    }

    // UVs in [0,1], no flipped triangle (v points down in glTF: the area
    // of a front face is negative there), and a vertex is split only if
    // its copies have different UVs
    std::map<std::vector<float>, std::set<std::vector<float>>> uvs_at;
    for(std::size_t v = 0; v < n; ++v)
    {
      const std::vector<float> t = accessor_floats(out, uv, v);
      EXPECT_TRUE(t[0] >= 0.f && t[0] <= 1.f && t[1] >= 0.f && t[1] <= 1.f);
      EXPECT_TRUE(uvs_at[accessor_floats(out, pos, v)].insert(t).second) << "vertex " << v << " split without a seam";
    }
    EXPECT_EQ(uvs_at.size(), in.accessors[std::size_t(pi.attributes.at("POSITION"))].count);
    for(std::size_t t = 0; t < io.size(); t += 3)
    {
      const auto a = accessor_floats(out, uv, io[t]), b = accessor_floats(out, uv, io[t + 1]), c = accessor_floats(out, uv, io[t + 2]);
      const double area2 = double(b[0] - a[0]) * (c[1] - a[1]) - double(b[1] - a[1]) * (c[0] - a[0]);
      EXPECT_LT(area2, 0.) << "triangle " << t / 3 << " is flipped";
    }
  }
}

TEST_P(Gltf_round_trip, khronos_validator_accepts_the_output)
{
  if(std::string(CUT_PARAM_GLTF_VALIDATOR_SCRIPT).empty()) GTEST_SKIP() << "the glTF-Validator check is off (-DCUT_PARAM_GLTF_VALIDATOR=OFF)";
  ASSERT_NO_FATAL_FAILURE(unwrap("validator"));
  expect_validator_accepts(output);
}

INSTANTIATE_TEST_SUITE_P(Formats, Gltf_round_trip, ::testing::Values("gltf", "glb"));

// The standard output of a shell command.
std::string output_of(const std::string& command)
{
  std::string out;
  if(FILE* pipe = popen(command.c_str(), "r"))
  {
    char buffer[4096];
    for(std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    pclose(pipe);
  }
  return out;
}

// The formats --help lists for --format ("format of the outputs: obj, ply, gltf or glb (default: ..."),
// which uv_unwrap builds from its table (tools/output_formats.h).
std::vector<std::string> listed_formats()
{
  std::string help = output_of("\"" + uv_unwrap_program + "\" --help");
  const std::string lead = "format of the outputs: ";
  const std::size_t from = help.find(lead);
  if(from == std::string::npos) return {};
  std::string list = help.substr(from + lead.size(), help.find(" (default", from) - from - lead.size());
  if(const std::size_t o = list.rfind(" or "); o != std::string::npos) list.replace(o, 4, ", ");
  std::vector<std::string> names;
  for(std::size_t at = 0; at <= list.size();)
  {
    const std::size_t comma = std::min(list.find(", ", at), list.size());
    names.push_back(list.substr(at, comma - at));
    at = comma + 2;
  }
  return names;
}

// True if `file` reads back as a mesh with texture coordinates in the format of its extension.
::testing::AssertionResult reads_back_with_uvs(const fs::path& file)
{
  const std::string extension = file.extension().string();
  if(!fs::exists(file)) return ::testing::AssertionFailure() << file << " was not written";
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(extension == ".obj")
  {
    if(text.find("\nvt ") != std::string::npos && text.find("\nf ") != std::string::npos &&
       text.find('/', text.find("\nf ")) != std::string::npos)
      return ::testing::AssertionSuccess();
  }
  else if(extension == ".ply")
  {
    if(text.rfind("ply\n", 0) == 0 && text.find("property list uchar float texcoord") != std::string::npos)
      return ::testing::AssertionSuccess();
  }
  else if(extension == ".gltf" || extension == ".glb")
  {
    const tinygltf::Model m = load_gltf(file.string());
    for(const tinygltf::Mesh& mesh : m.meshes)
      for(const tinygltf::Primitive& p : mesh.primitives)
        if(p.attributes.count("TEXCOORD_0")) return ::testing::AssertionSuccess();
  }
  else
    return ::testing::AssertionFailure() << "no read-back check for the format of " << file << " in this test";
  return ::testing::AssertionFailure() << file << " has no texture coordinates";
}

// Every output format of uv_unwrap's table, chosen by -o's extension and by --format: each has a writer
// and its extension is recognized; its file reads back with UVs. A format that needs a glTF input (the
// mesh input is refused) is written from a glTF input.
// A flat 4 x 4 grid in two halves of their own vertices, normals (0, 0, 1)
// left of x = 2 and (0.28, 0, 0.96) right of it: the file splits its normals
// along that line (the halves share positions there, welded on reading).
tinygltf::Model split_normal_grid()
{
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.buffers.emplace_back();
  std::vector<float> pos, nrm;
  std::vector<std::uint16_t> idx;
  for(int half = 0; half < 2; ++half)
  {
    const auto first = std::uint16_t(pos.size() / 3);
    for(int j = 0; j <= 4; ++j)
      for(int i = 0; i <= 2; ++i)
      {
        pos.insert(pos.end(), {float(2 * half + i), float(j), 0.f});
        nrm.insert(nrm.end(), {half ? 0.28f : 0.f, 0.f, half ? 0.96f : 1.f});
      }
    add_grid_triangles(idx, 2, 4, first);
  }
  tinygltf::Primitive p = triangle_primitive(m, pos, idx);
  add_float_attribute(m, p, "NORMAL", nrm, TINYGLTF_TYPE_VEC3);
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(p);
  m.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  return m;
}

TEST(Gltf_split_normals, are_seams_with_hard_edge_angle_only)
{
  ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
  const fs::path dir = fs::temp_directory_path() / "cut_param_gltf_split_normals";
  fs::remove_all(dir);
  fs::create_directories(dir);
  tinygltf::Model m = split_normal_grid();
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&m, (dir / "grid.gltf").string(), false, true, true, false));
  // 180 degrees: no dihedral angle exceeds it (the grid is flat), the split normals alone cut
  const Unwrap_run hard = run_uv_unwrap(uv_unwrap_program, dir / "grid.gltf", dir / "hard.gltf", "--hard-edge-angle 180");
  ASSERT_TRUE(expect_valid_atlas(hard, "split normals"));
  EXPECT_EQ(hard.stats["charts"], 2);
  EXPECT_EQ(hard.stats["seam_edges"], 4); // the line x = 2
  const Unwrap_run plain = run_uv_unwrap(uv_unwrap_program, dir / "grid.gltf", dir / "plain.gltf");
  ASSERT_TRUE(expect_valid_atlas(plain, "without the option"));
  EXPECT_EQ(plain.stats["charts"], 1); // welded: one flat disk
  fs::remove_all(dir);
}

// The statistics' hard_edges: the box's 12 edges at --hard-edge-angle 30 (its
// face diagonals are flat), none without the option; a glTF adds up its primitives.
TEST(Statistics, hard_edges_are_the_edges_cut_by_the_angle)
{
  ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
  const fs::path dir = fs::temp_directory_path() / "cut_param_hard_edge_statistics";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream box(dir / "box.obj");
    for(int v = 0; v < 8; ++v) box << "v " << (v & 1) << ' ' << 2 * ((v >> 1) & 1) << ' ' << 3 * (v >> 2) << '\n';
    // the six sides, each two triangles, outward
    for(const char* f : {"1 3 4", "1 4 2", "5 6 8", "5 8 7", "1 2 6", "1 6 5",
                         "3 7 8", "3 8 4", "1 5 7", "1 7 3", "2 4 8", "2 8 6"})
      box << "f " << f << '\n';
  }
  const Unwrap_run hard = run_uv_unwrap(uv_unwrap_program, dir / "box.obj", dir / "hard.obj", "--hard-edge-angle 30");
  ASSERT_TRUE(expect_valid_atlas(hard, "box, hard edges"));
  EXPECT_EQ(hard.stats["hard_edges"], 12);
  EXPECT_EQ(hard.stats["charts"], 6);
  EXPECT_GE(hard.stats["seam_edges"].get<int>(), 12);
  const Unwrap_run plain = run_uv_unwrap(uv_unwrap_program, dir / "box.obj", dir / "plain.obj");
  ASSERT_TRUE(expect_valid_atlas(plain, "box"));
  EXPECT_EQ(plain.stats["hard_edges"], 0);
  fs::remove_all(dir);
}

TEST(Output_formats, each_format_is_written_and_read_back)
{
  ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
  const std::vector<std::string> names = listed_formats();
  ASSERT_GE(names.size(), 2u) << "no format list in uv_unwrap --help";
  const fs::path dir = fs::temp_directory_path() / "cut_param_output_formats";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string mesh = (dir / "grid.obj").string(), gltf = (dir / "two.gltf").string();
  {
    std::ofstream out(mesh);
    const int n = 4;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) out << "v " << i << " " << j << " " << 0.1 * (i * i + j * j) / n << "\n";
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
        out << "f " << a << " " << b << " " << d << "\nf " << a << " " << d << " " << c << "\n";
      }
  }
  tinygltf::Model model = two_primitives();
  ASSERT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToFile(&model, gltf, false, true, true, false));
  const std::string program = "\"" + uv_unwrap_program + "\" ";
  for(const std::string& name : names)
  {
    SCOPED_TRACE("format " + name);
    ASSERT_FALSE(name.empty());
    const fs::path by_extension = dir / ("by_extension." + name);
    std::string input = mesh;
    if(exit_status(program + "\"" + mesh + "\" -q -o \"" + by_extension.string() + "\"") != 0)
    {
      input = gltf;
      EXPECT_EQ(exit_status(program + "\"" + gltf + "\" -q -o \"" + by_extension.string() + "\""), 0)
        << "neither a mesh nor a glTF input gives a ." << name << " output";
    }
    EXPECT_TRUE(reads_back_with_uvs(by_extension));
    const fs::path by_option = dir / name;
    EXPECT_EQ(exit_status(program + "\"" + input + "\" -q --format " + name + " --output-dir \"" +
                          by_option.string() + "\""), 0);
    EXPECT_TRUE(reads_back_with_uvs(by_option / (fs::path(input).stem().string() + "_uv." + name)));
  }
  fs::remove_all(dir);
}

} // namespace

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if(const char* program = std::getenv("UV_UNWRAP")) uv_unwrap_program = program;
  return RUN_ALL_TESTS();
}
