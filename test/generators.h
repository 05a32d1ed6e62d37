// Mesh generators for the tests, and a few topology helpers.
//
// Every generator returns a `Soup` (points, faces as point indices, and for
// closed surfaces a `cut`: edges, as pairs of point indices, along which the
// surface opens into a topological disk). `build_mesh()` turns a soup into
// any CGAL MutableFaceGraph (Surface_mesh, Polyhedron_3, ...) and returns the
// mesh vertex of every soup point; `soup_edges()` maps index pairs to mesh
// edges.
//
//   auto soup = cut_test::sphere_soup(4);
//   Mesh mesh;
//   auto vertex_of = cut_test::build_mesh(soup, mesh);
//   auto seams = cut_test::soup_edges(mesh, vertex_of, soup.cut);
//
// All generators are deterministic (their own RNG, no std:: distributions).
#ifndef CUT_PARAM_TEST_GENERATORS_H
#define CUT_PARAM_TEST_GENERATORS_H

#include "test_support.h"

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace cut_test {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;

/// The mesh types every typed test is instantiated for:
/// TYPED_TEST_SUITE(Suite, Mesh_types). CTest names the cases Suite.case<0>
/// (Surface_mesh) and Suite.case<1> (Polyhedron_3).
using Mesh_types = ::testing::Types<Surface_mesh, Polyhedron>;

/// splitmix64: small, portable, reproducible.
class Rng
{
  std::uint64_t state_;

public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next()
  {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
};

constexpr double pi = 3.14159265358979323846;

struct Soup
{
  using Point = std::array<double, 3>;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  /// For closed (or otherwise non-disk) surfaces: edges to cut to get a topological disk.
  std::vector<std::pair<std::size_t, std::size_t>> cut;

  std::size_t add_point(double x, double y, double z)
  {
    points.push_back({x, y, z});
    return points.size() - 1;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) { faces.push_back({a, b, c}); }

  /// Applies f to every point.
  Soup& transform(const std::function<Point(const Point&)>& f)
  {
    for(Point& p : points) p = f(p);
    return *this;
  }
  Soup& scale(double s)
  {
    return transform([s](const Point& p) { return Point{s * p[0], s * p[1], s * p[2]}; });
  }
  Soup& translate(double dx, double dy, double dz)
  {
    return transform([=](const Point& p) { return Point{p[0] + dx, p[1] + dy, p[2] + dz}; });
  }
  /// Appends another soup (a separate component).
  Soup& append(const Soup& other)
  {
    const std::size_t offset = points.size();
    points.insert(points.end(), other.points.begin(), other.points.end());
    for(auto f : other.faces)
    {
      for(auto& i : f) i += offset;
      faces.push_back(f);
    }
    for(const auto& e : other.cut) cut.emplace_back(e.first + offset, e.second + offset);
    return *this;
  }
  /// Drops points no face uses (renumbering faces and cut).
  Soup& remove_unused_points()
  {
    std::vector<std::size_t> new_index(points.size(), std::size_t(-1));
    std::vector<Point> kept;
    for(auto& f : faces)
      for(auto& i : f)
      {
        if(new_index[i] == std::size_t(-1))
        {
          new_index[i] = kept.size();
          kept.push_back(points[i]);
        }
        i = new_index[i];
      }
    for(auto& e : cut)
    {
      e.first = new_index[e.first];
      e.second = new_index[e.second];
    }
    points.swap(kept);
    return *this;
  }
};

/// Flat nx × ny grid of [0,width]×[0,height] in the plane z = 0, each cell
/// split along a diagonal that alternates like a checkerboard. A disk.
inline Soup grid_soup(int nx, int ny, double width = 1., double height = 1.)
{
  Soup s;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      s.add_point(width * i / nx, height * j / ny, 0.);
  auto v = [nx](int i, int j) { return std::size_t(j * (nx + 1) + i); };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      if((i + j) % 2 == 0)
      {
        s.add_triangle(v(i, j), v(i + 1, j), v(i + 1, j + 1));
        s.add_triangle(v(i, j), v(i + 1, j + 1), v(i, j + 1));
      }
      else
      {
        s.add_triangle(v(i, j), v(i + 1, j), v(i, j + 1));
        s.add_triangle(v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
      }
    }
  return s;
}

/// Moves every point by a random in-plane (x, y) offset of at most
/// `amount` in each coordinate. With amount < 1/4 of the grid spacing a grid
/// stays free of flipped or degenerate triangles.
inline Soup& jitter_xy(Soup& s, double amount, std::uint64_t seed)
{
  Rng rng(seed);
  for(auto& p : s.points)
  {
    p[0] += rng.uniform(-amount, amount);
    p[1] += rng.uniform(-amount, amount);
  }
  return s;
}

/// Polar disk: a center point and `rings` rings of `sectors` points, mapped
/// to 3D by f(r, theta) with r in [0, 1] (r = 0 the center, r = 1 the
/// border) and theta in [0, 2π). Faces are oriented counterclockwise in the
/// (r cos θ, r sin θ) plane. A disk.
inline Soup polar_disk_soup(int rings, int sectors,
                            const std::function<Soup::Point(double r, double theta)>& f)
{
  Soup s;
  const Soup::Point c = f(0., 0.);
  s.add_point(c[0], c[1], c[2]);
  for(int i = 1; i <= rings; ++i)
    for(int k = 0; k < sectors; ++k)
    {
      const Soup::Point p = f(double(i) / rings, 2. * pi * k / sectors);
      s.add_point(p[0], p[1], p[2]);
    }
  auto v = [sectors](int i, int k) { return std::size_t(1 + (i - 1) * sectors + (k % sectors)); };
  for(int k = 0; k < sectors; ++k) s.add_triangle(0, v(1, k), v(1, k + 1));
  for(int i = 1; i < rings; ++i)
    for(int k = 0; k < sectors; ++k)
    {
      s.add_triangle(v(i, k), v(i + 1, k), v(i + 1, k + 1));
      s.add_triangle(v(i, k), v(i + 1, k + 1), v(i, k + 1));
    }
  return s;
}

/// Flat polar disk of the given radius in the plane z = 0.
inline Soup flat_disk_soup(int rings, int sectors, double radius = 1.)
{
  return polar_disk_soup(rings, sectors, [radius](double r, double t) {
    return Soup::Point{radius * r * std::cos(t), radius * r * std::sin(t), 0.};
  });
}

/// Upper hemisphere of a sphere of the given radius (pole at +z, open along
/// the equator). A disk, not developable.
inline Soup hemisphere_soup(int rings, int sectors, double radius = 1.)
{
  return polar_disk_soup(rings, sectors, [radius](double r, double t) {
    const double phi = 0.5 * pi * r;
    return Soup::Point{radius * std::sin(phi) * std::cos(t), radius * std::sin(phi) * std::sin(t),
                       radius * std::cos(phi)};
  });
}

/// A finger: a tube of the given radius and length, closed at its tip by a
/// hemisphere and open at its base circle; the rings run evenly from the
/// tip (r = 0) to the base. A disk whose Tutte map puts the base on the
/// circle and squeezes the tube inside it, each ring smaller than the last
/// by about the same factor: with many more rings than the tube's
/// circumference holds edges, the tip's faces are crushed by orders of
/// magnitude (a long bone or limb cut along a short seam).
inline Soup finger_soup(int rings, int sectors, double radius = 0.5, double length = 4.)
{
  const double cap = 0.5 * pi * radius;
  return polar_disk_soup(rings, sectors, [=](double r, double t) {
    const double s = r * (cap + length);
    if(s < cap)
    {
      const double phi = s / radius;
      return Soup::Point{radius * std::sin(phi) * std::cos(t), radius * std::sin(phi) * std::sin(t),
                         -radius * std::cos(phi)};
    }
    return Soup::Point{radius * std::cos(t), radius * std::sin(t), s - cap};
  });
}

/// Cone with its apex at (0, 0, height), open along its base circle. A disk
/// with one interior vertex (the apex) of positive curvature.
inline Soup cone_soup(int rings, int sectors, double radius = 1., double height = 1.)
{
  return polar_disk_soup(rings, sectors, [=](double r, double t) {
    return Soup::Point{radius * r * std::cos(t), radius * r * std::sin(t), height * (1. - r)};
  });
}

/// A random-ish disk: polar disk with jittered radii and angles (the border
/// too) and a wavy height field. Deterministic for a given seed.
inline Soup wavy_disk_soup(int rings, int sectors, std::uint64_t seed = 1)
{
  Rng rng(seed);
  return polar_disk_soup(rings, sectors, [&](double r, double t) {
    if(r == 0.) return Soup::Point{0., 0., 0.3};
    const double rr = r + rng.uniform(-0.25, 0.25) / rings;
    const double tt = t + rng.uniform(-0.25, 0.25) * 2. * pi / sectors;
    const double x = rr * std::cos(tt), y = rr * std::sin(tt);
    const double z = 0.3 * std::cos(2. * pi * rr) + 0.15 * rr * rr * std::sin(3. * tt) + 0.1 * x * y;
    return Soup::Point{x, y, z};
  });
}

/// A piece of the cylinder of the given radius around the z axis: `angle`
/// radians (< 2π) around, `height` high, n_around × n_up cells. A
/// developable disk.
inline Soup cylinder_patch_soup(int n_around, int n_up, double radius = 1., double angle = 0.5 * pi,
                                double height = 1.)
{
  Soup s = grid_soup(n_around, n_up, angle, height);
  return s.transform([radius](const Soup::Point& p) {
    return Soup::Point{radius * std::cos(p[0]), radius * std::sin(p[0]), p[1]};
  });
}

/// Closed axis-aligned box [0,a] x [0,b] x [0,c], two triangles per side
/// (a cube by default): the low-poly case, its curvature all in 8 corners.
inline Soup box_soup(double a = 1., double b = 1., double c = 1.)
{
  Soup s;
  for(int k = 0; k < 8; ++k) s.add_point(k & 1 ? a : 0., k & 2 ? b : 0., k & 4 ? c : 0.);
  // sides as quads (outward normals), split along a diagonal
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads)
  {
    s.add_triangle(q[0], q[1], q[2]);
    s.add_triangle(q[0], q[2], q[3]);
  }
  return s;
}

/// Closed sphere: octahedron with every face split into n² triangles,
/// projected on the sphere of the given radius. `cut` is a path from the
/// north pole (0,0,r) through (r,0,0) to the south pole, whose cutting leaves a disk.
inline Soup sphere_soup(int n, double radius = 1.)
{
  Soup s;
  std::map<std::array<int, 3>, std::size_t> index;
  auto vertex = [&](int a, int b, int c) {
    const std::array<int, 3> key{a, b, c};
    auto it = index.find(key);
    if(it != index.end()) return it->second;
    const double norm = std::sqrt(double(a) * a + double(b) * b + double(c) * c);
    const std::size_t i = s.add_point(radius * a / norm, radius * b / norm, radius * c / norm);
    index.emplace(key, i);
    return i;
  };
  for(int sx = -1; sx <= 1; sx += 2)
    for(int sy = -1; sy <= 1; sy += 2)
      for(int sz = -1; sz <= 1; sz += 2)
      {
        const bool flip = sx * sy * sz < 0;
        auto tri = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
          const std::size_t a = vertex(sx * i0, sy * j0, sz * (n - i0 - j0));
          const std::size_t b = vertex(sx * i1, sy * j1, sz * (n - i1 - j1));
          const std::size_t c = vertex(sx * i2, sy * j2, sz * (n - i2 - j2));
          if(flip) s.add_triangle(a, c, b);
          else s.add_triangle(a, b, c);
        };
        for(int i = 0; i < n; ++i)
          for(int j = 0; i + j < n; ++j)
          {
            tri(i, j, i + 1, j, i, j + 1);
            if(i + j < n - 1) tri(i + 1, j, i + 1, j + 1, i, j + 1);
          }
      }
  for(int i = 0; i < n; ++i) s.cut.emplace_back(vertex(i, 0, n - i), vertex(i + 1, 0, n - i - 1));
  for(int i = 0; i < n; ++i) s.cut.emplace_back(vertex(n - i, 0, -i), vertex(n - i - 1, 0, -i - 1));
  return s;
}

