// uv_unwrap --atlas on generated files (two OBJ meshes of different sizes and
// a glTF of four primitives), measured on what it wrote, independently of the
// library: every mesh's UVs in [0,1] of its page, no flipped triangle, and on
// the combined UVs of all the meshes of a page no crossing of UV borders and
// no texel covered twice; the texel density (UV length per 3D length) of
// every mesh the one reported, within 1%; the statistics give each mesh's
// page; the glTF passes the Khronos glTF-Validator. At 1.3 times the largest
// density that fits one page the scene goes on several pages, each valid,
// and --svg frames every page. --uv-set 1 adds TEXCOORD_1 to the glTF
// (TEXCOORD_0 kept) and writes an OBJ's one set with a warning;
// --texels-per-unit without --atlas is refused. Stacked parts
// (--stacking-tolerance): ten OBJ copies of a mesh moved rigidly and a glb
// whose mesh ten nodes use, plus a rigid copy of it as a mesh of its own,
// take the texels of one copy each: the charts packed and the density those
// of the scene without the copies, every copy's UVs its original's, the
// meshes with texels of their own a valid atlas.
//   UV_UNWRAP=<uv_unwrap executable> test_scene_atlas_cli
#include "tests/gltf_test_files.h"

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace uv_unwrap_test;
std::string uv_unwrap_program;

using P3 = std::array<double, 3>;
using P2 = std::array<double, 2>;

// One mesh as written: 3D corners and UV corners of each triangle.
struct Written_mesh
{
  std::string name;
  int page = -1;
  std::vector<std::array<P3, 3>> xyz;
  std::vector<std::array<P2, 3>> uv;
};

// The rotation by `angle` about the unit axis `u` (Rodrigues), applied to p.
P3 rotated(const P3& p, const P3& u, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle), d = u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
  const P3 x{u[1] * p[2] - u[2] * p[1], u[2] * p[0] - u[0] * p[2], u[0] * p[1] - u[1] * p[0]};
  return {c * p[0] + s * x[0] + (1. - c) * d * u[0], c * p[1] + s * x[1] + (1. - c) * d * u[1],
          c * p[2] + s * x[2] + (1. - c) * d * u[2]};
}

// A rigid motion that changes with k (k = 0: none): a turn about a tilted axis, then a shift.
P3 moved(const P3& p, int k)
{
  if(k == 0) return p;
  const double n = std::sqrt(1. + 0.09 * k * k + 0.25);
  const P3 q = rotated(p, {1. / n, 0.3 * k / n, 0.5 / n}, 0.7 * k);
  return {q[0] + 3. * k, q[1] - 1.5 * k, q[2] + 0.5};
}

// A bumpy open cylinder of radius r and height its circumference: it needs a seam, and its chart is
// squarish; moved by moved(·, copy).
void write_cylinder_obj(const fs::path& file, double r, int n, int copy = 0)
{
  std::ofstream out(file);
  out.precision(17);
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i < 2 * n; ++i)
    {
      const double a = M_PI * i / n, z = 2. * M_PI * r * j / n, rr = r * (1. + 0.1 * std::sin(3. * a) * std::sin(2. * z));
      const P3 p = moved({rr * std::cos(a), rr * std::sin(a), z}, copy);
      out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < 2 * n; ++i)
    {
      const int a = j * 2 * n + i + 1, b = j * 2 * n + (i + 1) % (2 * n) + 1, c = a + 2 * n, d = b + 2 * n;
      out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
}

