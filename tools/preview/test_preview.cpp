// Writes the previews of a synthetic slit disk and checks what a reader
// relies on: the files parse, carry the right counts, and show something
// (GoogleTest).
//
//   PREVIEW_OUT=DIR test_preview                  synthetic mesh + bad-input checks
//   PREVIEW_MESH=MESH.obj [PREVIEW_UP=z] test_preview --gtest_filter=Preview.real_mesh
//       a real mesh: its own UVs (f v/vt), else a cylindrical projection;
//       PREVIEW_UP is its up axis (x, y, z, -z...)
#include "preview.h"
#include "preview_detail.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace fs = std::filesystem;
using uv_preview_detail::Rgb;


static const double pi = 3.14159265358979323846;

// sigma1^2 + sigma2^2 + sigma1^-2 + sigma2^-2 of the map from the 3D triangle
// to its UV triangle: |J|_F^2 (1 + 1/det J^2) for a 2x2 Jacobian J.
static double face_distortion(const Preview_mesh& m, std::size_t f)
{
  const auto& P = m.points;
  const auto& t = m.faces[f];
  double e1[3], e2[3];
  for(int k = 0; k < 3; ++k)
  {
    e1[k] = P[std::size_t(t[1])][std::size_t(k)] - P[std::size_t(t[0])][std::size_t(k)];
    e2[k] = P[std::size_t(t[2])][std::size_t(k)] - P[std::size_t(t[0])][std::size_t(k)];
  }
  // Triangle in its own 2D frame: (l1, 0), (x2, y2).
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  const double x2 = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
  const double y2 = std::sqrt(std::max(0.0, e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2] - x2 * x2));
  const auto& uv = m.corner_uv[f];
  const double a = uv[1][0] - uv[0][0], c = uv[1][1] - uv[0][1];
  const double b = uv[2][0] - uv[0][0], d = uv[2][1] - uv[0][1];
  // J * [[l1, x2], [0, y2]] = [[a, b], [c, d]]
  const double j00 = a / l1, j10 = c / l1;
  const double j01 = (b - j00 * x2) / y2, j11 = (d - j10 * x2) / y2;
  const double frob = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
  const double det = j00 * j11 - j01 * j10;
  return frob * (1 + 1 / (det * det));
}

// Polar grid disk, bumpy in z, slit along sector 0. The UV unrolls the
// angle onto 0.85 of a turn (so the slit opens into a wedge) and stretches
// radii as r^1.6, giving distortion that grows toward the center.
static Preview_mesh make_slit_disk(int rings, int sectors)
{
  Preview_mesh m;
  auto vid = [&](int r, int s) { return r == 0 ? 0 : 1 + (r - 1) * sectors + (s % sectors); };
  m.points.push_back({0, 0, 0.3});
  for(int r = 1; r <= rings; ++r)
    for(int s = 0; s < sectors; ++s)
    {
      const double rho = double(r) / rings, th = 2 * pi * double(s) / sectors;
      const double x = rho * std::cos(th), y = rho * std::sin(th);
      m.points.push_back({x, y, 0.3 * std::cos(2.5 * x) * std::cos(2.0 * y)});
    }
  // UV of ring r at sector index s; s = sectors is the far side of the slit.
  auto uv = [&](int r, int s) {
    const double rho = std::pow(double(r) / rings, 1.6);
    const double th = 0.85 * 2 * pi * s / sectors;
    return std::array<double, 2>{rho * std::cos(th), rho * std::sin(th)};
  };
  auto add = [&](std::array<int, 2> a, std::array<int, 2> b, std::array<int, 2> c) {
    m.faces.push_back({vid(a[0], a[1]), vid(b[0], b[1]), vid(c[0], c[1])});
    m.corner_uv.push_back({uv(a[0], a[1]), uv(b[0], b[1]), uv(c[0], c[1])});
  };
  for(int s = 0; s < sectors; ++s)
  {
    add({0, 0}, {1, s}, {1, s + 1});
    for(int r = 1; r < rings; ++r)
    {
      add({r, s}, {r + 1, s}, {r + 1, s + 1});
      add({r, s}, {r + 1, s + 1}, {r, s + 1});
    }
  }
  for(int r = 0; r < rings; ++r)
    m.seam_edges.emplace_back(vid(r, 0), vid(r + 1, 0));
  for(std::size_t f = 0; f < m.faces.size(); ++f)
  {
    m.face_distortion.push_back(face_distortion(m, f));
    // Synthetic v: low next to the slit, 1 away from it.
    const auto& t = m.faces[f];
    double cx = 0, cy = 0;
    for(int k = 0; k < 3; ++k)
    {
      cx += m.points[std::size_t(t[k])][0] / 3;
      cy += m.points[std::size_t(t[k])][1] / 3;
    }
    const double dist_to_slit = cx > 0 ? std::abs(cy) : std::hypot(cx, cy);
    m.face_v.push_back(std::min(1.0, dist_to_slit / 0.4));
  }
  return m;
}

