// Trials judged by a few Newton iterations without box and border barrier:
// the splits' (relax_charts(), on the charts a cut runs through) and the
// zips' (relax_map()).
#ifndef CGAL_SMP_CUT_INTERNAL_RELAX_H
#define CGAL_SMP_CUT_INTERNAL_RELAX_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_error_codes.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/solver/minimize_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/Map_state.h>
#include <CGAL/Surface_mesh_parameterization/internal/Cut_parameterization/pipeline/work_log.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace cut {

/// At most `iterations` iterations of the inner `solver` (weights 1, no box,
/// no barrier) on the charts of `s` that hold a face flagged in `faces` (all charts if
/// `faces` is empty); the other charts keep their map, and `s.distortion`
/// becomes the E_d of the whole map. A trial split changes only the charts
/// its cut runs through, and the charts of this energy are independent:
/// solving those alone judges the split locally, at the cost of its charts
/// instead of the whole map's (a low-poly part beside a large mesh: a
/// 12-face box beside an 80k-face sphere).
inline Error_code relax_charts(int iterations, double tolerance, Inner_solver solver, const std::vector<char>& faces,
                               Map_state& s, Work_log& log)
{
  const Chart_mesh& full = s.chart;
  Chart_mesh part;
  std::vector<int> full_vertex; // of each vertex of `part`
  if(!faces.empty())
  {
    int charts = 0;
    const std::vector<int> chart_of_face = chart_of_faces(full, charts);
    std::vector<char> solved(std::size_t(charts), 0);
    for(std::size_t f = 0; f < full.number_of_faces(); ++f)
      if(faces[f]) solved[std::size_t(chart_of_face[f])] = 1;
    std::vector<int> part_vertex(std::size_t(full.number_of_vertices), -1);
    for(std::size_t f = 0; f < full.number_of_faces(); ++f)
    {
      if(!solved[std::size_t(chart_of_face[f])]) continue;
      std::array<int, 3> corners;
      for(int k = 0; k < 3; ++k)
      {
        int& v = part_vertex[std::size_t(full.faces[f][k])];
        if(v < 0)
        {
          v = int(full_vertex.size());
          full_vertex.push_back(full.faces[f][k]);
        }
        corners[k] = v;
      }
      part.faces.push_back(corners);
      part.rest_inverse.push_back(full.rest_inverse[f]);
      part.area.push_back(full.area[f]);
    }
    part.number_of_vertices = int(full_vertex.size());
  }
  const bool whole = faces.empty() || part.number_of_faces() == full.number_of_faces();
  const Chart_mesh& solved_mesh = whole ? full : part;
  UV_vector y;
  if(whole) y = s.x;
  else
  {
    y.resize(2 * Eigen::Index(full_vertex.size()));
    for(std::size_t v = 0; v < full_vertex.size(); ++v)
      y.template segment<2>(2 * Eigen::Index(v)) = s.x.template segment<2>(2 * Eigen::Index(full_vertex[v]));
  }
  Distortion_minimizer minimizer(solved_mesh, std::vector<double>(solved_mesh.number_of_faces(), 1.), false, 0., 0.,
                                 solver);
  const Newton_report report = minimizer.minimize(y, iterations, tolerance);
  log.relax_work += log.count(report);
  if(whole) s.x = y;
  else
    for(std::size_t v = 0; v < full_vertex.size(); ++v)
      s.x.template segment<2>(2 * Eigen::Index(full_vertex[v])) = y.template segment<2>(2 * Eigen::Index(v));
  s.distortion = mean_distortion(s.chart, s.x);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

/// At most `iterations` Newton iterations on the map of `s` (weights 1, no
/// box, no barrier), which judge a trial cut or zip; `s.distortion` is set
/// to the E_d they leave.
inline Error_code relax_map(int iterations, double tolerance, Inner_solver solver, Map_state& s, Work_log& log)
{
  Distortion_minimizer minimizer(s.chart, std::vector<double>(s.chart.number_of_faces(), 1.), false, 0., 0., solver);
  const Newton_report report = minimizer.minimize(s.x, iterations, tolerance);
  log.relax_work += log.count(report);
  s.distortion = mean_distortion(s.chart, s.x);
  return report.ok() ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

} // namespace cut
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
