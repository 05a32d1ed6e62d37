// Hard edges as seams (named parameter hard_edge_angle): the interior edges
// whose dihedral angle (the angle between the normals of their two faces,
// 0 on a flat surface) exceeds a given angle are cut before anything else,
// as given seams are, so that no chart crosses a crease: a lightmap's texel
// must not straddle an edge where the lighting jumps. The cut search adds
// its own cuts on top where the distortion asks for them. The same creases
// tell a hard-surface (CAD-like) part, which the plan splits in batches.
#ifndef CGAL_SMP_CUT_INTERNAL_HARD_EDGES_H
#define CGAL_SMP_CUT_INTERNAL_HARD_EDGES_H

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/cuts/Cut_rules.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/tuning.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// Dihedral angle in degrees at the interior face-edge `fe` of `surface`
/// (0: flat, 180: folded back); 0 where a face has no normal (zero area),
/// so that a degenerate face makes no hard edge.
template <typename Surface>
double dihedral_angle_degrees(const Surface& surface, int fe)
{
  auto normal = [&](int f) {
    const auto& c = surface.corner_vertex[std::size_t(f)];
    const Vector3 &a = surface.points[std::size_t(c[0])], &b = surface.points[std::size_t(c[1])],
                  &d = surface.points[std::size_t(c[2])];
    return Vector3((b - a).cross(d - a));
  };
  const Vector3 n1 = normal(fe / 3), n2 = normal(surface.twin[std::size_t(fe)] / 3);
  const double sine = n1.cross(n2).norm(), cosine = n1.dot(n2);
  if(!(sine > 0. || cosine > 0.)) return cosine < 0. ? 180. : 0.; // parallel normals, or one is zero
  return std::atan2(sine, cosine) * 180. / M_PI; // atan2: accurate near 0 and 180, unlike acos
}

/// Flags in `is_cut` (per surface edge) every interior edge whose dihedral
/// angle exceeds `degrees`, except forbidden ones (`rules`): the user's
/// word on an edge wins. Returns the number of edges flagged that were not cut yet.
/// \pre 0 <= degrees <= 180; `is_cut` has one entry per edge of `surface`
template <typename Surface>
std::size_t cut_hard_edges(const Surface& surface, double degrees, const Cut_rules& rules, std::vector<char>& is_cut)
{
  std::size_t added = 0;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int twin = surface.twin[std::size_t(fe)];
    if(twin < fe) continue; // border (-1), or the edge seen from its other face
    const int e = surface.edge_of[std::size_t(fe)];
    if(is_cut[std::size_t(e)] || rules.is_forbidden(e) || !(dihedral_angle_degrees(surface, fe) > degrees)) continue;
    is_cut[std::size_t(e)] = 1;
    ++added;
  }
  return added;
}

/// True if `surface` is a hard-surface (CAD-like) part: at least
/// tuning::hard_surface_min_creases interior edges, and
/// tuning::hard_surface_crease_fraction of them, are sharp creases (dihedral
/// angle above tuning::hard_surface_crease_degrees). Each of its many features
/// (a gear's teeth, a plate's holes) asks for splits of its own.
template <typename Surface>
bool is_hard_surface(const Surface& surface)
{
  std::size_t interior = 0, creases = 0;
  for(int fe = 0; fe < int(surface.twin.size()); ++fe)
  {
    const int twin = surface.twin[std::size_t(fe)];
    if(twin < fe) continue; // each interior edge once (a border one: twin -1)
    ++interior;
    creases += dihedral_angle_degrees(surface, fe) > tuning::hard_surface_crease_degrees;
  }
  return creases >= tuning::hard_surface_min_creases
         && double(creases) >= tuning::hard_surface_crease_fraction * double(interior);
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
