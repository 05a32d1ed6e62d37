#include "packing.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/atlas/chart_packing.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

namespace cut_benchmark {

namespace {

namespace ic = CGAL::Surface_mesh_parameterization::internal::cut;
using ic::Vector2;

/// `count` charts of random shapes, sizes (1 to 5 times) and angles, scattered.
void generated_charts(int count, ic::Chart_mesh& mesh, ic::UV_vector& x)
{
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::vector<Vector2> uv;
  auto add = [&](std::vector<Vector2> p, const std::vector<std::array<int, 3>>& triangles) {
    const double a = 6.3 * unit(rng), c = std::cos(a), s = std::sin(a);
    const Vector2 t(10. * unit(rng), 10. * unit(rng));
    const int offset = int(uv.size());
    for(Vector2& q : p) uv.push_back(Vector2(c * q.x() - s * q.y(), s * q.x() + c * q.y()) + t);
    for(const auto& tri : triangles)
    {
      const std::size_t f = mesh.number_of_faces();
      mesh.resize_faces(f + 1);
      mesh.faces[f] = {tri[0] + offset, tri[1] + offset, tri[2] + offset};
      auto p3 = [&](int i) { return ic::Vector3(p[i].x(), p[i].y(), 0.); };
      mesh.set_rest_shape(f, p3(tri[0]), p3(tri[1]), p3(tri[2]));
    }
  };
  for(int k = 0; k < count; ++k)
  {
    const double s = 1. + 4. * unit(rng), r = 0.2 + 0.8 * unit(rng);
    switch(k % 4)
    {
      case 0: add({{0., 0.}, {s, 0.}, {s, r * s}, {0., r * s}}, {{{0, 1, 2}}, {{0, 2, 3}}}); break;
      case 1: add({{0., 0.}, {s, 0.}, {s, 0.5 * s}, {0.5 * s, 0.5 * s}, {0.5 * s, s}, {0., s}},
                  {{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}, {{0, 4, 5}}}); break; // an L
      case 2: add({{0., 0.}, {s, 0.}, {0., r * s}}, {{{0, 1, 2}}}); break;
      default:
      {
        std::vector<Vector2> p{{0., 0.}};
        std::vector<std::array<int, 3>> t;
        for(int i = 0; i < 8; ++i)
        {
          p.emplace_back(0.5 * s * std::cos(0.785398 * i), 0.5 * r * s * std::sin(0.785398 * i));
          t.push_back({0, 1 + i, 1 + (i + 1) % 8});
        }
        add(p, t);
      }
    }
  }
  mesh.number_of_vertices = int(uv.size());
  x.resize(2 * uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i) x.segment<2>(2 * i) = uv[i];
}

} // namespace

int run_packing(const Options&)
{
  std::printf("Atlas packing of generated charts (padding 2 texels)\n");
  std::printf("%8s %8s %12s %10s %12s %10s %9s\n", "charts", "texels", "rect s", "rect cov", "shape s", "shape cov",
              "by shape");
  for(int count : {1000, 10000})
    for(int texels : {1024, 4096})
    {
      ic::Chart_mesh mesh;
      ic::UV_vector input;
      generated_charts(count, mesh, input);
      double seconds[2], coverage[2];
      bool by_shape = false;
      for(int shapes = 0; shapes < 2; ++shapes)
      {
        ic::UV_vector x = input;
        ic::Packing_settings settings;
        settings.texture_size = texels;
        settings.shapes = shapes == 1;
        const auto start = std::chrono::steady_clock::now();
        const ic::Packing_result r = ic::pack_charts(mesh, x, settings);
        seconds[shapes] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        coverage[shapes] = r.coverage;
        if(shapes) by_shape = r.by_shape;
      }
      std::printf("%8d %8d %12.3f %10.3f %12.3f %10.3f %9s\n", count, texels, seconds[0], coverage[0], seconds[1],
                  coverage[1], by_shape ? "yes" : "no");
    }
  return 0;
}

} // namespace cut_benchmark