/// Closed torus (genus 1) around the z axis, radii R > r, nu × nv cells
/// (nu, nv >= 3). `cut` is one meridian and one longitude through the same
/// vertex: cutting both leaves a disk (a square).
inline Soup torus_soup(int nu, int nv, double R = 1., double r = 0.4)
{
  Soup s;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double u = 2. * pi * i / nu, v = 2. * pi * j / nv;
      s.add_point((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto idx = [=](int i, int j) { return std::size_t((i % nu) * nv + (j % nv)); };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      s.add_triangle(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
      s.add_triangle(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
    }
  for(int i = 0; i < nu; ++i) s.cut.emplace_back(idx(i, 0), idx(i + 1, 0));
  for(int j = 0; j < nv; ++j) s.cut.emplace_back(idx(0, j), idx(0, j + 1));
  return s;
}

/// n × n flat grid of the unit square with `holes` square holes of 2 × 2
/// cells along the diagonal, apart from each other and from the border.
/// Requires n >= 3 * holes + 1. Genus 0, 1 + holes border cycles.
inline Soup disk_with_holes_soup(int n, int holes)
{
  if(n < 3 * holes + 1) throw std::invalid_argument("disk_with_holes_soup: grid too small");
  Soup grid = grid_soup(n, n);
  Soup s;
  s.points = grid.points;
  // grid_soup emits two triangles per cell, cell (i, j) at 2 * (j * n + i)
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      bool in_hole = false;
      for(int h = 0; h < holes; ++h)
      {
        const int lo = 1 + 3 * h;
        if(i >= lo && i <= lo + 1 && j >= lo && j <= lo + 1) in_hole = true;
      }
      if(in_hole) continue;
      const std::size_t cell = std::size_t(2 * (j * n + i));
      s.faces.push_back(grid.faces[cell]);
      s.faces.push_back(grid.faces[cell + 1]);
    }
  s.remove_unused_points();
  return s;
}

/// Two disjoint flat grids (n × n each), side by side.
inline Soup two_components_soup(int n)
{
  Soup s = grid_soup(n, n);
  Soup other = grid_soup(n, n);
  other.translate(2., 0., 0.5);
  return s.append(other);
}

/// Flat nx × ny grid of quads (not triangulated).
inline Soup quad_grid_soup(int nx, int ny)
{
  Soup s;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      s.add_point(double(i) / nx, double(j) / ny, 0.);
  auto v = [nx](int i, int j) { return std::size_t(j * (nx + 1) + i); };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      s.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
  return s;
}

// ---------------------------------------------------------------------------
// Soup -> mesh

template <typename Mesh>
using Vertex_of = std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>;

template <typename Mesh>
using Mesh_point = typename boost::property_traits<
  typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;

/// Adds the soup to `mesh`; returns the vertex of every soup point. Throws
/// std::runtime_error if a face cannot be added (non-manifold soup).
template <typename Mesh>
Vertex_of<Mesh> build_mesh(const Soup& soup, Mesh& mesh)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Point = Mesh_point<Mesh>;
  auto vpm = get(CGAL::vertex_point, mesh);
  Vertex_of<Mesh> vertex_of;
  vertex_of.reserve(soup.points.size());
  for(const auto& p : soup.points)
  {
    const vertex_descriptor v = add_vertex(mesh);
    put(vpm, v, Point(p[0], p[1], p[2]));
    vertex_of.push_back(v);
  }
  for(const auto& f : soup.faces)
  {
    std::vector<vertex_descriptor> vs;
    for(std::size_t i : f) vs.push_back(vertex_of.at(i));
    if(CGAL::Euler::add_face(vs, mesh) == boost::graph_traits<Mesh>::null_face())
      throw std::runtime_error("build_mesh: cannot add a face");
  }
  return vertex_of;
}

template <typename Mesh>
Mesh make_mesh(const Soup& soup)
{
  Mesh mesh;
  build_mesh(soup, mesh);
  return mesh;
}

/// Mesh edges of the given soup index pairs. Throws if a pair is not an edge.
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::edge_descriptor>
soup_edges(const Mesh& mesh, const Vertex_of<Mesh>& vertex_of,
           const std::vector<std::pair<std::size_t, std::size_t>>& pairs)
{
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> result;
  for(const auto& p : pairs)
  {
    const auto h = halfedge(vertex_of.at(p.first), vertex_of.at(p.second), mesh);
    if(!h.second) throw std::runtime_error("soup_edges: not an edge of the mesh");
    result.push_back(edge(h.first, mesh));
  }
  return result;
}

// ---------------------------------------------------------------------------
// Topology helpers (any FaceListGraph / HalfedgeListGraph)

/// V - E + F.
template <typename Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

/// Number of border cycles (holes).
template <typename Mesh>
std::size_t number_of_border_cycles(const Mesh& mesh)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  std::vector<halfedge_descriptor> border;
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh)) border.push_back(h);
  std::unordered_map<halfedge_descriptor, bool> seen;
  std::size_t cycles = 0;
  for(halfedge_descriptor h : border)
  {
    if(seen[h]) continue;
    ++cycles;
    halfedge_descriptor g = h;
    do
    {
      seen[g] = true;
      g = next(g, mesh);
    } while(g != h);
  }
  return cycles;
}

