"""Where the unwrapping runs: the Python module uv_unwrap, as installed for
Blender's Python (scripts/setup.sh puts it on Debian's python3 path, which
Debian's Blender shares) or as shipped inside this add-on's zip (built for
the same Python version)."""
import importlib
import os
import sys

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
    _problem = ("the Python module uv_unwrap cannot be loaded by Blender's Python %d.%d (%s); build it for "
                "this Python (scripts/setup.sh) or use the add-on zip built with it"
                % (sys.version_info[0], sys.version_info[1], "; ".join(errors)))
    return None


def problem():
    return _problem
