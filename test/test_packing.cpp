// Atlas packing (internal pack_charts, chart_packing.h) on hand-built chart
// meshes: every UV in the square, charts apart by the padding (bounding
// rectangles and exact border distances), no face flipped or mirrored, shapes
// kept up to the common scale, coverage as reported, world units, determinism,
// single-chart orientation, degenerate inputs, and 2000 tiny charts in time.
#include "generators.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>

#include <algorithm>
#include <chrono>

namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using namespace cut_test;
using ic::Vector2;

namespace {

/// A chart mesh built chart by chart; `x` holds the UVs given to the packer.
struct Atlas
{
  ic::Chart_mesh mesh;
  std::vector<Vector2> uv;

  /// Adds a chart: points (also its flat 3D shape) and triangles (local indices).
  void add_chart(const std::vector<Vector2>& points, const std::vector<std::array<int, 3>>& triangles)
  {
    const int offset = int(uv.size());
    uv.insert(uv.end(), points.begin(), points.end());
    for(const auto& t : triangles)
    {
      const std::size_t f = mesh.number_of_faces();
      mesh.resize_faces(f + 1);
      mesh.faces[f] = {t[0] + offset, t[1] + offset, t[2] + offset};
      auto p3 = [&](int i) { return ic::Vector3(points[i].x(), points[i].y(), 0.); };
      mesh.set_rest_shape(f, p3(t[0]), p3(t[1]), p3(t[2]));
    }
    mesh.number_of_vertices = int(uv.size());
  }
  /// A vertex in no face.
  void add_loose_vertex(const Vector2& p)
  {
    uv.push_back(p);
    mesh.number_of_vertices = int(uv.size());
  }
  ic::UV_vector x() const
  {
    ic::UV_vector v(2 * uv.size());
    for(std::size_t i = 0; i < uv.size(); ++i) v.segment<2>(2 * i) = uv[i];
    return v;
  }
};

/// Moves points by a rotation (angle) and a translation.
std::vector<Vector2> moved(std::vector<Vector2> p, double angle, const Vector2& t)
{
  const double c = std::cos(angle), s = std::sin(angle);
  for(Vector2& q : p) q = Vector2(c * q.x() - s * q.y(), s * q.x() + c * q.y()) + t;
  return p;
}

/// nx × ny grid of a w × h rectangle, counterclockwise triangles. With
/// `skip_corner`, the upper right quarter is left out (an L shape).
void add_grid(Atlas& atlas, double w, double h, int nx, int ny, double angle, const Vector2& t,
              bool skip_corner = false)
{
  std::vector<Vector2> p;
  std::vector<std::array<int, 3>> tris;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i) p.emplace_back(w * i / nx, h * j / ny);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      if(skip_corner && 2 * i >= nx && 2 * j >= ny) continue;
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  atlas.add_chart(moved(p, angle, t), tris); // unused grid points of an L are loose inside the chart: fine
}

/// Fan disk of radius r with m border points (an ellipse if ry != r).
void add_disk(Atlas& atlas, double r, double ry, int m, double angle, const Vector2& t)
{
  std::vector<Vector2> p{Vector2(0., 0.)};
  std::vector<std::array<int, 3>> tris;
  for(int k = 0; k < m; ++k)
  {
    const double a = 2. * pi * k / m;
    p.emplace_back(r * std::cos(a), ry * std::sin(a));
    tris.push_back({0, 1 + k, 1 + (k + 1) % m});
  }
  atlas.add_chart(moved(p, angle, t), tris);
}

/// 30 charts: rectangles of varied aspect ratios, disks, ellipses, L shapes,
/// each rotated and placed arbitrarily (overlapping) in the input.
Atlas varied_atlas(std::uint64_t seed = 7)
{
  Rng rng(seed);
  Atlas atlas;
  for(int c = 0; c < 30; ++c)
  {
    const double angle = rng.uniform(0., 2. * pi);
    const Vector2 t(rng.uniform(-3., 3.), rng.uniform(-3., 3.));
    const double s = rng.uniform(0.3, 2.);
    switch(c % 4)
    {
      case 0: add_grid(atlas, s, s * rng.uniform(0.1, 1.), 4, 3, angle, t); break;
      case 1: add_disk(atlas, s * 0.5, s * 0.5, 12, angle, t); break;
      case 2: add_disk(atlas, s * 0.6, s * rng.uniform(0.1, 0.4), 16, angle, t); break;
      default: add_grid(atlas, s, s * rng.uniform(0.5, 1.5), 4, 4, angle, t, true); break;
    }
  }
  return atlas;
}

