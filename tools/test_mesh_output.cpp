// The output files of uv_unwrap (mesh_output.h): an OBJ read without repair
// comes back with its normals, names, materials, smoothing groups and face
// order unchanged, and only texture coordinates added; a PLY carries each
// face's UVs as a texcoord list.
#include "mesh_input.h"
#include "mesh_output.h"

#include <CGAL/Surface_mesh_parameterization/cut_and_parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterization_metrics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
using Mesh = mesh_input::Mesh;
using Point_2 = mesh_input::Kernel::Point_2;

// A box of 6 quads in two groups with two materials, per-face normals,
// smoothing groups, an old texture coordinate and relative indices.
const char* const box_obj =
  "# box\n"
  "mtllib box.mtl\n"
  "o Box\n"
  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
  "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
  "vt 0.5 0.5\n"
  "g caps\n"
  "usemtl red\n"
  "s off\n"
  "f 1//1 4//1 3//1 2//1\n"
  "f 5//2 6//2 7//2 8//2\n"
  "g sides\n"
  "usemtl blue\n"
  "s 1\n"
  "f 1/1/3 2/1/3 6/1/3 5/1/3\n"
  "f -7//4 -6//4 -2//4 -3//4\n"
  "f 3//5 4//5 8//5 7//5\n"
  "f 4//6 1//6 5//6 8//6\n";

std::vector<std::string> lines_of(const std::string& file)
{
  std::ifstream in(file);
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string keyword(const std::string& line)
{
  std::istringstream words(line);
  std::string k;
  words >> k;
  return k;
}

struct Unwrapped
{
  Mesh mesh;
  mesh_input::Input_report report;
  Mesh::Property_map<Mesh::Halfedge_index, Point_2> uv;
};

// Reads `file` as uv_unwrap does and unwraps it with the defaults.
void unwrap(const std::string& file, Unwrapped& u)
{
  mesh_input::read_input_mesh(file, u.mesh, u.report);
  auto seams = u.mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  u.uv = u.mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  const auto result = SMP::cut_and_parameterize(u.mesh, seams, u.uv);
  ASSERT_TRUE(result.ok()) << SMP::error_message(result.error);
}

class Mesh_output : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir = fs::temp_directory_path() /
          ("cut_param_mesh_output_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir);
    input = (dir / "box.obj").string();
    std::ofstream(input) << box_obj;
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
  std::string input;
};

TEST_F(Mesh_output, obj_keeps_every_line_but_texture_coordinates_and_faces)
{
  Unwrapped u;
  ASSERT_NO_FATAL_FAILURE(unwrap(input, u));
  ASSERT_EQ(u.report.face_origin.size(), num_faces(u.mesh));
  const std::string output = (dir / "box_uv.obj").string();
  std::string problem;
  ASSERT_TRUE(mesh_output::write_obj_keeping_input(input, output, u.mesh, u.uv, u.report.face_origin, problem))
    << problem;

  const std::vector<std::string> in = lines_of(input), out = lines_of(output);
  std::vector<std::string> kept_in, kept_out;
  for(const std::string& l : in)
    if(keyword(l) != "vt" && keyword(l) != "f") kept_in.push_back(l);
  for(const std::string& l : out)
    if(keyword(l) != "vt" && keyword(l) != "f") kept_out.push_back(l);
  EXPECT_EQ(kept_in, kept_out); // normals, o/g names, mtllib/usemtl, s, comments: same lines, same order

  // Each output face lies in the group and material of its polygon: the
  // non-face line before every run of faces is the same as in the input.
  auto context_of_faces = [](const std::vector<std::string>& lines) {
    std::vector<std::string> context;
    std::string last;
    for(const std::string& l : lines)
    {
      const std::string k = keyword(l);
      if(k == "f") context.push_back(last);
      else if(k != "vt") last = l;
    }
    return context;
  };
  std::vector<std::string> in_context = context_of_faces(in), out_context = context_of_faces(out);
  out_context.erase(std::unique(out_context.begin(), out_context.end()), out_context.end());
  in_context.erase(std::unique(in_context.begin(), in_context.end()), in_context.end());
  EXPECT_EQ(in_context, out_context);

  // Faces: the triangles of each quad in the quad's place, each corner with
  // the quad's normal, a texture coordinate equal to the UV map's.
  std::vector<std::array<double, 2>> vt;
  std::vector<std::vector<std::array<long, 3>>> out_faces;
  for(const std::string& l : out)
  {
    std::istringstream words(l);
    std::string k, token;
    words >> k;
    if(k == "vt")
    {
      std::array<double, 2> uv;
      words >> uv[0] >> uv[1];
      vt.push_back(uv);
    }
    if(k != "f") continue;
    std::vector<std::array<long, 3>> corners;
    while(words >> token)
    {
      std::array<long, 3> c = {0, 0, 0};
      ASSERT_EQ(std::sscanf(token.c_str(), "%ld/%ld/%ld", &c[0], &c[1], &c[2]), 3) << "corner " << token;
      corners.push_back(c);
    }
    out_faces.push_back(corners);
  }
  ASSERT_EQ(out_faces.size(), num_faces(u.mesh));
  ASSERT_EQ(out_faces.size(), 12u);
  const long quad_normal[6] = {1, 2, 3, 4, 5, 6};
  std::size_t k = 0;
  // the faces of polygon p, in the mesh's order, are the output's faces 2p and 2p+1
  std::vector<std::vector<Mesh::Face_index>> faces_of(6);
  for(Mesh::Face_index f : faces(u.mesh)) faces_of[u.report.face_origin[std::size_t(f)]].push_back(f);
  for(std::size_t p = 0; p < 6; ++p)
  {
    ASSERT_EQ(faces_of[p].size(), 2u);
    for(Mesh::Face_index f : faces_of[p])
    {
      const auto& corners = out_faces[k++];
      ASSERT_EQ(corners.size(), 3u);
      std::size_t c = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, u.mesh), u.mesh))
      {
        EXPECT_EQ(corners[c][0], long(std::size_t(target(h, u.mesh))) + 1);
        EXPECT_EQ(corners[c][2], quad_normal[p]) << "polygon " << p;
        ASSERT_GE(corners[c][1], 1);
        ASSERT_LE(corners[c][1], long(vt.size()));
        EXPECT_NEAR(vt[std::size_t(corners[c][1] - 1)][0], u.uv[h].x(), 1e-15);
        EXPECT_NEAR(vt[std::size_t(corners[c][1] - 1)][1], u.uv[h].y(), 1e-15);
        ++c;
      }
    }
  }
}