/// Number of connected components (through edges), isolated vertices included.
template <typename Mesh>
std::size_t number_of_components(const Mesh& mesh)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::unordered_map<vertex_descriptor, bool> seen;
  std::size_t components = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    if(seen[v]) continue;
    ++components;
    std::vector<vertex_descriptor> stack{v};
    seen[v] = true;
    while(!stack.empty())
    {
      const vertex_descriptor u = stack.back();
      stack.pop_back();
      if(halfedge(u, mesh) == boost::graph_traits<Mesh>::null_halfedge()) continue;
      for(vertex_descriptor w : vertices_around_target(u, mesh))
        if(!seen[w])
        {
          seen[w] = true;
          stack.push_back(w);
        }
    }
  }
  return components;
}

/// Genus of a connected orientable surface with `b` border cycles:
/// χ = 2 - 2g - b.
template <typename Mesh>
long genus(const Mesh& mesh)
{
  return (2 - euler_characteristic(mesh) - long(number_of_border_cycles(mesh))) / 2;
}

/// Edges of a path with fewest edges from a to b (breadth-first search);
/// empty if b is unreachable or a == b.
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::edge_descriptor>
shortest_edge_path(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor a,
                   typename boost::graph_traits<Mesh>::vertex_descriptor b)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  std::unordered_map<vertex_descriptor, halfedge_descriptor> reached_by; // halfedge whose target is the key
  std::unordered_map<vertex_descriptor, bool> seen;
  std::queue<vertex_descriptor> queue;
  queue.push(a);
  seen[a] = true;
  while(!queue.empty() && !seen[b])
  {
    const vertex_descriptor u = queue.front();
    queue.pop();
    for(halfedge_descriptor h : halfedges_around_source(u, mesh))
    {
      const vertex_descriptor w = target(h, mesh);
      if(seen[w]) continue;
      seen[w] = true;
      reached_by[w] = h;
      queue.push(w);
    }
  }
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> path;
  if(a == b || !seen[b]) return path;
  for(vertex_descriptor v = b; v != a; v = source(reached_by[v], mesh))
    path.push_back(edge(reached_by[v], mesh));
  return path;
}

