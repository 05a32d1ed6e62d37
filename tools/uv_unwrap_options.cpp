// uv_unwrap's command line, declared with CLI11: syntax (--name value,
// --name=value, -o FILE), unknown options, missing values and --help are
// CLI11's; the values are checked by the validators below, whose messages
// name the value and what was expected.
#include "uv_unwrap_options.h"

#include "output_formats.h"

#include "options/cli_options.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace uv_unwrap {

namespace {

std::string invalid(const std::string& text, const std::string& expected)
{
  return "invalid value '" + text + "' (expected " + expected + ")";
}

using cut_options::parse_cli_number;

// A finite number for which `accept` holds, rewritten with all its digits so
// that CLI11's conversion gives the same double as std::stod.
CLI::Validator number(const std::string& expected, std::function<bool(double)> accept)
{
  return CLI::Validator(
    [expected, accept](std::string& text) -> std::string {
      double value = 0.;
      if(!parse_cli_number(text, value) || !accept(value)) return invalid(text, expected);
      char digits[32];
      std::snprintf(digits, sizeof digits, "%.17g", value);
      text = digits;
      return {};
    },
    "");
}

const char* const description =
  "Cuts meshes (OBJ, OFF, PLY, STL, glTF) along seams chosen jointly with a\n"
  "low-distortion UV map (Ambrosio-Tortorelli method) and writes each result\n"
  "with texture coordinates: an OBJ keeps the input's other lines (normals,\n"
  "groups, materials), a PLY gets a per-face texcoord list, a glTF gets\n"
  "TEXCOORD_0 on every triangle primitive (everything else kept). Without INPUT, runs\n"
  "on a built-in mesh. Polygons are triangulated and non-manifold input is\n"
  "repaired, with a warning on stderr. With several inputs (or a directory),\n"
  "a failed mesh does not stop the others; the exit status is the number of\n"
  "failed inputs (at most 100), 0 when all succeeded.";

// Each directory of `inputs` replaced by its mesh files, sorted by name.
std::vector<std::string> expand_directories(const std::vector<std::string>& inputs)
{
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for(const std::string& input : inputs)
  {
    std::error_code ec;
    if(!fs::is_directory(input, ec)) { files.push_back(input); continue; }
    std::vector<std::string> found;
    for(const fs::directory_entry& entry : fs::directory_iterator(input, ec))
    {
      std::string extension = entry.path().extension().string();
      for(char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
      if(entry.is_regular_file(ec) && is_mesh_extension(extension)) found.push_back(entry.path().string());
    }
    if(ec) throw Failure("cannot list the directory '" + input + "': " + ec.message(), "ERROR_CANNOT_READ");
    if(found.empty()) throw Failure("no mesh file (.obj .off .ply .stl .gltf .glb) in the directory '" + input + "'");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

} // namespace

bool is_mesh_extension(const std::string& extension)
{
  return extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl" ||
         extension == ".gltf" || extension == ".glb";
}

bool parse_arguments(int argc, char** argv, Options& options)
{
  CLI::App app(description, "uv_unwrap");
  app.get_formatter()->column_width(26);
  // as before CLI11: an option given twice takes its last value
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

  app.add_option("INPUT", options.inputs,
                 "mesh files, or directories (their .obj .off .ply .stl .gltf\n"
                 ".glb files, "
                 "sorted by name); default: CGAL's meshes/mushroom.off through\n"
                 "CGAL_DATA_DIR or the build's data/, else a built-in mesh")
    ->type_name("FILE|DIR");

  const std::string output = "Output";
  app.add_option("-o,--output", options.output,
                 "output file, one input only; its extension (" +
                   output_formats::list(".", output_formats::Inputs::mesh) + ")\n"
                 "gives the format (default: <input name>_uv.<ext> in --output-dir)")
    ->type_name("FILE")->group(output);
  app.add_option("--output-dir", options.output_dir, "folder of the outputs (default: the current directory;\n"
                                                      "created if missing)")
    ->type_name("DIR")->group(output);
  std::vector<std::string> format_names;
  for(const output_formats::Output_format& f : output_formats::table) format_names.emplace_back(f.name);
  app.add_option("--format", options.output_format,
                 "format of the outputs: " + output_formats::list() + " (default: that of\n"
                 "-o, else of the input; " + std::string(output_formats::table[0].name) +
                 " for .off and .stl inputs; a glTF\n"
                 "input gives " + output_formats::list("", output_formats::Inputs::gltf) + ")")
    ->type_name("FMT")->check(CLI::IsMember(format_names))->group(output);
  app.add_option("--uv-set", options.uv_set,
                 "glTF: write the UVs to TEXCOORD_<N>, e.g. 1 for a lightmap set\n"
                 "beside the material's (default 0); the sets below N must exist.\n"
                 "OBJ and PLY have one set: N > 0 writes it, with a warning")
    ->type_name("N")->check(CLI::Range(0, 7))->group(output);
  app.add_flag("--atlas", options.atlas,
               "one atlas for all the inputs: every mesh and every glTF\n"
               "primitive unwrapped on its own, then all their charts packed\n"
               "together at one texel density (--texels-per-unit, pages of\n"
               "--atlas-size texels); each input written as without it, the\n"
               "page of each mesh in its statistics; --svg draws every page")
    ->group("Texture atlas");
  app.add_option("--stats", options.stats, "write statistics as JSON, one input only")->type_name("FILE")->group(output);
  app.add_option("--jsonl", options.jsonl, "write statistics as JSON Lines: one line per input\n"
                                           "('-': standard output)")
    ->type_name("FILE")->group(output);
  app.add_flag("-q,--quiet", options.quiet, "print nothing but warnings and errors")->group(output);

  // the library's options: the rows of the option table
  cut_options::Given_options given;
  cut_options::add_cli_options(app, given);

  const std::string seams = "Seams";
  app.add_option("--hide-seams", options.hide_seams,
                 "move seams to where the surface is least visible (ambient\n"
                 "occlusion): seams cost exp(S (v - mean v)) times more, v\n"
                 "the face's visibility in [0,1]; S >= 0 (default 6 when\n"
                 "given alone: write the input first, or --hide-seams=S)")
    ->type_name("[S]")->expected(0, 1)->default_str("6")
    ->transform(number("a number >= 0", [](double x) { return x >= 0.; }))->group(seams);
  app.add_flag("--report-visibility", options.report_visibility,
               "compute the visibility and report seam_visibility (the mean\n"
               "visibility along the seams) without steering the seams")->group(seams);
  app.add_option("--seams", options.seams_file,
                 "cut these edges (CGAL selection file: its third line lists\n"
                 "edges as pairs of 0-based vertex indices of the input)")
    ->type_name("FILE")->check(CLI::ExistingFile)->group(seams);
  app.add_option("--forbid", options.forbid_file,
                 "never cut these edges (selection file, as --seams); a mesh\n"
                 "that cannot be opened without them fails with\n"
                 "ERROR_FORBIDDEN_EDGES_BLOCK_CUT")
    ->type_name("FILE")->check(CLI::ExistingFile)->group(seams);
  app.add_option("--save-seams", options.save_seams_file,
                 "write the seams found as a selection file (for --seams or\n"
                 "--forbid, or CGAL's Seam_mesh::add_seams())")
    ->type_name("FILE")->group(seams);
  app.add_option("--lambda-from-ply-property", options.lambda_property,
                 "per-face seam cost factors from a PLY input: a face or\n"
                 "vertex property NAME (values > 0), or 'color': gray g in\n"
                 "[0,1] of the face or vertex colors gives 10^(2g-1), black\n"
                 "draws seams, white keeps them away")
    ->type_name("NAME")->group(seams);

  bool no_box = false;
  app.add_flag("--no-box", no_box, "no bounding box at all (same as --box-stiffness 0)")->group("Texture atlas");
  std::string atlas_size;
  app.add_option("--atlas-size", atlas_size, "texels per side of a page of the atlas (same as --texture-size)")
    ->type_name("N")
    ->check(CLI::Validator(
      [](std::string& text) {
        double value = 0.;
        const cut_options::Option_spec& spec = cut_options::option_table()[cut_options::option_index("texture_size")];
        return cut_options::parse_cli_value(spec, text, value) ? std::string()
                                                               : invalid(text, cut_options::expected_text(spec));
      },
      ""))
    ->group("Texture atlas");
  bool fast = false;
  app.add_flag("--fast", fast, "for interactive use (same as --preset fast)")->group("Method");

  const std::string pictures = "Pictures";
  app.add_option("--svg", options.svg, "write the UV layout, colored by distortion, as SVG")
    ->type_name("FILE")->group(pictures);
  app.add_option("--png", options.png, "write a checkerboard-textured render of the mesh as PNG")
    ->type_name("FILE")->group(pictures);
  app.add_option_function<std::string>("--up",
      [&options](const std::string& axis) { preview_camera_for_up_axis(axis, options.camera); },
      "up axis of the mesh for --png: x, y, z, -z, ... (default y)")
    ->type_name("AXIS")
    ->check(CLI::Validator(
        [](std::string& axis) {
          Preview_camera camera;
          return preview_camera_for_up_axis(axis, camera) ? std::string()
                                                          : invalid(axis, "x, y, z, -x, -y or -z");
        },
        ""))
    ->group(pictures);
  app.add_option("--v-field", options.v_field, "write the discontinuity field v as a colored PLY")
    ->type_name("FILE.ply")->group(pictures);
  app.add_option("--v-png", options.v_png, "render the mesh colored by the field v (red: v = 0, where\n"
                                           "cuts go; blue: v = 1) with the seams in black, as PNG")
    ->type_name("FILE.png")->group(pictures);

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::CallForHelp& e)
  {
    app.exit(e); // prints the help on stdout
    return false;
  }
  catch(const CLI::ParseError& e)
  {
    throw Failure(std::string(e.what()) + " (see --help)");
  }

  const std::size_t stiffness = cut_options::option_index("bounding_box_stiffness");
  if(no_box)
  {
    if(given[stiffness].value_or(0.) > 0.) throw Failure("--no-box contradicts --box-stiffness (give one of them)");
    given[stiffness] = 0.;
  }
  const std::size_t preset = cut_options::option_index("preset");
  if(fast)
  {
    if(given[preset].value_or(1.) != 1.) throw Failure("--fast contradicts --preset (give one of them)");
    given[preset] = 1.; // the row's choice "fast"
  }
  const std::size_t texture_size = cut_options::option_index("texture_size");
  if(!atlas_size.empty())
  {
    const double size = std::stod(atlas_size); // checked by its validator
    if(given[texture_size] && *given[texture_size] != size)
      throw Failure("--atlas-size contradicts --texture-size (give one of them)");
    given[texture_size] = size;
  }
  if(given[cut_options::option_index("texels_per_unit")] && !options.atlas)
    throw Failure("--texels-per-unit is the density of a scene atlas: give --atlas too");
  if(given[cut_options::option_index("stacking_tolerance")] && !options.atlas)
    throw Failure("--stacking-tolerance shares texels between the meshes of a scene atlas: give --atlas too");
  // the options not given stay unset: the library's rules (the default box) decide
  cut_options::apply(given, options.method);
  const bool several = options.inputs.size() > 1 ||
                       (options.inputs.size() == 1 && std::filesystem::is_directory(options.inputs.front()));
  options.inputs = expand_directories(options.inputs);
  if(several && !options.output.empty())
    throw Failure("-o/--output takes one input; give --output-dir for several");
  if(!options.output.empty() && !options.output_dir.empty())
    throw Failure("give -o/--output or --output-dir, not both");
  if(several && !options.stats.empty())
    throw Failure("--stats takes one input; give --jsonl for several");
  if(options.atlas && !options.output.empty())
    throw Failure("--atlas writes each input under its own name: give --output-dir, not -o");
  if(options.atlas && !(options.png.empty() && options.v_field.empty() && options.v_png.empty()))
    throw Failure("--png, --v-field and --v-png show one mesh: not with --atlas (--svg draws the atlas's pages)");
  if(several && !options.atlas && !(options.svg.empty() && options.png.empty() && options.v_field.empty() && options.v_png.empty()))
    throw Failure("--svg, --png, --v-field and --v-png take one input");
  if(several && !(options.seams_file.empty() && options.forbid_file.empty() && options.save_seams_file.empty()))
    throw Failure("--seams, --forbid and --save-seams take one input (vertex indices are a mesh's own)");
  if(options.method.epsilon_end > options.method.epsilon_start)
    throw Failure("--epsilon-end must not exceed --epsilon-start");
  return true;
}

} // namespace uv_unwrap
