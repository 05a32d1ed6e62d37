// The options of the front ends (uv_unwrap, the Python module, the Blender
// add-on, the benchmark), each written once here: its field of
// Cut_parameterization_options (= its named parameter), its command-line
// flag, its Python keyword, its Blender property, its kind, its range, its
// group and its help. The default is the library's (read from a
// default-constructed Cut_parameterization_options, not restated here, but
// for the one front_end_options() changes); an
// option the user did not give stays as the library leaves it ("unset"
// for the std::optional fields, whose rule is the library's).
//
// The CLI (cli_options.h) and the Python module (python/) are built from
// CUT_PARAM_OPTION_TABLE; the Blender add-on reads option_table.py, which
// export_option_table.cpp writes from it at build time into the add-on's zip;
// tools/tests/check_option_coverage.py fails when a named parameter of the
// library is in no row (or a row is missing from a front end).
//
// Adding an option: a field and named parameter in the library, then a row here.
#ifndef CUT_PARAM_TOOLS_OPTIONS_OPTION_TABLE_H
#define CUT_PARAM_TOOLS_OPTIONS_OPTION_TABLE_H

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cut_options {

namespace SMP = CGAL::Surface_mesh_parameterization;

/// How a front end shows an option.
enum class Kind
{
  REAL,           ///< a number in [min, max] (min excluded if min_open)
  COUNT,          ///< a whole number in [min, max]
  FLAG,           ///< a bool: a flag sets it to true
  INVERTED_FLAG,  ///< a bool that the front ends name by its negation: the flag sets it to false
  RATIO,          ///< a positive number; CLI: W:H, Python: (w, h) or a ratio
  CHOICE          ///< an enumeration: its names in `choices` ("a|b"), in the enum's order
};

constexpr double unbounded = std::numeric_limits<double>::infinity();

// X(field, kind, CLI flag, Python keyword, Blender property, min, min excluded, max, choices, group, help)
// Names differ from the field where users already rely on them (lambda:
// --lambda / seam_cost; distortion_bound: --max-distortion / max_distortion;
// global_injectivity: --allow-overlaps / allow_overlaps, inverted).
#define CUT_PARAM_OPTION_TABLE(X)                                                                                    \
  X(lambda, REAL, "--lambda", "seam_cost", "seam_cost", 0., true, unbounded, "", "Method",                          \
    "seam cost, relative to the mean edge length (higher: shorter seams, more distortion)")                          \
  X(distortion_bound, REAL, "--max-distortion", "max_distortion", "max_distortion", 4., false, unbounded, "",        \
    "Method",                                                                                                        \
    "E_d at most this (>= 4, the E_d of an isometry), with the shortest seams found by cuts added where the map "   \
    "is most distorted, or else by runs with other seam costs (default: no bound)")                                  \
  X(epsilon_start, REAL, "--epsilon-start", "epsilon_start", "epsilon_start", 0., true, unbounded, "", "Method",    \
    "first epsilon, relative to the mean edge length")                                                               \
  X(epsilon_end, REAL, "--epsilon-end", "epsilon_end", "epsilon_end", 0., true, unbounded, "", "Method",            \
    "epsilon is halved while above this value")                                                                      \
  X(iterations_per_epsilon, COUNT, "--iterations", "iterations_per_epsilon", "iterations_per_epsilon", 1., false,   \
    1e6, "", "Method", "alternations (u-step, v-step) per epsilon")                                                  \
  X(gamma, REAL, "--gamma", "gamma", "gamma", 0., true, unbounded, "", "Method",                                    \
    "keeps the distortion weight v^2 + gamma positive")                                                             \
  X(number_of_passes, COUNT, "--passes", "number_of_passes", "number_of_passes", 1., false, 1e6, "", "Method",      \
    "optimize-and-cut passes")                                                                                       \
  X(minimum_relative_cut_length, REAL, "--min-relative-cut-length", "minimum_relative_cut_length",                   \
    "minimum_relative_cut_length", 0., false, 1., "", "Method",                                                      \
    "cut paths shorter than this fraction of the longest are dropped")                                              \
  X(number_of_iterations, COUNT, "--max-newton-iterations", "max_newton_iterations", "max_newton_iterations", 1.,   \
    false, 1e6, "", "Method", "the most Newton iterations of one minimization")                                       \
  X(multiresolution_faces, COUNT, "--multiresolution-faces", "multiresolution_faces", "multiresolution_faces", 0.,  \
    false, 1e9, "", "Method",                                                                                        \
    "above this many faces the first u-step runs on a simplified copy (0: never)")                                   \
  X(inner_solver, CHOICE, "--inner-solver", "inner_solver", "inner_solver", 0., false, 1., "newton|proxy-quasi-newton", \
    "Method",                                                                                                        \
    "inner solver of the UV minimizations: newton (a factorization per iteration) or proxy-quasi-newton (the "     \
    "Hessian factorized at a few iterates, L-BFGS steps between them: more iterations, most without a "             \
    "factorization)")                                                                                                \
  X(reject_degenerate_faces, FLAG, "--reject-degenerate-faces", "reject_degenerate_faces", "reject_degenerate_faces", \
    0., false, 1., "", "Method", "fail with ERROR_DEGENERATE_FACE on degenerate faces instead of clamping them")   \
  X(weld_colocal_vertices, INVERTED_FLAG, "--no-weld", "no_weld", "no_weld", 0., false, 1., "", "Method",           \
    "keep vertices at the same position apart (each piece of a mesh exported with split normals its own chart) "  \
    "instead of unwrapping them as one vertex")                                                                     \
  X(hard_edge_angle, REAL, "--hard-edge-angle", "hard_edge_angle", "hard_edge_angle", 0., false, 180., "",        \
    "Method", "edges whose dihedral angle exceeds this many degrees are seams, and so are the edges where the "    \
    "input's normals are split (OBJ vn, glTF NORMAL; 180: those only), as lightmaps need (default: none)")       \
  X(global_injectivity, INVERTED_FLAG, "--allow-overlaps", "allow_overlaps", "allow_overlaps", 0., false, 1., "",   \
    "Texture atlas", "let a chart overlap itself (no border barrier; charts still packed apart)")                    \
  X(texture_size, COUNT, "--texture-size", "texture_size", "texture_size", 1., false, 1e6, "", "Texture atlas",     \
    "texture width and height in texels, the unit of the padding")                                                   \
  X(padding, REAL, "--padding", "padding", "margin", 0., false, unbounded, "", "Texture atlas",                     \
    "gap between charts and to the square's sides, in texels")                                                       \
  X(texels_per_unit, REAL, "--texels-per-unit", "texels_per_unit", "texels_per_unit", 0., false, unbounded, "",     \
    "Texture atlas",                                                                                                 \
    "scene atlas only (--atlas, unwrap_scene()): texels per unit of 3D length, the same for every mesh, pages "     \
    "added as needed; 0: the largest density at which all fit one page")                                            \
  X(stacking_tolerance, REAL, "--stacking-tolerance", "stacking_tolerance", "stacking_tolerance", 0., false, 1., "",  \
    "Texture atlas",                                                                                                 \
    "scene atlas only (--atlas, unwrap_scene()): a mesh that a rotation and a translation (never a mirror) move "   \
    "onto an earlier one of the same faces, within this fraction of its bounding box diagonal (e.g. 0.0001), "      \
    "shares its texels: unwrapped once, packed once (default: every mesh its own texels; a glTF mesh used by "      \
    "several nodes always has one set)")                                                                             \
  X(split_charts_for_packing, REAL, "--split-charts-for-packing", "split_charts_for_packing",                       \
    "split_charts_for_packing", 0., true, 1., "", "Texture atlas",                                                   \
    "cut every chart that fills less than this fraction of its smallest bounding rectangle (e.g. 0.5) into pieces " \
    "that fill more before packing, by straight cuts across it, short ones preferred: more charts and seams, "      \
    "UVs, distortion and guarantees unchanged, a fuller atlas (default: charts never cut for packing)")            \
  X(world_units, FLAG, "--world-units", "world_units", "world_units", 0., false, 1., "", "Texture atlas",           \
    "keep UVs in 3D units (charts still packed) instead of [0,1]")                                                   \
  X(bounding_box_aspect_ratio, RATIO, "--box", "box", "box_aspect", 0., true, unbounded, "", "Texture atlas",       \
    "pull each chart tightly into a box of this aspect ratio (W:H, e.g. 2:1); without it, a gentle pull into a "    \
    "square rounds charts off")                                                                                      \
  X(bounding_box_stiffness, REAL, "--box-stiffness", "box_stiffness", "box_stiffness", 0., false, unbounded, "",    \
    "Texture atlas",                                                                                                 \
    "how hard the box pulls, >= 0 (default 5, or 300 with a box asked for; 0: no box); given, the box is kept "     \
    "whatever it costs")                                                                                             \
  X(bounding_box_distortion_budget, REAL, "--box-distortion-budget", "box_distortion_budget",                        \
    "box_distortion_budget", 0., false, unbounded, "", "Texture atlas",                                              \
    "the largest E_d increase the box may cost before it is weakened, then dropped (default 0.045 for the "         \
    "default box, no limit for a box asked for)")                                                                   \
  X(preset, CHOICE, "--preset", "preset", "preset", 0., false, 1., "default|fast", "Method",                        \
    "default: quality first; fast: for interactive use (cuts decided on a simplified copy above 2000 faces, no "    \
    "seam rerouting, looser Newton tolerances, no search for the default distortion target; the same guarantees)")

/// One row of the table.
struct Option_spec
{
  const char* name;     ///< the field of Cut_parameterization_options and the named parameter
  Kind kind;
  const char* cli;      ///< the command-line flag
  const char* python;   ///< the keyword of uv_unwrap.unwrap()
  const char* blender;  ///< the property of the Blender operator
  double min;
  bool min_open;        ///< min itself excluded
  double max;
  const char* choices;  ///< CHOICE: the names, '|'-separated, in the enum's order
  const char* group;    ///< the section of --help
  const char* help;
  /// sets the field from a value (a bool or an enum as 0, 1, ...)
  void (*set)(SMP::Cut_parameterization_options&, double);
  /// the field's value; nullopt for an unset std::optional field
  std::optional<double> (*get)(const SMP::Cut_parameterization_options&);
};

namespace internal {
inline void assign(double& field, double x) { field = x; }
inline void assign(int& field, double x) { field = static_cast<int>(x); }
inline void assign(bool& field, double x) { field = x != 0.; }
inline void assign(std::optional<double>& field, double x) { field = x; }
inline void assign(SMP::Inner_solver& field, double x) { field = static_cast<SMP::Inner_solver>(static_cast<int>(x)); }
inline void assign(SMP::Preset& field, double x) { field = static_cast<SMP::Preset>(static_cast<int>(x)); }
inline std::optional<double> value(double field) { return field; }
inline std::optional<double> value(int field) { return double(field); }
inline std::optional<double> value(bool field) { return field ? 1. : 0.; }
inline std::optional<double> value(const std::optional<double>& field) { return field; }
inline std::optional<double> value(SMP::Inner_solver field) { return double(static_cast<int>(field)); }
inline std::optional<double> value(SMP::Preset field) { return double(static_cast<int>(field)); }
} // namespace internal

#define CUT_PARAM_OPTION_SPEC(FIELD, KIND, CLI, PY, BLENDER, MIN, MIN_OPEN, MAX, CHOICES, GROUP, HELP)              \
  Option_spec{#FIELD, Kind::KIND, CLI, PY, BLENDER, MIN, MIN_OPEN, MAX, CHOICES, GROUP, HELP,                         \
              [](SMP::Cut_parameterization_options& o, double x) { internal::assign(o.FIELD, x); },                   \
              [](const SMP::Cut_parameterization_options& o) { return internal::value(o.FIELD); }},

/// The rows, in the table's order.
inline const std::vector<Option_spec>& option_table()
{
  static const std::vector<Option_spec> table{CUT_PARAM_OPTION_TABLE(CUT_PARAM_OPTION_SPEC)};
  return table;
}

#undef CUT_PARAM_OPTION_SPEC

/// The options the front ends start from: the library's defaults, except
/// that colocal vertices are welded (a file exported with split normals is
/// one surface to its user; a library caller's mesh is taken as it is).
inline SMP::Cut_parameterization_options front_end_options()
{
  SMP::Cut_parameterization_options o;
  o.weld_colocal_vertices = true;
  return o;
}

/// The front ends' default of `spec` (nullopt: unset, the library's rule applies).
inline std::optional<double> default_value(const Option_spec& spec)
{
  return spec.get(front_end_options());
}

/// The names of a CHOICE, in order.
inline std::vector<std::string> choice_names(const Option_spec& spec)
{
  std::vector<std::string> names;
  std::string text = spec.choices;
  for(std::size_t start = 0; !text.empty();)
  {
    const std::size_t bar = text.find('|', start);
    names.push_back(text.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
    if(bar == std::string::npos) break;
    start = bar + 1;
  }
  return names;
}

/// `x` is in the range of `spec` (and whole for a COUNT).
inline bool in_range(const Option_spec& spec, double x)
{
  if(!std::isfinite(x)) return false;
  if(spec.kind == Kind::COUNT && x != std::floor(x)) return false;
  return (spec.min_open ? x > spec.min : x >= spec.min) && x <= spec.max;
}

/// What the range asks for, for error messages: "a positive number", "a number >= 4", "at least 1"...
inline std::string expected_text(const Option_spec& spec)
{
  auto number = [](double x) {
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if(!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  if(spec.kind == Kind::COUNT)
    return spec.max >= 1e6 ? "at least " + number(spec.min) : "an integer in [" + number(spec.min) + ", " + number(spec.max) + "]";
  if(spec.kind == Kind::RATIO) return "a positive number";
  if(spec.kind == Kind::FLAG || spec.kind == Kind::INVERTED_FLAG) return "true or false";
  if(spec.kind == Kind::CHOICE) return "one of " + std::string(spec.choices);
  if(spec.min == 0. && spec.min_open && spec.max == unbounded) return "a positive number";
  if(spec.max == unbounded) return "a number " + std::string(spec.min_open ? "> " : ">= ") + number(spec.min);
  return "a number in " + std::string(spec.min_open ? "(" : "[") + number(spec.min) + ", " + number(spec.max) + "]";
}

/// The default as a front end offers it: the library's, unless it is unset
/// or outside the range (distortion_bound's 0, "no bound"): then nullopt,
/// and the front end's "not given" stands for it.
inline std::optional<double> front_end_default(const Option_spec& spec)
{
  const std::optional<double> d = default_value(spec);
  if(!d || spec.kind == Kind::FLAG || spec.kind == Kind::INVERTED_FLAG || spec.kind == Kind::CHOICE) return d;
  return in_range(spec, *d) ? d : std::nullopt;
}

/// The default as a front end shows it: "1", "0.01", "newton"; "" for unset.
inline std::string default_text(const Option_spec& spec)
{
  const std::optional<double> d = front_end_default(spec);
  if(!d) return "";
  if(spec.kind == Kind::CHOICE) return choice_names(spec).at(std::size_t(*d));
  if(spec.kind == Kind::FLAG || spec.kind == Kind::INVERTED_FLAG) return *d != 0. ? "true" : "false";
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.15g", *d);
  return digits;
}

/// The values a front end was given, one slot per row of option_table()
/// (nullopt: not given).
using Given_options = std::vector<std::optional<double>>;

/// The row named `name` (a field of Cut_parameterization_options); its index in the table.
inline std::size_t option_index(const std::string& name)
{
  const std::vector<Option_spec>& table = option_table();
  for(std::size_t i = 0; i < table.size(); ++i)
    if(name == table[i].name) return i;
  throw std::logic_error("no option " + name + " in the option table");
}

/// Copies the values given into `o`; the others keep their value (the library's default, or unset).
inline void apply(const Given_options& given, SMP::Cut_parameterization_options& o)
{
  const std::vector<Option_spec>& table = option_table();
  for(std::size_t i = 0; i < given.size() && i < table.size(); ++i)
    if(given[i]) table[i].set(o, *given[i]);
}

} // namespace cut_options

#endif