static std::string slurp(const fs::path& p)
{
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

static std::size_t count_of(const std::string& s, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + what.size()))
    ++n;
  return n;
}

// The d attribute of the element with the given id.
static std::string path_data(const std::string& svg, const std::string& id)
{
  const std::size_t at = svg.find("id=\"" + id + "\"");
  if(at == std::string::npos)
    return {};
  const std::size_t d = svg.find(" d=\"", at);
  const std::size_t end = svg.find('"', d + 4);
  return svg.substr(d + 4, end - d - 4);
}

static void check_svg(const fs::path& file, const Preview_mesh& m, std::size_t boundary_edges, std::size_t seam_sides,
                      bool color_bar = true)
{
  EXPECT_TRUE(fs::exists(file));
  const std::string svg = slurp(file);
  EXPECT_TRUE(svg.rfind("<svg ", 0) == 0);
  EXPECT_TRUE(svg.find("</svg>") != std::string::npos);
  EXPECT_TRUE(count_of(svg, "<polygon ") == m.faces.size());
  EXPECT_TRUE(svg.find("id=\"legend\"") != std::string::npos);
  EXPECT_TRUE((svg.find("linearGradient") != std::string::npos) == color_bar);
  EXPECT_TRUE(svg.find("E_d = ") != std::string::npos);
  EXPECT_TRUE(svg.find("E_s = ") != std::string::npos);
  // One move-to per drawn segment.
  if(boundary_edges > 0)
    EXPECT_TRUE(count_of(path_data(svg, "chart-outlines"), "M") == boundary_edges);
  if(seam_sides > 0)
    EXPECT_TRUE(count_of(path_data(svg, "seams"), "M") == seam_sides);
  // Size: no per-face styling, so well under 100 bytes per face.
  EXPECT_TRUE(svg.size() < 100 * m.faces.size() + 8000);
}

// Big-endian 32-bit value from the PNG header.
static unsigned be32(const std::string& s, std::size_t at)
{
  return (unsigned(static_cast<unsigned char>(s[at])) << 24) | (unsigned(static_cast<unsigned char>(s[at + 1])) << 16) |
         (unsigned(static_cast<unsigned char>(s[at + 2])) << 8) | unsigned(static_cast<unsigned char>(s[at + 3]));
}

