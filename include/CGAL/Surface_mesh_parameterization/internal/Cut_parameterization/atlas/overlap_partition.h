// Charts whose map overlaps itself much, cut into pieces that do not.
#ifndef CGAL_SMP_CUT_INTERNAL_OVERLAP_PARTITION_H
#define CGAL_SMP_CUT_INTERNAL_OVERLAP_PARTITION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/Border_barrier_term.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// True if the UV triangles `a` and `b` overlap by more than `slack` (a
/// length): no line separates them by more than -slack, on the normals of
/// their six edges (exact for convex polygons). With a positive slack,
/// triangles that only touch (a shared vertex or edge, the two sides of a
/// slit) do not overlap; with a negative one, triangles closer than -slack
/// do.
inline bool triangles_overlap(const std::array<Vector2, 3>& a, const std::array<Vector2, 3>& b, double slack)
{
  for(const auto* t : {&a, &b})
    for(int k = 0; k < 3; ++k)
    {
      const Vector2 e = (*t)[(k + 1) % 3] - (*t)[k];
      const double length = e.norm();
      if(!(length > 0.)) continue;
      const Vector2 n(-e.y() / length, e.x() / length);
      double low[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
      double high[2] = {-low[0], -low[1]};
      for(int s = 0; s < 2; ++s)
        for(const Vector2& p : (s == 0 ? a : b))
        {
          const double d = n.dot(p);
          low[s] = (std::min)(low[s], d);
          high[s] = (std::max)(high[s], d);
        }
      if(high[0] <= low[1] + slack || high[1] <= low[0] + slack) return false;
    }
  return true;
}

/// Corners of face f at x.
inline std::array<Vector2, 3> uv_triangle(const Chart_mesh& mesh, const UV_vector& x, std::size_t f)
{
  const auto& t = mesh.faces[f];
  return {Vector2(x[2*t[0]], x[2*t[0]+1]), Vector2(x[2*t[1]], x[2*t[1]+1]), Vector2(x[2*t[2]], x[2*t[2]+1])};
}

/// Relative slack of the overlap tests: this fraction of the mean UV edge length.
constexpr double overlap_tolerance = 1e-6;
/// Two faces of a piece that share no UV vertex are at least this fraction
/// of the mean UV edge length apart: the border barrier needs a border that
/// does not touch itself.
constexpr double piece_gap = 1e-3;

/// Mean UV edge length of the faces flagged in `faces` (all if empty).
inline double mean_uv_edge_length(const Chart_mesh& mesh, const UV_vector& x, const std::vector<char>& faces = {})
{
  double sum = 0.;
  std::size_t n = 0;
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    if(faces.empty() || faces[f])
    {
      const auto t = uv_triangle(mesh, x, f);
      for(int k = 0; k < 3; ++k) sum += (t[(k + 1) % 3] - t[k]).norm();
      n += 3;
    }
  return n > 0 ? sum / double(n) : 0.;
}

/// Per face: 1 if its UV triangle overlaps that of another face of its chart
/// (`chart`: the chart of each face, as chart_of_faces() gives them).
inline std::vector<char> self_overlapping_faces(const Chart_mesh& mesh, const UV_vector& x,
                                                const std::vector<int>& chart)
{
  const std::size_t nf = mesh.number_of_faces();
  std::vector<std::array<double, 4>> boxes(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto t = uv_triangle(mesh, x, f);
    boxes[f] = {(std::min)({t[0].x(), t[1].x(), t[2].x()}), (std::min)({t[0].y(), t[1].y(), t[2].y()}),
                (std::max)({t[0].x(), t[1].x(), t[2].x()}), (std::max)({t[0].y(), t[1].y(), t[2].y()})};
  }
  const double tolerance = overlap_tolerance * mean_uv_edge_length(mesh, x);
  std::vector<char> overlapping(nf, 0);
  for_each_overlapping_box_pair(boxes, boxes, [&](int i, int j) {
    if(i >= j || chart[std::size_t(i)] != chart[std::size_t(j)]) return;
    if(overlapping[std::size_t(i)] && overlapping[std::size_t(j)]) return;
    if(triangles_overlap(uv_triangle(mesh, x, std::size_t(i)), uv_triangle(mesh, x, std::size_t(j)), tolerance))
      overlapping[std::size_t(i)] = overlapping[std::size_t(j)] = 1;
  });
  return overlapping;
}

/// Per chart (ids of chart_of_faces()): the number of its faces whose UV
/// triangle overlaps another of the chart (self_overlapping_faces()).
inline std::vector<std::size_t> self_overlapping_face_counts(const Chart_mesh& mesh, const UV_vector& x)
{
  int charts = 0;
  const std::vector<int> chart = chart_of_faces(mesh, charts);
  const std::vector<char> overlapping = self_overlapping_faces(mesh, x, chart);
  std::vector<std::size_t> count(std::size_t(charts), 0);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f) count[std::size_t(chart[f])] += overlapping[f] != 0;
  return count;
}

