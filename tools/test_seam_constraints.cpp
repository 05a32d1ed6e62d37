// Seam constraints from files (seam_constraints.h) and through uv_unwrap:
// selection files in CGAL's format are read (third line, pairs of vertex
// indices) and written back, bad files are refused with a message, indices
// refer to the input file also after a repair, PLY face and vertex
// properties and colors become λ factors; uv_unwrap keeps forced seams
// (--seams), never cuts forbidden edges (--forbid) and moves seams to where
// a painted PLY property makes them cheap (--lambda-from-ply-property);
// the split normals of an OBJ (split_normals.h) are seams with
// --hard-edge-angle, and only then.
//
//   UV_UNWRAP=<uv_unwrap executable> test_seam_constraints
#include "mesh_input.h"
#include "seam_constraints.h"
#include "split_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using seam_constraints::Constraint_error;
using seam_constraints::Edge_pairs;
using Mesh = mesh_input::Mesh;

std::string uv_unwrap_program;

fs::path fresh_directory(const std::string& name)
{
  const fs::path dir = fs::temp_directory_path() / ("cut_param_constraints_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& file, const std::string& text)
{
  std::ofstream out(file);
  out << text;
}

/// A spherical cap (a disk too curved to flatten without seams): a pole and
/// `rings` rings of `segments` vertices down to 165 degrees from the pole.
struct Cap
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> faces;
};

Cap spherical_cap(int rings = 16, int segments = 48)
{
  Cap cap;
  cap.points.push_back({0., 0., 1.});
  for(int k = 0; k < rings; ++k)
  {
    const double theta = 0.92 * M_PI * (k + 1) / rings;
    for(int j = 0; j < segments; ++j)
    {
      const double phi = 2. * M_PI * j / segments;
      cap.points.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  }
  auto at = [&](int k, int j) { return std::size_t(1 + k * segments + (j % segments)); };
  for(int j = 0; j < segments; ++j)
  {
    cap.faces.push_back({0, at(0, j), at(0, j + 1)});
    for(int k = 0; k + 1 < rings; ++k)
    {
      cap.faces.push_back({at(k, j), at(k + 1, j), at(k + 1, j + 1)});
      cap.faces.push_back({at(k, j), at(k + 1, j + 1), at(k, j + 1)});
    }
  }
  return cap;
}

/// The cap as an ASCII PLY with a float face property `cost` and vertex
/// colors (both from the functions given, of the face's centroid and of the
/// vertex).
template <typename FaceCost, typename VertexGray>
void write_cap_ply(const fs::path& file, const Cap& cap, FaceCost cost, VertexGray gray)
{
  std::ofstream out(file);
  out << "ply\nformat ascii 1.0\nelement vertex " << cap.points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << cap.faces.size() << "\nproperty list uchar int vertex_indices\nproperty float cost\n"
      << "end_header\n";
  for(const auto& p : cap.points)
  {
    const int g = int(std::lround(255. * gray(p)));
    out << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << g << ' ' << g << ' ' << g << '\n';
  }
  for(const auto& f : cap.faces)
  {
    std::array<double, 3> c{0., 0., 0.};
    for(std::size_t v : f)
      for(int i = 0; i < 3; ++i) c[i] += cap.points[v][i] / 3.;
    out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << ' ' << cost(c) << '\n';
  }
}

std::set<std::pair<std::size_t, std::size_t>> undirected(const Edge_pairs& pairs)
{
  std::set<std::pair<std::size_t, std::size_t>> s;
  for(auto [a, b] : pairs) s.insert({std::min(a, b), std::max(a, b)});
  return s;
}

int run_uv_unwrap(const std::string& arguments)
{
  const std::string command = "\"" + uv_unwrap_program + "\" " + arguments + " -q";
  return std::system(command.c_str());
}

// ------------------------------------------------------------ selection files

TEST(Selection_file, round_trip_in_cgal_format)
{
  const fs::path dir = fresh_directory("round_trip");
  const Edge_pairs edges{{0, 1}, {1, 5}, {42, 7}};
  ASSERT_TRUE(seam_constraints::write_selection_edges((dir / "s.selection.txt").string(), edges));
  std::ifstream in(dir / "s.selection.txt");
  std::string line1, line2, line3;
  std::getline(in, line1);
  std::getline(in, line2);
  std::getline(in, line3);
  EXPECT_EQ(line1, "");
  EXPECT_EQ(line2, "");
  EXPECT_EQ(line3, "0 1 1 5 42 7");
  EXPECT_EQ(seam_constraints::read_selection_edges((dir / "s.selection.txt").string()), edges);
  fs::remove_all(dir);
}

// a file as CGAL's demo writes it: selected vertices, faces, then edges
TEST(Selection_file, vertex_and_face_lines_are_skipped)
{
  const fs::path dir = fresh_directory("cgal_lines");
  write_text(dir / "lion.selection.txt", "3 9 27\n5 6\n10 11 11 12\n");
  const Edge_pairs expected{{10, 11}, {11, 12}};
  EXPECT_EQ(seam_constraints::read_selection_edges((dir / "lion.selection.txt").string()), expected);
  fs::remove_all(dir);
}

TEST(Selection_file, bad_files_are_refused_with_a_message)
{
  const fs::path dir = fresh_directory("bad");
  write_text(dir / "odd.txt", "\n\n1 2 3\n");
  write_text(dir / "word.txt", "\n\n1 two\n");
  write_text(dir / "negative.txt", "\n\n1 -2\n");
  write_text(dir / "short.txt", "1 2\n");
  for(const char* name : {"odd.txt", "word.txt", "negative.txt", "short.txt", "missing.txt"})
  {
    try
    {
      seam_constraints::read_selection_edges((dir / name).string());
      ADD_FAILURE() << name << " was accepted";
    }
    catch(const Constraint_error& e)
    {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

// ------------------------------------------------------------ edges of a mesh

TEST(Selection_edges, flag_the_mesh_edges_and_refuse_others)
{
  const fs::path dir = fresh_directory("flag");
  // two triangles sharing the edge between points 1 and 2 (0-based); in the
  // second file points 4 and 5 repeat 1 and 2, and a degenerate face makes
  // the soup repair run (it merges the repeated points)
  write_text(dir / "plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  write_text(dir / "repaired.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 5 4 6\nf 1 1 2\n");
  for(const char* name : {"plain.obj", "repaired.obj"})
  {
    Mesh mesh;
    mesh_input::Input_report report;
    mesh_input::read_input_mesh((dir / name).string(), mesh, report);
    ASSERT_EQ(report.repaired, std::string(name) == "repaired.obj");
    ASSERT_EQ(num_faces(mesh), 2u);
    auto flags = mesh.add_property_map<Mesh::Edge_index, bool>("e:flag", false).first;
    const std::size_t shared_a = 1, shared_b = std::string(name) == "plain.obj" ? 2 : 5; // file indices
    seam_constraints::flag_edges(mesh, report, {{shared_a, shared_b}}, name, flags);
    std::size_t flagged = 0;
    for(auto e : edges(mesh)) flagged += flags[e] ? 1 : 0;
    EXPECT_EQ(flagged, 1u) << name;
    EXPECT_EQ(undirected(seam_constraints::flagged_edges(mesh, report, flags)).size(), 1u) << name;
    EXPECT_THROW(seam_constraints::flag_edges(mesh, report, {{0, 3}}, name, flags), Constraint_error) << name;
    EXPECT_THROW(seam_constraints::flag_edges(mesh, report, {{0, 99}}, name, flags), Constraint_error) << name;
  }
  fs::remove_all(dir);
}

// ------------------------------------------------------------ PLY properties

TEST(Ply_lambda, face_property_vertex_colors_and_errors)
{
  const fs::path dir = fresh_directory("ply");
  const Cap cap = spherical_cap(4, 12);
  write_cap_ply(dir / "cap.ply", cap, [](const std::array<double, 3>& c) { return c[0] < 0. ? 0.5 : 4.; },
                [](const std::array<double, 3>& p) { return p[0] < 0. ? 0. : 1.; });
  Mesh mesh;
  mesh_input::Input_report report;
  mesh_input::read_input_mesh((dir / "cap.ply").string(), mesh, report);
  ASSERT_EQ(num_faces(mesh), cap.faces.size());

  const std::vector<double> cost = seam_constraints::face_lambda_from_ply((dir / "cap.ply").string(), mesh, report, "cost");
  const std::vector<double> gray = seam_constraints::face_lambda_from_ply((dir / "cap.ply").string(), mesh, report, "color");
  for(Mesh::Face_index f : faces(mesh))
  {
    double x = 0.;
    std::vector<double> corner_x;
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh))
    {
      x += mesh.point(v).x() / 3.;
      corner_x.push_back(mesh.point(v).x());
    }
    EXPECT_DOUBLE_EQ(cost[std::size_t(f)], x < 0. ? 0.5 : 4.);
    // each corner 0.1 (black) or 10 (white): the face takes 10^(2 mean(g) - 1)
    double mean_gray = 0.;
    for(double cx : corner_x) mean_gray += (cx < 0. ? 0. : 1.) / 3.;
    EXPECT_NEAR(gray[std::size_t(f)], std::pow(10., 2. * mean_gray - 1.), 1e-9);
  }
  EXPECT_THROW(seam_constraints::face_lambda_from_ply((dir / "cap.ply").string(), mesh, report, "missing"),
               Constraint_error);

  write_cap_ply(dir / "zero.ply", cap, [](const std::array<double, 3>&) { return 0.; },
                [](const std::array<double, 3>&) { return 0.5; });
  EXPECT_THROW(seam_constraints::face_lambda_from_ply((dir / "zero.ply").string(), mesh, report, "cost"),
               Constraint_error);
  write_text(dir / "cap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_THROW(seam_constraints::face_lambda_from_ply((dir / "cap.obj").string(), mesh, report, "cost"),
               Constraint_error);
  fs::remove_all(dir);
}

// ------------------------------------------------------------ through uv_unwrap

class Uv_unwrap_constraints : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_FALSE(uv_unwrap_program.empty()) << "set UV_UNWRAP to the uv_unwrap executable";
    dir = fresh_directory(::testing::UnitTest::GetInstance()->current_test_info()->name());
    cap = spherical_cap();
    // seams cheap (λ × 0.05) where x < 0, dear (× 20) elsewhere
    write_cap_ply(dir / "cap.ply", cap, [](const std::array<double, 3>& c) { return c[0] < 0. ? 0.05 : 20.; },
                  [](const std::array<double, 3>&) { return 0.5; });
  }
  void TearDown() override { fs::remove_all(dir); }

  /// 3D length of the edges of `pairs` on each side of the plane x = 0.
  std::pair<double, double> length_by_side(const Edge_pairs& pairs) const
  {
    double negative = 0., positive = 0.;
    for(auto [a, b] : pairs)
    {
      const auto& p = cap.points.at(a);
      const auto& q = cap.points.at(b);
      const double length = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                      (p[2] - q[2]) * (p[2] - q[2]));
      (p[0] + q[0] < 0. ? negative : positive) += length;
    }
    return {negative, positive};
  }

  fs::path dir;
  Cap cap;
};

TEST_F(Uv_unwrap_constraints, forbidden_edges_are_never_cut_and_forced_seams_kept)
{
  const std::string input = (dir / "cap.ply").string(), seams = (dir / "seams.txt").string();
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "a.obj").string() + "\" --save-seams \"" + seams + "\""), 0);
  const Edge_pairs first = seam_constraints::read_selection_edges(seams);
  ASSERT_FALSE(first.empty());

  // forbid every seam of the first run
  const std::string again = (dir / "again.txt").string();
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "b.obj").string() + "\" --forbid \"" + seams +
                          "\" --save-seams \"" + again + "\""), 0);
  const auto forbidden = undirected(first);
  const Edge_pairs second = seam_constraints::read_selection_edges(again);
  EXPECT_FALSE(second.empty());
  for(const auto& e : undirected(second)) EXPECT_EQ(forbidden.count(e), 0u) << e.first << "-" << e.second;

  // a selection file written here, in CGAL's format: its edges stay seams
  const std::string forced = (dir / "forced.selection.txt").string();
  write_text(forced, "0\n\n" + std::to_string(first[0].first) + " " + std::to_string(first[0].second) + "\n");
  const std::string kept = (dir / "kept.txt").string();
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "c.obj").string() + "\" --seams \"" + forced +
                          "\" --lambda 20 --save-seams \"" + kept + "\""), 0);
  EXPECT_EQ(undirected(seam_constraints::read_selection_edges(kept)).count(*undirected({first[0]}).begin()), 1u);

  // a pair that is no edge: refused with a message and a failure status
  write_text(dir / "bad.txt", "\n\n0 " + std::to_string(cap.points.size() - 1) + "\n");
  EXPECT_NE(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "d.obj").string() + "\" --forbid \"" +
                          (dir / "bad.txt").string() + "\""), 0);
}

