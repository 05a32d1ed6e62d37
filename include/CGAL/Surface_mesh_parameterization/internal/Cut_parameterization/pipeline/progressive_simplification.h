// The copies whose map is carried back to the input by undoing their
// collapses (pipeline/progressive_map.h): half-edge collapses on the index
// arrays, cheapest first by the quadric error of the plane of each face
// (Garland and Heckbert 1997) at the endpoint that stays, each collapse
// recorded. These copies only start a solve of the input, whose cuts they
// keep: they need a valid progressive mesh, not CGAL's Lindstrom-Turk
// placement, which the copy that decides the cuts keeps
// (simplify_surface() in pipeline/multiresolution.h; measurements:
// doc/design/pipeline.dox).
#ifndef CGAL_SMP_CUT_INTERNAL_PROGRESSIVE_SIMPLIFICATION_H
#define CGAL_SMP_CUT_INTERNAL_PROGRESSIVE_SIMPLIFICATION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/multiresolution.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {
namespace progressive_simplification {

/// The quadric of a sum of squared distances to planes: xᵀ A x + 2 bᵀ x + c.
struct Quadric
{
  double a[6] = {0., 0., 0., 0., 0., 0.}; // A: xx, xy, xz, yy, yz, zz
  double b[3] = {0., 0., 0.};
  double c = 0.;

  /// Adds `weight` times the squared distance to the plane n.x + d = 0 (|n| = 1).
  void add_plane(const Vector3& n, double d, double weight)
  {
    a[0] += weight * n.x() * n.x(); a[1] += weight * n.x() * n.y(); a[2] += weight * n.x() * n.z();
    a[3] += weight * n.y() * n.y(); a[4] += weight * n.y() * n.z(); a[5] += weight * n.z() * n.z();
    b[0] += weight * d * n.x(); b[1] += weight * d * n.y(); b[2] += weight * d * n.z();
    c += weight * d * d;
  }
  void add(const Quadric& q)
  {
    for(int i = 0; i < 6; ++i) a[i] += q.a[i];
    for(int i = 0; i < 3; ++i) b[i] += q.b[i];
    c += q.c;
  }
  double at(const Vector3& p) const
  {
    const double x = p.x(), y = p.y(), z = p.z();
    return a[0] * x * x + 2. * a[1] * x * y + 2. * a[2] * x * z + a[3] * y * y + 2. * a[4] * y * z + a[5] * z * z
           + 2. * (b[0] * x + b[1] * y + b[2] * z) + c;
  }
};

/// A candidate collapse: `removed` into `kept` at `cost`, valid while both
/// vertices keep the stamps it was computed with.
struct Candidate
{
  double cost;
  int removed, kept;
  unsigned removed_stamp, kept_stamp;

  /// Cheapest first; ties by vertex indices, so that the order is the same everywhere.
  bool operator<(const Candidate& o) const
  {
    if(cost != o.cost) return cost > o.cost;
    if(removed != o.removed) return removed > o.removed;
    return kept > o.kept;
  }
};

inline std::uint64_t pair_key(int a, int b)
{
  return (std::uint64_t(std::uint32_t((std::min)(a, b))) << 32) | std::uint32_t((std::max)(a, b));
}

} // namespace progressive_simplification