// A glTF of `count` bumpy grids of growing sizes (primitives of one mesh), each with a TEXCOORD_0 of its own.
void write_grids_gltf(const fs::path& file, int count)
{
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.buffers.emplace_back();
  tinygltf::Mesh mesh;
  for(int k = 0; k < count; ++k)
  {
    const int n = 10;
    const float size = 0.7f + 0.15f * float(k);
    std::vector<float> pos, tex;
    std::vector<std::uint16_t> idx;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
      {
        const float x = size * float(i) / n, y = size * float(j) / n;
        pos.insert(pos.end(), {x, y, 3.f * k + 0.4f * size * std::sin(3.f * x / size) * std::cos(2.f * y / size)});
        tex.insert(tex.end(), {float(i) / n, float(j) / n});
      }
    add_grid_triangles(idx, n, n);
    tinygltf::Primitive p = triangle_primitive(m, pos, idx);
    add_float_attribute(m, p, "TEXCOORD_0", tex, TINYGLTF_TYPE_VEC2);
    mesh.primitives.push_back(p);
  }
  m.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&m, file.string(), true, true, true, file.extension() == ".glb"));
}

// A glb of a bumpy grid (mesh 0) that `instances` nodes use, each with its
// own rotation and translation, and of a rigid copy of it, moved in its
// positions (mesh 1, one node).
void write_instanced_gltf(const fs::path& file, int instances)
{
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.buffers.emplace_back();
  tinygltf::Scene scene;
  for(int copy = 0; copy < 2; ++copy)
  {
    const int n = 12;
    std::vector<float> pos;
    std::vector<std::uint16_t> idx;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
      {
        const double x = 1.2 * i / n, y = 0.9 * j / n;
        const P3 p = moved({x, y, 0.3 * std::sin(4. * x) * std::cos(3. * y)}, 3 * copy);
        pos.insert(pos.end(), {float(p[0]), float(p[1]), float(p[2])});
      }
    add_grid_triangles(idx, n, n);
    const tinygltf::Primitive p = triangle_primitive(m, pos, idx);
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(p);
    m.meshes.push_back(mesh);
    for(int k = 0; k < (copy == 0 ? instances : 1); ++k)
    {
      tinygltf::Node node;
      node.mesh = copy;
      const double half = 0.35 * k; // a turn about z by 0.7 k
      node.rotation = {0., 0., std::sin(half), std::cos(half)};
      node.translation = {2. * k, 5. * copy, 0.};
      scene.nodes.push_back(int(m.nodes.size()));
      m.nodes.push_back(node);
    }
  }
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&m, file.string(), true, true, true, true));
}

Written_mesh read_obj(const fs::path& file)
{
  Written_mesh w;
  w.name = file.filename().string();
  std::ifstream in(file);
  std::vector<P3> v;
  std::vector<P2> vt;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v") { P3 p; s >> p[0] >> p[1] >> p[2]; v.push_back(p); }
    else if(tag == "vt") { P2 p; s >> p[0] >> p[1]; vt.push_back(p); }
    else if(tag == "f")
    {
      std::array<P3, 3> x;
      std::array<P2, 3> t;
      for(int k = 0; k < 3; ++k)
      {
        std::string c;
        s >> c;
        const std::size_t slash = c.find('/');
        x[k] = v.at(std::size_t(std::stol(c.substr(0, slash)) - 1));
        t[k] = vt.at(std::size_t(std::stol(c.substr(slash + 1)) - 1));
      }
      w.xyz.push_back(x);
      w.uv.push_back(t);
    }
  }
  return w;
}

std::vector<Written_mesh> read_gltf(const fs::path& file, int uv_set)
{
  const tinygltf::Model m = load_gltf(file);
  std::vector<Written_mesh> out;
  for(const tinygltf::Mesh& mesh : m.meshes)
    for(const tinygltf::Primitive& p : mesh.primitives)
    {
      Written_mesh w;
      w.name = file.filename().string() + " primitive " + std::to_string(out.size());
      const auto at = p.attributes.find("TEXCOORD_" + std::to_string(uv_set));
      EXPECT_NE(at, p.attributes.end()) << w.name << " has no TEXCOORD_" << uv_set;
      if(at == p.attributes.end()) continue;
      const std::vector<std::uint32_t> idx = primitive_indices(m, p);
      for(std::size_t i = 0; i + 2 < idx.size(); i += 3)
      {
        std::array<P3, 3> x;
        std::array<P2, 3> t;
        for(int k = 0; k < 3; ++k)
        {
          const auto q = accessor_floats(m, p.attributes.at("POSITION"), idx[i + std::size_t(k)]);
          const auto u = accessor_floats(m, at->second, idx[i + std::size_t(k)]);
          x[k] = {q[0], q[1], q[2]};
          t[k] = {u[0], 1. - u[1]}; // glTF's v points down
        }
        w.xyz.push_back(x);
        w.uv.push_back(t);
      }
      out.push_back(w);
    }
  return out;
}