std::vector<int> charts_of_vertices(const ic::Chart_mesh& mesh, int& n)
{
  const std::vector<int> chart_of_face = ic::chart_of_faces(mesh, n);
  std::vector<int> chart(mesh.number_of_vertices, -1);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int v : mesh.faces[f]) chart[v] = chart_of_face[f];
  return chart;
}

double segment_distance(const Vector2& a, const Vector2& b, const Vector2& c, const Vector2& d)
{
  auto point_segment = [](const Vector2& p, const Vector2& s0, const Vector2& s1) {
    const Vector2 e = s1 - s0;
    const double l2 = e.squaredNorm();
    const double t = l2 > 0. ? std::clamp((p - s0).dot(e) / l2, 0., 1.) : 0.;
    return (s0 + t * e - p).norm(); };
  auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if(((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.;
  return (std::min)({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

/// Exact distances between the face edges of different charts (a sweep over
/// x), and no chart inside another (a vertex of each chart in no face of
/// another): every chart at least `gap` from every other.
void check_chart_distances(const ic::Chart_mesh& mesh, const std::vector<int>& chart, const ic::UV_vector& uv,
                           double gap)
{
  struct Segment { Vector2 a, b; int chart; };
  std::vector<Segment> segments;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      Vector2 a = uv.segment<2>(2 * mesh.faces[f][k]), b = uv.segment<2>(2 * mesh.faces[f][(k + 1) % 3]);
      if(b.x() < a.x()) std::swap(a, b);
      segments.push_back({a, b, chart[mesh.faces[f][0]]});
    }
  std::sort(segments.begin(), segments.end(), [](const Segment& s, const Segment& t) { return s.a.x() < t.a.x(); });
  double closest = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < segments.size(); ++i)
    for(std::size_t j = i + 1; j < segments.size() && segments[j].a.x() <= segments[i].b.x() + gap; ++j)
      if(segments[i].chart != segments[j].chart)
        closest = (std::min)(closest, segment_distance(segments[i].a, segments[i].b, segments[j].a, segments[j].b));
  EXPECT_TRUE(closest >= gap) << "closest border distance " << closest << " < " << gap;
  // a chart inside another: one of its vertices inside a face of the other
  int n = 0;
  for(int c : chart) n = (std::max)(n, c + 1);
  std::vector<int> sample(n, -1);
  for(int v = 0; v < mesh.number_of_vertices; ++v)
    if(chart[v] >= 0 && sample[chart[v]] < 0) sample[chart[v]] = v;
  auto cross = [](const Vector2& u, const Vector2& v) { return u.x() * v.y() - u.y() * v.x(); };
  int inside = 0;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const Vector2 p0 = uv.segment<2>(2 * mesh.faces[f][0]), p1 = uv.segment<2>(2 * mesh.faces[f][1]),
                  p2 = uv.segment<2>(2 * mesh.faces[f][2]);
    const Vector2 low = p0.cwiseMin(p1).cwiseMin(p2), high = p0.cwiseMax(p1).cwiseMax(p2);
    for(int c = 0; c < n; ++c)
    {
      if(sample[c] < 0 || c == chart[mesh.faces[f][0]]) continue;
      const Vector2 q = uv.segment<2>(2 * sample[c]);
      if((q - low).minCoeff() < 0. || (high - q).minCoeff() < 0.) continue;
      const double d0 = cross(p1 - p0, q - p0), d1 = cross(p2 - p1, q - p1), d2 = cross(p0 - p2, q - p2);
      inside += (d0 >= 0. && d1 >= 0. && d2 >= 0.) || (d0 <= 0. && d1 <= 0. && d2 <= 0.);
    }
  }
  EXPECT_EQ(inside, 0);
}

/// Checks every guarantee of pack_charts on `packed` (from `input`) with result r.
/// `gap`: the padding expected in output units; `exact_borders`: also compute
/// exact distances between all face edges of different charts (small inputs).
void check_layout(const Atlas& atlas, const ic::UV_vector& input, const ic::UV_vector& packed,
                  const ic::Packing_result& r, double gap, bool exact_borders)
{
  const ic::Chart_mesh& mesh = atlas.mesh;
  ASSERT_TRUE(packed.allFinite());
  EXPECT_TRUE(r.scale > 0. && std::isfinite(r.scale));
  EXPECT_TRUE(r.side > 0. && std::isfinite(r.side));
  int n = 0;
  const std::vector<int> chart = charts_of_vertices(mesh, n);
  const double slack = 1e-12 * r.side;

  // inside the square; loose vertices untouched
  int outside = 0, moved_loose = 0;
  for(int v = 0; v < mesh.number_of_vertices; ++v)
  {
    const Vector2 p = packed.segment<2>(2 * v);
    if(chart[v] < 0) { moved_loose += (p != input.segment<2>(2 * v)); continue; }
    outside += !(p.minCoeff() >= 0. && p.maxCoeff() <= r.side);
  }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(moved_loose, 0);

  // orientation of every face kept (no mirror), shapes kept up to r.scale
  int sign_changed = 0, bad_edges = 0;
  double uv_area = 0.;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    const double before = mesh.uv_edges(input, f).determinant(), after = mesh.uv_edges(packed, f).determinant();
    if(before != 0.) sign_changed += !((before > 0.) == (after > 0.)); // zero: rounding decides
    uv_area += 0.5 * std::abs(after);
    for(int k = 0; k < 3; ++k)
    {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      const double l0 = (input.segment<2>(2 * a) - input.segment<2>(2 * b)).norm();
      const double l1 = (packed.segment<2>(2 * a) - packed.segment<2>(2 * b)).norm();
      if(l0 > 0. && !(std::abs(l1 / l0 - r.scale) <= 1e-9 * r.scale)) ++bad_edges;
    }
  }
  EXPECT_EQ(sign_changed, 0);
  EXPECT_EQ(bad_edges, 0);
  EXPECT_REL(r.coverage, uv_area / (r.side * r.side), 1e-9);

  // bounding rectangles of the packed points: gap to the sides and between charts
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Vector2> low(n, Vector2(inf, inf)), high(n, Vector2(-inf, -inf));
  for(int v = 0; v < mesh.number_of_vertices; ++v)
    if(chart[v] >= 0)
    {
      low[chart[v]] = low[chart[v]].cwiseMin(packed.segment<2>(2 * v));
      high[chart[v]] = high[chart[v]].cwiseMax(packed.segment<2>(2 * v));
    }
  int near_side = 0, near_pair = 0;
  for(int c = 0; c < n; ++c)
  {
    near_side += !(low[c].minCoeff() >= gap - slack && high[c].maxCoeff() <= r.side - gap + slack);
    for(int d = c + 1; d < n && !r.by_shape; ++d) // the shape packing nests rectangles
    {
      const Vector2 sep = (low[d] - high[c]).cwiseMax(low[c] - high[d]);
      near_pair += !(sep.maxCoeff() >= gap - slack);
    }
  }
  EXPECT_TRUE(near_side == 0) << near_side << " charts closer than " << gap << " to the square's sides";
  EXPECT_TRUE(near_pair == 0) << near_pair << " pairs of chart rectangles closer than " << gap;
  if(exact_borders || r.by_shape) check_chart_distances(mesh, chart, packed, gap - slack);
}

ic::Packing_result pack(const Atlas& atlas, ic::UV_vector& x, const ic::Packing_settings& s = ic::Packing_settings())
{
  x = atlas.x();
  return ic::pack_charts(atlas.mesh, x, s);
}

} // namespace

TEST(Packing, varied_charts_are_packed_apart_with_shapes_kept)
{
  Atlas atlas = varied_atlas();
  atlas.add_loose_vertex(Vector2(-5., 7.));
  ic::UV_vector x;
  const ic::Packing_result r = pack(atlas, x);
  EXPECT_EQ(r.side, 1.);
  check_layout(atlas, atlas.x(), x, r, 2. / 1024., true);
  std::cout << std::setprecision(4) << "  30 varied charts: coverage " << r.coverage << ", scale " << r.scale << std::endl;
  EXPECT_TRUE(r.coverage > 0.6); // 0.74 here; the former shelf packer: 0.44 (without the padding rule)
  // the padding is given in texels
  for(double padding : {0., 8., 40.})
  {
    SCOPED_TRACE("padding " + to_text(padding));
    ic::Packing_settings s;
    s.padding = padding;
    s.texture_size = 512;
    ic::UV_vector y;
    const ic::Packing_result q = pack(atlas, y, s);
    check_layout(atlas, atlas.x(), y, q, padding / 512., false);
    if(padding > 0.) EXPECT_TRUE(q.scale < r.scale);
  }
}

TEST(Packing, mirrored_charts_stay_mirrored)
{
  // clockwise charts (negative signed areas) must come out clockwise: no mirror
  Atlas atlas = varied_atlas(11);
  for(auto& t : atlas.mesh.faces) std::swap(t[1], t[2]);
  ic::UV_vector x;
  const ic::Packing_result r = pack(atlas, x);
  check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
  int positive = 0;
  for(std::size_t f = 0; f < atlas.mesh.number_of_faces(); ++f) positive += atlas.mesh.uv_edges(x, f).determinant() > 0.;
  EXPECT_EQ(positive, 0);
}

TEST(Packing, world_units_keep_scale_one_and_the_same_layout)
{
  const Atlas atlas = varied_atlas();
  ic::UV_vector unit, world;
  const ic::Packing_result r = pack(atlas, unit);
  ic::Packing_settings s;
  s.world_units = true;
  const ic::Packing_result w = pack(atlas, world, s);
  EXPECT_EQ(w.scale, 1.);
  EXPECT_REL(w.side, 1. / r.scale, 1e-12);
  EXPECT_REL(w.coverage, r.coverage, 1e-9);
  check_layout(atlas, atlas.x(), world, w, 2. / 1024. * w.side, true);
  int n = 0;
  const std::vector<int> chart = charts_of_vertices(atlas.mesh, n);
  double worst = 0.;
  for(int v = 0; v < atlas.mesh.number_of_vertices; ++v)
    if(chart[v] >= 0) // the unused points of the L shapes are left where they are
      worst = (std::max)(worst, (world.segment<2>(2 * v) / w.side - unit.segment<2>(2 * v)).cwiseAbs().maxCoeff());
  EXPECT_TRUE(worst < 1e-12) << "largest difference " << worst;
}

TEST(Packing, packing_is_deterministic)
{
  const Atlas atlas = varied_atlas(3);
  ic::UV_vector a, b;
  pack(atlas, a);
  pack(atlas, b);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(std::equal(a.data(), a.data() + a.size(), b.data())); // bit for bit
}

TEST(Packing, single_thin_rectangle_fills_the_square_along_its_diagonal)
{
  for(double angle : {0., 0.5, 1.2, 2.9, -2.})
  {
    SCOPED_TRACE("angle " + to_text(angle));
    Atlas atlas;
    add_grid(atlas, 10., 0.5, 20, 2, angle, Vector2(3., -1.));
    ic::UV_vector x;
    const ic::Packing_result r = pack(atlas, x);
    check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
    Vector2 low = Vector2::Constant(1e300), high = -low;
    for(int v = 0; v < atlas.mesh.number_of_vertices; ++v)
    {
      low = low.cwiseMin(x.segment<2>(2 * v));
      high = high.cwiseMax(x.segment<2>(2 * v));
    }
    // its smallest enclosing square is the one at 45 degrees, of side 10.5 / sqrt(2)
    const Vector2 extent = high - low;
    EXPECT_REL(extent.maxCoeff(), 1. - 4. / 1024., 1e-9); // it spans the square
    EXPECT_REL(extent.x(), extent.y(), 1e-9);
    EXPECT_REL(r.scale, (1. - 4. / 1024.) / (10.5 / std::sqrt(2.)), 1e-9);
  }
}

TEST(Packing, charts_are_turned_to_their_minimum_area_rectangle)
{
  // rectangles and L shapes given askew come out axis-aligned: the bounding
  // box of each packed chart is the (scaled) rectangle itself
  Atlas atlas;
  const double w[] = {3., 1., 2., 0.5, 1.5, 2.5}, h[] = {0.4, 1., 1.2, 0.5, 0.2, 2.};
  for(int c = 0; c < 6; ++c) add_grid(atlas, w[c], h[c], 3, 2, 0.4 + 0.7 * c, Vector2(c, -c), c == 5);
  ic::UV_vector x;
  const ic::Packing_result r = pack(atlas, x);
  check_layout(atlas, atlas.x(), x, r, 2. / 1024., true);
  int n = 0;
  const std::vector<int> chart = charts_of_vertices(atlas.mesh, n);
  ASSERT_EQ(n, 6);
  std::vector<Vector2> low(n, Vector2::Constant(1e300)), high(n, Vector2::Constant(-1e300));
  for(int v = 0; v < atlas.mesh.number_of_vertices; ++v)
    if(chart[v] >= 0)
    {
      low[chart[v]] = low[chart[v]].cwiseMin(x.segment<2>(2 * v));
      high[chart[v]] = high[chart[v]].cwiseMax(x.segment<2>(2 * v));
    }
  for(int c = 0; c < n; ++c)
  {
    SCOPED_TRACE("chart " + to_text(c));
    EXPECT_REL((high[c] - low[c]).prod(), w[c] * h[c] * r.scale * r.scale, 1e-9);
  }
}

TEST(Packing, single_square_chart_covers_the_square)
{
  for(double angle : {0., 0.3, 0.785})
  {
    Atlas atlas;
    add_grid(atlas, 1., 1., 3, 3, angle, Vector2(0.2, 0.1));
    ic::UV_vector x;
    const ic::Packing_result r = pack(atlas, x);
    check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
    EXPECT_TRUE(r.coverage > 0.98) << "coverage " << r.coverage;
  }
  // a disk: any orientation, coverage π/4 up to padding
  Atlas disk;
  add_disk(disk, 1., 1., 64, 0.1, Vector2(0., 0.));
  ic::UV_vector x;
  const ic::Packing_result r = pack(disk, x);
  check_layout(disk, disk.x(), x, r, 2. / 1024., false);
  EXPECT_TRUE(r.coverage > 0.77);
}

TEST(Packing, degenerate_inputs_give_valid_layouts)
{
  {
    Atlas empty;
    empty.add_loose_vertex(Vector2(2., 3.));
    ic::UV_vector x;
    const ic::Packing_result r = pack(empty, x);
    EXPECT_EQ(r.coverage, 0.);
    EXPECT_TRUE(x == empty.x());
  }
  {
    // charts of zero extent (all points equal), and a segment, with normal charts
    Atlas atlas = varied_atlas(5);
    atlas.add_chart({Vector2(1., 1.), Vector2(1., 1.), Vector2(1., 1.)}, {{{0, 1, 2}}});
    atlas.add_chart({Vector2(0., 0.), Vector2(1., 1.), Vector2(2., 2.)}, {{{0, 1, 2}}});
    ic::UV_vector x;
    const ic::Packing_result r = pack(atlas, x);
    check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
  }
  {
    // a non-finite UV: nothing to do, x unchanged
    const Atlas atlas = varied_atlas(5);
    ic::UV_vector x = atlas.x();
    x[2 * atlas.mesh.faces[7][1]] = std::numeric_limits<double>::quiet_NaN();
    const ic::UV_vector before = x;
    const ic::Packing_result r = ic::pack_charts(atlas.mesh, x);
    EXPECT_EQ(r.coverage, 0.);
    EXPECT_TRUE(std::equal(x.data(), x.data() + x.size(), before.data(),
                     [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }));
  }
  {
    // only zero-extent charts
    Atlas atlas;
    for(int c = 0; c < 5; ++c) atlas.add_chart({Vector2(c, 0.), Vector2(c, 0.), Vector2(c, 0.)}, {{{0, 1, 2}}});
    ic::UV_vector x;
    const ic::Packing_result r = pack(atlas, x);
    check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
  }
  for(double padding : {300., 512., 5000.})
  {
    // padding too large to fit: a lower effective padding, still a valid layout
    SCOPED_TRACE("padding " + to_text(padding));
    const Atlas atlas = varied_atlas(9);
    ic::Packing_settings s;
    s.padding = padding;
    ic::UV_vector x;
    const ic::Packing_result r = pack(atlas, x, s);
    check_layout(atlas, atlas.x(), x, r, 0.5 / (6 + 1), false); // 30 charts: 6 × 6 grid
    EXPECT_TRUE(r.coverage > 0.);
  }
}

// The layout of many small charts (the time is printed, not asserted: a
// busy machine would fail it; timings belong to the benchmark)
TEST(Packing, thousands_of_tiny_charts_get_a_valid_layout)
{
  Rng rng(42);
  Atlas atlas;
  for(int c = 0; c < 2000; ++c)
  {
    const double s = rng.uniform(0.01, 0.05);
    if(c % 2) add_grid(atlas, s, s * rng.uniform(0.2, 1.), 1, 1, rng.uniform(0., 6.), Vector2(rng.uniform(), rng.uniform()));
    else add_disk(atlas, s, s * rng.uniform(0.3, 1.), 6, rng.uniform(0., 6.), Vector2(rng.uniform(), rng.uniform()));
  }
  ic::UV_vector x = atlas.x();
  const auto start = std::chrono::steady_clock::now();
  const ic::Packing_result r = ic::pack_charts(atlas.mesh, x);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::setprecision(4) << "  2000 charts: " << seconds << " s, coverage " << r.coverage << std::endl;
  check_layout(atlas, atlas.x(), x, r, 2. / 1024., false);
  EXPECT_TRUE(r.coverage > 0.5);
}


TEST(Packing, shapes_nest_where_rectangles_cannot)
{
  // L shapes and triangles: their rectangles leave half of them empty
  Atlas atlas;
  Rng rng(5);
  for(int c = 0; c < 16; ++c)
  {
    const double s = rng.uniform(0.5, 1.5);
    const Vector2 t(rng.uniform(-3., 3.), rng.uniform(-3., 3.));
    if(c % 2) add_grid(atlas, s, s, 4, 4, rng.uniform(0., 6.), t, true);
    else atlas.add_chart(moved({Vector2(0., 0.), Vector2(s, 0.), Vector2(0., s)}, rng.uniform(0., 6.), t), {{{0, 1, 2}}});
  }
  for(double padding : {0., 2., 8.})
  {
    SCOPED_TRACE("padding " + to_text(padding));
    ic::Packing_settings s;
    s.padding = padding;
    s.texture_size = 256;
    ic::UV_vector by_shape, by_rectangle;
    const ic::Packing_result a = pack(atlas, by_shape, s);
    s.shapes = false;
    const ic::Packing_result b = pack(atlas, by_rectangle, s);
    EXPECT_TRUE(a.by_shape);
    EXPECT_FALSE(b.by_shape);
    check_layout(atlas, atlas.x(), by_shape, a, padding / 256., true);
    check_layout(atlas, atlas.x(), by_rectangle, b, padding / 256., true);
    std::cout << "  padding " << padding << ": coverage by shape " << a.coverage << ", by rectangle " << b.coverage
              << std::endl;
    EXPECT_TRUE(a.coverage > 1.05 * b.coverage); // 1.13, 1.06, 1.10 when written
  }
}

TEST(Packing, raster_placement_fills_holes_the_skyline_cannot_reach)
{
  // C shapes (a 5 × 5 grid less the middle of its right side, opening
  // sideways) and small squares: a skyline sees only the highest texel of
  // each column, so it cannot put a square into a C's mouth under its upper
  // arm; the raster placement can
  Atlas atlas;
  Rng rng(11);
  for(int c = 0; c < 6; ++c)
  {
    std::vector<Vector2> p;
    std::vector<std::array<int, 3>> tris;
    const int m = 5;
    for(int j = 0; j <= m; ++j)
      for(int i = 0; i <= m; ++i) p.emplace_back(0.4 * i, 0.4 * j);
    auto id = [&](int i, int j) { return j * (m + 1) + i; };
    for(int j = 0; j < m; ++j)
      for(int i = 0; i < m; ++i)
      {
        if(i >= 1 && j >= 1 && j <= 3) continue; // the mouth: 4 × 3 cells open to the right
        tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    atlas.add_chart(moved(p, rng.uniform(0., 6.), Vector2(rng.uniform(-3., 3.), rng.uniform(-3., 3.))), tris);
  }
  for(int c = 0; c < 18; ++c)
    add_grid(atlas, 0.7, 0.7, 1, 1, rng.uniform(0., 6.), Vector2(rng.uniform(-3., 3.), rng.uniform(-3., 3.)));
  // padding 2 (with padding 0 both find 0.572 when written: the rectangles' layout)
  for(double padding : {2.})
  {
    SCOPED_TRACE("padding " + to_text(padding));
    ic::Packing_settings s;
    s.padding = padding;
    s.texture_size = 128;
    ic::UV_vector by_raster, by_skyline;
    const auto start = std::chrono::steady_clock::now();
    const ic::Packing_result a = pack(atlas, by_raster, s);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    s.raster = false;
    const ic::Packing_result b = pack(atlas, by_skyline, s);
    EXPECT_TRUE(a.by_shape && a.by_raster);
    EXPECT_FALSE(b.by_raster);
    check_layout(atlas, atlas.x(), by_raster, a, padding / 128., true);
    check_layout(atlas, atlas.x(), by_skyline, b, padding / 128., true);
    std::cout << "  padding " << padding << ": coverage by raster " << a.coverage << " (" << seconds
              << " s), by skyline " << b.coverage << (b.by_shape ? "" : " (rectangles)") << std::endl;
    EXPECT_TRUE(a.coverage > b.coverage); // 0.517 against 0.470 when written
    EXPECT_LT(seconds, 1.);
  }
}

namespace {
// A w × h raster whose every texel is set (its extents the whole rectangle).
ic::packing::Chart_raster full_raster(int w, int h)
{
  ic::packing::Chart_raster r;
  r.w = w; r.h = h; r.words = (w + 63) / 64;
  r.col_lo.assign(w, 0); r.col_hi.assign(w, h - 1);
  r.row_lo.assign(h, 0); r.row_hi.assign(h, w - 1);
  r.bits.assign(std::size_t(h) * r.words, 0);
  for(int j = 0; j < h; ++j) ic::packing::set_bits(&r.bits[std::size_t(j) * r.words], 0, w - 1);
  return r;
}
} // namespace

TEST(Packing, a_one_row_raster_is_placed_beside_a_chart_in_its_row)
{
  // the first row tried holds a chart at its left: the one-row raster's
  // position moves right, where its single row agrees at once (once looped
  // forever: a sliver chart of CGAL's mpi_triang.off)
  const int n = 128, pad = 2;
  ic::packing::Raster_page page(n, pad);
  ic::packing::Raster_placement square, sliver, turned;
  ASSERT_TRUE(page.drop(full_raster(30, 30), square));
  EXPECT_EQ(square.x, pad);
  EXPECT_EQ(square.y, pad);
  ASSERT_TRUE(page.drop(full_raster(40, 1), sliver));
  EXPECT_EQ(sliver.turn % 2, 0);
  EXPECT_EQ(sliver.y, pad);                     // the lowest row
  EXPECT_GT(sliver.x, square.x + 30 + pad - 1); // right of the square, more than pad texels apart
  EXPECT_LE(sliver.x + 40, n - pad);
  // a one-column raster: placed turned into one row, or upright beside them
  ASSERT_TRUE(page.drop(full_raster(1, 40), turned));
  const bool lying = turned.turn % 2 != 0;
  EXPECT_LE(turned.x + (lying ? 40 : 1), n - pad);
  EXPECT_LE(turned.y + (lying ? 1 : 40), n - pad);
}
