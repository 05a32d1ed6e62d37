"""Where the unwrapping runs: the Python module uv_unwrap, as installed for
Blender's Python (scripts/setup.sh puts it on Debian's python3 path, which
Debian's Blender shares) or as shipped inside this add-on's zip (built for
one Python version); where neither loads (a Blender whose Python differs),
the uv_unwrap program (uv_unwrap_cli.py), found in the add-on's preferences,
the UV_UNWRAP environment variable or the PATH.
UV_UNWRAP_SEAMS_BACKEND=uv_unwrap forces the program (the test uses it)."""
import importlib
import os
import shutil
import sys

from . import uv_unwrap_cli

_module = None
_problem = None


def module():
    """The uv_unwrap module, or None (see problem())."""
    global _module, _problem
    if _module is not None or _problem is not None:
        return _module
    errors = []
    try:
        _module = importlib.import_module("uv_unwrap")
        return _module
    except ImportError as e:
        errors.append(str(e))
    bundled = os.path.join(os.path.dirname(__file__), "lib")
    if os.path.isdir(bundled) and bundled not in sys.path:
        sys.path.insert(0, bundled)
        try:
            _module = importlib.import_module("uv_unwrap")
            return _module
        except ImportError as e:
            errors.append(str(e))
    _problem = ("the Python module uv_unwrap cannot be loaded by Blender's Python %d.%d (%s)"
                % (sys.version_info[0], sys.version_info[1], "; ".join(errors)))
    return None


def problem():
    return _problem


def program(preferred=""):
    """The uv_unwrap program: `preferred` (the add-on's preference), UV_UNWRAP, or on the PATH."""
    for candidate in (preferred, os.environ.get("UV_UNWRAP", ""), shutil.which("uv_unwrap") or ""):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


def unwrap_function(preferred_program=""):
    """(unwrap, description): a function with the module's unwrap() signature. Call on the main thread."""
    forced = os.environ.get("UV_UNWRAP_SEAMS_BACKEND", "") == "uv_unwrap"
    m = None if forced else module()
    if m is not None:
        return m.unwrap, "module uv_unwrap"
    path = program(preferred_program)
    if path is None:
        raise RuntimeError((problem() or "uv_unwrap forced") + "; and no uv_unwrap program was found (give its "
                           "path in the add-on's preferences, or build the module for this Python)")
    return (lambda V, F, **options: uv_unwrap_cli.unwrap(path, V, F, **options)), "program " + path


def unwrap_scene_function():
    """The module's unwrap_scene() (one atlas for several meshes); RuntimeError where the module does not
    load: the uv_unwrap program's fallback unwraps one mesh at a time. Call on the main thread."""
    forced = os.environ.get("UV_UNWRAP_SEAMS_BACKEND", "") == "uv_unwrap"
    m = None if forced else module()
    if m is None or not hasattr(m, "unwrap_scene"):
        raise RuntimeError("one atlas for all selected objects needs the Python module uv_unwrap (%s)"
                           % (problem() or "the program backend is forced"))
    return m.unwrap_scene
