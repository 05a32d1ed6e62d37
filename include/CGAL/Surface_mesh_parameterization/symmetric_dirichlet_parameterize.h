#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SYMMETRIC_DIRICHLET_PARAMETERIZE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SYMMETRIC_DIRICHLET_PARAMETERIZE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/mesh/Indexed_surface.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/tutte_embedding.h>

#include <CGAL/boost/graph/properties.h>
#include <boost/property_map/property_map.hpp>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

inline Error_code to_error_code(Indexing_status status)
{
  switch(status)
  {
    case Indexing_status::OK: return OK;
    case Indexing_status::EMPTY: return ERROR_EMPTY_MESH;
    case Indexing_status::NOT_TRIANGLE: return ERROR_NON_TRIANGULAR_MESH;
    case Indexing_status::NON_MANIFOLD: return ERROR_NON_MANIFOLD;
    default: return ERROR_NON_FINITE_COORDINATE;
  }
}

/// Reads UVs of every corner from a vertex-keyed map.
template <typename TriangleMesh, typename VertexUVMap>
void read_vertex_uvs(const TriangleMesh& mesh, const Indexed_surface<TriangleMesh>& surface,
                     const std::vector<int>& corner_uv, VertexUVMap uvmap, UV_vector& x)
{
  for(std::size_t c = 0; c < corner_uv.size(); ++c)
  {
    const auto& p = get(uvmap, target(surface.corner_halfedge[c / 3][c % 3], mesh));
    x[2*corner_uv[c]] = CGAL::to_double(p.x());
    x[2*corner_uv[c]+1] = CGAL::to_double(p.y());
  }
}

template <typename TriangleMesh, typename VertexUVMap>
void write_vertex_uvs(const TriangleMesh& mesh, const Indexed_surface<TriangleMesh>& surface,
                      const std::vector<int>& corner_uv, const UV_vector& x, VertexUVMap uvmap)
{
  using Point_2 = typename boost::property_traits<VertexUVMap>::value_type;
  for(std::size_t c = 0; c < corner_uv.size(); ++c)
    put(uvmap, target(surface.corner_halfedge[c / 3][c % 3], mesh),
        Point_2(x[2*corner_uv[c]], x[2*corner_uv[c]+1]));
}

} // namespace cut
} // namespace internal

