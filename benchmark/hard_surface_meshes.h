// Generated hard-surface meshes, tessellated as CAD exporters do: planar
// outlines (with holes) extruded, each cap a constrained Delaunay
// triangulation of its outline without Steiner points (long thin triangles,
// fans around holes), each side wall one quad per outline segment split into
// two triangles (slivers), every outline edge a sharp crease. Shapes:
// extruded gears with a bore, plates with a grid of round holes, L brackets
// with holes, cylinders with few segments and fan caps.
#ifndef CUT_PARAM_BENCHMARK_HARD_SURFACE_MESHES_H
#define CUT_PARAM_BENCHMARK_HARD_SURFACE_MESHES_H

#include "benchmark_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <list>
#include <string>
#include <vector>

namespace cut_benchmark {
namespace hard_surface {

using Loop = std::vector<std::array<double, 2>>; // a closed outline, counter-clockwise for the outside

/// A circle of `n` segments, counter-clockwise (reversed: a hole).
inline Loop circle(double cx, double cy, double r, int n, bool hole)
{
  Loop loop;
  for(int i = 0; i < n; ++i)
  {
    const double a = 2. * CGAL_PI * (hole ? -i : i) / n;
    loop.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return loop;
}

/// The region bounded by `outer` (counter-clockwise) minus `holes`
/// (clockwise) extruded to `height`: a closed mesh (see the file's comment).
inline Mesh extrude(const Loop& outer, const std::vector<Loop>& holes, double height)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  struct Face_info { int nesting = -1; };
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
  using Fbi = CGAL::Triangulation_face_base_with_info_2<Face_info, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

  std::vector<const Loop*> loops{&outer};
  for(const Loop& h : holes) loops.push_back(&h);
  std::vector<std::array<double, 2>> points;
  CDT cdt;
  for(const Loop* loop : loops)
  {
    std::vector<CDT::Vertex_handle> handles;
    for(const auto& p : *loop)
    {
      handles.push_back(cdt.insert(K::Point_2(p[0], p[1])));
      handles.back()->info() = int(points.size());
      points.push_back(p);
    }
    for(std::size_t i = 0; i < handles.size(); ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  }
  // faces inside: odd nesting level, found by a flood fill across constraints
  std::list<CDT::Edge> border;
  auto fill = [&](CDT::Face_handle start, int level) {
    std::list<CDT::Face_handle> queue{start};
    while(!queue.empty())
    {
      CDT::Face_handle f = queue.front();
      queue.pop_front();
      if(f->info().nesting != -1) continue;
      f->info().nesting = level;
      for(int i = 0; i < 3; ++i)
      {
        CDT::Face_handle n = f->neighbor(i);
        if(n->info().nesting != -1) continue;
        if(cdt.is_constrained(CDT::Edge(f, i))) border.push_back(CDT::Edge(f, i));
        else queue.push_back(n);
      }
    }
  };
  fill(cdt.infinite_face(), 0);
  while(!border.empty())
  {
    CDT::Edge e = border.front();
    border.pop_front();
    CDT::Face_handle n = e.first->neighbor(e.second);
    if(n->info().nesting == -1) fill(n, e.first->info().nesting + 1);
  }

  Mesh mesh;
  const std::size_t n = points.size();
  std::vector<Mesh::Vertex_index> bottom(n), top(n);
  for(std::size_t i = 0; i < n; ++i) bottom[i] = mesh.add_vertex(Kernel::Point_3(points[i][0], points[i][1], 0.));
  for(std::size_t i = 0; i < n; ++i) top[i] = mesh.add_vertex(Kernel::Point_3(points[i][0], points[i][1], height));
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if(f->info().nesting % 2 != 1) continue;
    const int a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
    mesh.add_face(top[a], top[b], top[c]);
    mesh.add_face(bottom[a], bottom[c], bottom[b]);
  }
  std::size_t first = 0;
  for(const Loop* loop : loops)
  {
    const std::size_t m = loop->size();
    for(std::size_t i = 0; i < m; ++i)
    {
      const std::size_t a = first + i, b = first + (i + 1) % m;
      mesh.add_face(bottom[a], bottom[b], top[b]);
      mesh.add_face(bottom[a], top[b], top[a]);
    }
    first += m;
  }
  return mesh;
}

/// A spur gear of `teeth` teeth (trapezoids, `tooth_points` points on each
/// tip and root arc) around a round bore of `bore_segments` segments.
inline Mesh gear(int teeth, int tooth_points, int bore_segments, double thickness)
{
  const double root = 1., tip = 1.2;
  Loop outer;
  for(int t = 0; t < teeth; ++t)
  {
    const double a0 = 2. * CGAL_PI * t / teeth, step = 2. * CGAL_PI / teeth;
    for(int k = 0; k < tooth_points; ++k) // root arc, then tip arc (narrower)
    {
      const double a = a0 + 0.5 * step * k / tooth_points;
      outer.push_back({root * std::cos(a), root * std::sin(a)});
    }
    for(int k = 0; k < tooth_points; ++k)
    {
      const double a = a0 + step * (0.6 + 0.3 * k / std::max(1, tooth_points - 1));
      outer.push_back({tip * std::cos(a), tip * std::sin(a)});
    }
  }
  return extrude(outer, {circle(0., 0., 0.3, bore_segments, true)}, thickness);
}

/// A rectangular plate `nx` x `ny` holes of `segments` segments each.
inline Mesh plate(int nx, int ny, int segments, double thickness)
{
  const double pitch = 1.;
  const Loop outer{{0., 0.}, {nx * pitch, 0.}, {nx * pitch, ny * pitch}, {0., ny * pitch}};
  std::vector<Loop> holes;
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j) holes.push_back(circle((i + 0.5) * pitch, (j + 0.5) * pitch, 0.3 * pitch, segments, true));
  return extrude(outer, holes, thickness);
}

/// An L bracket (legs 4 x 1) with `holes` holes of `segments` segments along each leg.
inline Mesh bracket(int holes, int segments, double thickness)
{
  const Loop outer{{0., 0.}, {4., 0.}, {4., 1.}, {1., 1.}, {1., 4.}, {0., 4.}};
  std::vector<Loop> loops;
  const double spacing = 2.2 / holes, r = std::min(0.25, 0.4 * spacing); // holes apart
  for(int i = 0; i < holes; ++i)
  {
    const double s = 1.5 + spacing * (i + 0.5);
    loops.push_back(circle(s, 0.5, r, segments, true));
    loops.push_back(circle(0.5, s, r, segments, true));
  }
  return extrude(outer, loops, thickness);
}

/// A cylinder of `segments` segments, `length` long (radius 1): fan caps, long side slivers.
inline Mesh cylinder(int segments, double length) { return extrude(circle(0., 0., 1., segments, false), {}, length); }

struct Generated
{
  std::string name;
  Mesh (*make)();
};

/// The generated corpus, from about 100 to about 100k faces.
inline const std::vector<Generated>& generated_meshes()
{
  static const std::vector<Generated> list{
    {"cylinder_12", [] { return cylinder(12, 8.); }},
    {"cylinder_24", [] { return cylinder(24, 3.); }},
    {"gear_20_teeth", [] { return gear(20, 6, 48, 0.3); }},
    {"gear_48_teeth", [] { return gear(48, 10, 96, 0.4); }},
    {"bracket_2_holes", [] { return bracket(2, 64, 0.2); }},
    {"bracket_6_holes", [] { return bracket(6, 96, 0.2); }},
    {"plate_3x2_holes", [] { return plate(3, 2, 64, 0.1); }},
    {"plate_8x6_holes", [] { return plate(8, 6, 64, 0.1); }},
    {"plate_12x10_holes", [] { return plate(12, 10, 96, 0.1); }},
    {"plate_20x16_holes", [] { return plate(20, 16, 96, 0.1); }},
  };
  return list;
}

/// CGAL's CAD-like meshes of its data set (meshes/), in the hard-surface corpus.
inline const std::vector<std::string>& cgal_cad_meshes()
{
  static const std::vector<std::string> list{"cross.off", "part.off", "joint.off", "anchor.off", "anchor_dense.off",
                                             "fandisk.off", "mech-holes-shark.off", "blade.off", "fandisk_large.off"};
  return list;
}

} // namespace hard_surface
} // namespace cut_benchmark

#endif
