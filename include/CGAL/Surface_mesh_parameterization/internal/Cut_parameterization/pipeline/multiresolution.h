// Multiresolution: the alternation only decides where to cut, so on a large
// mesh it runs on a simplified copy, and its cuts are carried back to the
// input. The copy is made by CGAL's Surface_mesh_simplification with
// half-edge collapses (each collapse keeps one endpoint where it is), so every
// vertex of the copy is a vertex of the input and a cut edge (a, b) of the
// copy becomes the shortest edge path from a to b on the input.
#ifndef CGAL_SMP_CUT_INTERNAL_MULTIRESOLUTION_H
#define CGAL_SMP_CUT_INTERNAL_MULTIRESOLUTION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Edge_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/cut_mesh.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <boost/optional.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

using Coarse_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

/// One half-edge collapse of the simplification, in input vertex indices:
/// `removed` merged into `kept`; `star`: the faces around `removed` just
/// before (each in its orientation), those with `kept` disappearing.
struct Collapse
{
  int removed = -1, kept = -1;
  std::vector<std::array<int, 3>> star;
};

/// The simplified copy, indexed, with where its vertices come from.
struct Coarse_surface
{
  Coarse_mesh mesh;
  Indexed_surface<Coarse_mesh> surface;
  std::vector<int> fine_vertex;  // per vertex of `surface`: its index in the input
  std::vector<char> is_cut;      // per edge of `surface`: a seam of the input (kept by the simplification)
  std::vector<char> forbidden;   // per edge of `surface`: a forbidden edge of the input (kept); empty: none
  std::vector<double> face_lambda;
  std::vector<Collapse> collapses; // in the order made (simplify_for_carrying() only)
};

namespace multiresolution {

using Vertex = Coarse_mesh::Vertex_index;
using Edge = Coarse_mesh::Edge_index;

/// Vertices that must not move: on the border, on a seam or on a forbidden
/// edge of the input (a collapse keeps them, and never merges two of them
/// across the inside). The seams and forbidden edges stay edges of the copy.
struct Pins
{
  Coarse_mesh::Property_map<Vertex, char> on_border, on_seam;
  Coarse_mesh::Property_map<Edge, bool> constrained, seam, forbidden;

  bool pinned(Vertex v) const { return on_border[v] || on_seam[v]; }

  /// 0 or 1: the endpoint of the collapsed edge that stays; -1: no collapse.
  template <typename Profile>
  int kept(const Profile& profile) const
  {
    const Vertex v0 = profile.v0(), v1 = profile.v1();
    const Coarse_mesh& mesh = profile.surface_mesh();
    if(is_border(edge(profile.v0_v1(), mesh), mesh)) // along the border: only seams pin
    {
      if(on_seam[v0] && on_seam[v1]) return -1;
      return on_seam[v1] ? 1 : 0;
    }
    if(pinned(v0) && pinned(v1)) return -1;
    return pinned(v1) ? 1 : 0;
  }
};

/// Placement of a half-edge collapse: one of the endpoints, as Pins says.
struct Endpoint_placement
{
  const Pins* pins;

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const
  {
    const int k = pins->kept(profile);
    if(k < 0) return boost::none;
    return k == 0 ? profile.p0() : profile.p1();
  }
};

/// Carries the input vertex of the endpoint that stays to the merged vertex.
struct Origin_visitor : CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Coarse_mesh>
{
  Coarse_mesh::Property_map<Vertex, int> origin;
  Pins* pins;

  template <typename Profile>
  void OnCollapsed(const Profile& profile, Vertex kept)
  {
    // the placement was p0 or p1, copied exactly; equal points: either origin is right
    const bool second = profile.surface_mesh().point(kept) == profile.p1()
                        && !(profile.p0() == profile.p1());
    const int from = second ? origin[profile.v1()] : origin[profile.v0()];
    origin[kept] = from;
    // the merged vertex has both endpoints' seams and border
    pins->on_seam[kept] = char(pins->on_seam[profile.v0()] || pins->on_seam[profile.v1()]);
    pins->on_border[kept] = char(pins->on_border[profile.v0()] || pins->on_border[profile.v1()]);
  }
};

} // namespace multiresolution