static void check_png(const fs::path& file, int w, int h, bool expect_seams)
{
  EXPECT_TRUE(fs::exists(file));
  const std::string bytes = slurp(file);
  EXPECT_TRUE(bytes.size() > 33);
  if(bytes.size() <= 33)
    return;
  EXPECT_TRUE(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  EXPECT_TRUE(bytes.compare(12, 4, "IHDR") == 0);
  EXPECT_TRUE(be32(bytes, 16) == unsigned(w));
  EXPECT_TRUE(be32(bytes, 20) == unsigned(h));

  int iw = 0, ih = 0, comp = 0;
  unsigned char* px = stbi_load(file.string().c_str(), &iw, &ih, &comp, 3);
  EXPECT_TRUE(px != nullptr);
  if(!px)
    return;
  EXPECT_TRUE(iw == w && ih == h);
  std::set<unsigned> colors;
  std::size_t seam = 0, bluish = 0, light = 0;
  for(long i = 0; i < long(iw) * ih; ++i)
  {
    const unsigned char* p = px + 3 * i;
    colors.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
    if(Rgb{p[0], p[1], p[2]} == uv_preview_detail::seam_rgb)
      ++seam;
    // Checker squares, whatever the shading: dark blue vs warm light.
    if(int(p[2]) > int(p[0]) + 50)
      ++bluish;
    if(p[0] > 120 && int(p[0]) >= int(p[2]) + 6)
      ++light;
  }
  stbi_image_free(px);
  const double n = double(iw) * ih;
  EXPECT_TRUE(colors.size() > 200);   // shading + checker, not a flat image
  EXPECT_TRUE(double(bluish) > 0.02 * n); // both checker colors show
  EXPECT_TRUE(double(light) > 0.02 * n);
  if(expect_seams)
    EXPECT_TRUE(double(seam) > 0.0005 * n); // seams drawn in their own color
  std::printf("  %s: %zu colors, seam px %zu, dark squares %.1f%%, light squares %.1f%%\n",
              file.filename().string().c_str(), colors.size(), seam, 100 * double(bluish) / n,
              100 * double(light) / n);
}

// A render of v: red where v is low, blue where it is high (both present in
// the mesh given), seams in black.
static void check_v_png(const fs::path& file, int w, int h)
{
  int iw = 0, ih = 0, comp = 0;
  unsigned char* px = stbi_load(file.string().c_str(), &iw, &ih, &comp, 3);
  EXPECT_TRUE(px != nullptr);
  if(!px)
    return;
  EXPECT_TRUE(iw == w && ih == h);
  std::size_t red = 0, blue = 0, black = 0;
  for(long i = 0; i < long(iw) * ih; ++i)
  {
    const unsigned char* p = px + 3 * i;
    if(int(p[0]) > int(p[2]) + 60)
      ++red;
    if(int(p[2]) > int(p[0]) + 60)
      ++blue;
    if(p[0] < 40 && p[1] < 40 && p[2] < 40)
      ++black;
  }
  stbi_image_free(px);
  const double n = double(iw) * ih;
  EXPECT_TRUE(double(red) > 0.01 * n);
  EXPECT_TRUE(double(blue) > 0.01 * n);
  EXPECT_TRUE(double(black) > 0.0005 * n);
  std::printf("  %s: red %.1f%%, blue %.1f%%, black (seams) %zu px\n", file.filename().string().c_str(),
              100 * double(red) / n, 100 * double(blue) / n, black);
}

static void check_ply(const fs::path& file, const Preview_mesh& m)
{
  EXPECT_TRUE(fs::exists(file));
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_TRUE(line == "ply");
  std::size_t nv = 0, nf = 0;
  bool has_v = false, has_rgb = false, ended = false;
  while(std::getline(in, line))
  {
    if(line.rfind("element vertex ", 0) == 0)
      nv = std::stoul(line.substr(15));
    else if(line.rfind("element face ", 0) == 0)
      nf = std::stoul(line.substr(13));
    else if(line == "property float v")
      has_v = true;
    else if(line == "property uchar red")
      has_rgb = true;
    else if(line == "end_header")
    {
      ended = true;
      break;
    }
  }
  EXPECT_TRUE(ended && has_v && has_rgb);
  EXPECT_TRUE(nv == m.points.size());
  EXPECT_TRUE(nf == m.faces.size());
  std::size_t vertex_lines = 0, face_lines = 0;
  bool faces_ok = true;
  for(std::size_t i = 0; i < nv && std::getline(in, line); ++i)
  {
    std::istringstream ss(line);
    double x, y, z;
    if(ss >> x >> y >> z)
      ++vertex_lines;
  }
  for(std::size_t i = 0; i < nf && std::getline(in, line); ++i)
  {
    std::istringstream ss(line);
    int n, a, b, c;
    unsigned r, g, bl;
    double v;
    if(!(ss >> n >> a >> b >> c >> r >> g >> bl >> v) || n != 3 || r > 255 || g > 255 || bl > 255)
      faces_ok = false;
    else
    {
      const auto& t = m.faces[i];
      faces_ok = faces_ok && a == t[0] && b == t[1] && c == t[2] && std::abs(v - m.face_v[i]) < 1e-5;
      const Rgb want = uv_preview_detail::v_field_color(m.face_v[i]);
      faces_ok = faces_ok && r == want[0] && g == want[1] && bl == want[2];
      ++face_lines;
    }
  }
  EXPECT_TRUE(vertex_lines == nv);
  EXPECT_TRUE(face_lines == nf);
  EXPECT_TRUE(faces_ok);
  EXPECT_TRUE(!std::getline(in, line) || line.empty());
}

static void check_bad_inputs(const fs::path& dir, const Preview_mesh& good)
{
  const Preview_caption cap;
  auto svg = dir / "bad.svg", png = dir / "bad.png", ply = dir / "bad.ply";
  auto none_written = [&] { return !fs::exists(svg) && !fs::exists(png) && !fs::exists(ply); };

  Preview_mesh empty;
  EXPECT_TRUE(!write_uv_svg(svg.string(), empty, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), empty));
  EXPECT_TRUE(!write_v_field_ply(ply.string(), empty));

  Preview_mesh nan_uv = good;
  nan_uv.corner_uv[3][1][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(!write_uv_svg(svg.string(), nan_uv, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), nan_uv));

  Preview_mesh inf_point = good;
  inf_point.points[2][1] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(!write_uv_svg(svg.string(), inf_point, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), inf_point));
  EXPECT_TRUE(!write_v_field_ply(ply.string(), inf_point));

  Preview_mesh bad_index = good;
  bad_index.faces[0][2] = int(good.points.size());
  EXPECT_TRUE(!write_uv_svg(svg.string(), bad_index, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), bad_index));
  EXPECT_TRUE(!write_v_field_ply(ply.string(), bad_index));

  Preview_mesh bad_seam = good;
  bad_seam.seam_edges.emplace_back(-1, 0);
  EXPECT_TRUE(!write_uv_svg(svg.string(), bad_seam, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), bad_seam));

  Preview_mesh short_uv = good;
  short_uv.corner_uv.pop_back();
  EXPECT_TRUE(!write_uv_svg(svg.string(), short_uv, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), short_uv));

  Preview_mesh short_d = good;
  short_d.face_distortion.pop_back();
  EXPECT_TRUE(!write_uv_svg(svg.string(), short_d, cap));

  Preview_mesh no_v = good;
  no_v.face_v.clear();
  EXPECT_TRUE(!write_v_field_ply(ply.string(), no_v));

  Preview_mesh flat_uv = good; // every corner at one UV point
  for(auto& f : flat_uv.corner_uv)
    f = {{{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}}};
  EXPECT_TRUE(!write_uv_svg(svg.string(), flat_uv, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), flat_uv));

  Preview_mesh huge_uv = good; // extent overflows to infinity
  huge_uv.corner_uv[0][0] = {-1e308, 0};
  huge_uv.corner_uv[1][0] = {1e308, 0};
  EXPECT_TRUE(!write_uv_svg(svg.string(), huge_uv, cap));
  EXPECT_TRUE(!write_checker_png(png.string(), huge_uv));

  Preview_mesh tiny_uv = good; // extent too small to scale to the page
  for(auto& f : tiny_uv.corner_uv)
    for(auto& uv : f)
      uv = {uv[0] * 1e-310, uv[1] * 1e-310};
  EXPECT_TRUE(!write_uv_svg(svg.string(), tiny_uv, cap));

  Preview_mesh huge_mesh = good;
  huge_mesh.points[0] = {-1e308, 0, 0};
  huge_mesh.points[1] = {1e308, 0, 0};
  EXPECT_TRUE(!write_checker_png(png.string(), huge_mesh));

  Preview_mesh point_mesh = good; // all vertices coincide
  for(auto& p : point_mesh.points)
    p = {1, 1, 1};
  EXPECT_TRUE(!write_checker_png(png.string(), point_mesh));

  EXPECT_TRUE(!write_checker_png(png.string(), good, 0, 100));
  EXPECT_TRUE(!write_checker_png(png.string(), good, 100, -5));
  EXPECT_TRUE(none_written());

  // Unwritable destinations.
  const fs::path missing = dir / "no_such_dir" / "x";
  EXPECT_TRUE(!write_uv_svg(missing.string() + ".svg", good, cap));
  EXPECT_TRUE(!write_checker_png(missing.string() + ".png", good));
  EXPECT_TRUE(!write_v_field_ply(missing.string() + ".ply", good));
}