/// Simplifies `surface` to about `target_faces` faces into `coarse` by
/// half-edge collapses (each removed vertex merged into an endpoint that
/// stays, where it is), cheapest first by quadric error, every collapse
/// recorded in `coarse.collapses` for undo_collapses(). As simplify_surface():
/// the border vertices, the seams of `is_cut` and the `forbidden` edges
/// (empty: none) are kept (a border vertex moves only along the border, into
/// a neighbour on it, and not off a seam), the faces' orientation too (a
/// collapse that turns a face's normal by a right angle or more is refused),
/// and each coarse face gets the mean λ of its three vertices. A collapse
/// keeps the mesh a manifold (the link condition), never removes a vertex of
/// a single face (its restored face would have no neighbour to take corners
/// from) nor makes two faces of the same vertices. Returns false if the copy
/// could not be built (then the caller works without it).
template <typename Surface>
bool simplify_for_carrying(const Surface& surface, const std::vector<char>& is_cut, const std::vector<char>& forbidden,
                           const std::vector<double>& face_lambda, std::size_t target_faces, Coarse_surface& coarse)
{
  using namespace progressive_simplification;
  const int nv = int(surface.number_of_vertices()), nf = int(surface.number_of_faces());
  const std::size_t vertices = surface.number_of_vertices(), faces = surface.number_of_faces();
  const std::vector<Vector3>& point = surface.points;
  std::vector<std::array<int, 3>> face = surface.corner_vertex;
  std::vector<char> face_alive(faces, 1), vertex_alive(vertices, 1);
  std::vector<std::vector<int>> faces_at(vertices);
  for(int f = 0; f < nf; ++f)
    for(int v : face[std::size_t(f)]) faces_at[std::size_t(v)].push_back(f);
  std::vector<char> on_border(vertices, 0), on_seam(vertices, 0);
  std::unordered_set<std::uint64_t> constrained;
  std::unordered_map<std::uint64_t, int> input_edge;
  std::vector<Quadric> quadric(vertices);
  for(int f = 0; f < nf; ++f)
  {
    const auto& cv = face[std::size_t(f)];
    const Vector3 n = (point[cv[1]] - point[cv[0]]).cross(point[cv[2]] - point[cv[0]]);
    const double twice_area = n.norm();
    if(!(twice_area > 0.)) continue;
    const Vector3 unit = n / twice_area;
    for(int v : cv) quadric[std::size_t(v)].add_plane(unit, -unit.dot(point[cv[0]]), 0.5 * twice_area);
    for(int k = 0; k < 3; ++k)
    {
      const int fe = 3 * f + k;
      if(surface.twin[std::size_t(fe)] >= 0) continue;
      // the border's own plane, across the face: a border vertex leaves the border line at a cost
      const Vector3 edge = point[surface.edge_target(fe)] - point[surface.edge_source(fe)];
      const Vector3 across = edge.cross(unit);
      const double length = across.norm();
      if(!(length > 0.)) continue;
      const Vector3 m = across / length;
      for(int v : {surface.edge_source(fe), surface.edge_target(fe)})
        quadric[std::size_t(v)].add_plane(m, -m.dot(point[surface.edge_source(fe)]), edge.squaredNorm());
    }
  }
  for(int fe = 0; fe < 3 * nf; ++fe)
  {
    const int a = surface.edge_source(fe), b = surface.edge_target(fe);
    const int e = surface.edge_of[std::size_t(fe)];
    input_edge.emplace(pair_key(a, b), e);
    if(surface.twin[std::size_t(fe)] < 0) on_border[std::size_t(a)] = on_border[std::size_t(b)] = 1;
    else if(is_cut[std::size_t(e)] || is_flagged(forbidden, e))
    {
      on_seam[std::size_t(a)] = on_seam[std::size_t(b)] = 1;
      constrained.insert(pair_key(a, b));
    }
  }

  std::vector<unsigned> stamp(vertices, 0);
  std::vector<int> mark(vertices, -1); // scratch: neighbours of the vertex being judged
  int mark_round = 0;
  auto shared_faces = [&](int a, int b, int* out) {
    int count = 0;
    for(int f : faces_at[std::size_t(a)])
    {
      const auto& cv = face[std::size_t(f)];
      if(cv[0] == b || cv[1] == b || cv[2] == b)
      {
        if(count < 2) out[count] = f;
        ++count;
      }
    }
    return count;
  };
  std::priority_queue<Candidate> queue;
  // the collapse of edge (a, b): the endpoints that may stay, as Pins::kept() (multiresolution.h)
  // allows (a border edge: those off a seam may go; else those off the border and the seams), the
  // cheaper of the two where both may
  auto cost_of = [&](int removed, int kept) {
    Quadric q = quadric[std::size_t(removed)];
    q.add(quadric[std::size_t(kept)]);
    // among collapses of equal error (flat parts), the shorter edge first: rounder faces
    const double length2 = (point[std::size_t(removed)] - point[std::size_t(kept)]).squaredNorm();
    return (std::max)(0., q.at(point[std::size_t(kept)])) + 1e-3 * length2 * length2;
  };
  auto push = [&](int a, int b) {
    if(constrained.count(pair_key(a, b)) != 0) return;
    int shared[2];
    const int count = shared_faces(a, b, shared);
    if(count == 0 || count > 2) return;
    const bool along_border = count == 1;
    auto may_go = [&](int v) { return along_border ? !on_seam[std::size_t(v)] : !(on_border[std::size_t(v)] || on_seam[std::size_t(v)]); };
    const bool a_goes = may_go(a), b_goes = may_go(b);
    if(!a_goes && !b_goes) return;
    const double a_cost = a_goes ? cost_of(a, b) : 0., b_cost = b_goes ? cost_of(b, a) : 0.;
    const bool remove_a = a_goes && (!b_goes || a_cost < b_cost || (a_cost == b_cost && a > b));
    const int removed = remove_a ? a : b, kept = remove_a ? b : a;
    queue.push(Candidate{remove_a ? a_cost : b_cost, removed, kept, stamp[std::size_t(removed)], stamp[std::size_t(kept)]});
  };
  for(int fe = 0; fe < 3 * nf; ++fe)
  {
    const int twin = surface.twin[std::size_t(fe)];
    if(twin < 0 || twin > fe) push(surface.edge_source(fe), surface.edge_target(fe));
  }

  std::vector<int> common, neighbours; // scratch of the judging and of each collapse
  // the collapse of `r` into `k`, if it keeps a valid progressive mesh
  auto valid = [&](int r, int k, const int* shared, int count) {
    if(faces_at[std::size_t(r)].size() <= 1) return false; // a vertex of a single face
    // link condition: the common neighbours of r and k are the far corners of their shared faces
    ++mark_round;
    for(int f : faces_at[std::size_t(r)])
      for(int v : face[std::size_t(f)]) mark[std::size_t(v)] = mark_round;
    common.clear();
    for(int f : faces_at[std::size_t(k)])
      for(int v : face[std::size_t(f)])
        if(v != k && v != r && mark[std::size_t(v)] == mark_round
           && std::find(common.begin(), common.end(), v) == common.end())
          common.push_back(v);
    if(int(common.size()) != count) return false;
    for(int f : faces_at[std::size_t(r)])
    {
      if(f == shared[0] || (count > 1 && f == shared[1])) continue;
      const auto& cv = face[std::size_t(f)];
      int i = 0;
      while(cv[i] != r) ++i;
      const int a = cv[(i + 1) % 3], b = cv[(i + 2) % 3];
      // no face (k, a, b) twice
      for(int g : faces_at[std::size_t(k)])
      {
        const auto& gv = face[std::size_t(g)];
        const bool has_a = gv[0] == a || gv[1] == a || gv[2] == a, has_b = gv[0] == b || gv[1] == b || gv[2] == b;
        if(has_a && has_b) return false;
      }
      const Vector3 before = (point[a] - point[r]).cross(point[b] - point[r]);
      const Vector3 after = (point[a] - point[k]).cross(point[b] - point[k]);
      if(!(before.dot(after) > 0.)) return false;
    }
    return true;
  };

  std::size_t edges = surface.edges.size();
  const std::size_t stop = 3 * target_faces / 2; // a closed mesh has 3/2 edges per face, a disk a little fewer
  while(edges >= stop && !queue.empty())
  {
    const Candidate c = queue.top();
    queue.pop();
    const int r = c.removed, k = c.kept;
    if(!vertex_alive[std::size_t(r)] || !vertex_alive[std::size_t(k)] || stamp[std::size_t(r)] != c.removed_stamp
       || stamp[std::size_t(k)] != c.kept_stamp)
      continue;
    int shared[2];
    const int count = shared_faces(r, k, shared);
    if(count == 0 || count > 2 || !valid(r, k, shared, count)) continue;
    Collapse record;
    record.removed = r;
    record.kept = k;
    for(int f : faces_at[std::size_t(r)])
    {
      const auto& cv = face[std::size_t(f)];
      int i = 0;
      while(cv[i] != r) ++i;
      record.star.push_back({cv[(i + 2) % 3], r, cv[(i + 1) % 3]});
    }
    coarse.collapses.push_back(std::move(record));
    for(int s = 0; s < count; ++s)
    {
      const int f = shared[s];
      face_alive[std::size_t(f)] = 0;
      for(int v : face[std::size_t(f)])
      {
        std::vector<int>& around = faces_at[std::size_t(v)];
        around.erase(std::find(around.begin(), around.end(), f));
      }
    }
    for(int f : faces_at[std::size_t(r)])
    {
      for(int& v : face[std::size_t(f)])
        if(v == r) v = k;
      faces_at[std::size_t(k)].push_back(f);
    }
    faces_at[std::size_t(r)].clear();
    vertex_alive[std::size_t(r)] = 0;
    quadric[std::size_t(k)].add(quadric[std::size_t(r)]); // a removed vertex is off the seams, and off the border unless k is on it
    edges -= count == 2 ? 3 : 2;
    ++stamp[std::size_t(k)];
    ++mark_round;
    neighbours.clear();
    for(int f : faces_at[std::size_t(k)])
      for(int v : face[std::size_t(f)])
        if(v != k && mark[std::size_t(v)] != mark_round)
        {
          mark[std::size_t(v)] = mark_round;
          neighbours.push_back(v);
        }
    std::sort(neighbours.begin(), neighbours.end());
    for(int v : neighbours) push(k, v);
  }

  // the copy: the live faces on the live vertices, in the input's order
  Coarse_mesh& mesh = coarse.mesh;
  std::vector<Coarse_mesh::Vertex_index> vertex(vertices);
  std::vector<int> origin;
  for(int v = 0; v < nv; ++v)
    if(vertex_alive[std::size_t(v)] && !faces_at[std::size_t(v)].empty())
    {
      const Vector3& p = point[std::size_t(v)];
      vertex[std::size_t(v)] = mesh.add_vertex(Coarse_mesh::Point(p.x(), p.y(), p.z()));
      origin.push_back(v);
    }
  for(int f = 0; f < nf; ++f)
    if(face_alive[std::size_t(f)])
    {
      const auto& cv = face[std::size_t(f)];
      if(mesh.add_face(vertex[std::size_t(cv[0])], vertex[std::size_t(cv[1])], vertex[std::size_t(cv[2])])
         == Coarse_mesh::null_face())
        return false;
    }
  if(index_surface(mesh, get(CGAL::vertex_point, mesh), coarse.surface) != Indexing_status::OK) return false;
  const Indexed_surface<Coarse_mesh>& cs = coarse.surface;
  coarse.fine_vertex.resize(cs.number_of_vertices());
  for(std::size_t v = 0; v < cs.number_of_vertices(); ++v) coarse.fine_vertex[v] = origin[std::size_t(cs.vertices[v])];
  coarse.is_cut.assign(cs.edges.size(), 0);
  if(!forbidden.empty()) coarse.forbidden.assign(cs.edges.size(), 0);
  for(int fe = 0; fe < int(cs.twin.size()); ++fe)
  {
    const int a = coarse.fine_vertex[std::size_t(cs.edge_source(fe))], b = coarse.fine_vertex[std::size_t(cs.edge_target(fe))];
    const auto it = input_edge.find(pair_key(a, b));
    if(it == input_edge.end()) continue; // an edge the collapses made: no seam
    const std::size_t e = std::size_t(cs.edge_of[std::size_t(fe)]);
    coarse.is_cut[e] = is_cut[std::size_t(it->second)];
    if(!forbidden.empty()) coarse.forbidden[e] = forbidden[std::size_t(it->second)];
  }
  coarse.face_lambda = coarse_face_lambda(surface, face_lambda, coarse);
  return true;
}

/// simplify_surface() in two stages: simplify_for_carrying() to
/// `first_faces` faces, then simplify_surface() of that copy to about
/// `target_faces`; the result is as simplify_surface()'s (every vertex a
/// vertex of `surface`, `fine_vertex` in its indices, λ from its faces), and
/// CGAL's collapse only sees the smaller copy (doc/design/pipeline.dox).
template <typename Surface>
bool simplify_surface_in_two_stages(const Surface& surface, const std::vector<char>& is_cut,
                                    const std::vector<char>& forbidden, const std::vector<double>& face_lambda,
                                    std::size_t first_faces, std::size_t target_faces, Coarse_surface& coarse)
{
  Coarse_surface first;
  if(!simplify_for_carrying(surface, is_cut, forbidden, face_lambda, first_faces, first)
     || !simplify_surface(first.surface, first.is_cut, first.forbidden, first.face_lambda, target_faces, coarse))
    return false;
  for(int& v : coarse.fine_vertex) v = first.fine_vertex[std::size_t(v)];
  coarse.face_lambda = coarse_face_lambda(surface, face_lambda, coarse);
  return true;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