/// Per face of `mesh`, its neighbors across the edges of the chart mesh
/// that are flagged in `split` (-1: none).
inline std::vector<std::array<int, 3>> flagged_neighbors(const Chart_mesh& mesh, const std::vector<char>& split)
{
  const std::size_t nf = mesh.number_of_faces();
  // neighbors across the edges of the chart mesh
  std::unordered_map<std::uint64_t, int> face_of_edge;
  face_of_edge.reserve(3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
      face_of_edge.emplace(directed_edge_key(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]), int(f));
  std::vector<std::array<int, 3>> neighbor(nf, {-1, -1, -1});
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const auto it = face_of_edge.find(directed_edge_key(mesh.faces[f][(k + 1) % 3], mesh.faces[f][k]));
      if(it != face_of_edge.end() && split[std::size_t(it->second)]) neighbor[f][k] = it->second;
    }
  return neighbor;
}

/// The faces flagged in `split`, deepest first (rings from the border of
/// the flagged faces; equal depths by index).
inline std::vector<int> seeds_deepest_first(const std::vector<std::array<int, 3>>& neighbor,
                                            const std::vector<char>& split)
{
  const std::size_t nf = neighbor.size();
  // depth: rings from the border of the flagged faces
  std::vector<int> depth(nf, -1);
  std::deque<int> queue;
  for(std::size_t f = 0; f < nf; ++f)
    if(split[f] && std::find(neighbor[f].begin(), neighbor[f].end(), -1) != neighbor[f].end())
    {
      depth[f] = 0;
      queue.push_back(int(f));
    }
  while(!queue.empty())
  {
    const int f = queue.front();
    queue.pop_front();
    for(int g : neighbor[std::size_t(f)])
      if(g >= 0 && depth[std::size_t(g)] < 0)
      {
        depth[std::size_t(g)] = depth[std::size_t(f)] + 1;
        queue.push_back(g);
      }
  }
  std::vector<int> seeds;
  for(std::size_t f = 0; f < nf; ++f)
    if(split[f]) seeds.push_back(int(f));
  std::stable_sort(seeds.begin(), seeds.end(), [&](int a, int b) { return depth[std::size_t(a)] > depth[std::size_t(b)]; });

  return seeds;
}