// Minimal OBJ reader: positions, texture coordinates and faces (polygons
// fanned). Corner UVs are taken from "f v/vt" when every face has them.
static bool read_obj(const std::string& file, Preview_mesh& m)
{
  std::ifstream in(file);
  if(!in)
    return false;
  std::vector<std::array<double, 2>> vt;
  std::vector<std::array<int, 3>> face_vt;
  bool all_vt = true;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if(tag == "v")
    {
      std::array<double, 3> p{};
      ss >> p[0] >> p[1] >> p[2];
      m.points.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> t{};
      ss >> t[0] >> t[1];
      vt.push_back(t);
    }
    else if(tag == "f")
    {
      std::vector<int> ids, tids;
      std::string tok;
      while(ss >> tok)
      {
        const int i = std::stoi(tok);
        ids.push_back(i < 0 ? int(m.points.size()) + i : i - 1);
        const std::size_t slash = tok.find('/');
        if(slash != std::string::npos && slash + 1 < tok.size() && tok[slash + 1] != '/')
        {
          const int t = std::stoi(tok.substr(slash + 1));
          tids.push_back(t < 0 ? int(vt.size()) + t : t - 1);
        }
      }
      all_vt = all_vt && tids.size() == ids.size();
      for(std::size_t k = 1; k + 1 < ids.size(); ++k)
      {
        m.faces.push_back({ids[0], ids[k], ids[k + 1]});
        if(all_vt)
          face_vt.push_back({tids[0], tids[k], tids[k + 1]});
      }
    }
  }
  if(all_vt && face_vt.size() == m.faces.size())
    for(const auto& t : face_vt)
    {
      std::array<std::array<double, 2>, 3> uv{};
      for(std::size_t k = 0; k < 3; ++k)
        if(t[k] >= 0 && std::size_t(t[k]) < vt.size())
          uv[k] = vt[std::size_t(t[k])];
      m.corner_uv.push_back(uv);
    }
  return !m.faces.empty();
}

