// A model of CGAL's Parameterizer_3 concept that minimizes the symmetric
// Dirichlet energy: symmetric_dirichlet_parameterize() behind the interface
// of CGAL's parameterizers, so that it can be passed to
// CGAL::Surface_mesh_parameterization::parameterize() like ARAP_parameterizer_3.
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SYMMETRIC_DIRICHLET_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SYMMETRIC_DIRICHLET_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/symmetric_dirichlet_parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
///
/// A parameterizer of a topological disk that minimizes the symmetric
/// Dirichlet energy Σ_f A_f Ψ_f(u), Ψ = ½(σ1² + σ2² + σ1⁻² + σ2⁻²) − 2,
/// with a free border and no flipped face: the solver of
/// `symmetric_dirichlet_parameterize()` with the interface of %CGAL's
/// parameterizers, so that it can be passed to
/// `CGAL::Surface_mesh_parameterization::parameterize()` as
/// `CGAL::Surface_mesh_parameterization::ARAP_parameterizer_3` is, for
/// example on a `CGAL::Seam_mesh` opened by the seams of
/// `cut_and_parameterize()` (see `make_seam_mesh()`).
///
/// The minimization starts from a Tutte embedding of the disk (uniform
/// weights, border on a circle of the mesh's area), or from the UVs already
/// in the map (`initialize_from_uv_map`), and runs projected Newton with a
/// line search that never lets a face collapse: every iterate is flip-free,
/// and the energy never rises above the start's.
///
/// \cgalModels{<a href="https://doc.cgal.org/5.5/Surface_mesh_parameterization/classParameterizer__3.html">`Parameterizer_3`</a>}
///
/// \tparam TriangleMesh_ a model of `FaceGraph` whose faces are triangles,
///   e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3` or a `CGAL::Seam_mesh`
///   of one of them
///
/// \sa `symmetric_dirichlet_parameterize()`, the function this class calls
template <typename TriangleMesh_>
class Symmetric_dirichlet_parameterizer_3
{
public:
  /// The mesh type.
  typedef TriangleMesh_ TriangleMesh;
  /// The mesh type (the name %CGAL's parameterizers use too).
  typedef TriangleMesh_ Triangle_mesh;
  /// Halfedge descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  /// Vertex descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;

  /// Builds a parameterizer.
  ///
  /// \param iterations the most projected Newton iterations (0: the initial
  ///   map is returned as is)
  /// \param tolerance Newton stops when its decrement divided by the total
  ///   area falls below this value (a bound on the decrease of the mean
  ///   distortion, independent of the mesh's scale)
  /// \param initialize_from_uv_map `true`: start from the UVs already in the
  ///   map given to `parameterize()` (finite, no flipped face) instead of a
  ///   Tutte embedding
  ///
  /// \pre `tolerance >= 0`
  /// \post `iterations()`, `tolerance()` and `initialize_from_uv_map()` return the arguments
  explicit Symmetric_dirichlet_parameterizer_3(unsigned int iterations = 500, double tolerance = 1e-9,
                                               bool initialize_from_uv_map = false)
    : m_iterations(iterations), m_tolerance(tolerance), m_initialize_from_uv_map(initialize_from_uv_map)
  {
    CGAL_precondition(tolerance >= 0.);
  }

  /// The most projected Newton iterations.
  unsigned int iterations() const { return m_iterations; }
  /// The stopping tolerance of Newton.
  double tolerance() const { return m_tolerance; }
  /// Whether the minimization starts from the UVs already in the map.
  bool initialize_from_uv_map() const { return m_initialize_from_uv_map; }

  /// Computes a flip-free UV map of `mesh` that minimizes the symmetric
  /// Dirichlet energy, and flags every vertex in `vpmap`.
  ///
  /// \tparam VertexUVMap a `ReadWritePropertyMap` with `vertex_descriptor` as
  ///   key type and a 2D point type (such as `Kernel::Point_2`) as value type
  /// \tparam VertexIndexMap a `ReadablePropertyMap` with `vertex_descriptor`
  ///   as key type and an integer as value type (not used: the solver numbers
  ///   the vertices itself; part of the concept's interface)
  /// \tparam VertexParameterizedMap a `ReadWritePropertyMap` with
  ///   `vertex_descriptor` as key type and `bool` as value type
  ///
  /// \param mesh the mesh: one topological disk
  /// \param bhd a border halfedge of `mesh`
  /// \param uvmap output UVs (and input with `initialize_from_uv_map()`)
  /// \param vimap a vertex index map
  /// \param vpmap set to `true` for every vertex of `mesh` on success
  ///
  /// \pre `mesh` is a triangle mesh, connected, and a topological disk
  /// \pre `bhd` is a border halfedge of `mesh`
  /// \post on `OK`: every UV is finite, no face is flipped (every UV
  ///   triangle has a positive signed area), and the energy is at most that
  ///   of the initial map (the Tutte embedding, or the map given)
  ///
  /// \return `OK`, or the error of `symmetric_dirichlet_parameterize()`
  ///   (`ERROR_NO_TOPOLOGICAL_DISC`, `ERROR_NO_1_TO_1_MAPPING` for a given
  ///   initial map with a flipped face, ...); on error `vpmap` is left unchanged
  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVMap uvmap,
                          VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    CGAL_precondition(bhd != boost::graph_traits<Triangle_mesh>::null_halfedge() && is_border(bhd, mesh));
    CGAL_USE(bhd);
    CGAL_USE(vimap);
    const Error_code status = symmetric_dirichlet_parameterize(
      mesh, uvmap,
      parameters::initialize_from_uv_map(m_initialize_from_uv_map,
                                         parameters::stopping_tolerance(m_tolerance,
                                           CGAL::parameters::number_of_iterations(int(m_iterations)))));
    if(status != OK) return status;
    for(vertex_descriptor v : vertices(mesh)) put(vpmap, v, true);
    return OK;
  }

private:
  unsigned int m_iterations;
  double m_tolerance;
  bool m_initialize_from_uv_map;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