double signed_area(const std::array<P2, 3>& t)
{
  return 0.5 * ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]));
}

double area_3d(const std::array<P3, 3>& t)
{
  const P3 a{t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
  const P3 b{t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
  const P3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

// UV border segments of all the meshes: triangle sides whose 3D edge has no
// other side with the same two UVs (keyed by mesh and 3D end points).
std::vector<std::array<P2, 2>> border_segments(const std::vector<const Written_mesh*>& meshes)
{
  std::map<std::tuple<std::size_t, P3, P3>, std::vector<std::array<P2, 2>>> sides;
  for(std::size_t m = 0; m < meshes.size(); ++m)
    for(std::size_t f = 0; f < meshes[m]->xyz.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        P3 a = meshes[m]->xyz[f][k], b = meshes[m]->xyz[f][(k + 1) % 3];
        P2 ua = meshes[m]->uv[f][k], ub = meshes[m]->uv[f][(k + 1) % 3];
        if(b < a) { std::swap(a, b); std::swap(ua, ub); }
        sides[{m, a, b}].push_back({ua, ub});
      }
  std::vector<std::array<P2, 2>> out;
  for(const auto& [key, s] : sides)
    if(!(s.size() == 2 && s[0] == s[1])) out.insert(out.end(), s.begin(), s.end());
  return out;
}

double orient(const P2& a, const P2& b, const P2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

std::size_t crossings(const std::vector<std::array<P2, 2>>& s)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < s.size(); ++i)
    for(std::size_t j = i + 1; j < s.size(); ++j)
      if(orient(s[i][0], s[i][1], s[j][0]) * orient(s[i][0], s[i][1], s[j][1]) < 0 &&
         orient(s[j][0], s[j][1], s[i][0]) * orient(s[j][0], s[j][1], s[i][1]) < 0)
        ++n;
  return n;
}

// Centres of an n x n raster of the page strictly inside two or more triangles.
std::size_t doubly_covered(const std::vector<const Written_mesh*>& meshes, int n)
{
  std::vector<unsigned char> count(std::size_t(n) * std::size_t(n), 0);
  std::size_t twice = 0;
  for(const Written_mesh* w : meshes)
    for(const auto& t : w->uv)
    {
      const double sign = signed_area(t) > 0 ? 1. : -1.;
      const int x0 = std::max(0, int(std::floor(std::min({t[0][0], t[1][0], t[2][0]}) * n))),
                x1 = std::min(n - 1, int(std::ceil(std::max({t[0][0], t[1][0], t[2][0]}) * n))),
                y0 = std::max(0, int(std::floor(std::min({t[0][1], t[1][1], t[2][1]}) * n))),
                y1 = std::min(n - 1, int(std::ceil(std::max({t[0][1], t[1][1], t[2][1]}) * n)));
      for(int y = y0; y <= y1; ++y)
        for(int x = x0; x <= x1; ++x)
        {
          const P2 p{(x + 0.5) / n, (y + 0.5) / n};
          if(sign * orient(t[0], t[1], p) > 0 && sign * orient(t[1], t[2], p) > 0 && sign * orient(t[2], t[0], p) > 0)
            if(++count[std::size_t(y) * std::size_t(n) + std::size_t(x)] == 2) ++twice;
        }
    }
  return twice;
}

// Runs uv_unwrap --atlas on the scene; the meshes it wrote, with their pages from the JSON lines.
std::vector<Written_mesh> run_scene(const fs::path& dir, const std::vector<fs::path>& inputs,
                                    const std::string& extra, int uv_set, nlohmann::json& first_stats)
{
  fs::remove_all(dir / "out");
  std::string command = "\"" + uv_unwrap_program + "\"";
  for(const fs::path& p : inputs) command += " \"" + p.string() + "\"";
  const fs::path jsonl = dir / "stats.jsonl";
  command += " --atlas -q --output-dir \"" + (dir / "out").string() + "\" --jsonl \"" + jsonl.string() + "\" " + extra;
  EXPECT_EQ(exit_status(command), 0) << command;
  std::vector<Written_mesh> meshes;
  std::ifstream in(jsonl);
  std::string line;
  bool first = true;
  while(std::getline(in, line))
  {
    const nlohmann::json s = nlohmann::json::parse(line);
    if(first) first_stats = s;
    first = false;
    EXPECT_EQ(s["status"], "ok") << line;
    const fs::path output = s["output"].get<std::string>();
    std::vector<Written_mesh> written;
    if(output.extension() == ".obj") written.push_back(read_obj(output));
    else written = read_gltf(output, uv_set);
    const auto& pages = s["atlas"]["pages"];
    EXPECT_EQ(pages.size(), written.size()) << "one page per mesh in the statistics of " << output;
    for(std::size_t k = 0; k < written.size() && k < pages.size(); ++k)
    {
      written[k].page = pages[k].get<int>();
      meshes.push_back(written[k]);
    }
    if(output.extension() != ".obj") expect_validator_accepts(output);
  }
  return meshes;
}

// Every page valid on its combined UVs; the density of every mesh `texels_per_unit` within 1%.
// \pre `meshes` are those with texels of their own (no stacked copy)
void expect_valid_pages(const std::vector<Written_mesh>& meshes, int pages, double texels_per_unit, int size)
{
  for(int page = 0; page < pages; ++page)
  {
    std::vector<const Written_mesh*> on_page;
    for(const Written_mesh& w : meshes)
      if(w.page == page) on_page.push_back(&w);
    EXPECT_FALSE(on_page.empty()) << "page " << page << " holds no mesh";
    for(const Written_mesh* w : on_page)
    {
      double uv_area = 0., xyz_area = 0.;
      std::size_t flipped = 0;
      bool inside = true;
      for(std::size_t f = 0; f < w->uv.size(); ++f)
      {
        const double a = signed_area(w->uv[f]);
        flipped += !(a > 0.);
        uv_area += std::abs(a);
        xyz_area += area_3d(w->xyz[f]);
        for(const P2& p : w->uv[f]) inside = inside && p[0] >= 0. && p[0] <= 1. && p[1] >= 0. && p[1] <= 1.;
      }
      EXPECT_TRUE(inside) << w->name << ": UVs outside [0,1]";
      EXPECT_EQ(flipped, 0u) << w->name;
      const double density = size * std::sqrt(uv_area / xyz_area); // texels per unit of length
      EXPECT_NEAR(density / texels_per_unit, 1., 0.01) << w->name << ": " << density << " texels per unit";
    }
    EXPECT_EQ(crossings(border_segments(on_page)), 0u) << "page " << page;
    EXPECT_EQ(doubly_covered(on_page, 1024), 0u) << "page " << page << ": texels covered twice";
  }
}

class Scene_atlas_cli : public ::testing::Test
{
protected:
  fs::path dir;
  std::vector<fs::path> inputs;
  void SetUp() override
  {
    ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
    dir = fs::temp_directory_path() / ("uv_unwrap_scene_atlas_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_cylinder_obj(dir / "small.obj", 0.5, 8);
    write_cylinder_obj(dir / "large.obj", 0.7, 10);
    write_grids_gltf(dir / "grids.glb", 4);
    inputs = {dir / "small.obj", dir / "large.obj", dir / "grids.glb"};
  }
  void TearDown() override { if(!std::getenv("KEEP")) fs::remove_all(dir); }
};

TEST_F(Scene_atlas_cli, one_page_at_the_largest_density)
{
  nlohmann::json stats;
  const std::vector<Written_mesh> meshes = run_scene(dir, inputs, "--atlas-size 256 --padding 2", 0, stats);
  ASSERT_EQ(meshes.size(), 6u) << "two OBJ meshes and four primitives";
  EXPECT_EQ(stats["atlas"]["page_count"], 1);
  const double tpu = stats["atlas"]["texels_per_unit"].get<double>();
  EXPECT_GT(tpu, 0.);
  for(const auto& page : stats["atlas"]["page_measures"])
  {
    EXPECT_EQ(page["flipped_faces"], 0);
    EXPECT_EQ(page["border_crossings"], 0);
    EXPECT_EQ(page["overlap_area"], 0.);
  }
  expect_valid_pages(meshes, 1, tpu, 256);
}

TEST_F(Scene_atlas_cli, pages_when_one_is_not_enough)
{
  nlohmann::json stats;
  run_scene(dir, inputs, "--atlas-size 256", 0, stats);
  const double one_page = stats["atlas"]["texels_per_unit"].get<double>();
  const fs::path svg = dir / "pages.svg";
  const std::vector<Written_mesh> meshes = run_scene(
    dir, inputs, "--atlas-size 256 --texels-per-unit " + std::to_string(1.3 * one_page) + " --svg \"" + svg.string() + "\"",
    0, stats);
  const int pages = stats["atlas"]["page_count"].get<int>();
  // the SVG frames every page
  std::ifstream in(svg);
  const std::string picture((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for(int page = 0; page <= pages; ++page)
    EXPECT_EQ(picture.find("<rect id=\"page-" + std::to_string(page) + "\"") != std::string::npos, page < pages)
      << "page " << page << " of " << pages << " in the SVG";
  EXPECT_GE(pages, 2) << "1.3 times the largest density that fits one page";
  EXPECT_NEAR(stats["atlas"]["texels_per_unit"].get<double>(), 1.3 * one_page, 1e-6 * one_page);
  expect_valid_pages(meshes, pages, 1.3 * one_page, 256);
}

TEST_F(Scene_atlas_cli, lightmap_set_beside_the_material_set)
{
  nlohmann::json stats;
  const std::vector<Written_mesh> meshes = run_scene(dir, inputs, "--atlas-size 256 --uv-set 1", 1, stats);
  ASSERT_EQ(meshes.size(), 6u);
  expect_valid_pages(meshes, 1, stats["atlas"]["texels_per_unit"].get<double>(), 256);
  // the glTF keeps its TEXCOORD_0 as it was: the grid's own (i/n, j/n) (v read as 1 - v: still tenths)
  for(const Written_mesh& w : read_gltf(dir / "out" / "grids_uv.glb", 0))
    for(const auto& t : w.uv)
      for(const P2& p : t)
        EXPECT_NEAR(p[0] * 10., std::round(p[0] * 10.), 1e-4) << w.name << ": TEXCOORD_0 changed";
  EXPECT_TRUE(has_warning(stats, "one set of texture coordinates")) << stats.dump();
}

TEST_F(Scene_atlas_cli, stacked_copies_take_the_texels_of_one)
{
  std::vector<fs::path> scene, alone;
  for(int k = 0; k < 10; ++k)
  {
    scene.push_back(dir / ("copy" + std::to_string(k) + ".obj"));
    write_cylinder_obj(scene.back(), 0.5, 8, k);
  }
  write_instanced_gltf(dir / "instances.glb", 10);
  scene.push_back(dir / "instances.glb");
  alone = {scene.front(), scene.back()};
  const std::string options = "--atlas-size 256 --padding 2 --stacking-tolerance 1e-4";
  nlohmann::json stats;
  const std::vector<Written_mesh> one = run_scene(dir, alone, options, 0, stats);
  ASSERT_EQ(one.size(), 3u) << "one cylinder, the glb's two meshes";
  const double one_density = stats["atlas"]["texels_per_unit"].get<double>();
  const int one_charts = stats["atlas"]["charts_packed"].get<int>();

  const std::vector<Written_mesh> meshes = run_scene(dir, scene, options, 0, stats);
  ASSERT_EQ(meshes.size(), 12u) << "ten cylinders, the glb's two meshes (its instances are nodes)";
  EXPECT_EQ(stats["atlas"]["charts_packed"], one_charts) << "the copies' charts are not packed again";
  const double density = stats["atlas"]["texels_per_unit"].get<double>();
  EXPECT_NEAR(density, one_density, 1e-9 * one_density) << "the copies take no texels";
  EXPECT_EQ(stats["atlas"]["stacked_on"], nlohmann::json::array({nullptr}));
  // read every input's statistics back: who is stacked on whom
  std::ifstream in(dir / "stats.jsonl");
  std::vector<nlohmann::json> lines;
  for(std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), scene.size());
  for(std::size_t k = 1; k < 10; ++k)
  {
    ASSERT_EQ(lines[k]["atlas"]["stacked_on"].size(), 1u);
    EXPECT_EQ(lines[k]["atlas"]["stacked_on"][0], scene.front().string()) << scene[k];
    EXPECT_EQ(lines[k]["charts"], lines[0]["charts"]);
  }
  const auto& glb = lines[10]["atlas"]["stacked_on"];
  ASSERT_EQ(glb.size(), 2u);
  EXPECT_TRUE(glb[0].is_null());
  EXPECT_EQ(glb[1], scene.back().string() + ", mesh 0, primitive 0") << "the rigid copy of the glb's mesh";
  // the copies' UVs are their originals', corner by corner; the others a valid atlas
  for(std::size_t k = 1; k < 10; ++k)
  {
    EXPECT_EQ(meshes[k].uv, meshes[0].uv) << meshes[k].name;
    EXPECT_EQ(meshes[k].page, meshes[0].page);
  }
  EXPECT_EQ(meshes[11].uv, meshes[10].uv) << "the glb's copy";
  const std::vector<Written_mesh> own{meshes[0], meshes[10]};
  expect_valid_pages(own, 1, density, 256);
  for(const auto& page : stats["atlas"]["page_measures"])
  {
    EXPECT_EQ(page["flipped_faces"], 0);
    EXPECT_EQ(page["border_crossings"], 0);
    EXPECT_EQ(page["overlap_area"], 0.);
  }
  // without the option every copy has texels of its own: a lower density
  run_scene(dir, scene, "--atlas-size 256 --padding 2", 0, stats);
  EXPECT_LT(stats["atlas"]["texels_per_unit"].get<double>(), 0.5 * density);
  EXPECT_NE(exit_status("\"" + uv_unwrap_program + "\" \"" + scene[0].string() + "\" -q -o \"" +
                        (dir / "x.obj").string() + "\" --stacking-tolerance 1e-4 2>/dev/null"),
            0)
    << "--stacking-tolerance without --atlas";
}

TEST_F(Scene_atlas_cli, density_without_atlas_is_refused)
{
  EXPECT_NE(exit_status("\"" + uv_unwrap_program + "\" \"" + inputs[0].string() + "\" -q -o \"" +
                        (dir / "x.obj").string() + "\" --texels-per-unit 10 2>/dev/null"),
            0);
  EXPECT_FALSE(fs::exists(dir / "x.obj"));
}

} // namespace

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if(const char* program = std::getenv("UV_UNWRAP")) uv_unwrap_program = program;
  return RUN_ALL_TESTS();
}
