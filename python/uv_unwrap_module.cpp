// The compiled part of the Python package uv_unwrap (uv_unwrap._uv_unwrap,
// whose names uv_unwrap/__init__.py exports): cut_and_parameterize() on
// numpy arrays (the arguments: unwrap_arguments.h; the result: unwrap_result.h).
//
//   import uv_unwrap
//   r = uv_unwrap.unwrap(V, F)        # V (n,3) floats, F (m,3) vertex indices
//   r.uv, r.faces_uv                  # (k,2) UVs and (m,3) indices into them, per corner
//   r.seams, r.face_charts, r.stats   # seams as vertex pairs, chart per face, uv_unwrap's --stats
//
// The mesh goes through the input path of uv_unwrap (tools/mesh_input.h:
// validation, repair of non-manifold soups, with a warning) and the same run
// (tools/unwrap_run.h: options, visibility, measures, statistics). The
// outputs are in the numbering of the input: vertex i is V[i], face j is
// F[j], even when the mesh had to be repaired. The GIL is released while
// the library works; the progress callback (Python's, and the check of
// Ctrl-C) takes it back for each report.
#include "blas_setup.h"
#include "mesh_input.h"
#include "scene_atlas_run.h"
#include "seam_constraints.h"
#include "unwrap_arguments.h"
#include "unwrap_result.h"
#include "unwrap_run.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

#if defined(__GNUC__) && defined(__ELF__)
extern "C" int openblas_get_num_threads(void) __attribute__((weak));
#endif

