// Local relaxation of a map carried from a solved copy (undo_collapses(),
// pipeline/progressive_map.h): each interior vertex of a carried chart whose
// fan holds a face far from isometric moves inside its fan, by a few Newton
// steps on its faces' symmetric Dirichlet energy with the other vertices
// held. Undoing the collapses crushes a few faces, and the input's solve
// would otherwise spend full-resolution Newton iterations on them; where
// restored vertices were shrunk together, a vertex inside the cluster gains
// nothing alone, so the faces still crushed after the sweeps move their
// neighbourhood again, sweep after sweep, from the cluster's rim in. A step
// never reaches a collapse of a fan face, so no face flips; border vertices
// are held, so the chart's border does not move. Serial, in vertex order:
// the same result on any number of threads.
#ifndef CGAL_SMP_CUT_INTERNAL_CARRIED_MAP_RELAXATION_H
#define CGAL_SMP_CUT_INTERNAL_CARRIED_MAP_RELAXATION_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/energy/symmetric_dirichlet.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Chart_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

namespace carried_relaxation {

/// The corners (3 f + k) around each vertex of `chart`, as offsets `start`
/// into `corners`.
inline void corners_around_vertices(const Chart_mesh& chart, std::vector<int>& start, std::vector<int>& corners)
{
  const std::size_t nv = std::size_t(chart.number_of_vertices);
  start.assign(nv + 1, 0);
  for(const auto& face : chart.faces)
    for(int v : face) ++start[std::size_t(v) + 1];
  for(std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  corners.assign(std::size_t(start[nv]), 0);
  std::vector<int> next(start.begin(), start.end() - 1);
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k) corners[std::size_t(next[std::size_t(chart.faces[f][k])]++)] = int(3 * f) + k;
}

/// True if the fan of the corners [first, last) closes around its vertex:
/// the vertices after it in its faces are those before it (an interior vertex).
inline bool closed_fan(const Chart_mesh& chart, const int* first, const int* last, std::vector<int>& after,
                       std::vector<int>& before)
{
  after.clear();
  before.clear();
  for(const int* c = first; c != last; ++c)
  {
    const auto& face = chart.faces[std::size_t(*c / 3)];
    const int k = *c % 3;
    after.push_back(face[std::size_t((k + 1) % 3)]);
    before.push_back(face[std::size_t((k + 2) % 3)]);
  }
  std::sort(after.begin(), after.end());
  std::sort(before.begin(), before.end());
  return after.size() >= 3 && after == before;
}

/// The energy of the fan's faces (area times symmetric Dirichlet), +inf if one is flipped or
/// collapsed; `worst` gets the largest per-face energy density.
inline double fan_energy(const Chart_mesh& chart, const UV_vector& x, const int* first, const int* last, double& worst)
{
  double energy = 0.;
  worst = 0.;
  for(const int* c = first; c != last; ++c)
  {
    const std::size_t f = std::size_t(*c / 3);
    const double psi = symmetric_dirichlet(chart.jacobian(x, f));
    if(!std::isfinite(psi)) return std::numeric_limits<double>::infinity();
    energy += chart.area[f] * psi;
    worst = (std::max)(worst, psi);
  }
  return energy;
}

} // namespace carried_relaxation