// ---------------------------------------------------------------------------
// More shapes (for the cut-and-parameterize tests)

/// Polar disk of radius 1 in the plane z = 0 with a tall narrow bump at its
/// center: z = height · exp(-(ρ / width)²). The rings are denser near the
/// center (ρ = r^1.5) so the bump is resolved. A disk with one obvious place
/// to cut: the bump.
inline Soup spike_disk_soup(int rings, int sectors, double height = 1.5, double width = 0.2)
{
  return polar_disk_soup(rings, sectors, [=](double r, double t) {
    const double rho = std::pow(r, 1.5);
    return Soup::Point{rho * std::cos(t), rho * std::sin(t),
                       height * std::exp(-(rho / width) * (rho / width))};
  });
}

/// Cap of the unit sphere around the pole +z, from the pole to the polar
/// angle `angle` (π/2: the hemisphere; close to π: a deep bowl whose rim is
/// narrower than its belly). A disk, far from developable for large angles.
inline Soup sphere_cap_soup(int rings, int sectors, double angle)
{
  return polar_disk_soup(rings, sectors, [angle](double r, double t) {
    const double phi = angle * r;
    return Soup::Point{std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t), std::cos(phi)};
  });
}

/// Closed surface enclosing the slab `sheet` × [-thickness/2, thickness/2]:
/// the sheet (triangles, oriented counterclockwise seen from +z, lying in a
/// plane z = const) is copied to the top and, reversed, to the bottom, and
/// every border edge gets a wall of two triangles. Outward oriented. A flat
/// sheet with b border cycles gives a closed surface of genus b - 1.
inline Soup thickened_soup(const Soup& sheet, double thickness)
{
  Soup s;
  const std::size_t n = sheet.points.size();
  for(const auto& p : sheet.points) s.add_point(p[0], p[1], p[2] + 0.5 * thickness);
  for(const auto& p : sheet.points) s.add_point(p[0], p[1], p[2] - 0.5 * thickness);
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& f : sheet.faces)
  {
    if(f.size() != 3) throw std::invalid_argument("thickened_soup: triangles only");
    s.add_triangle(f[0], f[1], f[2]);
    s.add_triangle(n + f[0], n + f[2], n + f[1]);
    for(int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
  }
  for(const auto& f : sheet.faces)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = f[k], b = f[(k + 1) % 3];
      if(directed.count({b, a})) continue; // interior edge
      // top has a -> b, bottom has b' -> a': the wall has b -> a and a' -> b'
      s.add_triangle(b, a, n + a);
      s.add_triangle(b, n + a, n + b);
    }
  return s;
}