/// Per face of the copy `coarse` of `surface`: the mean λ of its three
/// vertices, a vertex having the mean λ of its faces in `surface`.
template <typename Surface>
std::vector<double> coarse_face_lambda(const Surface& surface, const std::vector<double>& face_lambda,
                                       const Coarse_surface& coarse)
{
  std::vector<double> vertex_lambda(surface.number_of_vertices(), 0.), faces_at(surface.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f)
    for(int v : surface.corner_vertex[f])
    {
      vertex_lambda[std::size_t(v)] += face_lambda[f];
      faces_at[std::size_t(v)] += 1.;
    }
  const Indexed_surface<Coarse_mesh>& cs = coarse.surface;
  std::vector<double> lambda(cs.number_of_faces());
  for(std::size_t f = 0; f < cs.number_of_faces(); ++f)
  {
    double sum = 0.;
    for(int v : cs.corner_vertex[f])
    {
      const int fine = coarse.fine_vertex[std::size_t(v)];
      sum += vertex_lambda[std::size_t(fine)] / faces_at[std::size_t(fine)];
    }
    lambda[f] = sum / 3.;
  }
  return lambda;
}

/// Simplifies `surface` to about `target_faces` faces into `coarse`, keeping
/// the border vertices, the seams of `is_cut` and the `forbidden` edges
/// (empty: none) as edges of the copy, and
/// the orientation of the faces (collapses that turn a normal by more than
/// CGAL's bound are refused). Each coarse face gets the mean λ of its three
/// vertices, a vertex having the mean λ of its faces. Returns false if the
/// copy could not be built (then the caller works at full resolution).
template <typename Surface>
bool simplify_surface(const Surface& surface, const std::vector<char>& is_cut, const std::vector<char>& forbidden,
                      const std::vector<double>& face_lambda, std::size_t target_faces, Coarse_surface& coarse)
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  using namespace multiresolution;
  Coarse_mesh& mesh = coarse.mesh;
  std::vector<Vertex> vertex(surface.number_of_vertices());
  for(std::size_t v = 0; v < vertex.size(); ++v)
  {
    const Vector3& p = surface.points[v];
    vertex[v] = mesh.add_vertex(Coarse_mesh::Point(p.x(), p.y(), p.z()));
  }
  for(const auto& cv : surface.corner_vertex)
    if(mesh.add_face(vertex[cv[0]], vertex[cv[1]], vertex[cv[2]]) == Coarse_mesh::null_face()) return false;

  Pins pins;
  pins.on_border = mesh.add_property_map<Vertex, char>("v:cut_on_border", 0).first;
  pins.on_seam = mesh.add_property_map<Vertex, char>("v:cut_on_seam", 0).first;
  pins.constrained = mesh.add_property_map<Edge, bool>("e:cut_constrained", false).first;
  pins.seam = mesh.add_property_map<Edge, bool>("e:cut_seam", false).first;
  pins.forbidden = mesh.add_property_map<Edge, bool>("e:cut_forbidden", false).first;
  Origin_visitor visitor;
  visitor.pins = &pins;
  visitor.origin = mesh.add_property_map<Vertex, int>("v:cut_origin", -1).first;
  for(std::size_t v = 0; v < vertex.size(); ++v) visitor.origin[vertex[v]] = int(v);
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const Vertex a = vertex[surface.edge_source(fe)], b = vertex[surface.edge_target(fe)];
    const int e = surface.edge_of[fe];
    if(surface.twin[fe] < 0) pins.on_border[a] = pins.on_border[b] = 1;
    else if(is_cut[e] || is_flagged(forbidden, e))
    {
      pins.on_seam[a] = pins.on_seam[b] = 1;
      const Edge edge = mesh.edge(mesh.halfedge(a, b));
      pins.constrained[edge] = true;
      (is_cut[e] ? pins.seam : pins.forbidden)[edge] = true;
    }
  }

  // a closed mesh has 3/2 edges per face, a disk a little fewer
  SMS::Count_stop_predicate<Coarse_mesh> stop(3 * target_faces / 2);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Coarse_mesh>())
                       .get_placement(SMS::Bounded_normal_change_placement<Endpoint_placement>(Endpoint_placement{&pins}))
                       .edge_is_constrained_map(pins.constrained)
                       .visitor(visitor));

  if(index_surface(mesh, get(CGAL::vertex_point, mesh), coarse.surface) != Indexing_status::OK) return false;
  const Indexed_surface<Coarse_mesh>& cs = coarse.surface;
  coarse.fine_vertex.resize(cs.number_of_vertices());
  for(std::size_t v = 0; v < cs.number_of_vertices(); ++v) coarse.fine_vertex[v] = visitor.origin[cs.vertices[v]];
  coarse.is_cut.resize(cs.edges.size());
  for(std::size_t e = 0; e < cs.edges.size(); ++e) coarse.is_cut[e] = char(pins.seam[cs.edges[e]]);
  if(!forbidden.empty())
  {
    coarse.forbidden.resize(cs.edges.size());
    for(std::size_t e = 0; e < cs.edges.size(); ++e) coarse.forbidden[e] = char(pins.forbidden[cs.edges[e]]);
  }
  coarse.face_lambda = coarse_face_lambda(surface, face_lambda, coarse);
  return true;
}

