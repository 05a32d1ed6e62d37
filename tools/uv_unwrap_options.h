// The command line of uv_unwrap (parsed with CLI11 in uv_unwrap_options.cpp)
// and the exception that carries every failure to one line on stderr.
#ifndef CUT_PARAM_TOOLS_UV_UNWRAP_OPTIONS_H
#define CUT_PARAM_TOOLS_UV_UNWRAP_OPTIONS_H

#include "options/option_table.h"
#include "preview/preview.h"

#include <CGAL/Surface_mesh_parameterization/cut_parameterization_options.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace uv_unwrap {

// Any failure the user should read about: main prints it as one line.
// `status` goes to the statistics (ERROR_USAGE for command-line mistakes).
struct Failure : std::runtime_error
{
  explicit Failure(const std::string& message, std::string status_ = "ERROR_USAGE")
    : std::runtime_error(message), status(std::move(status_)) {}
  std::string status;
};

struct Options
{
  std::vector<std::string> inputs; // files and directories; empty: the built-in default mesh
  std::string output;         // one input only; empty: <input stem>_uv.<ext> in output_dir
  std::string output_dir;     // empty: the current directory
  std::string output_format;  // a name of tools/output_formats.h; empty: the input's (obj for off and stl)
  std::string stats;          // one input only
  int uv_set = 0;              // glTF: the UVs go to TEXCOORD_<uv_set>; OBJ, PLY: their one set, with a warning
  bool atlas = false;          // every mesh of every input in one scene atlas (scene_atlas_run.h)
  std::string jsonl;          // one line of statistics per input ("-": stdout)
  std::string svg, png, v_field, v_png; // pictures, written by tools/preview
  Preview_camera camera;         // of the PNG; y up unless --up
  // the library's options, filled from the option table's flags
  // (options/option_table.h); those not given stay as the library leaves
  // them (unset: its rules, e.g. the default box, decide)
  CGAL::Surface_mesh_parameterization::Cut_parameterization_options method = cut_options::front_end_options();
  // seams and visibility (face_visibility.h)
  double hide_seams = 0.;        // > 0: λ from the visibility, with this strength
  bool report_visibility = false; // compute seam_visibility without steering the seams
  // constraints (tools/seam_constraints.h)
  std::string seams_file;        // selection file: edges to cut
  std::string forbid_file;       // selection file: edges never cut
  std::string save_seams_file;   // selection file: the seams found
  std::string lambda_property;   // PLY face or vertex property (or "color") giving λ factors
  bool quiet = false;
};

// ".obj", ".off", ".ply", ".stl", ".gltf" or ".glb" (lower case): the files taken from a
// directory given as input.
bool is_mesh_extension(const std::string& extension);

// Fills `options` from the command line. Returns false when the program
// should stop successfully (--help, after printing the help); throws Failure
// on a mistake (unknown option, missing or invalid value). Directories
// among the inputs are replaced by their mesh files.
bool parse_arguments(int argc, char** argv, Options& options);

} // namespace uv_unwrap

#endif