namespace {

using namespace uv_unwrap_python;

// A failure of the method or of the input's repair, raised as
// uv_unwrap.UnwrapError (uv_unwrap.Cancelled for ERROR_CANCELED) with the
// library's error name in its `name` attribute.
struct Unwrap_failure
{
  std::string name, message;
};

PyObject* unwrap_error_type = nullptr;
PyObject* cancelled_type = nullptr;

// OpenBLAS's threads, one during a run as uv_unwrap has (tools/blas_setup.h),
// given back after it: the module shares its process with numpy.
struct One_blas_thread
{
  int before = -1;
  One_blas_thread()
  {
#if defined(__GNUC__) && defined(__ELF__)
    if(openblas_get_num_threads != nullptr) before = openblas_get_num_threads();
#endif
    if(!cut_tools::use_one_blas_thread()) before = -1;
  }
  ~One_blas_thread()
  {
#if defined(__GNUC__) && defined(__ELF__)
    if(before > 0) openblas_set_num_threads(before);
#endif
  }
};

// ---------------------------------------------------------------- unwrap

// one parameter per row of the option table, named by its field
#define CUT_PARAM_PY_PARAMETER(FIELD, ...) const py::object& FIELD,
#define CUT_PARAM_PY_GIVEN(FIELD, ...) FIELD,
#define CUT_PARAM_PY_KEYWORD(FIELD, ...) keyword_argument(#FIELD),

// One mesh's arrays checked and converted; `prefix` names it in messages ("meshes[2]: ").
struct Arrays
{
  std::vector<mesh_input::File_point> file_points;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::array<std::size_t, 3>> triangles;
  seam_constraints::Edge_pairs seam_pairs, forbidden_pairs;
  std::vector<double> weights;
};

Arrays read_arrays(const py::object& V_object, const py::object& F_object, const py::object& seams_object,
                   const py::object& forbidden_object, const py::object& face_weights_object,
                   const std::string& prefix = "")
{
  Arrays arrays;
  std::vector<mesh_input::File_point>& file_points = arrays.file_points;
  std::vector<Point_3>& points = arrays.points;
  std::vector<std::vector<std::size_t>>& polygons = arrays.polygons;
  std::vector<std::array<std::size_t, 3>>& triangles = arrays.triangles;
  const std::string V_name = prefix + "V", F_name = prefix + "F";
  const auto V = as_doubles(checked_array(V_object, V_name.c_str(), 3, "fiu", "numbers (float or integer coordinates)"));
  const auto F = as_indices(checked_array(F_object, F_name.c_str(), 3, "iu", "integer vertex indices"));
  const std::size_t n = std::size_t(V.shape(0)), m = std::size_t(F.shape(0));
  if(m == 0) throw py::value_error(prefix + "F has no faces: nothing to unwrap");

  file_points.reserve(n);
  points.reserve(n);
  const auto v = V.unchecked<2>();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!std::isfinite(v(i, 0)) || !std::isfinite(v(i, 1)) || !std::isfinite(v(i, 2)))
      throw py::value_error(prefix + "V[" + std::to_string(i) + "] = (" + std::to_string(v(i, 0)) + ", " +
                            std::to_string(v(i, 1)) + ", " + std::to_string(v(i, 2)) +
                            ") has a non-finite coordinate");
    file_points.emplace_back(v(i, 0), v(i, 1), v(i, 2));
    points.emplace_back(v(i, 0), v(i, 1), v(i, 2));
  }
  polygons.resize(m);
  triangles.resize(m);
  const auto f = F.unchecked<2>();
  for(std::size_t j = 0; j < m; ++j)
    for(int k = 0; k < 3; ++k)
    {
      if(f(j, k) < 0 || std::size_t(f(j, k)) >= n)
        throw py::index_error(prefix + "F[" + std::to_string(j) + ", " + std::to_string(k) + "] = " +
                              std::to_string(f(j, k)) + " is not a vertex index (V has " + std::to_string(n) +
                              " rows)");
      polygons[j].push_back(std::size_t(f(j, k)));
      triangles[j][k] = std::size_t(f(j, k));
    }
  arrays.seam_pairs = edge_pairs(seams_object, "seams", n);
  arrays.forbidden_pairs = edge_pairs(forbidden_object, "forbidden", n);
  {
    std::set<std::pair<std::size_t, std::size_t>> cut;
    for(const auto& [a, b] : arrays.seam_pairs) cut.emplace(std::min(a, b), std::max(a, b));
    for(const auto& [a, b] : arrays.forbidden_pairs)
      if(cut.count({std::min(a, b), std::max(a, b)}))
        throw py::value_error("the edge (" + std::to_string(a) + ", " + std::to_string(b) +
                              ") is both in seams (to cut) and in forbidden (never to cut)");
  }
  if(!face_weights_object.is_none())
  {
    const auto w = as_doubles(checked_array(face_weights_object, "face_weights", 0, "fiu", "numbers"));
    if(std::size_t(w.shape(0)) != m)
      throw py::value_error("face_weights must have one value per face of F (" + std::to_string(m) + "), not " +
                            std::to_string(w.shape(0)));
    const auto r = w.unchecked<1>();
    for(std::size_t j = 0; j < m; ++j)
    {
      if(!(r(j) > 0.) || !std::isfinite(r(j)))
        throw py::value_error("face_weights[" + std::to_string(j) + "] = " + std::to_string(r(j)) +
                              " (seam cost factors must be positive and finite)");
      arrays.weights.push_back(r(j));
    }
  }
  return arrays;
}

// A mesh unwrapped from its arrays (its mesh shared with a scene atlas's parts).
struct Unwrapped
{
  std::shared_ptr<Mesh> mesh = std::make_shared<Mesh>();
  mesh_input::Input_report report;
  uv_unwrap::Run_summary summary;
};

// The number of threads asked for (0: all); ValueError below 1.
int thread_count_of(const py::object& threads)
{
  int thread_count = 0;
  if(!threads.is_none())
  {
    thread_count = threads.cast<int>();
    if(thread_count < 1) throw py::value_error("threads must be at least 1");
  }
  return thread_count;
}

