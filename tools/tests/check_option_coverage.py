"""Every named parameter of the library reaches every front end.

Lists the library's named parameters (the CGAL_SMP_CUT_NAMED_PARAMETER lines
of cut_parameterization_named_parameters.h and the fields of
Cut_parameterization_options) and fails when one is neither a row of the
option table (option_table.json, written from tools/options/option_table.h)
nor in EXEMPT below, when a row names no parameter of the library, or when a
row is missing from the front end checked:
  --cli PROGRAM        uv_unwrap --help lists the row's flag
  --python DIR         the module uv_unwrap in DIR: unwrap()'s signature has
                       the row's keyword, with the table's default, and its
                       documentation names the row
  --blender ZIP        (run inside Blender: blender -b --python this -- ...)
                       the add-on's operator has the row's property
Usage: check_option_coverage.py --table T.json --header NP.h --options-header O.h [--cli P] [--python D] [--blender Z]
"""
import json
import math
import re
import subprocess
import sys

# Library parameters that are not options of the unwrap front ends, each with why.
EXEMPT = {
    "face_weight_map": "symmetric_dirichlet_parameterize()'s per-face weights, not an option of cut_and_parameterize()",
    "initialize_from_uv_map": "symmetric_dirichlet_parameterize()'s start from given UVs; the front ends give no UVs",
    "stopping_tolerance": "symmetric_dirichlet_parameterize()'s stopping test, not read by cut_and_parameterize()",
    "face_lambda_map": "a property map: the front ends fill it (face_weights, --lambda-from-ply-property, hide_seams)",
    "forbidden_seam_edge_map": "a property map: the front ends fill it (forbidden, --forbid, Blender's sharp edges)",
    "face_discontinuity_map": "an output property map (uv_unwrap --v-field, --v-png)",
    "progress_callback": "a callback: each front end passes its own (progress=, stderr lines, Blender's status bar)",
    "number_of_rays": "face_visibility()'s, which the front ends run with its defaults (hide_seams)",
    "maximum_distance": "face_visibility()'s, which the front ends run with its defaults (hide_seams)",
    "instance_of": "pack_scene_atlas()'s instances (stacked parts), given by a scene front end, not a run's option",
    "uv_scale": "the metrics' (distortion_energy()), not an option of a run",
}


def arguments(argv):
    args, i = {}, 0
    while i < len(argv):
        if argv[i].startswith("--") and i + 1 < len(argv):
            args[argv[i][2:]] = argv[i + 1]
            i += 2
        else:
            i += 1
    return args


def library_parameters(header, options_header):
    """{name: where} of the named parameters and of the options struct's fields."""
    names = {}
    for m in re.finditer(r"^CGAL_SMP_CUT_NAMED_PARAMETER\(\s*\w+\s*,\s*(\w+)\s*\)", open(header).read(), re.M):
        names[m.group(1)] = "named parameter"
    text = open(options_header).read()
    body = re.search(r"struct Cut_parameterization_options\s*\{(.*?)\n\};", text, re.S)
    if not body:
        raise SystemExit("no struct Cut_parameterization_options in " + options_header)
    # the data members: "type name [= value];" at the struct's level (the member functions' bodies left out)
    members = re.sub(r"\{[^{}]*\}", "", body.group(1))
    for m in re.finditer(r"^\s+([A-Za-z_][\w:]*(?:<[^;]*?>)?)\s+(\w+)\s*(?:=[^;]*)?;", members, re.M):
        if m.group(1) not in ("return", "if"):
            names.setdefault(m.group(2), "field of Cut_parameterization_options")
    return names


failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def check_library(rows, header, options_header):
    library = library_parameters(header, options_header)
    check(len(library) >= 20, "the library has %d named parameters and fields (parsed)" % len(library))
    names = {row["name"] for row in rows}
    for name, where in sorted(library.items()):
        if name in EXEMPT:
            print("skip  %s (%s): %s" % (name, where, EXEMPT[name]))
        else:
            check(name in names, "%s (%s) is a row of the option table" % (name, where))
    for name in sorted(names):
        check(name in library, "the row %s is a named parameter of the library" % name)
    for name in EXEMPT:
        check(name in library, "the exemption %s names a parameter of the library" % name)


def check_cli(rows, program):
    shown = subprocess.run([program, "--help"], capture_output=True, text=True, check=True).stdout
    for row in rows:
        check(re.search(r"(^|\s)" + re.escape(row["cli"]) + r"\b", shown) is not None,
              "uv_unwrap --help lists %s (%s)" % (row["cli"], row["name"]))
        for choice in row["choices"]:
            check(choice in shown, "uv_unwrap --help lists %s's choice %s" % (row["cli"], choice))


def same_default(text, row):
    """The default as the signature shows it (Python's repr) is the table's."""
    default = row["default"]
    if default is None:
        return text == "None"
    if row["kind"] == "inverted_flag":
        return text == repr(not default)
    if row["kind"] == "choice":
        return text == repr(row["choices"][default])
    if row["kind"] == "flag":
        return text == repr(default)
    try:
        return math.isclose(float(text), float(default), rel_tol=1e-12)
    except ValueError:
        return False


def check_python(rows, directory):
    sys.path.insert(0, directory)
    import uv_unwrap
    doc = uv_unwrap.unwrap.__doc__
    signature = doc.split("\n", 1)[0]
    for row in rows:
        keyword = row["python"]
        m = re.search(r"[(,]\s*" + re.escape(keyword) + r"\s*:\s*\w+\s*=\s*([^,)]+)", signature)
        check(m is not None and same_default(m.group(1).strip(), row),
              "unwrap() has the keyword %s (%s) with the default %r (%s)"
              % (keyword, row["name"], row["default"], m.group(1) if m else "absent"))
        check(("\n" + keyword + ":") in doc, "unwrap()'s documentation describes %s" % keyword)


def check_blender(rows, zip_path):
    import bpy
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")
    properties = bpy.ops.uv.unwrap_optimized_seams.get_rna_type().properties
    for row in rows:
        check(row["blender"] in properties, "the Blender operator has the property %s (%s)"
              % (row["blender"], row["name"]))
        if row["kind"] == "choice" and row["blender"] in properties:
            items = [item.name for item in properties[row["blender"]].enum_items]
            check(items == row["choices"], "its choices %s are the table's %s" % (items, row["choices"]))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    args = arguments(argv)
    rows = json.load(open(args["table"]))
    check(len(rows) > 0, "the option table has %d rows" % len(rows))
    check_library(rows, args["header"], args["options-header"])
    if "cli" in args:
        check_cli(rows, args["cli"])
    if "python" in args:
        check_python(rows, args["python"])
    if "blender" in args:
        check_blender(rows, args["blender"])
    print("%d failures" % len(failures))
    sys.exit(1 if failures else 0)


main()