/// Pieces of the faces flagged in `split`, each free of overlap at x: per
/// face, its piece (0, 1, ...), or -1 for a face not flagged; `pieces` is
/// their number. A piece grows from a seed, ring by ring across the edges of
/// the chart mesh, and takes each face it reaches whose UV triangle overlaps
/// none of its faces (triangles_overlap()); a face that does stops its growth
/// there and goes to a later piece. Seeds are the faces farthest from the
/// border of the flagged faces (in rings), so that the first pieces are the
/// largest. The result depends on the mesh and x only. Small pieces stay:
/// a pass that joined each piece, from the smallest up, to a neighbor it
/// does not overlap joined none of the 145 pieces of CGAL's cheese.off
/// (where a piece meets an earlier one, its faces there overlapped it).
inline std::vector<int> overlap_free_pieces(const Chart_mesh& mesh, const UV_vector& x, const std::vector<char>& split,
                                            int& pieces)
{
  const std::size_t nf = mesh.number_of_faces();
  const std::vector<std::array<int, 3>> neighbor = flagged_neighbors(mesh, split);
  const std::vector<int> seeds = seeds_deepest_first(neighbor, split);
  std::deque<int> queue;

  // a grid of the faces taken, about two mean UV edges per cell
  const double edge = mean_uv_edge_length(mesh, x, split);
  const double h = 2. * edge, tolerance = overlap_tolerance * edge, gap = piece_gap * edge;
  double low[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double high[2] = {-low[0], -low[1]};
  for(std::size_t f = 0; f < nf; ++f)
    if(split[f])
      for(int v : mesh.faces[f])
        for(int a = 0; a < 2; ++a)
        {
          low[a] = (std::min)(low[a], x[2 * v + a]);
          high[a] = (std::max)(high[a], x[2 * v + a]);
        }
  constexpr int max_cells = 1024;
  int cells[2];
  double cell[2];
  for(int a = 0; a < 2; ++a)
  {
    const double extent = high[a] - low[a];
    cells[a] = h > 0. && extent > 0. ? (std::max)(1, (std::min)(max_cells, int(std::ceil(extent / h)))) : 1;
    cell[a] = extent > 0. ? extent / cells[a] : 1.;
  }
  auto cell_range = [&](const std::array<Vector2, 3>& t, int r[4]) {
    for(int a = 0; a < 2; ++a)
    {
      const double lo = (std::min)({t[0][a], t[1][a], t[2][a]}), hi = (std::max)({t[0][a], t[1][a], t[2][a]});
      r[a] = (std::max)(0, (std::min)(cells[a] - 1, int((lo - gap - low[a]) / cell[a])));
      r[a + 2] = (std::max)(0, (std::min)(cells[a] - 1, int((hi + gap - low[a]) / cell[a])));
    }
  };
  auto share_vertex = [&](int f, int g) {
    for(int a : mesh.faces[std::size_t(f)])
      for(int b : mesh.faces[std::size_t(g)])
        if(a == b) return true;
    return false;
  };
  std::vector<std::vector<int>> grid(std::size_t(cells[0]) * std::size_t(cells[1]));

  std::vector<int> piece(nf, -1), reached(nf, -1);
  // true if face f overlaps a face of piece p
  auto overlaps_piece = [&](int f, int p) {
    const std::array<Vector2, 3> t = uv_triangle(mesh, x, std::size_t(f));
    int r[4];
    cell_range(t, r);
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx)
        for(int g : grid[std::size_t(cy) * std::size_t(cells[0]) + std::size_t(cx)])
          if(piece[std::size_t(g)] == p
             && triangles_overlap(t, uv_triangle(mesh, x, std::size_t(g)), share_vertex(f, g) ? tolerance : -gap))
            return true;
    return false;
  };
  auto add_to_grid = [&](int f) {
    int r[4];
    cell_range(uv_triangle(mesh, x, std::size_t(f)), r);
    for(int cy = r[1]; cy <= r[3]; ++cy)
      for(int cx = r[0]; cx <= r[2]; ++cx) grid[std::size_t(cy) * std::size_t(cells[0]) + std::size_t(cx)].push_back(f);
  };
  pieces = 0;
  for(int seed : seeds)
  {
    if(piece[std::size_t(seed)] >= 0) continue;
    const int p = pieces++;
    queue.assign(1, seed);
    reached[std::size_t(seed)] = p;
    while(!queue.empty())
    {
      const int f = queue.front();
      queue.pop_front();
      if(overlaps_piece(f, p)) continue;
      piece[std::size_t(f)] = p;
      add_to_grid(f);
      for(int g : neighbor[std::size_t(f)])
        if(g >= 0 && piece[std::size_t(g)] < 0 && reached[std::size_t(g)] != p)
        {
          reached[std::size_t(g)] = p;
          queue.push_back(g);
        }
    }
  }
  return piece;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