/// Closed genus-2 surface: a thickened n × n square plate with two square
/// holes (a "figure eight"), see thickened_soup() and disk_with_holes_soup().
inline Soup double_torus_soup(int n = 8, double thickness = 0.1)
{
  return thickened_soup(disk_with_holes_soup(n, 2), thickness);
}

// ---------------------------------------------------------------------------
// Shapes whose best flattening overlaps itself (global injectivity tests)

/// Grid of (n_along + 1) × (n_across + 1) points f(s, t), s, t in [0, 1],
/// split into triangles; with `wrap`, the last column is the first one
/// (a closed band).
inline Soup parametric_strip_soup(int n_along, int n_across, bool wrap,
                                  const std::function<Soup::Point(double s, double t)>& f)
{
  Soup soup;
  const int columns = wrap ? n_along : n_along + 1;
  for(int i = 0; i < columns; ++i)
    for(int j = 0; j <= n_across; ++j)
    {
      const Soup::Point p = f(double(i) / n_along, double(j) / n_across);
      soup.add_point(p[0], p[1], p[2]);
    }
  auto v = [=](int i, int j) { return std::size_t((i % columns) * (n_across + 1) + j); };
  for(int i = 0; i < n_along; ++i)
    for(int j = 0; j < n_across; ++j)
    {
      soup.add_triangle(v(i, j), v(i + 1, j), v(i + 1, j + 1));
      soup.add_triangle(v(i, j), v(i + 1, j + 1), v(i, j + 1));
    }
  return soup;
}

