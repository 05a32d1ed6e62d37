// Error codes of the cut-and-parameterize package: CGAL's
// Surface_mesh_parameterization::Error_code values, unchanged, plus the cases
// CGAL's list lacks, and one message table for all of them.
#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_ERROR_CODES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_PARAMETERIZATION_ERROR_CODES_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgCutParameterizationRef
/// A vertex coordinate is NaN or infinite.
constexpr Error_code ERROR_NON_FINITE_COORDINATE = Error_code(ERROR_WRONG_PARAMETER + 1);
/// \ingroup PkgCutParameterizationRef
/// A face has zero area (or is so thin that its shape cannot be inverted).
constexpr Error_code ERROR_DEGENERATE_FACE = Error_code(ERROR_WRONG_PARAMETER + 2);
/// \ingroup PkgCutParameterizationRef
/// An edge or a vertex is non-manifold.
constexpr Error_code ERROR_NON_MANIFOLD = Error_code(ERROR_WRONG_PARAMETER + 3);
/// \ingroup PkgCutParameterizationRef
/// The progress callback asked to stop; the output maps are left unchanged.
constexpr Error_code ERROR_CANCELED = Error_code(ERROR_WRONG_PARAMETER + 4);

/// \ingroup PkgCutParameterizationRef
/// The forbidden seam edges (`forbidden_seam_edge_map`) leave no cut that
/// opens the mesh into topological disks: for example every edge of a closed
/// surface is forbidden, or forbidden edges cross every loop around a handle.
constexpr Error_code ERROR_FORBIDDEN_EDGES_BLOCK_CUT = Error_code(ERROR_WRONG_PARAMETER + 5);
/// \ingroup PkgCutParameterizationRef
/// Message for any code of CGAL's `Error_code` or of this package (CGAL's own
/// table is off by one from code 4 on; this one is not).
/// \pre none: any value is accepted
/// \post the result is a non-null static string ("Unknown error" for a value that is no code)
inline const char* error_message(Error_code code)
{
  switch(int(code))
  {
    case OK: return "Success";
    case ERROR_EMPTY_MESH: return "Input mesh is empty";
    case ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangular";
    case ERROR_NO_TOPOLOGICAL_DISC: return "Input mesh is not a topological disc";
    case ERROR_NO_TOPOLOGICAL_BALL: return "Input mesh is not a topological ball";
    case ERROR_BORDER_TOO_SHORT: return "This border parameterization requires a longer border";
    case ERROR_NON_CONVEX_BORDER: return "This parameterization method requires a convex border";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
    case ERROR_NO_1_TO_1_MAPPING: return "Parameterization failed: no one-to-one mapping";
    case ERROR_WRONG_PARAMETER: return "A method received an unexpected parameter";
    case int(ERROR_NON_FINITE_COORDINATE): return "A vertex coordinate is not finite";
    case int(ERROR_DEGENERATE_FACE): return "A face is degenerate (zero area)";
    case int(ERROR_NON_MANIFOLD): return "The mesh is not manifold";
    case int(ERROR_CANCELED): return "Canceled by the progress callback";
    case int(ERROR_FORBIDDEN_EDGES_BLOCK_CUT): return "The forbidden seam edges leave no cut that opens the mesh into disks";
    default: return "Unknown error";
  }
}

/// \ingroup PkgCutParameterizationRef
/// Short identifier of a code, such as "ERROR_DEGENERATE_FACE" (and "ok" for
/// `OK`), for logs and JSON.
/// \pre none: any value is accepted
/// \post the result is a non-null static string ("ERROR_UNKNOWN" for a value that is no code)
inline const char* error_name(Error_code code)
{
  switch(int(code))
  {
    case OK: return "ok";
    case ERROR_EMPTY_MESH: return "ERROR_EMPTY_MESH";
    case ERROR_NON_TRIANGULAR_MESH: return "ERROR_NON_TRIANGULAR_MESH";
    case ERROR_NO_TOPOLOGICAL_DISC: return "ERROR_NO_TOPOLOGICAL_DISC";
    case ERROR_NO_TOPOLOGICAL_BALL: return "ERROR_NO_TOPOLOGICAL_BALL";
    case ERROR_BORDER_TOO_SHORT: return "ERROR_BORDER_TOO_SHORT";
    case ERROR_NON_CONVEX_BORDER: return "ERROR_NON_CONVEX_BORDER";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM";
    case ERROR_NO_1_TO_1_MAPPING: return "ERROR_NO_1_TO_1_MAPPING";
    case ERROR_WRONG_PARAMETER: return "ERROR_WRONG_PARAMETER";
    case int(ERROR_NON_FINITE_COORDINATE): return "ERROR_NON_FINITE_COORDINATE";
    case int(ERROR_DEGENERATE_FACE): return "ERROR_DEGENERATE_FACE";
    case int(ERROR_NON_MANIFOLD): return "ERROR_NON_MANIFOLD";
    case int(ERROR_CANCELED): return "ERROR_CANCELED";
    case int(ERROR_FORBIDDEN_EDGES_BLOCK_CUT): return "ERROR_FORBIDDEN_EDGES_BLOCK_CUT";
    default: return "ERROR_UNKNOWN";
  }
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
