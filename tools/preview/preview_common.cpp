#include "preview_detail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace uv_preview_detail {

namespace {

// Piecewise-linear ramp through equally spaced control colors.
template <std::size_t N>
Rgb ramp(const std::array<Rgb, N>& stops, double t)
{
  if(!(t > 0)) // also catches NaN
    t = 0;
  if(t > 1)
    t = 1;
  const double x = t * double(N - 1);
  const std::size_t i = std::min<std::size_t>(std::size_t(x), N - 2);
  const double w = x - double(i);
  Rgb c;
  for(int k = 0; k < 3; ++k)
    c[k] = static_cast<unsigned char>(std::lround((1 - w) * stops[i][k] + w * stops[i + 1][k]));
  return c;
}

} // namespace

Rgb viridis(double t)
{
  // Nine samples of viridis at k/8; linear interpolation between them stays
  // within a couple of units of the true map.
  static const std::array<Rgb, 9> stops{{{68, 1, 84},
                                          {71, 45, 123},
                                          {59, 82, 139},
                                          {44, 114, 142},
                                          {33, 144, 140},
                                          {39, 173, 129},
                                          {93, 200, 99},
                                          {170, 220, 50},
                                          {253, 231, 37}}};
  return ramp(stops, t);
}

Rgb v_field_color(double v)
{
  static const std::array<Rgb, 5> stops{
    {{165, 0, 38}, {244, 109, 67}, {255, 255, 191}, {116, 173, 209}, {49, 54, 149}}};
  return ramp(stops, v);
}

std::string hex(const Rgb& c)
{
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

bool valid_mesh(const Preview_mesh& m, bool need_uv)
{
  if(m.faces.empty() || m.points.empty())
    return false;
  const long n = long(m.points.size());
  for(const auto& p : m.points)
    for(double x : p)
      if(!std::isfinite(x))
        return false;
  for(const auto& f : m.faces)
    for(int i : f)
      if(i < 0 || i >= n)
        return false;
  for(const auto& e : m.seam_edges)
    if(e.first < 0 || e.first >= n || e.second < 0 || e.second >= n)
      return false;
  if(!m.face_distortion.empty() && m.face_distortion.size() != m.faces.size())
    return false;
  if(!m.face_v.empty() && m.face_v.size() != m.faces.size())
    return false;
  if(need_uv)
  {
    if(m.corner_uv.size() != m.faces.size())
      return false;
    for(const auto& f : m.corner_uv)
      for(const auto& uv : f)
        if(!std::isfinite(uv[0]) || !std::isfinite(uv[1]))
          return false;
  }
  return true;
}

double uv_signed_area2(const Preview_mesh& m, std::size_t f)
{
  const auto& a = m.corner_uv[f][0];
  const auto& b = m.corner_uv[f][1];
  const auto& c = m.corner_uv[f][2];
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

Box2 uv_bounds(const Preview_mesh& m)
{
  Box2 b{{HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL}};
  for(const auto& f : m.corner_uv)
    for(const auto& uv : f)
      for(int k = 0; k < 2; ++k)
      {
        b.lo[k] = std::min(b.lo[k], uv[k]);
        b.hi[k] = std::max(b.hi[k], uv[k]);
      }
  return b;
}

std::vector<std::pair<std::size_t, int>> uv_boundary_edges(const Preview_mesh& m)
{
  const Box2 box = uv_bounds(m);
  const double extent = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], 1e-300});
  const double quantum = extent * 1e-9;
  auto q = [&](double x) { return std::llround(x / quantum); };

  // Key: (low vertex, high vertex, UV of low, UV of high), so both
  // orientations of a shared edge land on the same key.
  using Key = std::tuple<int, int, long long, long long, long long, long long>;
  std::map<Key, int> count;
  std::vector<Key> keys;
  keys.reserve(3 * m.faces.size());
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
      keys.emplace_back(a, b, q(ua[0]), q(ua[1]), q(ub[0]), q(ub[1]));
      ++count[keys.back()];
    }
  std::vector<std::pair<std::size_t, int>> out;
  for(std::size_t i = 0; i < keys.size(); ++i)
    if(count[keys[i]] == 1)
      out.emplace_back(i / 3, int(i % 3));
  return out;
}

} // namespace uv_preview_detail