/// The ramp of a spiral staircase: a narrow helicoidal strip going `turns`
/// times around the z axis between radii 1 and 1 + width, rising `pitch`
/// per turn. Nearly developable; laid flat it is an arc of about 2π · turns:
/// beyond one turn its ends overlap unless the map is kept injective.
inline Soup spiral_ramp_soup(int n_along, int n_across, double turns = 1.5, double width = 0.3,
                             double pitch = 0.2)
{
  return parametric_strip_soup(n_along, n_across, false, [=](double s, double t) {
    const double angle = 2. * pi * turns * s, radius = 1. + width * t;
    return Soup::Point{radius * std::cos(angle), radius * std::sin(angle), pitch * turns * s};
  });
}

/// A thin annulus on a monkey saddle, radii 0.8 to 1, z = amplitude · r³ ·
/// sin(3θ): its inner circle has a total geodesic curvature above 2π (the
/// saddle inside has negative curvature), so once cut open it lays flat over
/// more than a full turn and its ends overlap unless kept injective.
inline Soup saddle_annulus_soup(int n_around, int n_across, double amplitude = 0.8)
{
  return parametric_strip_soup(n_around, n_across, true, [=](double s, double t) {
    const double angle = 2. * pi * s, radius = 0.8 + 0.2 * t;
    return Soup::Point{radius * std::cos(angle), radius * std::sin(angle),
                       amplitude * radius * radius * radius * std::sin(3. * angle)};
  });
}