// Unwraps `arrays` as uv_unwrap does, the GIL released; raises the
// progress callback's exception or the library's failure. `copied`, if
// given, is asked first, once the mesh is built: true (a stacked copy, its
// result filled by it) leaves the mesh without UVs.
void unwrap_arrays(const Arrays& arrays, const uv_unwrap::Options& options, const py::object& progress,
                   int thread_count, Unwrapped& out,
                   const std::function<bool(const Mesh&, uv_unwrap::Run_summary&)>& copied = {})
{
  const auto& file_points = arrays.file_points;
  const auto& polygons = arrays.polygons;
  const auto& seam_pairs = arrays.seam_pairs;
  const auto& forbidden_pairs = arrays.forbidden_pairs;
  const auto& weights = arrays.weights;
  Mesh& mesh = *out.mesh;
  mesh_input::Input_report& report = out.report;
  uv_unwrap::Run_summary& summary = out.summary;
  summary.input = "arrays";
  std::optional<Unwrap_failure> failure;
  std::optional<py::error_already_set> python_error; // raised by progress, or Ctrl-C
  {
    py::gil_scoped_release release;
    // the callback of every progress report: Ctrl-C, then Python's progress
    uv_unwrap::Progress on_progress = [&](const SMP::Cut_and_parameterize_progress& p) {
      py::gil_scoped_acquire acquire;
      if(python_error) return false;
      try
      {
        if(PyErr_CheckSignals() != 0) throw py::error_already_set();
        if(progress.is_none()) return true;
        const py::object go_on = progress(p.phase, py::arg("pass_") = p.pass, py::arg("alternation") = p.alternation,
                                          py::arg("alternations") = p.alternations_per_pass,
                                          py::arg("distortion") = p.distortion);
        return go_on.is_none() || go_on.cast<bool>();
      }
      catch(py::error_already_set& e)
      {
        python_error.emplace(std::move(e));
        return false;
      }
      catch(const py::cast_error&)
      {
        PyErr_SetString(PyExc_TypeError, "progress must return True, False or None");
        python_error.emplace();
        return false;
      }
    };
    auto run = [&] {
      try
      {
        mesh_input::mesh_from_polygon_soup(file_points, polygons, "the mesh (V, F)", mesh, report);
        summary.vertices = num_vertices(mesh);
        summary.faces = num_faces(mesh);
        summary.warnings = report.warnings;
        auto seams = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
        auto uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
        auto v_field = mesh.add_property_map<face_descriptor, double>("f:v", 1.).first;
        try
        {
          seam_constraints::flag_edges(mesh, report, seam_pairs, "seams", seams);
        }
        catch(const seam_constraints::Constraint_error& e)
        {
          throw uv_unwrap::Failure(e.what(), "ERROR_WRONG_PARAMETER");
        }
        if(copied && copied(mesh, summary)) return;
        One_blas_thread one_blas_thread;
        uv_unwrap::unwrap_mesh(options, mesh, seams, uvmap, v_field, on_progress,
                               [&](auto forbidden, auto face_lambda) {
                                 try
                                 {
                                   seam_constraints::flag_edges(mesh, report, forbidden_pairs, "forbidden", forbidden);
                                 }
                                 catch(const seam_constraints::Constraint_error& e)
                                 {
                                   throw uv_unwrap::Failure(e.what(), "ERROR_WRONG_PARAMETER");
                                 }
                                 if(weights.empty()) return;
                                 if(report.repaired)
                                   throw uv_unwrap::Failure("face_weights need a manifold, consistently oriented "
                                                            "mesh: the repair renumbered the faces",
                                                            "ERROR_WRONG_PARAMETER");
                                 for(face_descriptor fd : faces(mesh)) face_lambda[fd] *= weights[std::size_t(fd)];
                               },
                               summary);
      }
      catch(const mesh_input::Input_error& e)
      {
        failure = Unwrap_failure{e.status, e.what()};
      }
      catch(const uv_unwrap::Failure& e)
      {
        failure = Unwrap_failure{e.status, e.what()};
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(thread_count > 0)
    {
      tbb::task_arena arena(thread_count);
      arena.execute(run);
    }
    else
      run();
#else
    run();
#endif
  }
  if(python_error) throw std::move(*python_error);
  if(failure) throw *failure;
}

// The Result of an unwrapped mesh, in its arrays' numbering; warnings raised as UserWarning.
Result result_of(Unwrapped& u, const Arrays& arrays)
{
  Result result;
  const Mesh& mesh = *u.mesh;
  auto seams = mesh.property_map<edge_descriptor, bool>("e:seam").first;
  auto uvmap = mesh.property_map<halfedge_descriptor, Point_2>("h:uv").first;
  fill_result(mesh, uvmap, seams, arrays.points, arrays.triangles, u.report.repaired, result);
  for(const std::string& w : result.warnings) u.summary.warnings.push_back(w);
  result.warnings = u.summary.warnings;
  py::module_ json = py::module_::import("json");
  result.stats = json.attr("loads")(uv_unwrap::statistics_text(u.summary));
  for(const std::string& w : result.warnings)
    if(PyErr_WarnEx(PyExc_UserWarning, ("uv_unwrap: " + w).c_str(), 1) != 0) throw py::error_already_set();
  return result;
}

Result unwrap(const py::object& V_object, const py::object& F_object,
              CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_PARAMETER) const py::object& seams_object,
              const py::object& forbidden_object, const py::object& face_weights_object, const py::object& hide_seams,
              const py::object& progress, const py::object& threads)
{
  const std::vector<py::object> given{CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_GIVEN)};
  const Arrays arrays = read_arrays(V_object, F_object, seams_object, forbidden_object, face_weights_object);
  const uv_unwrap::Options options = options_of(given, hide_seams);
  if(options.method.texels_per_unit != 0.)
    throw py::value_error("texels_per_unit is the density of a scene atlas: give it to unwrap_scene()");
  if(options.method.stacking_tolerance)
    throw py::value_error("stacking_tolerance shares texels between the meshes of a scene atlas: give it to "
                          "unwrap_scene()");
  const int thread_count = thread_count_of(threads);
  if(!progress.is_none() && !PyCallable_Check(progress.ptr())) throw py::type_error("progress must be callable");
  Unwrapped u;
  unwrap_arrays(arrays, options, progress, thread_count, u);
  return result_of(u, arrays);
}

