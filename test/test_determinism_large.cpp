// Thread-count determinism where the large-mesh code runs: meshes whose
// Newton systems (two unknowns per UV vertex) are above the thresholds of
// the sparse Cholesky (Sparse_cholesky.h: CHOLMOD with OpenBLAS from
// cholmod_threshold unknowns, METIS ordering from metis_threshold), in the
// default mode and under a distortion bound. The same seams, UVs (bit for
// bit) and Newton iterations with 1, 2 and 4 TBB threads; skipped without
// TBB. Lean options (one alternation per ε, few Newton iterations) keep the
// runs short: determinism does not need a converged map.
#include "cut_result_checks.h"

#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/Sparse_cholesky.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
using namespace cut_test;

namespace {

namespace ic = SMP::internal::cut;

// UV vertices of a run: at least the mesh's vertices (seams add copies)
template <typename Mesh>
long unknowns_at_least(const Mesh& mesh)
{
  return 2 * long(num_vertices(mesh));
}

} // namespace

// 16,290 vertices (32,580 unknowns, over metis_threshold): 32,400 faces,
// so the alternation runs on the multiresolution copy (10,000 faces,
// over cholmod_threshold) and the final solve on the whole mesh.
TEST(Determinism_large, default_mode_above_the_metis_threshold)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(90, 180, 1.5, 0.2));
  ASSERT_GE(unknowns_at_least(mesh), long(ic::Sparse_cholesky::metis_threshold));
  namespace P = SMP::parameters;
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    const auto& result = run.run(P::iterations_per_epsilon(1, CGAL::parameters::number_of_iterations(20)));
    check_cut_result(mesh, run);
    return result;
  });
}

// 5,050 vertices (10,100 unknowns, over cholmod_threshold), under a
// distortion bound: its trials run two at a time.
TEST(Determinism_large, bound_mode_above_the_cholmod_threshold)
{
  const Surface_mesh mesh = make_mesh<Surface_mesh>(spike_disk_soup(50, 100, 1.5, 0.2));
  ASSERT_GE(unknowns_at_least(mesh), long(ic::Sparse_cholesky::cholmod_threshold));
  namespace P = SMP::parameters;
  expect_same_result_for_thread_counts(mesh, {1, 2, 4}, [&](Cut_run<Surface_mesh>& run) {
    const auto& result = run.run(P::distortion_bound(4.2, P::iterations_per_epsilon(1, CGAL::parameters::number_of_iterations(20))));
    check_cut_result(mesh, run);
    return result;
  });
}