/// \ingroup PkgCutParameterizationRef
///
/// Computes a flip-free UV map of a topological disk that minimizes the
/// weighted symmetric Dirichlet energy Σ_f w_f A_f Ψ_f(u), with
/// Ψ = ½(σ1² + σ2² + σ1⁻² + σ2⁻²) − 2.
///
/// Starts from a Tutte embedding (uniform weights, boundary on a circle of
/// the mesh's area), or from the UVs in `uvmap`, and runs projected Newton
/// (analytic eigensystem of Ψ, sparse Cholesky with the symbolic analysis
/// done once) with a line search that never lets a face collapse.
/// `Symmetric_dirichlet_parameterizer_3` offers it as a model of %CGAL's
/// `Parameterizer_3` concept.
///
/// Works through the seam-mesh convention: with `TriangleMesh` a
/// `CGAL::Seam_mesh`, the mesh is the one opened by the seams and `uvmap` is
/// keyed by its vertices, i.e. by halfedges of the underlying mesh.
///
/// Degenerate faces (zero area, needles, coincident corners) are accepted:
/// their rest shape is clamped to a height of 1e-4 times their longest side,
/// so they stay non-flipped and produce no NaN.
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam VertexUVMap a `ReadWritePropertyMap` from vertex descriptors to a 2D point type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param mesh a topological disk, or several disjoint ones (each then gets its own circle)
/// \param uvmap output UVs (and input when `initialize_from_uv_map(true)`)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type (%CGAL's named parameter)}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_weight_map}
///     \cgalParamDescription{the weight w_f of each face in the energy; weights below 1e-7
///       times the mean are raised to that floor, so every face keeps a barrier against
///       collapse}
///     \cgalParamType{a `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///       as key type and `double` (≥ 0, finite, not all zero) as value type}
///     \cgalParamDefault{`1` on every face}
///   \cgalParamNEnd
///   \cgalParamNBegin{initialize_from_uv_map}
///     \cgalParamDescription{`true`: start from the UVs already in `uvmap` (finite, no flipped
///       face) instead of a Tutte embedding}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most projected Newton iterations (0: the initial map is
///       returned as is)}
///     \cgalParamType{`int`, ≥ 0 (%CGAL's named parameter)}
///     \cgalParamDefault{`500`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stopping_tolerance}
///     \cgalParamDescription{Newton stops when its decrement -gᵀd divided by Σ_f w_f A_f falls
///       below this value: both scale with the square of the mesh's size, so the same mesh
///       scaled by any factor stops at the same map up to scale}
///     \cgalParamType{`double`, ≥ 0}
///     \cgalParamDefault{`1e-9`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`, `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///   `ERROR_NO_TOPOLOGICAL_DISC`, `ERROR_NON_FINITE_COORDINATE`, `ERROR_NON_MANIFOLD` (pinched vertex, or two edges joining the same two vertices),
///   `ERROR_WRONG_PARAMETER` (negative or non-finite weight), `ERROR_NO_1_TO_1_MAPPING` (the input UVs, when
///   used, have a flipped face), or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`.
///
/// \pre every face of `mesh` is a triangle (else `ERROR_NON_TRIANGULAR_MESH`)
/// \pre with `initialize_from_uv_map(true)`, `uvmap` holds a finite UV for every vertex
/// \post on `OK`, every UV is finite, every face has a UV triangle of positive
///   signed area, and the energy is at most that of the initial map
/// \post on error, `uvmap` is left unchanged
///
/// \sa `Symmetric_dirichlet_parameterizer_3`, \ref Chapter_Cut_parameterization
template <typename TriangleMesh, typename VertexUVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code symmetric_dirichlet_parameterize(const TriangleMesh& mesh, VertexUVMap uvmap,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ic = internal::cut;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  ic::Indexed_surface<TriangleMesh> surface;
  const Error_code indexing = ic::to_error_code(ic::index_surface(mesh, vpm, surface));
  if(indexing != OK) return indexing;

  ic::Chart_mesh chart;
  std::vector<int> corner_uv;
  ic::build_chart_mesh(surface, std::vector<char>(surface.edges.size(), 0), chart, corner_uv);

  std::vector<double> weights(chart.number_of_faces(), 1.);
  const auto weight_map = choose_parameter(get_parameter(np, internal_np::face_weight_map),
                                           CGAL::Constant_property_map<typename ic::Indexed_surface<TriangleMesh>::face_descriptor, double>(1.));
  double weight_sum = 0.;
  for(std::size_t f = 0; f < weights.size(); ++f)
  {
    weights[f] = get(weight_map, surface.faces[f]);
    if(!(weights[f] >= 0.) || !std::isfinite(weights[f])) return ERROR_WRONG_PARAMETER;
    weight_sum += weights[f];
  }
  if(!(weight_sum > 0.)) return ERROR_WRONG_PARAMETER;
  // A face without weight would have no barrier against collapsing: give it
  // a tiny one (the joint method's gamma, relative to the mean weight).
  const double weight_floor = 1e-7 * weight_sum / double(weights.size());
  for(double& w : weights) w = (std::max)(w, weight_floor);

  ic::UV_vector x(2 * chart.number_of_vertices);
  if(choose_parameter(get_parameter(np, internal_np::initialize_from_uv_map), false))
  {
    ic::read_vertex_uvs(mesh, surface, corner_uv, uvmap, x);
    if(!x.allFinite() || ic::number_of_flipped_faces(chart, x) > 0) return ERROR_NO_1_TO_1_MAPPING;
  }
  else
  {
    const ic::Embedding_status embedding = ic::disk_charts_embedding(chart, x);
    if(embedding == ic::Embedding_status::NOT_DISKS) return ERROR_NO_TOPOLOGICAL_DISC;
    if(embedding == ic::Embedding_status::SOLVE_FAILED) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    if(embedding == ic::Embedding_status::FLIPPED) return ERROR_NO_1_TO_1_MAPPING;
  }

  ic::Distortion_minimizer minimizer(chart, std::move(weights));
  const ic::Newton_report report = minimizer.minimize(
    x, choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 500),
    choose_parameter(get_parameter(np, internal_np::stopping_tolerance), 1e-9));
  if(!report.ok()) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(!x.allFinite() || ic::number_of_flipped_faces(chart, x) > 0) return ERROR_NO_1_TO_1_MAPPING;
  ic::write_vertex_uvs(mesh, surface, corner_uv, x, uvmap);
  return OK;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
