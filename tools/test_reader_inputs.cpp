// Files that common tools write and CGAL's readers or the glTF path did not
// read (issue 57), each generated here and unwrapped by uv_unwrap with its
// defaults: an OBJ face continued on the next line with a backslash; an OBJ
// of polylines and points only (the clean "has no faces" error, with its
// name); an ASCII PLY whose element lines carry more values than its header
// lists (VCG/MeshLab's faces); an OFF file whose counts follow the keyword
// without a space; a glTF primitive with an edge of more than two faces
// (repaired as mesh files are), and primitives in triangle-strip and
// triangle-fan modes (read as triangles, written back as lists). Each must
// give exit 0, status ok, a valid atlas (no flipped face, no border
// crossing, UVs in the unit square), every face of the file, and the
// warning that says what the reader did. The glTF outputs keep the input's
// triangles corner by corner, with their winding, and pass the Khronos
// glTF-Validator (tools/tests/validate_gltf.js, as in test_gltf_round_trip;
// skipped when the build turns the check off).
//
//   UV_UNWRAP=<uv_unwrap executable> test_reader_inputs
#include "generators.h"
#include "tests/gltf_test_files.h"
#include "tests/uv_unwrap_runs.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>


namespace {

namespace fs = std::filesystem;
using cut_test::Soup;
using namespace uv_unwrap_test;

std::string uv_unwrap_program;

fs::path work_directory()
{
  const fs::path dir = fs::temp_directory_path() / "cut_param_reader_inputs";
  fs::create_directories(dir);
  return dir;
}

/// Unwraps `input` and checks a valid atlas of `faces` faces with a warning
/// holding `warning`; returns the statistics.
nlohmann::json expect_valid_atlas(const fs::path& input, const std::string& output_extension, std::size_t faces,
                                  const std::string& warning)
{
  if(uv_unwrap_program.empty())
  {
    ADD_FAILURE() << "set UV_UNWRAP to the uv_unwrap executable";
    return {};
  }
  const fs::path output = input.parent_path() / (input.stem().string() + "_uv." + output_extension);
  const Unwrap_run r = run_uv_unwrap(uv_unwrap_program, input, output);
  if(!uv_unwrap_test::expect_valid_atlas(r, input.string(), warning)) return r.stats;
  EXPECT_EQ(r.stats["faces"].get<std::size_t>(), faces) << "faces of the unwrapped mesh";
  EXPECT_TRUE(fs::exists(output));
  return r.stats;
}

/// A wavy n x n grid (a disk, 2 n^2 triangles, normals up).
Soup wavy_grid(int n)
{
  Soup s = cut_test::grid_soup(n, n);
  s.transform([](const Soup::Point& p) {
    return Soup::Point{p[0], p[1], 0.2 * std::sin(3. * p[0]) * std::cos(2. * p[1])};
  });
  return s;
}

void write_vertices(std::ofstream& out, const Soup& s, const std::string& prefix)
{
  out.precision(17);
  for(const auto& p : s.points) out << prefix << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
}

// ---------------------------------------------------------------- OBJ

TEST(ReaderInputs, obj_face_continued_on_the_next_line)
{
  // every face line broken after its first corner, and one vertex line too
  const Soup s = wavy_grid(8);
  const fs::path file = work_directory() / "continued.obj";
  {
    std::ofstream out(file);
    out.precision(17);
    for(std::size_t v = 0; v < s.points.size(); ++v)
    {
      const auto& p = s.points[v];
      if(v == 3) out << "v " << p[0] << " \\\n  " << p[1] << ' ' << p[2] << '\n';
      else out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    out << "# a comment ending with a backslash does not go on \\\n";
    for(const auto& f : s.faces) out << "f " << f[0] + 1 << " \\\r\n" << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  }
  const nlohmann::json stats = expect_valid_atlas(file, "obj", s.faces.size(), "end with a backslash: joined");
  // the output OBJ keeps the file's lines, the continued ones joined
  EXPECT_FALSE(has_warning(stats, "not kept")) << stats["warnings"].dump();
}

TEST(ReaderInputs, obj_polylines_and_points_alone_have_no_faces)
{
  ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
  const Soup s = wavy_grid(4);
  const fs::path file = work_directory() / "polylines.obj";
  {
    std::ofstream out(file);
    write_vertices(out, s, "v ");
    out << "l 1 2 3 4 5\nl 6 7\np 1 2 3\n";
  }
  const Unwrap_run r = run_uv_unwrap(uv_unwrap_program, file, work_directory() / "polylines_uv.obj");
  const nlohmann::json& stats = r.stats;
  ASSERT_FALSE(stats.is_discarded());
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_EQ(stats["status"], "ERROR_EMPTY_MESH") << stats.dump();
  EXPECT_NE(stats["error"].get<std::string>().find("has no faces"), std::string::npos) << stats.dump();
  EXPECT_NE(stats["error"].get<std::string>().find("2 polyline ('l') and 1 point ('p')"), std::string::npos)
    << stats.dump();
}

TEST(ReaderInputs, obj_polylines_beside_faces_are_ignored)
{
  const Soup s = wavy_grid(6);
  const fs::path file = work_directory() / "faces_and_polylines.obj";
  {
    std::ofstream out(file);
    write_vertices(out, s, "v ");
    out << "l 1 2 3\n";
    for(const auto& f : s.faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
    out << "l 4 5\np 7\n";
  }
  expect_valid_atlas(file, "obj", s.faces.size(), "2 polyline ('l') and 1 point ('p') statements ignored");
}

// ---------------------------------------------------------------- PLY

/// An ASCII PLY of `s` whose header lists x y z and vertex_indices; with
/// `extra`, VCG/MeshLab-like lines: faces carry texture coordinates and a
/// flag, some vertices a quality value, that the header does not list.
void write_ply(const Soup& s, const fs::path& file, bool extra, bool split_faces = false)
{
  std::ofstream out(file);
  out.precision(17);
  out << "ply\nformat ascii 1.0\ncomment VCGLIB generated\nelement vertex " << s.points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << s.faces.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    const auto& p = s.points[v];
    out << p[0] << ' ' << p[1] << ' ' << p[2] << (extra && v % 3 == 0 ? " 0.5" : "") << '\n';
  }
  for(const auto& f : s.faces)
  {
    out << "3 " << f[0] << ' ' << f[1] << (split_faces ? "\n" : " ") << f[2];
    if(extra) out << " 6 0.1 0.2 0.3 0.4 0.5 0.6 0";
    out << '\n';
  }
}

TEST(ReaderInputs, ply_extra_values_at_the_end_of_element_lines)
{
  const Soup s = wavy_grid(8);
  const fs::path file = work_directory() / "vcg_extra_values.ply";
  write_ply(s, file, true);
  const nlohmann::json stats =
    expect_valid_atlas(file, "obj", s.faces.size(), "'face' element lines of the PLY file (first: element 0) end with "
                                                    "values that its header does not list (up to 8 more): ignored");
  EXPECT_TRUE(has_warning(stats, "'vertex' element lines")) << stats["warnings"].dump();
}

TEST(ReaderInputs, ply_elements_over_several_lines_are_read_as_before)
{
  // values one after the other, whatever the lines, as CGAL reads them: no cut, no warning
  const Soup s = wavy_grid(6);
  const fs::path file = work_directory() / "split_faces.ply";
  write_ply(s, file, false, true);
  const nlohmann::json stats = expect_valid_atlas(file, "obj", s.faces.size(), "");
  EXPECT_FALSE(has_warning(stats, "PLY")) << stats["warnings"].dump();
}

// ---------------------------------------------------------------- OFF

TEST(ReaderInputs, off_counts_glued_to_the_keyword)
{
  // a cube of quads, as "OFF8 6 12"
  const fs::path file = work_directory() / "glued_counts.off";
  {
    std::ofstream out(file);
    out << "OFF8 6 12\n";
    for(int k = 0; k < 8; ++k) out << (k & 1) << ' ' << ((k >> 1) & 1) << ' ' << ((k >> 2) & 1) << '\n';
    out << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  }
  const nlohmann::json stats = expect_valid_atlas(file, "obj", 12, "read as 'OFF 8'");
  EXPECT_TRUE(has_warning(stats, "triangulated")) << stats["warnings"].dump();
}

// ---------------------------------------------------------------- glTF

/// A primitive of `mode` over `points` (float positions, normals up), with
/// 16-bit `indices` (none if empty).
tinygltf::Primitive primitive(tinygltf::Model& m, const std::vector<Soup::Point>& points,
                              const std::vector<std::uint16_t>& indices, int mode)
{
  std::vector<float> pos, nrm;
  for(const auto& p : points)
  {
    pos.insert(pos.end(), {float(p[0]), float(p[1]), float(p[2])});
    nrm.insert(nrm.end(), {0.f, 0.f, 1.f});
  }
  tinygltf::Primitive p;
  p.attributes["POSITION"] = add_accessor(m, pos.data(), pos.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                          TINYGLTF_TYPE_VEC3, points.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
  p.attributes["NORMAL"] = add_accessor(m, nrm.data(), nrm.size() * 4, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                        TINYGLTF_TYPE_VEC3, points.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
  if(!indices.empty())
    p.indices = add_accessor(m, indices.data(), indices.size() * 2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_TYPE_SCALAR, indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  p.mode = mode;
  p.material = 0;
  return p;
}

/// A model of one mesh, one node and one material holding `primitives`.
tinygltf::Model model_of(const std::vector<tinygltf::Primitive>& primitives, tinygltf::Model m)
{
  m.asset.version = "2.0";
  tinygltf::Mesh mesh;
  mesh.primitives = primitives;
  m.meshes.push_back(mesh);
  m.materials.emplace_back();
  m.materials.back().name = "surface";
  tinygltf::Node node;
  node.mesh = 0;
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  return m;
}

tinygltf::Model new_model()
{
  tinygltf::Model m;
  m.buffers.emplace_back();
  return m;
}

using Triangle = std::array<std::array<float, 3>, 3>; // corner positions

/// The output's primitive `k`: a list of triangles (mode 4) whose corners
/// are `expected`, in order and with their winding; UVs in [0,1]; among the
/// first `facing_up` triangles (those of a surface facing up), none of
/// positive area whose UV triangle is flipped or degenerate.
void expect_triangle_list(const tinygltf::Model& out, std::size_t k, const std::vector<Triangle>& expected,
                          std::size_t facing_up)
{
  SCOPED_TRACE("primitive " + std::to_string(k));
  ASSERT_EQ(out.meshes.size(), 1u);
  ASSERT_GT(out.meshes[0].primitives.size(), k);
  const tinygltf::Primitive& p = out.meshes[0].primitives[k];
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  ASSERT_TRUE(p.attributes.count("TEXCOORD_0"));
  ASSERT_GE(p.indices, 0);
  const int pos = p.attributes.at("POSITION"), uv = p.attributes.at("TEXCOORD_0");
  const std::vector<std::uint32_t> idx = primitive_indices(out, p);
  ASSERT_EQ(idx.size(), 3 * expected.size());
  for(std::size_t t = 0; t < expected.size(); ++t)
  {
    std::array<std::vector<float>, 3> x, u;
    for(std::size_t c = 0; c < 3; ++c)
    {
      x[c] = accessor_floats(out, pos, idx[3 * t + c]);
      u[c] = accessor_floats(out, uv, idx[3 * t + c]);
      EXPECT_EQ(x[c], std::vector<float>(expected[t][c].begin(), expected[t][c].end())) << "triangle " << t;
      EXPECT_TRUE(u[c][0] >= 0.f && u[c][0] <= 1.f && u[c][1] >= 0.f && u[c][1] <= 1.f) << "triangle " << t;
    }
    // area seen from +z (all the test surfaces face up) and in UV (v down in glTF: a front face is negative)
    const double area_z = double(x[1][0] - x[0][0]) * (x[2][1] - x[0][1]) - double(x[1][1] - x[0][1]) * (x[2][0] - x[0][0]);
    const double area_uv = double(u[1][0] - u[0][0]) * (u[2][1] - u[0][1]) - double(u[1][1] - u[0][1]) * (u[2][0] - u[0][0]);
    if(t < facing_up && area_z > 1e-9) EXPECT_LT(area_uv, 0.) << "triangle " << t << " is flipped or degenerate in UV";
  }
}

class Gltf_readers : public ::testing::TestWithParam<std::string>
{
protected:
  /// Writes `m` as NAME.gltf, unwraps it into NAME_uv.<format> (the
  /// parameter), checks a valid atlas of `faces` faces with `warning`, and
  /// returns the output, which the validator checks.
  tinygltf::Model unwrap(tinygltf::Model m, const std::string& name, std::size_t faces, const std::string& warning)
  {
    const fs::path dir = work_directory() / (name + "_" + GetParam());
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path input = dir / (name + ".gltf");
    tinygltf::TinyGLTF writer;
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&m, input.string(), false, true, true, false));
    const nlohmann::json stats = expect_valid_atlas(input, GetParam(), faces, warning);
    output = dir / (name + "_uv." + GetParam());
    expect_validator_accepts(output);
    return load_gltf(output);
  }

  fs::path output;
};

Triangle corners(const std::vector<Soup::Point>& points, std::size_t a, std::size_t b, std::size_t c)
{
  Triangle t;
  for(std::size_t k = 0; k < 3; ++k)
    for(std::size_t j = 0; j < 3; ++j) t[k][j] = float(points[std::array<std::size_t, 3>{a, b, c}[k]][j]);
  return t;
}

/// A glTF of one indexed primitive (mode 4) over the triangles of `s`; `expected`: their corners.
tinygltf::Model triangles_model(const Soup& s, std::vector<Triangle>& expected)
{
  std::vector<std::uint16_t> indices;
  expected.clear();
  for(const auto& f : s.faces)
  {
    for(std::size_t v : f) indices.push_back(std::uint16_t(v));
    expected.push_back(corners(s.points, f[0], f[1], f[2]));
  }
  tinygltf::Model m = new_model();
  const tinygltf::Primitive p = primitive(m, s.points, indices, TINYGLTF_MODE_TRIANGLES);
  return model_of({p}, m);
}

TEST_P(Gltf_readers, non_manifold_primitive_is_repaired)
{
  // a wavy grid with three fins hung on an inner diagonal: an edge of five
  // faces (refused before: ERROR_NON_MANIFOLD), as OBJ input is repaired
  const int n = 8;
  Soup s = wavy_grid(n);
  const std::size_t a = std::size_t(3 * (n + 1) + 3), b = std::size_t(4 * (n + 1) + 4); // (3,3)-(4,4)
  for(int i = 0; i < 3; ++i) s.add_triangle(a, b, s.add_point(0.4 + 0.05 * i, 0.45, 0.15 + 0.05 * i));
  std::vector<Triangle> expected;
  const tinygltf::Model out = unwrap(triangles_model(s, expected), "non_manifold", s.faces.size(),
                                     "mesh 0, primitive 0: not a manifold, consistently oriented mesh (edge (" +
                                       std::to_string(a) + ", " + std::to_string(b) + ") is shared by 5 faces");
  // every triangle of the file kept, the fins' too (the grid's face up; the fins stand)
  expect_triangle_list(out, 0, expected, std::size_t(2 * n * n));
}

TEST_P(Gltf_readers, faces_dropped_by_the_repair_keep_their_place)
{
  // a triangle with a repeated corner and one repeated reversed: the repair
  // drops them from the mesh it unwraps, the output keeps them (the first
  // with the UVs of its corners' positions, the second those of its twin)
  const int n = 8;
  Soup s = wavy_grid(n);
  s.add_triangle(0, 1, 1);
  s.add_triangle(s.faces[10][2], s.faces[10][1], s.faces[10][0]);
  std::vector<Triangle> expected;
  const tinygltf::Model out =
    unwrap(triangles_model(s, expected), "dropped_faces", std::size_t(2 * n * n), "repaired as a polygon soup");
  expect_triangle_list(out, 0, expected, std::size_t(2 * n * n));
  // the reversed copy of triangle 10 has its UVs, corner by corner
  ASSERT_EQ(out.meshes.size(), 1u);
  const tinygltf::Primitive& p = out.meshes[0].primitives[0];
  const std::vector<std::uint32_t> idx = primitive_indices(out, p);
  ASSERT_EQ(idx.size(), 3 * s.faces.size());
  const int uv = p.attributes.at("TEXCOORD_0");
  const std::size_t twin = s.faces.size() - 1;
  for(std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(accessor_floats(out, uv, idx[3 * twin + k]), accessor_floats(out, uv, idx[3 * 10 + 2 - k])) << "corner " << k;
}

TEST_P(Gltf_readers, triangle_strip_is_read_with_its_winding)
{
  // one strip over the rows of a wavy grid, joined by triangles with a
  // repeated index; every triangle faces up once the odd ones are turned
  const int n = 8;
  const Soup s = wavy_grid(n);
  auto v = [n](int i, int j) { return std::uint16_t(j * (n + 1) + i); };
  std::vector<std::uint16_t> strip;
  std::vector<Triangle> expected;
  for(int j = 0; j < n; ++j)
  {
    if(j > 0) strip.insert(strip.end(), {v(n, j - 1), v(0, j + 1)}); // join: 4 triangles with a repeated index
    for(int i = 0; i <= n; ++i) strip.insert(strip.end(), {v(i, j + 1), v(i, j)});
    for(int i = 0; i < n; ++i)
    {
      expected.push_back(corners(s.points, v(i, j + 1), v(i, j), v(i + 1, j + 1)));
      expected.push_back(corners(s.points, v(i, j), v(i + 1, j), v(i + 1, j + 1)));
    }
  }
  tinygltf::Model m = new_model();
  const tinygltf::Primitive p = primitive(m, s.points, strip, TINYGLTF_MODE_TRIANGLE_STRIP);
  const tinygltf::Model out = unwrap(model_of({p}, m), "strip", 2 * n * n,
                                     "mesh 0, primitive 0: a triangle strip (mode 5), read as its triangles and "
                                     "written back as a list of triangles (mode 4)");
  expect_triangle_list(out, 0, expected, expected.size());
}

TEST_P(Gltf_readers, triangle_fan_is_read_as_triangles)
{
  // a bumpy disk as a fan without indices: center first, the ring counter-clockwise, closed by its first point again
  const int sectors = 24;
  std::vector<Soup::Point> points = {{0., 0., 0.3}};
  for(int k = 0; k <= sectors; ++k)
  {
    const double angle = 2. * M_PI * (k % sectors) / sectors;
    points.push_back({std::cos(angle), std::sin(angle), 0.1 * std::sin(3. * angle)});
  }
  std::vector<Triangle> expected;
  for(std::size_t k = 1; k <= std::size_t(sectors); ++k) expected.push_back(corners(points, k, k + 1, 0));
  tinygltf::Model m = new_model();
  const tinygltf::Primitive p = primitive(m, points, {}, TINYGLTF_MODE_TRIANGLE_FAN);
  const tinygltf::Model out = unwrap(model_of({p}, m), "fan", std::size_t(sectors), "a triangle fan (mode 6)");
  expect_triangle_list(out, 0, expected, expected.size());
}

INSTANTIATE_TEST_SUITE_P(Formats, Gltf_readers, ::testing::Values("gltf", "glb"));

} // namespace

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if(const char* program = std::getenv("UV_UNWRAP")) uv_unwrap_program = program;
  return RUN_ALL_TESTS();
}