// Cylindrical UV around the longest bounding-box axis, cut where the angle
// wraps: a crude real-mesh map with a real seam, stretch and flips.
static void cylindrical_uv(Preview_mesh& m)
{
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const auto& p : m.points)
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[std::size_t(k)]);
      hi[k] = std::max(hi[k], p[std::size_t(k)]);
    }
  int axis = 0;
  for(int k = 1; k < 3; ++k)
    if(hi[k] - lo[k] > hi[axis] - lo[axis])
      axis = k;
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double c1 = (lo[a1] + hi[a1]) / 2, c2 = (lo[a2] + hi[a2]) / 2;
  double mean_r = 0;
  for(const auto& p : m.points)
    mean_r += std::hypot(p[std::size_t(a1)] - c1, p[std::size_t(a2)] - c2) / double(m.points.size());

  m.corner_uv.clear();
  for(const auto& t : m.faces)
  {
    std::array<double, 3> th;
    for(int k = 0; k < 3; ++k)
    {
      const auto& p = m.points[std::size_t(t[k])];
      th[std::size_t(k)] = std::atan2(p[std::size_t(a2)] - c2, p[std::size_t(a1)] - c1);
    }
    // Faces straddling the wrap take the +2pi copy of their negative angles.
    if(*std::max_element(th.begin(), th.end()) - *std::min_element(th.begin(), th.end()) > pi)
      for(double& x : th)
        if(x < 0)
          x += 2 * pi;
    std::array<std::array<double, 2>, 3> uv;
    for(int k = 0; k < 3; ++k)
      uv[std::size_t(k)] = {mean_r * th[std::size_t(k)], m.points[std::size_t(t[k])][std::size_t(axis)]};
    m.corner_uv.push_back(uv);
  }
}

static double face_area(const Preview_mesh& m, std::size_t f)
{
  const auto& t = m.faces[f];
  double e1[3], e2[3];
  for(std::size_t k = 0; k < 3; ++k)
  {
    e1[k] = m.points[std::size_t(t[1])][k] - m.points[std::size_t(t[0])][k];
    e2[k] = m.points[std::size_t(t[2])][k] - m.points[std::size_t(t[0])][k];
  }
  return 0.5 * std::sqrt(std::pow(e1[1] * e2[2] - e1[2] * e2[1], 2) + std::pow(e1[2] * e2[0] - e1[0] * e2[2], 2) +
                         std::pow(e1[0] * e2[1] - e1[1] * e2[0], 2));
}