// Several meshes in one atlas (tools/scene_atlas_run.h): each unwrapped as
// unwrap() does, then all their charts packed at one texel density.
std::vector<Result> unwrap_scene(const py::object& meshes_object, CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_PARAMETER)
                                 const py::object& seams_object, const py::object& forbidden_object,
                                 const py::object& hide_seams, const py::object& progress, const py::object& threads)
{
  const std::vector<py::object> given{CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_GIVEN)};
  if(!py::isinstance<py::sequence>(meshes_object) || py::isinstance<py::str>(meshes_object))
    throw py::type_error("meshes must be a sequence of (V, F) pairs");
  const py::sequence meshes = meshes_object.cast<py::sequence>();
  if(meshes.size() == 0) throw py::value_error("meshes is empty: nothing to unwrap");
  // seams= and forbidden=: None, or one entry (None or an (s, 2) array) per mesh
  auto per_mesh = [&](const py::object& object, const char* name) {
    std::vector<py::object> entries(meshes.size(), py::none());
    if(object.is_none()) return entries;
    if(!py::isinstance<py::sequence>(object) || py::len(object) != meshes.size())
      throw py::value_error(std::string(name) + " must be None or hold one entry per mesh (" +
                            std::to_string(meshes.size()) + ")");
    for(std::size_t i = 0; i < meshes.size(); ++i) entries[i] = object.cast<py::sequence>()[i];
    return entries;
  };
  const std::vector<py::object> seams = per_mesh(seams_object, "seams"), forbidden = per_mesh(forbidden_object, "forbidden");
  std::vector<Arrays> arrays;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    const std::string prefix = "meshes[" + std::to_string(i) + "]";
    const py::object pair = meshes[i];
    if(!py::isinstance<py::sequence>(pair) || py::len(pair) != 2)
      throw py::type_error(prefix + " must be a (V, F) pair");
    arrays.push_back(read_arrays(pair[py::int_(0)], pair[py::int_(1)], seams[i], forbidden[i], py::none(), prefix + ": "));
  }
  const uv_unwrap::Options options = options_of(given, hide_seams);
  const int thread_count = thread_count_of(threads);
  if(!progress.is_none() && !PyCallable_Check(progress.ptr())) throw py::type_error("progress must be callable");
  std::vector<Unwrapped> unwrapped(arrays.size());
  std::vector<uv_unwrap::Scene_part> parts;
  for(std::size_t i = 0; i < arrays.size(); ++i)
  {
    int original = -1;
    auto copied = [&](const Mesh& mesh, uv_unwrap::Run_summary& summary) {
      original = uv_unwrap::stacked_original(parts, mesh, options.method.stacking_tolerance);
      if(original >= 0) uv_unwrap::take_stacked_result(parts[std::size_t(original)], summary);
      return original >= 0;
    };
    try
    {
      unwrap_arrays(arrays[i], options, progress, thread_count, unwrapped[i], copied);
    }
    catch(Unwrap_failure& e)
    {
      e.message = "meshes[" + std::to_string(i) + "]: " + e.message;
      throw;
    }
    Mesh& mesh = *unwrapped[i].mesh;
    parts.push_back({i, "meshes[" + std::to_string(i) + "]", unwrapped[i].mesh,
                     mesh.property_map<edge_descriptor, bool>("e:seam").first,
                     mesh.property_map<halfedge_descriptor, Point_2>("h:uv").first, {}, -1, original,
                     unwrapped[i].summary.result});
  }
  uv_unwrap::Scene_packing packing;
  try
  {
    py::gil_scoped_release release;
    packing = uv_unwrap::pack_scene(parts, options.method);
  }
  catch(const uv_unwrap::Failure& e)
  {
    throw Unwrap_failure{e.status, e.what()};
  }
  std::vector<Result> results;
  for(std::size_t i = 0; i < arrays.size(); ++i)
  {
    uv_unwrap::Run_summary& s = unwrapped[i].summary;
    const Mesh& mesh = *parts[i].mesh;
    s.atlas = uv_unwrap::atlas_statistics(parts, i, packing);
    s.flipped_faces = SMP::number_of_flipped_faces(mesh, parts[i].uvmap);
    s.border_crossings = SMP::number_of_border_crossings(mesh, parts[i].uvmap);
    s.overlap_area = SMP::uv_overlap_area(mesh, parts[i].uvmap);
    s.result.uv_coverage = SMP::uv_area(mesh, parts[i].uvmap);
    s.result.number_of_charts += parts[i].added_charts; // cut for packing
    s.result.seam_length += parts[i].added_seam_length;
    s.result.uv_scale = packing.texels_per_unit / options.method.texture_size;
    s.uv_in_unit_square = packing.page[std::size_t(parts[i].page)].uv_in_unit_square;
    results.push_back(result_of(unwrapped[i], arrays[i]));
    results.back().page = parts[i].page;
  }
  return results;
}
} // namespace