TEST_F(Uv_unwrap_constraints, painted_property_moves_the_seams)
{
  const std::string input = (dir / "cap.ply").string();
  const std::string plain = (dir / "plain.txt").string(), painted = (dir / "painted.txt").string();
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "a.obj").string() + "\" --save-seams \"" + plain + "\""), 0);
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "b.obj").string() +
                          "\" --lambda-from-ply-property cost --save-seams \"" + painted + "\""), 0);
  const auto [plain_cheap, plain_dear] = length_by_side(seam_constraints::read_selection_edges(plain));
  const auto [cheap, dear] = length_by_side(seam_constraints::read_selection_edges(painted));
  ASSERT_GT(plain_cheap + plain_dear, 0.);
  // the seams go where the property makes them cheap
  EXPECT_GT(cheap, 4. * dear) << "with the property: " << cheap << " cheap, " << dear << " dear; without: "
                              << plain_cheap << ", " << plain_dear;
  EXPECT_LT(dear, plain_dear + 1e-12);
}

/// A flat 4 x 4 grid of quads in OBJ, whose left half's corners name the
/// normal 1 and right half's the normal 2: its normals are split along the
/// line x = 2 (4 edges), where the surface is flat.
void write_split_normal_grid(const fs::path& file)
{
  std::ofstream out(file);
  for(int j = 0; j <= 4; ++j)
    for(int i = 0; i <= 4; ++i) out << "v " << i << ' ' << j << " 0\n";
  out << "vn 0 0 1\nvn 0.28 0 0.96\n";
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i)
    {
      const int n = i < 2 ? 1 : 2, a = 1 + i + 5 * j;
      out << "f " << a << "//" << n << ' ' << a + 1 << "//" << n << ' ' << a + 6 << "//" << n << ' ' << a + 5 << "//" << n
          << '\n';
    }
}