// Fills seams (interior edges whose two faces disagree on the UVs),
// distortion, a stand-in v field and the caption metrics from the UVs.
static void derive_from_uv(Preview_mesh& m, Preview_caption& cap)
{
  std::map<std::pair<int, int>, std::vector<std::array<double, 4>>> sides;
  for(std::size_t f = 0; f < m.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
      auto ua = m.corner_uv[f][k], ub = m.corner_uv[f][(k + 1) % 3];
      if(a > b)
      {
        std::swap(a, b);
        std::swap(ua, ub);
      }
      sides[{a, b}].push_back({ua[0], ua[1], ub[0], ub[1]});
    }
  double seam_len = 0, area = 0, area_d = 0;
  for(const auto& e : sides)
    if(e.second.size() == 2 && e.second[0] != e.second[1])
    {
      m.seam_edges.push_back(e.first);
      const auto& p = m.points[std::size_t(e.first.first)];
      const auto& q = m.points[std::size_t(e.first.second)];
      seam_len += std::sqrt(std::pow(p[0] - q[0], 2) + std::pow(p[1] - q[1], 2) + std::pow(p[2] - q[2], 2));
    }
  for(std::size_t f = 0; f < m.faces.size(); ++f)
  {
    const double d = face_distortion(m, f), a = face_area(m, f);
    m.face_distortion.push_back(d);
    // A stand-in v field: low where the map stretches.
    m.face_v.push_back(std::isfinite(d) ? std::clamp(1.5 - 0.5 * std::log2(d / 4), 0.0, 1.0) : 0.0);
    area += a;
    if(std::isfinite(d))
      area_d += a * d;
  }
  cap.faces = m.faces.size();
  cap.distortion = area_d / area;
  cap.seam_length = seam_len / std::sqrt(area / pi);
}

// Where the pictures go: $PREVIEW_OUT, else preview_out (emptied of the
// files the refusal checks expect absent).
static fs::path output_directory()
{
  const char* out = std::getenv("PREVIEW_OUT");
  const fs::path dir = out && *out ? fs::path(out) : fs::path("preview_out");
  fs::create_directories(dir);
  for(const char* f : {"bad.svg", "bad.png", "bad.ply"})
    fs::remove(dir / f);
  return dir;
}

// A real mesh: the OBJ file in $PREVIEW_MESH (with UVs, or a cylindrical
// projection), seen with the up axis $PREVIEW_UP; skipped without it.
TEST(Preview, real_mesh)
{
  const char* file = std::getenv("PREVIEW_MESH");
  if(!file || !*file) GTEST_SKIP() << "PREVIEW_MESH not set";
  const fs::path dir = output_directory();
  {
    Preview_mesh m;
    EXPECT_TRUE(read_obj(file, m));
    ASSERT_FALSE(m.faces.empty());
    const bool has_uv = !m.corner_uv.empty();
    if(!has_uv)
      cylindrical_uv(m);
    const std::string stem = fs::path(file).stem().string();
    Preview_caption cap;
    cap.name = stem + (has_uv ? "" : " (cylindrical projection)");
    cap.charts = 1;
    cap.seconds = -1;
    derive_from_uv(m, cap);
    EXPECT_TRUE(write_uv_svg((dir / (stem + "_uv.svg")).string(), m, cap));
    Preview_camera camera;
    if(const char* up = std::getenv("PREVIEW_UP"))
      EXPECT_TRUE(preview_camera_for_up_axis(up, camera));
    EXPECT_TRUE(write_checker_png((dir / (stem + "_checker.png")).string(), m, 1024, 768, true, camera));
    EXPECT_TRUE(write_v_field_ply((dir / (stem + "_v.ply")).string(), m));
    check_svg(dir / (stem + "_uv.svg"), m, 0, 0);
    // Seams may all be hidden from both views of a real mesh.
    check_png(dir / (stem + "_checker.png"), 1024, 768, false);
    check_ply(dir / (stem + "_v.ply"), m);
  }
}

