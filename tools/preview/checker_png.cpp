// Software rasterizer for the checkerboard preview. Small and dependency
// free on purpose: the tool must produce images on a headless machine.
#include "preview_detail.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <unordered_set>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace {

using namespace uv_preview_detail;

struct V3
{
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 normalized(V3 a)
{
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? (1 / l) * a : V3{0, 0, 0};
}
V3 to_v3(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }

// Screen position (supersampled pixels) and camera depth.
struct Projected
{
  double x, y, z;
};

struct Camera
{
  V3 eye, right, up, fwd;
  double k = 1, ox = 0, oy = 0; // image-plane -> pixel mapping

  Projected project(V3 p) const
  {
    const V3 d = p - eye;
    const double z = dot(d, fwd);
    return {ox + k * dot(d, right) / z, oy - k * dot(d, up) / z, z};
  }
};

// Looks at the bounding sphere from the camera's azimuth/elevation (plus
// `turn` degrees of azimuth), then zooms so the projected mesh fills the
// viewport.
Camera make_camera(const std::vector<V3>& used, V3 center, double radius, const Preview_camera& view,
                   double turn, double vx0, double vw, double vh)
{
  const double pi = 3.14159265358979323846;
  const double az = (view.azimuth + turn) * pi / 180, el = view.elevation * pi / 180;
  const V3 up = normalized(to_v3(view.up));
  V3 front = to_v3(view.front);
  front = normalized(front - dot(front, up) * up);
  if(dot(front, front) == 0) // front parallel to up: any perpendicular will do
    front = normalized(std::abs(up.x) < 0.9 ? cross(up, V3{1, 0, 0}) : cross(up, V3{0, 1, 0}));
  const V3 side = cross(up, front);
  const V3 to_eye = std::cos(el) * (std::cos(az) * front + std::sin(az) * side) + std::sin(el) * up;
  const double half_fov = 15 * pi / 180;
  Camera c;
  c.eye = center + (radius / std::sin(half_fov)) * to_eye;
  c.fwd = -1 * to_eye;
  c.right = normalized(cross(c.fwd, up));
  if(dot(c.right, c.right) == 0) // looking straight down the up axis
    c.right = normalized(cross(c.fwd, front));
  c.up = cross(c.right, c.fwd);

  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for(const V3& p : used)
  {
    const Projected q = c.project(p); // k = 1, no offset: image-plane coords
    lo[0] = std::min(lo[0], q.x);
    hi[0] = std::max(hi[0], q.x);
    lo[1] = std::min(lo[1], -q.y);
    hi[1] = std::max(hi[1], -q.y);
  }
  const double margin = 0.06;
  const double ex = std::max(hi[0] - lo[0], 1e-12), ey = std::max(hi[1] - lo[1], 1e-12);
  c.k = std::min(vw * (1 - 2 * margin) / ex, vh * (1 - 2 * margin) / ey);
  c.ox = vx0 + vw / 2 - c.k * (lo[0] + hi[0]) / 2;
  c.oy = vh / 2 + c.k * (lo[1] + hi[1]) / 2;
  return c;
}

struct Frame
{
  int w, h;
  std::vector<float> depth;
  std::vector<float> rgb;
  Frame(int w_, int h_)
    : w(w_), h(h_), depth(std::size_t(w_) * std::size_t(h_), std::numeric_limits<float>::infinity()),
      rgb(3 * std::size_t(w_) * std::size_t(h_))
  {
    // Soft vertical gradient: separates the mesh from the page without
    // competing with the checker.
    for(int y = 0; y < h; ++y)
    {
      const float t = float(y) / float(std::max(1, h - 1));
      const float c[3] = {248 - 26 * t, 248 - 24 * t, 250 - 20 * t};
      for(int x = 0; x < w; ++x)
        for(int k = 0; k < 3; ++k)
          rgb[3 * (std::size_t(y) * std::size_t(w) + std::size_t(x)) + std::size_t(k)] = c[k];
    }
  }
  std::size_t at(int x, int y) const { return std::size_t(y) * std::size_t(w) + std::size_t(x); }
};

const float checker_light[3] = {238, 234, 222};
const float checker_dark[3] = {58, 92, 158};

struct Scene
{
  const Preview_mesh& mesh;
  std::vector<V3> normals; // per vertex, area weighted: smooth across seams
  double uv0[2];
  double cell;       // checker square size in UV units
  double seam_bias;  // world-space depth tolerance for seam visibility
  double seam_radius; // supersampled pixels
  bool field;         // faces colored by face_v (v_field_color) instead of the checker
  Rgb seam_color;
};

void draw_faces(const Scene& s, const Camera& cam, int x0, int x1, Frame& fr)
{
  const Preview_mesh& m = s.mesh;
  for(std::size_t f = 0; f < m.faces.size(); ++f)
  {
    V3 P[3];
    Projected q[3];
    for(int i = 0; i < 3; ++i)
    {
      P[i] = to_v3(m.points[std::size_t(m.faces[f][i])]);
      q[i] = cam.project(P[i]);
    }
    const double area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if(!(std::abs(area) > 1e-12))
      continue;
    const V3 nf = cross(P[1] - P[0], P[2] - P[0]);
    // Back faces (seen through holes or from inside) are darkened so the
    // inside of the surface reads as such.
    const double side = dot(nf, cam.eye - P[0]) >= 0 ? 1.0 : 0.6;

    const int bx0 = std::max(x0, int(std::floor(std::min({q[0].x, q[1].x, q[2].x}))));
    const int bx1 = std::min(x1 - 1, int(std::ceil(std::max({q[0].x, q[1].x, q[2].x}))));
    const int by0 = std::max(0, int(std::floor(std::min({q[0].y, q[1].y, q[2].y}))));
    const int by1 = std::min(fr.h - 1, int(std::ceil(std::max({q[0].y, q[1].y, q[2].y}))));
    const auto& uv = m.corner_uv[f];
    const V3 n[3] = {s.normals[std::size_t(m.faces[f][0])], s.normals[std::size_t(m.faces[f][1])],
                     s.normals[std::size_t(m.faces[f][2])]};
    for(int y = by0; y <= by1; ++y)
      for(int x = bx0; x <= bx1; ++x)
      {
        const double cx = x + 0.5, cy = y + 0.5;
        // Screen-space barycentrics (sign of area handles either winding).
        const double w0 = ((q[1].x - cx) * (q[2].y - cy) - (q[1].y - cy) * (q[2].x - cx)) / area;
        const double w1 = ((q[2].x - cx) * (q[0].y - cy) - (q[2].y - cy) * (q[0].x - cx)) / area;
        const double w2 = 1 - w0 - w1;
        if(w0 < 0 || w1 < 0 || w2 < 0)
          continue;
        // Perspective-correct: 1/z is affine in screen space.
        const double inv_z = w0 / q[0].z + w1 / q[1].z + w2 / q[2].z;
        const double z = 1 / inv_z;
        const std::size_t id = fr.at(x, y);
        if(!(z < fr.depth[id]))
          continue;
        fr.depth[id] = float(z);
        const double b0 = w0 / q[0].z * z, b1 = w1 / q[1].z * z, b2 = w2 / q[2].z * z;
        const double u = b0 * uv[0][0] + b1 * uv[1][0] + b2 * uv[2][0];
        const double v = b0 * uv[0][1] + b1 * uv[1][1] + b2 * uv[2][1];
        V3 nn = normalized(b0 * n[0] + b1 * n[1] + b2 * n[2]);
        if(dot(nn, nn) == 0)
          nn = normalized(nf);
        // Headlight: light comes from the camera, two-sided.
        const double lambert = std::abs(dot(nn, cam.fwd));
        const double shade = side * (0.22 + 0.78 * lambert);
        const long long i = (long long)std::floor((u - s.uv0[0]) / s.cell);
        const long long j = (long long)std::floor((v - s.uv0[1]) / s.cell);
        float base[3];
        if(s.field)
        {
          const Rgb c = v_field_color(m.face_v[f]);
          for(int k = 0; k < 3; ++k)
            base[k] = float(c[std::size_t(k)]);
        }
        else
          for(int k = 0; k < 3; ++k)
            base[k] = ((i + j) & 1) ? checker_dark[k] : checker_light[k];
        for(int k = 0; k < 3; ++k)
          fr.rgb[3 * id + std::size_t(k)] = float(base[k] * shade);
      }
  }
}

void draw_seams(const Scene& s, const Camera& cam, int x0, int x1, Frame& fr)
{
  const Preview_mesh& m = s.mesh;
  std::unordered_set<std::uint64_t> done;
  const double r = s.seam_radius;
  const int ir = int(std::ceil(r));
  for(const auto& e : m.seam_edges)
  {
    if(e.first == e.second || !done.insert(edge_key(e.first, e.second)).second)
      continue;
    const Projected a = cam.project(to_v3(m.points[std::size_t(e.first)]));
    const Projected b = cam.project(to_v3(m.points[std::size_t(e.second)]));
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = int(std::ceil(len / 0.5)) + 1;
    for(int i = 0; i <= steps; ++i)
    {
      const double t = double(i) / steps;
      const double px = a.x + t * (b.x - a.x), py = a.y + t * (b.y - a.y);
      const double z = 1 / ((1 - t) / a.z + t / b.z);
      for(int y = int(py) - ir; y <= int(py) + ir; ++y)
        for(int x = int(px) - ir; x <= int(px) + ir; ++x)
        {
          if(x < x0 || x >= x1 || y < 0 || y >= fr.h)
            continue;
          const double dx = x + 0.5 - px, dy = y + 0.5 - py;
          if(dx * dx + dy * dy > r * r)
            continue;
          // Depth-tested with a bias so the seam wins against the faces it
          // lies on but not against surfaces in front of it.
          const std::size_t id = fr.at(x, y);
          if(z > double(fr.depth[id]) + s.seam_bias)
            continue;
          for(int k = 0; k < 3; ++k)
            fr.rgb[3 * id + std::size_t(k)] = s.seam_color[std::size_t(k)];
        }
    }
  }
}

} // namespace