/// The 4 edges of the line x = 2 of that grid, as pairs of its vertex indices.
std::set<std::pair<std::size_t, std::size_t>> split_line()
{
  std::set<std::pair<std::size_t, std::size_t>> line;
  for(std::size_t j = 0; j < 4; ++j) line.insert({2 + 5 * j, 2 + 5 * (j + 1)});
  return line;
}

TEST(Split_normals, the_edges_where_an_obj_splits_its_normals_are_flagged)
{
  const fs::path dir = fresh_directory("split_normals");
  write_split_normal_grid(dir / "grid.obj");
  Mesh mesh;
  mesh_input::Input_report report;
  mesh_input::read_input_mesh((dir / "grid.obj").string(), mesh, report);
  ASSERT_EQ(num_faces(mesh), 32u); // the quads triangulated: their diagonals are no split
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto forbidden = mesh.add_property_map<Mesh::Edge_index, bool>("e:forbidden", false).first;
  std::string warning;
  EXPECT_EQ(split_normals::flag_split_normal_edges((dir / "grid.obj").string(), mesh, report, seams, forbidden, warning),
            4u);
  EXPECT_TRUE(warning.empty());
  EXPECT_EQ(undirected(seam_constraints::flagged_edges(mesh, report, seams)), split_line());
}

TEST(Split_normals, uv_unwrap_cuts_them_with_hard_edge_angle_only)
{
  const fs::path dir = fresh_directory("split_normals_run");
  write_split_normal_grid(dir / "grid.obj");
  const std::string input = (dir / "grid.obj").string(), hard = (dir / "hard.txt").string(),
                    plain = (dir / "plain.txt").string();
  // 180 degrees: no dihedral angle exceeds it, the split normals alone make the seams
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "a.obj").string() + "\" --hard-edge-angle 180 --save-seams \"" +
                          hard + "\""), 0);
  EXPECT_EQ(undirected(seam_constraints::read_selection_edges(hard)), split_line());
  ASSERT_EQ(run_uv_unwrap("\"" + input + "\" -o \"" + (dir / "b.obj").string() + "\" --save-seams \"" + plain + "\""), 0);
  EXPECT_TRUE(seam_constraints::read_selection_edges(plain).empty()); // a flat disk: no seam without the option
}

} // namespace

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if(const char* program = std::getenv("UV_UNWRAP")) uv_unwrap_program = program;
  return RUN_ALL_TESTS();
}