// A synthetic slit disk: every writer, every refusal, the camera choice.
TEST(Preview, synthetic_slit_disk)
{
  const fs::path dir = output_directory();
  {
    const int rings = 12, sectors = 48;
    const Preview_mesh m = make_slit_disk(rings, sectors);
    double dmin = 1e300, dmax = 0;
    for(double d : m.face_distortion)
    {
      dmin = std::min(dmin, d);
      dmax = std::max(dmax, d);
    }
    EXPECT_TRUE(dmin >= 4 - 1e-9);
    EXPECT_TRUE(dmax > 2 * dmin); // the distortion really varies

    Preview_caption cap{4.321, 1.234, 0.56, m.faces.size(), 1, "synthetic slit disk"};
    EXPECT_TRUE(write_uv_svg((dir / "disk_uv.svg").string(), m, cap));
    EXPECT_TRUE(write_checker_png((dir / "disk_checker.png").string(), m));
    EXPECT_TRUE(write_checker_png((dir / "disk_checker_single.png").string(), m, 400, 300, false));
    EXPECT_TRUE(write_v_field_ply((dir / "disk_v.ply").string(), m));
    // Outline: outer circle plus both sides of the slit; seams: both sides.
    check_svg(dir / "disk_uv.svg", m, std::size_t(sectors + 2 * rings), std::size_t(2 * rings));
    check_png(dir / "disk_checker.png", 1024, 768, true);
    check_png(dir / "disk_checker_single.png", 400, 300, true);
    check_ply(dir / "disk_v.ply", m);
    EXPECT_TRUE(write_v_field_png((dir / "disk_v.png").string(), m, 640, 480, true, Preview_camera()));
    check_v_png(dir / "disk_v.png", 640, 480);
    Preview_mesh short_v = m;
    short_v.face_v.pop_back();
    EXPECT_TRUE(!write_v_field_png((dir / "bad.png").string(), short_v, 640, 480, true, Preview_camera()));

    // Camera choice: a top view of the disk (z up, looking down) differs from
    // the default y-up view.
    Preview_camera top;
    EXPECT_TRUE(preview_camera_for_up_axis("+Z", top));
    EXPECT_TRUE(top.up[2] == 1 && top.front[1] == -1);
    EXPECT_TRUE(preview_camera_for_up_axis("-x", top));
    EXPECT_TRUE(top.up[0] == -1);
    EXPECT_TRUE(!preview_camera_for_up_axis("w", top));
    EXPECT_TRUE(!preview_camera_for_up_axis("", top));
    EXPECT_TRUE(top.up[0] == -1); // untouched by the failures
    EXPECT_TRUE(preview_camera_for_up_axis("z", top));
    top.elevation = 70;
    EXPECT_TRUE(write_checker_png((dir / "disk_checker_top.png").string(), m, 640, 480, true, top));
    check_png(dir / "disk_checker_top.png", 640, 480, true);
    EXPECT_TRUE(slurp(dir / "disk_checker_top.png") != slurp(dir / "disk_checker.png"));
    Preview_camera broken;
    broken.up = {0, 0, 0};
    EXPECT_TRUE(!write_checker_png((dir / "bad.png").string(), m, 640, 480, true, broken));
    broken = Preview_camera();
    broken.azimuth = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(!write_checker_png((dir / "bad.png").string(), m, 640, 480, true, broken));

    // Without distortion data the layout is still drawn, in gray.
    Preview_mesh plain = m;
    plain.face_distortion.clear();
    EXPECT_TRUE(write_uv_svg((dir / "disk_uv_plain.svg").string(), plain, cap));
    check_svg(dir / "disk_uv_plain.svg", plain, std::size_t(sectors + 2 * rings), std::size_t(2 * rings), false);

    // A flipped face is flagged.
    Preview_mesh flipped = m;
    std::swap(flipped.corner_uv[100][0], flipped.corner_uv[100][1]);
    EXPECT_TRUE(write_uv_svg((dir / "disk_uv_flipped.svg").string(), flipped, cap));
    EXPECT_TRUE(slurp(dir / "disk_uv_flipped.svg").find("flipped faces: 1") != std::string::npos);

    check_bad_inputs(dir, m);
  }
}