bool preview_camera_for_up_axis(const std::string& axis, Preview_camera& camera)
{
  std::string a;
  for(char ch : axis)
    a += char(std::tolower(static_cast<unsigned char>(ch)));
  double sign = 1;
  if(!a.empty() && (a[0] == '+' || a[0] == '-'))
  {
    sign = a[0] == '-' ? -1 : 1;
    a.erase(0, 1);
  }
  if(a != "x" && a != "y" && a != "z")
    return false;
  Preview_camera c = camera;
  const int k = a[0] - 'x';
  c.up = {0, 0, 0};
  c.up[std::size_t(k)] = sign;
  c.front = k == 2 ? std::array<double, 3>{0, -1, 0} : std::array<double, 3>{0, 0, 1};
  camera = c;
  return true;
}

bool write_checker_png(const std::string& path, const Preview_mesh& mesh, int width, int height, bool two_views)
{
  return write_checker_png(path, mesh, width, height, two_views, Preview_camera());
}

namespace {

// The render of write_checker_png() (field: false) and write_v_field_png() (true).
bool render_png(const std::string& path, const Preview_mesh& mesh, int width, int height, bool two_views,
                const Preview_camera& camera, bool field)
{
  if(!valid_mesh(mesh, true))
    return false;
  if(field && mesh.face_v.size() != mesh.faces.size())
    return false;
  if(field)
    for(double v : mesh.face_v)
      if(!std::isfinite(v))
        return false;
  for(double x : {camera.up[0], camera.up[1], camera.up[2], camera.front[0], camera.front[1], camera.front[2],
                  camera.azimuth, camera.elevation})
    if(!std::isfinite(x))
      return false;
  if(!(dot(to_v3(camera.up), to_v3(camera.up)) > 0))
    return false;
  if(width < 16 || height < 16 || width > 16384 || height > 16384)
    return false;
  const Box2 ub = uv_bounds(mesh);
  const double uv_extent = std::max(ub.hi[0] - ub.lo[0], ub.hi[1] - ub.lo[1]);
  if(!(uv_extent > 0) || !std::isfinite(uv_extent))
    return false;

  // Geometry actually referenced by faces: bounds and smooth normals.
  std::vector<char> used_flag(mesh.points.size(), 0);
  std::vector<V3> normals(mesh.points.size(), V3{0, 0, 0});
  for(const auto& f : mesh.faces)
  {
    const V3 p0 = to_v3(mesh.points[std::size_t(f[0])]);
    const V3 nf = cross(to_v3(mesh.points[std::size_t(f[1])]) - p0, to_v3(mesh.points[std::size_t(f[2])]) - p0);
    for(int i : f)
    {
      used_flag[std::size_t(i)] = 1;
      normals[std::size_t(i)] = normals[std::size_t(i)] + nf;
    }
  }
  std::vector<V3> used;
  V3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    normals[i] = normalized(normals[i]);
    if(!used_flag[i])
      continue;
    const V3 p = to_v3(mesh.points[i]);
    used.push_back(p);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const V3 center = 0.5 * (lo + hi);
  const double radius = 0.5 * std::sqrt(dot(hi - lo, hi - lo));
  if(!(radius > 0) || !std::isfinite(radius))
    return false;

  // 2x2 supersampling: cheap antialiasing for edges, checker and seams.
  const int ss = 2;
  Frame fr(width * ss, height * ss);
  const int views = two_views ? 2 : 1;
  Scene scene{mesh,
              std::move(normals),
              {ub.lo[0], ub.lo[1]},
              uv_extent / 24, // ~24 squares across the layout
              0.012 * radius,
              ss * std::max(1.0, 0.0036 * std::min(width / views, height)),
              field,
              field ? Rgb{20, 20, 20} : seam_rgb};
  for(int v = 0; v < views; ++v)
  {
    const int x0 = v * fr.w / views, x1 = (v + 1) * fr.w / views;
    // The second view looks from the opposite side.
    const Camera cam = make_camera(used, center, radius, camera, 180.0 * v, x0, x1 - x0, fr.h);
    draw_faces(scene, cam, x0, x1, fr);
    draw_seams(scene, cam, x0, x1, fr);
  }

  std::vector<unsigned char> img(3 * std::size_t(width) * std::size_t(height));
  for(int y = 0; y < height; ++y)
    for(int x = 0; x < width; ++x)
    {
      // Thin divider between the two views.
      if(two_views && x == width / 2)
      {
        for(int k = 0; k < 3; ++k)
          img[3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)) + std::size_t(k)] = 180;
        continue;
      }
      for(int k = 0; k < 3; ++k)
      {
        float sum = 0;
        for(int dy = 0; dy < ss; ++dy)
          for(int dx = 0; dx < ss; ++dx)
            sum += fr.rgb[3 * fr.at(x * ss + dx, y * ss + dy) + std::size_t(k)];
        img[3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)) + std::size_t(k)] =
          static_cast<unsigned char>(std::lround(std::clamp(sum / float(ss * ss), 0.0f, 255.0f)));
      }
    }
  return stbi_write_png(path.c_str(), width, height, 3, img.data(), width * 3) != 0;
}

} // namespace

bool write_checker_png(const std::string& path, const Preview_mesh& mesh, int width, int height, bool two_views,
                       const Preview_camera& camera)
{
  return render_png(path, mesh, width, height, two_views, camera, false);
}

bool write_v_field_png(const std::string& path, const Preview_mesh& mesh, int width, int height, bool two_views,
                       const Preview_camera& camera)
{
  return render_png(path, mesh, width, height, two_views, camera, true);
}
