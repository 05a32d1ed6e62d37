// The arguments of unwrap() checked and converted (python/uv_unwrap_module.cpp):
// numpy arrays of the right shape and dtype (TypeError, ValueError,
// IndexError naming the array, the row and the value otherwise), and the
// keyword options turned into uv_unwrap's options (tools/uv_unwrap_options.h),
// as its command line sets them.
#ifndef CUT_PARAM_PYTHON_UNWRAP_ARGUMENTS_H
#define CUT_PARAM_PYTHON_UNWRAP_ARGUMENTS_H

#include "seam_constraints.h"
#include "uv_unwrap_options.h"

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_named_parameters.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace uv_unwrap_python {

namespace py = pybind11;
namespace SMP = CGAL::Surface_mesh_parameterization;

inline std::string shape_of(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

inline std::string dtype_of(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// `object` as an array of `columns` columns (0: one dimension) whose dtype
// kind is one of `kinds` ("f", "iu"...); TypeError or ValueError otherwise.
inline py::array checked_array(const py::object& object, const char* name, py::ssize_t columns, const std::string& kinds,
                        const char* what)
{
  py::array a = py::array::ensure(object);
  if(!a) throw py::type_error(std::string(name) + " must be a numpy array (or a sequence that converts to one)");
  if(kinds.find(a.dtype().kind()) == std::string::npos)
    throw py::type_error(std::string(name) + " must hold " + what + ", not " + dtype_of(a));
  const bool ok = columns > 0 ? (a.ndim() == 2 && a.shape(1) == columns) : a.ndim() == 1;
  if(!ok)
    throw py::value_error(std::string(name) + " must have shape " +
                          (columns > 0 ? "(n, " + std::to_string(columns) + ")" : std::string("(n,)")) + ", not " +
                          shape_of(a));
  return a;
}

inline py::array_t<double, py::array::c_style | py::array::forcecast> as_doubles(const py::array& a)
{
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

inline py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> as_indices(const py::array& a)
{
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
}

// Vertex pairs (s,2) of the input's numbering, each checked against n.
inline seam_constraints::Edge_pairs edge_pairs(const py::object& object, const char* name, std::size_t n)
{
  seam_constraints::Edge_pairs pairs;
  if(object.is_none()) return pairs;
  const auto a = as_indices(checked_array(object, name, 2, "iu", "integer vertex indices"));
  const auto r = a.unchecked<2>();
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
  {
    for(int k = 0; k < 2; ++k)
      if(r(i, k) < 0 || std::size_t(r(i, k)) >= n)
        throw py::index_error(std::string(name) + "[" + std::to_string(i) + ", " + std::to_string(k) + "] = " +
                              std::to_string(r(i, k)) + " is not a vertex index (V has " + std::to_string(n) +
                              " rows)");
    pairs.emplace_back(std::size_t(r(i, 0)), std::size_t(r(i, 1)));
  }
  return pairs;
}


inline uv_unwrap::Options options_of(double seam_cost, const py::object& max_distortion, const py::object& hide_seams,
                              int texture_size, double padding, const py::object& box, bool allow_overlaps)
{
  uv_unwrap::Options o;
  o.quiet = true;
  if(!(seam_cost > 0.) || !std::isfinite(seam_cost))
    throw py::value_error("seam_cost must be a positive number, not " + std::to_string(seam_cost));
  o.lambda = seam_cost;
  if(!max_distortion.is_none())
  {
    o.max_distortion = max_distortion.cast<double>();
    if(!(o.max_distortion >= 4.) || !std::isfinite(o.max_distortion))
      throw py::value_error("max_distortion must be a number >= 4 (E_d of an isometry), not " +
                            std::to_string(o.max_distortion));
  }
  if(!hide_seams.is_none())
  {
    o.hide_seams = hide_seams.cast<double>();
    if(!(o.hide_seams >= 0.) || !std::isfinite(o.hide_seams))
      throw py::value_error("hide_seams must be a number >= 0, not " + std::to_string(o.hide_seams));
  }
  if(texture_size < 1) throw py::value_error("texture_size must be at least 1, not " + std::to_string(texture_size));
  o.texture_size = texture_size;
  if(!(padding >= 0.) || !std::isfinite(padding))
    throw py::value_error("padding must be a number >= 0 (texels), not " + std::to_string(padding));
  o.padding = padding;
  o.allow_overlaps = allow_overlaps;
  // the box as uv_unwrap's options set it: default gentle square within a
  // budget; asked for (--box W:H): tight, kept whatever it costs; False: none
  o.box_distortion_budget = SMP::gentle_bounding_box_distortion_budget;
  o.box_stiffness = SMP::gentle_bounding_box_stiffness;
  if(!box.is_none())
  {
    o.box_distortion_budget = std::numeric_limits<double>::infinity();
    if(py::isinstance<py::bool_>(box))
    {
      if(box.cast<bool>()) o.box_stiffness = SMP::tight_bounding_box_stiffness;
      else o.box_stiffness = 0.;
    }
    else
    {
      double ratio = 0.;
      if(py::isinstance<py::tuple>(box) || py::isinstance<py::list>(box))
      {
        const auto wh = box.cast<std::vector<double>>();
        if(wh.size() != 2) throw py::value_error("box must be (width, height), a ratio, True or False");
        ratio = wh[0] / wh[1];
      }
      else ratio = box.cast<double>();
      if(!(ratio > 0.) || !std::isfinite(ratio))
        throw py::value_error("box: the aspect ratio width / height must be a positive number");
      o.box_aspect_ratio = ratio;
      o.box_given = true;
      o.box_stiffness = SMP::tight_bounding_box_stiffness;
    }
  }
  return o;
}

} // namespace uv_unwrap_python

#endif
