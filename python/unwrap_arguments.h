// The arguments of unwrap() checked and converted (python/uv_unwrap_module.cpp):
// numpy arrays of the right shape and dtype (TypeError, ValueError,
// IndexError naming the array, the row and the value otherwise), and the
// keyword options, one per row of the option table (tools/options/option_table.h),
// turned into uv_unwrap's options (tools/uv_unwrap_options.h) as its command
// line sets them.
#ifndef CUT_PARAM_PYTHON_UNWRAP_ARGUMENTS_H
#define CUT_PARAM_PYTHON_UNWRAP_ARGUMENTS_H

#include "options/option_table.h"
#include "seam_constraints.h"
#include "uv_unwrap_options.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
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


// The value of the keyword `object` for the row `spec` of the option table
// (a bool or a choice as 0, 1, ...); ValueError or TypeError naming the
// keyword otherwise.
inline double option_value(const cut_options::Option_spec& spec, const py::object& object)
{
  using cut_options::Kind;
  const std::string keyword = spec.python;
  const std::string shown = py::repr(object).cast<std::string>();
  switch(spec.kind)
  {
  case Kind::FLAG: return object.cast<bool>() ? 1. : 0.;
  case Kind::INVERTED_FLAG: return object.cast<bool>() ? 0. : 1.;
  case Kind::CHOICE:
  {
    const std::vector<std::string> names = cut_options::choice_names(spec);
    const std::string name = py::isinstance<py::str>(object) ? object.cast<std::string>() : std::string();
    for(std::size_t k = 0; k < names.size(); ++k)
      if(names[k] == name) return double(k);
    std::string listed;
    for(std::size_t k = 0; k < names.size(); ++k)
      listed += (k == 0 ? "'" : k + 1 == names.size() ? " or '" : ", '") + names[k] + "'";
    throw py::value_error(keyword + " must be " + listed + ", not " + shown);
  }
  case Kind::RATIO:
  {
    double ratio = 0.;
    if(py::isinstance<py::bool_>(object)) ratio = 1.; // True: a square (False is handled by options_of)
    else if(py::isinstance<py::tuple>(object) || py::isinstance<py::list>(object))
    {
      const auto wh = object.cast<std::vector<double>>();
      if(wh.size() != 2) throw py::value_error(keyword + " must be (width, height), a ratio, True or False");
      ratio = wh[0] / wh[1];
    }
    else ratio = object.cast<double>();
    if(!(ratio > 0.) || !std::isfinite(ratio))
      throw py::value_error(keyword + ": the aspect ratio width / height must be a positive number");
    return ratio;
  }
  default:
  {
    if(py::isinstance<py::bool_>(object) || !(py::isinstance<py::float_>(object) || py::isinstance<py::int_>(object) ||
                                               PyNumber_Check(object.ptr())))
      throw py::type_error(keyword + " must be a number, not " + shown);
    const double x = object.cast<double>();
    if(!cut_options::in_range(spec, x))
      throw py::value_error(keyword + " must be " + cut_options::expected_text(spec) + ", not " + shown);
    return x;
  }
  }
}

// The keyword options turned into uv_unwrap's options: `given` holds the
// keyword of each row of the option table (None: not given, left as the
// library leaves it: its rules, e.g. the default box, decide).
inline uv_unwrap::Options options_of(const std::vector<py::object>& given, const py::object& hide_seams)
{
  uv_unwrap::Options o;
  o.quiet = true;
  const std::vector<cut_options::Option_spec>& table = cut_options::option_table();
  for(std::size_t i = 0; i < table.size(); ++i)
  {
    if(given[i].is_none()) continue;
    // box=False: no box, as uv_unwrap --no-box (a stiffness of 0)
    if(table[i].kind == cut_options::Kind::RATIO && py::isinstance<py::bool_>(given[i]) && !given[i].cast<bool>())
      o.method.bounding_box_stiffness = 0.;
    else
      table[i].set(o.method, option_value(table[i], given[i]));
  }
  if(!hide_seams.is_none())
  {
    o.hide_seams = hide_seams.cast<double>();
    if(!(o.hide_seams >= 0.) || !std::isfinite(o.hide_seams))
      throw py::value_error("hide_seams must be a number >= 0, not " + std::to_string(o.hide_seams));
  }
  return o;
}

/// The default of a row's keyword in unwrap()'s signature: the library's,
/// as the keyword shows it (None where the library's rule decides).
inline py::object keyword_default(const cut_options::Option_spec& spec)
{
  using cut_options::Kind;
  const std::optional<double> d = cut_options::front_end_default(spec);
  if(!d) return py::none();
  switch(spec.kind)
  {
  case Kind::FLAG: return py::bool_(*d != 0.);
  case Kind::INVERTED_FLAG: return py::bool_(*d == 0.);
  case Kind::COUNT: return py::int_(static_cast<long long>(*d));
  case Kind::CHOICE: return py::str(cut_options::choice_names(spec).at(std::size_t(*d)));
  default: return py::float_(*d);
  }
}

/// The keyword argument of the row whose field is `name`, with its default.
inline py::arg_v keyword_argument(const char* name)
{
  for(const cut_options::Option_spec& spec : cut_options::option_table())
    if(std::string(spec.name) == name) return py::arg_v(spec.python, keyword_default(spec));
  throw std::logic_error(std::string("no option ") + name + " in the option table");
}

/// The lines of unwrap()'s documentation on the table's keywords.
inline std::string keyword_documentation()
{
  std::string doc;
  for(const cut_options::Option_spec& spec : cut_options::option_table())
  {
    doc += std::string(spec.python) + ": " + spec.help;
    if(spec.kind == cut_options::Kind::CHOICE) doc += " ('" + std::string(spec.choices) + "')";
    doc += " [named parameter " + std::string(spec.name) + "]\n";
  }
  return doc;
}

} // namespace uv_unwrap_python

#endif