/// A saddle-shaped disk (monkey saddle z = amplitude · r³ · sin(3θ), total
/// angle above 2π around its center) slit along θ = 0 from the rim down to
/// ring `slit_from`: laid flat, the two sides of the slit overlap.
inline Soup slit_saddle_soup(int rings, int sectors, int slit_from, double amplitude = 0.8)
{
  Soup s;
  auto point = [&](int i, double theta) {
    const double r = double(i) / rings;
    s.add_point(r * std::cos(theta), r * std::sin(theta), amplitude * r * r * r * std::sin(3. * theta));
  };
  point(0, 0.);
  // ring i has sectors points, plus a copy of its first point if the slit cuts it
  std::vector<std::size_t> first(rings + 1), copy(rings + 1);
  for(int i = 1; i <= rings; ++i)
  {
    first[i] = s.points.size();
    for(int k = 0; k < sectors; ++k) point(i, 2. * pi * k / sectors);
    copy[i] = first[i];
    if(i >= slit_from) { copy[i] = s.points.size(); point(i, 2. * pi); }
  }
  auto v = [&](int i, int k) { return k == sectors ? copy[i] : first[i] + std::size_t(k); };
  for(int k = 0; k < sectors; ++k) s.add_triangle(0, v(1, k), v(1, k + 1));
  for(int i = 1; i < rings; ++i)
    for(int k = 0; k < sectors; ++k)
    {
      s.add_triangle(v(i, k), v(i + 1, k), v(i + 1, k + 1));
      s.add_triangle(v(i, k), v(i + 1, k + 1), v(i, k + 1));
    }
  return s;
}

/// A vertex-keyed (one UV per vertex) and a halfedge-keyed (one UV per
/// corner) dynamic UV map of `mesh`.
template <typename Mesh>
auto vertex_uv_map(const Mesh& mesh)
{
  return get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
}

template <typename Mesh>
auto halfedge_uv_map(const Mesh& mesh)
{
  return get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
}

} // namespace cut_test

#endif