PYBIND11_MODULE(_uv_unwrap, m)
{
  m.doc() = "Automatic UV unwrapping: seams and UV map optimized together (Ambrosio-Tortorelli method).";

  py::object runtime_error = py::reinterpret_borrow<py::object>(PyExc_RuntimeError);
  unwrap_error_type = PyErr_NewExceptionWithDoc(
    "uv_unwrap.UnwrapError",
    "The method or the input's repair failed; `name` is the library's error name (e.g. ERROR_NON_MANIFOLD).",
    runtime_error.ptr(), nullptr);
  cancelled_type = PyErr_NewExceptionWithDoc("uv_unwrap.Cancelled",
                                             "The progress callback returned False (name ERROR_CANCELED).",
                                             unwrap_error_type, nullptr);
  m.add_object("UnwrapError", py::reinterpret_borrow<py::object>(unwrap_error_type));
  m.add_object("Cancelled", py::reinterpret_borrow<py::object>(cancelled_type));
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const Unwrap_failure& e)
    {
      PyObject* type = e.name == "ERROR_CANCELED" ? cancelled_type : unwrap_error_type;
      py::object error = py::reinterpret_borrow<py::object>(type)(e.message);
      error.attr("name") = e.name;
      PyErr_SetObject(type, error.ptr());
    }
  });

  py::class_<Result>(m, "Result", "What unwrap() returns (see its documentation).")
    .def_readonly("uv", &Result::uv, "(k, 2) float64: the distinct UVs")
    .def_readonly("faces_uv", &Result::faces_uv, "(m, 3) int64: per face of F, the UV of each corner (index into uv)")
    .def_readonly("seams", &Result::seams, "(s, 2) int64: the seam edges as pairs of vertex indices of V (a < b)")
    .def_readonly("face_charts", &Result::face_charts, "(m,) int64: the chart of each face of F")
    .def_readonly("stats", &Result::stats, "dict: the statistics of `uv_unwrap --stats`")
    .def_readonly("warnings", &Result::warnings, "list of str: input repairs and remarks (also warned)")
    .def_readonly("page", &Result::page, "int: unwrap_scene()'s atlas page of the mesh (-1 from unwrap())")
    .def("__repr__", [](const Result& r) {
      auto get = [&](const char* k) { return py::str(r.stats[k]).cast<std::string>(); };
      return "<uv_unwrap.Result: " + get("charts") + " charts, E_d " + get("distortion") + ", E_s " +
             get("seam_length") + ", " + std::to_string(r.uv.shape(0)) + " UVs>";
    });

  // the documentation: the table's keywords between the arrays and the other arguments
  static const std::string documentation = std::string(R"doc(Cuts the triangle mesh (V, F) and computes its UV map: a texture atlas in the unit square.

V: (n, 3) vertex positions; F: (m, 3) vertex indices of the triangles.
The options (from the option table; not given: the library's default):
)doc") + keyword_documentation() + R"doc(box: also True (a tight square) or False (no box: box_stiffness 0); None: a gentle square within a budget.
seams: (s, 2) vertex pairs: edges to cut (kept as seams). forbidden: (s, 2) vertex pairs: edges never cut.
face_weights: (m,) positive factors of the seam cost per face (< 1 draws seams, > 1 keeps them away).
hide_seams: strength S >= 0 of moving seams to where the surface is least visible (uv_unwrap --hide-seams).
progress: called as progress(phase, pass_=, alternation=, alternations=, distortion=); False cancels
  (uv_unwrap.Cancelled). Ctrl-C cancels too (KeyboardInterrupt).
threads: number of threads (default: all cores); the result does not depend on it.

Returns a Result: uv (k, 2), faces_uv (m, 3) (per corner, OBJ style: V and F keep their order), seams
(s, 2) vertex pairs, face_charts (m,), stats (uv_unwrap --stats), warnings. The GIL is released while it runs.
Raises TypeError / ValueError / IndexError for bad arrays, UnwrapError (with .name) when the method fails.)doc";
  m.def("unwrap", &unwrap, py::arg("V"), py::arg("F"), py::kw_only(), CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_KEYWORD)
        py::arg("seams") = py::none(), py::arg("forbidden") = py::none(), py::arg("face_weights") = py::none(),
        py::arg("hide_seams") = py::none(), py::arg("progress") = py::none(), py::arg("threads") = py::none(),
        documentation.c_str());

  static const std::string scene_documentation = std::string(R"doc(One texture atlas for several meshes (a scene's lightmap, say).

meshes: a sequence of (V, F) pairs, each as unwrap() takes them. Each mesh is unwrapped on its own with the
options below (those of unwrap()), then the charts of all are packed together by their shape, at one texel
density (texels_per_unit, texels per unit of 3D length; 0: the largest at which all fit one page), into
pages of texture_size texels per side with padding texels between charts; a mesh's charts are on one page.
)doc") + keyword_documentation() + R"doc(seams, forbidden: None, or a list with one entry per mesh (None or (s, 2) vertex pairs), as in unwrap().
hide_seams, progress, threads: as in unwrap().

Returns a list of Result, one per mesh in order: uv in [0,1]^2 of the mesh's page, faces_uv, seams,
face_charts, page (the page's number), stats (with "atlas": pages, stacked_on (the mesh, "meshes[j]", whose
texels it shares, or None), page_count, texels_per_unit, charts_packed and the measures of every page on the
combined UVs of its meshes with texels of their own: flipped_faces, border_crossings, overlap_area,
uv_coverage). With stacking_tolerance, a mesh that a rotation and a translation move onto an earlier one
(same faces over the same vertex order) is not unwrapped: it gets that mesh's UVs and seams. Raises UnwrapError (name ERROR_WRONG_PARAMETER) when a mesh does not fit one page at the
density given.)doc";
  m.def("unwrap_scene", &unwrap_scene, py::arg("meshes"), py::kw_only(), CUT_PARAM_OPTION_TABLE(CUT_PARAM_PY_KEYWORD)
        py::arg("seams") = py::none(), py::arg("forbidden") = py::none(), py::arg("hide_seams") = py::none(),
        py::arg("progress") = py::none(), py::arg("threads") = py::none(), scene_documentation.c_str());
}
