"""The operator's method options, built from the option table of the
front ends (tools/options/option_table.h), which the build writes into this
add-on as option_table.json: one property per row (named by its `blender`
column), its translation to unwrap()'s keywords (`python` column) and, for
the uv_unwrap program, to its flags (`cli` column). A row whose default is
null (the library's rule decides, or no bound) gets a `use_` toggle; the
box's aspect ratio gets the `box` choice (gentle square, tight box, none)."""
import json
import os
import struct

from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty


def _load():
    path = os.path.join(os.path.dirname(__file__), "option_table.json")
    with open(path) as f:
        return json.load(f)


ROWS = _load()
BY_KEYWORD = {row["python"]: row for row in ROWS}

# starting values of the distortion bound, the hard edge angle, the stacking tolerance and the fill below which charts
# are cut for packing, off by default (the others start at what the library uses when they are not given:
# "unset_value")
_SUGGESTED = {"max_distortion": 4.2, "hard_edge_angle": 30., "stacking_tolerance": 1e-4,
              "split_charts_for_packing": 0.5}
_INT_MAX = 2 ** 31 - 1


def _identifier(choice):
    return choice.upper().replace("-", "_")


def _float32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def _toggle(row):
    """The property that says whether the row is given: None if always given."""
    if row["kind"] == "ratio":
        return row["python"]
    return "use_" + row["blender"] if row["default"] is None else None


def properties():
    """{name: property} for every row (with the toggles of the rows without default)."""
    props = {}
    for row in ROWS:
        name, kind, label = row["blender"], row["kind"], row["blender"].replace("_", " ").capitalize()
        help_text = row["help"]
        if kind in ("real", "ratio"):
            default = row["default"] if row["default"] is not None else _SUGGESTED.get(name, row["unset_value"])
            low = row["min"] if not row["min_open"] else min(default, 1e-3) * 1e-3
            high = row["max"] if row["max"] is not None else 1e9
            props[name] = FloatProperty(name=label, description=help_text, default=default, min=low, max=high,
                                        precision=3 if default >= 1e-3 or default == 0 else 6)
        elif kind == "count":
            default = row["default"] if row["default"] is not None else int(row["min"])
            props[name] = IntProperty(name=label, description=help_text, default=default, min=int(row["min"]),
                                      max=int(min(row["max"] or _INT_MAX, _INT_MAX)))
        elif kind in ("flag", "inverted_flag"):
            shown = row["default"] if kind == "flag" else not row["default"]
            props[name] = BoolProperty(name=label, description=help_text, default=shown)
        elif kind == "choice":
            items = [(_identifier(c), c, help_text) for c in row["choices"]]
            props[name] = EnumProperty(name=label, description=help_text, items=items,
                                       default=_identifier(row["choices"][row["default"]]))
        if kind == "ratio":
            props[row["python"]] = EnumProperty(
                name="Box", default='GENTLE',
                items=[('GENTLE', "Gentle square", "Round charts off toward a square, within a small "
                                                   "distortion budget"),
                       ('TIGHT', "Tight box", "Pull each chart into a box of the given aspect ratio"),
                       ('NONE', "None", "No box: the least distortion")])
        elif _toggle(row):
            props[_toggle(row)] = BoolProperty(name="Set " + label.lower(), default=False,
                                               description="Give this option (else the library decides)")
    return props


def add_properties(cls):
    """Adds properties() to the operator class (before it is registered)."""
    annotations = cls.__dict__.get("__annotations__")
    if annotations is None:
        annotations = {}
        cls.__annotations__ = annotations
    annotations.update(properties())


def keywords(operator):
    """unwrap()'s keywords of the options set on `operator`; a value equal to the
    library's default (as Blender stores it, in single precision) is left out, so
    that the library's own double is used."""
    options = {}
    for row in ROWS:
        name, kind, value = row["blender"], row["kind"], getattr(operator, row["blender"])
        if kind == "ratio":
            box = getattr(operator, row["python"])
            if box == 'TIGHT':
                options[row["python"]] = value
            elif box == 'NONE':
                options[row["python"]] = False
            continue
        toggle = _toggle(row)
        if toggle and not getattr(operator, toggle):
            continue
        if kind == "choice":
            value = next(c for c in row["choices"] if _identifier(c) == value)
            if value == row["choices"][row["default"]]:
                continue
        elif kind == "flag":
            if value == row["default"]:
                continue
        elif kind == "inverted_flag":
            if value == (not row["default"]):
                continue
        elif toggle is None and value == _float32(row["default"]):
            continue
        options[row["python"]] = value
    return options


def cli_arguments(options):
    """The uv_unwrap flags of unwrap()'s keywords in `options` (the table's rows)."""
    args = []
    for keyword, value in options.items():
        row = BY_KEYWORD.get(keyword)
        if row is None:
            raise TypeError("unwrap() got an unexpected keyword argument '%s'" % keyword)
        if value is None:
            continue
        kind, flag = row["kind"], row["cli"]
        if kind in ("flag", "inverted_flag"):
            if value:
                args.append(flag)
        elif kind == "choice":
            args += [flag, str(value)]
        elif kind == "ratio":
            if value is False:
                args.append("--no-box")
            elif value is True:
                args += [flag, "1:1"]
            else:
                w, h = value if isinstance(value, (tuple, list)) else (value, 1.0)
                args += [flag, "%r:%r" % (float(w), float(h))]
        elif kind == "count":
            args += [flag, str(int(value))]
        else:
            args += [flag, repr(float(value))]
    return args


def advanced_rows():
    """The rows drawn in the panel's Advanced section (the others have their own place)."""
    main = {"seam_cost", "max_distortion", "margin", "texture_size", "box_aspect", "preset", "texels_per_unit",
            "stacking_tolerance"}
    return [row for row in ROWS if row["blender"] not in main]


def draw_row(layout, operator, row):
    toggle = _toggle(row)
    if toggle and row["kind"] != "ratio":
        line = layout.row(heading=row["blender"].replace("_", " ").capitalize())
        line.prop(operator, toggle, text="")
        sub = line.row()
        sub.active = getattr(operator, toggle)
        sub.prop(operator, row["blender"], text="")
    else:
        layout.prop(operator, row["blender"])