/// Relaxes `x` on the charts of `chart` whose flag in `charts` is set (per
/// chart, in the order of chart_of_faces()): up to `sweeps` sweeps over the
/// interior vertices, each
/// vertex whose fan holds a face of symmetric Dirichlet energy above
/// tuning::carried_relaxation_energy taking up to
/// tuning::carried_relaxation_steps projected Newton steps, bounded before a
/// fan face collapses and backtracked until its fan's energy falls; then,
/// while a face of a flagged chart has an energy above
/// tuning::carried_crushed_energy (crushed), up to
/// tuning::carried_crushed_sweeps more sweeps over the vertices of the fans
/// of its vertices, until none is crushed or none of them moves.
///
/// Precondition: no face of a flagged chart is flipped or collapsed in `x`.
/// Postcondition: the same holds, the border vertices have not moved, and
/// the energy of each flagged chart is not higher.
inline void relax_carried_map(const Chart_mesh& chart, const std::vector<char>& charts, UV_vector& x,
                              int sweeps = tuning::carried_relaxation_sweeps)
{
  using namespace carried_relaxation;
  int number_of_charts = 0;
  const std::vector<int> chart_of_face = chart_of_faces(chart, number_of_charts);
  std::vector<int> start, corners;
  corners_around_vertices(chart, start, corners);
  const std::size_t nv = std::size_t(chart.number_of_vertices);
  std::vector<char> movable(nv, 0);
  std::vector<int> after, before;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const int* first = corners.data() + start[v];
    const int* last = corners.data() + start[v + 1];
    if(first == last) continue;
    bool flagged = true;
    for(const int* c = first; c != last && flagged; ++c)
    {
      const std::size_t chart_index = std::size_t(chart_of_face[std::size_t(*c / 3)]);
      flagged = chart_index < charts.size() && charts[chart_index];
    }
    movable[v] = flagged && closed_fan(chart, first, last, after, before);
  }

  // up to carried_relaxation_steps Newton steps of vertex v in its fan; true if it moved
  auto relax_vertex = [&](std::size_t v) {
    bool moved = false;
    const int* first = corners.data() + start[v];
    const int* last = corners.data() + start[v + 1];
    double worst = 0.;
    double energy = fan_energy(chart, x, first, last, worst);
    if(!(worst > tuning::carried_relaxation_energy) || !std::isfinite(energy)) return false;
    for(int step = 0; step < tuning::carried_relaxation_steps; ++step)
    {
      Vector2 g = Vector2::Zero();
      Matrix2 H = Matrix2::Zero();
      for(const int* c = first; c != last; ++c)
      {
        const std::size_t f = std::size_t(*c / 3);
        const int k = *c % 3;
        const Matrix2 J = chart.jacobian(x, f);
        const Eigen::Matrix<double, 4, 2> B = jacobian_operator(chart.rest_inverse[f]).middleCols<2>(2 * k);
        g += chart.area[f] * (B.transpose() * symmetric_dirichlet_gradient(J));
        H += chart.area[f] * (B.transpose() * symmetric_dirichlet_projected_hessian(J) * B);
      }
      H.diagonal().array() += tuning::hessian_shift * (std::max)(H.trace(), 1e-300);
      const double det = H.determinant();
      if(!(det > 0.)) return moved;
      const Vector2 d = -(Matrix2() << H(1, 1), -H(0, 1), -H(1, 0), H(0, 0)).finished() * g / det;
      const double slope = g.dot(d);
      if(!(slope < 0.)) return moved;
      // the longest step before a fan face collapses
      double reach = std::numeric_limits<double>::infinity();
      for(const int* c = first; c != last; ++c)
      {
        const std::size_t f = std::size_t(*c / 3);
        const int k = *c % 3;
        Matrix2 dD = Matrix2::Zero();
        if(k == 0) dD.colwise() = -d;
        else dD.col(k - 1) = d;
        reach = (std::min)(reach, first_collapse_time(chart.uv_edges(x, f), dD));
      }
      double alpha = (std::min)(1., tuning::carried_relaxation_reach * reach);
      const Vector2 p = x.segment<2>(2 * Eigen::Index(v));
      bool decreased = false;
      for(int halving = 0; halving < tuning::carried_relaxation_halvings && !decreased; ++halving, alpha *= 0.5)
      {
        x.segment<2>(2 * Eigen::Index(v)) = p + alpha * d;
        double w = 0.;
        const double trial = fan_energy(chart, x, first, last, w);
        decreased = trial <= energy + tuning::armijo * alpha * slope;
        if(decreased) energy = trial;
      }
      if(!decreased)
      {
        x.segment<2>(2 * Eigen::Index(v)) = p;
        return moved;
      }
      moved = true;
    }
    return moved;
  };
  for(int sweep = 0; sweep < sweeps; ++sweep)
  {
    bool moved = false;
    for(std::size_t v = 0; v < nv; ++v)
      if(movable[v] && relax_vertex(v)) moved = true;
    if(!moved) break;
  }
  // a face still crushed (restored vertices shrunk together): the vertices of its faces' fans
  // again, sweep after sweep, until none is crushed or they no longer move
  auto crushed = [&](std::size_t f) {
    const std::size_t chart_index = std::size_t(chart_of_face[f]);
    return chart_index < charts.size() && charts[chart_index]
           && symmetric_dirichlet(chart.jacobian(x, f)) > tuning::carried_crushed_energy;
  };
  auto for_fan = [&](std::size_t v, auto&& visit) { // each face around v
    for(const int* c = corners.data() + start[v]; c != corners.data() + start[v + 1]; ++c) visit(std::size_t(*c / 3));
  };
  auto sort_unique = [](std::vector<std::size_t>& list) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  };
  std::vector<std::size_t> faces, work;
  for(std::size_t f = 0; f < chart.number_of_faces(); ++f)
    if(crushed(f)) faces.push_back(f);
  for(int sweep = 0; sweep < tuning::carried_crushed_sweeps && !faces.empty(); ++sweep)
  {
    work.clear();
    for(std::size_t f : faces)
      for(int u : chart.faces[f])
        for_fan(std::size_t(u), [&](std::size_t g) {
          for(int w : chart.faces[g])
            if(movable[std::size_t(w)]) work.push_back(std::size_t(w));
        });
    sort_unique(work);
    bool moved = false;
    for(std::size_t v : work)
      if(relax_vertex(v)) moved = true;
    if(!moved) break;
    faces.clear(); // the crushed faces among those the moves changed
    for(std::size_t v : work)
      for_fan(v, [&](std::size_t g) {
        if(crushed(g)) faces.push_back(g);
      });
    sort_unique(faces);
  }
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