TEST_F(Mesh_output, obj_refuses_a_file_that_does_not_match)
{
  Unwrapped u;
  ASSERT_NO_FATAL_FAILURE(unwrap(input, u));
  std::ofstream(input) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"; // the file changed since it was read
  std::string problem;
  EXPECT_FALSE(mesh_output::write_obj_keeping_input(input, (dir / "out.obj").string(), u.mesh, u.uv,
                                                    u.report.face_origin, problem));
  EXPECT_FALSE(problem.empty());
}

TEST_F(Mesh_output, repaired_input_has_no_face_origin)
{
  const std::string twice = (dir / "twice.obj").string();
  Unwrapped u;
  std::ofstream(twice) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n"; // the same face twice
  mesh_input::read_input_mesh(twice, u.mesh, u.report);
  EXPECT_TRUE(u.report.repaired);
  EXPECT_TRUE(u.report.face_origin.empty());
}

TEST_F(Mesh_output, ply_carries_each_face_uvs_as_texcoord)
{
  Unwrapped u;
  ASSERT_NO_FATAL_FAILURE(unwrap(input, u));
  const std::string output = (dir / "box_uv.ply").string();
  ASSERT_TRUE(mesh_output::write_ply_with_texcoords(output, u.mesh, u.uv));
  std::ifstream in(output);
  std::string line;
  std::vector<std::string> header;
  while(std::getline(in, line) && line != "end_header") header.push_back(line);
  ASSERT_EQ(line, "end_header");
  EXPECT_NE(std::find(header.begin(), header.end(), "element vertex 8"), header.end());
  EXPECT_NE(std::find(header.begin(), header.end(), "element face 12"), header.end());
  EXPECT_NE(std::find(header.begin(), header.end(), "property list uchar float texcoord"), header.end());
  for(auto v : vertices(u.mesh))
  {
    double x, y, z;
    ASSERT_TRUE(in >> x >> y >> z);
    EXPECT_EQ(x, u.mesh.point(v).x());
    EXPECT_EQ(y, u.mesh.point(v).y());
    EXPECT_EQ(z, u.mesh.point(v).z());
  }
  for(Mesh::Face_index f : faces(u.mesh))
  {
    int n = 0, m = 0;
    ASSERT_TRUE(in >> n);
    ASSERT_EQ(n, 3);
    std::size_t index[3];
    for(std::size_t& i : index) in >> i;
    ASSERT_TRUE(in >> m);
    ASSERT_EQ(m, 6);
    int c = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, u.mesh), u.mesh))
    {
      double s, t;
      ASSERT_TRUE(in >> s >> t);
      EXPECT_EQ(index[c], std::size_t(target(h, u.mesh)));
      EXPECT_NEAR(s, u.uv[h].x(), 1e-6);
      EXPECT_NEAR(t, u.uv[h].y(), 1e-6);
      ++c;
    }
  }
  std::string rest;
  EXPECT_FALSE(in >> rest) << "unexpected data after the faces: " << rest;
}

} // namespace