/// Cuts on `surface` (the input) the cheapest edge path for `rules` between
/// the input vertices of each cut edge of the copy that is not on its
/// border, never on a forbidden edge.
template <typename Surface>
void transfer_cuts(const Surface& surface, const Coarse_surface& coarse, const std::vector<char>& coarse_is_cut,
                   const Cut_rules& rules, std::vector<char>& is_cut)
{
  std::vector<char> usable(surface.edges.size(), 1);
  for(std::size_t e = 0; e < usable.size(); ++e) usable[e] = char(!rules.is_forbidden(int(e)));
  const Edge_graph graph = surface_edge_graph(surface, usable, rules);
  const Indexed_surface<Coarse_mesh>& cs = coarse.surface;
  Shortest_paths scratch;
  for(int fe = 0; fe < int(cs.twin.size()); ++fe)
  {
    if(cs.twin[fe] < fe || !coarse_is_cut[cs.edge_of[fe]]) continue; // each inner edge once
    const int a = coarse.fine_vertex[cs.edge_source(fe)], b = coarse.fine_vertex[cs.edge_target(fe)];
    for(int e : graph.shortest_path(a, b, scratch)) is_cut[e] = 1;
  }
}

/// The copy's per-face field (v) on the faces of `surface`: each input vertex
/// takes the mean over the faces around the nearest vertex of the copy
/// (along edges), each face the mean of its three vertices.
template <typename Surface>
Eigen::VectorXd transfer_face_field(const Surface& surface, const Coarse_surface& coarse,
                                    const Eigen::VectorXd& coarse_field)
{
  const Indexed_surface<Coarse_mesh>& cs = coarse.surface;
  std::vector<double> at_coarse_vertex(cs.number_of_vertices(), 0.), faces_at(cs.number_of_vertices(), 0.);
  for(std::size_t f = 0; f < cs.number_of_faces(); ++f)
    for(int v : cs.corner_vertex[f])
    {
      at_coarse_vertex[v] += coarse_field[Eigen::Index(f)];
      faces_at[v] += 1.;
    }
  std::vector<double> at_vertex(surface.number_of_vertices(), 1.);
  std::vector<int> sources(cs.number_of_vertices());
  for(std::size_t v = 0; v < sources.size(); ++v)
  {
    sources[v] = coarse.fine_vertex[v];
    at_vertex[sources[v]] = at_coarse_vertex[v] / faces_at[v];
  }
  const Edge_graph graph = surface_edge_graph(surface, std::vector<char>(surface.edges.size(), 1));
  const Shortest_paths nearest = graph.shortest_paths(sources);
  // a vertex takes its parent's value: parents first, by increasing distance
  std::vector<int> order(surface.number_of_vertices());
  for(std::size_t v = 0; v < order.size(); ++v) order[v] = int(v);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return nearest.distance[a] < nearest.distance[b] || (nearest.distance[a] == nearest.distance[b] && a < b);
  });
  for(int v : order)
    if(nearest.parent[v] >= 0) at_vertex[v] = at_vertex[nearest.parent[v]];
  Eigen::VectorXd field(Eigen::Index(surface.number_of_faces()));
  for(std::size_t f = 0; f < surface.number_of_faces(); ++f)
  {
    const auto& cv = surface.corner_vertex[f];
    field[Eigen::Index(f)] = (at_vertex[cv[0]] + at_vertex[cv[1]] + at_vertex[cv[2]]) / 3.;
  }
  return field;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
