"""Automatic UV unwrapping: seams and UV map optimized together (Ambrosio-Tortorelli method).

    import uv_unwrap
    r = uv_unwrap.unwrap(V, F)        # V (n,3) floats, F (m,3) vertex indices
    r.uv, r.faces_uv                  # (k,2) UVs and (m,3) indices into them, per corner
    r.seams, r.face_charts, r.stats   # seams as vertex pairs, chart per face, uv_unwrap's --stats
    rs = uv_unwrap.unwrap_scene([(V1, F1), (V2, F2)])  # one atlas for all: rs[i].uv, rs[i].page

unwrap() is the compiled part (uv_unwrap._uv_unwrap); uv_unwrap.batch unwraps
a library of mesh files on a Dask cluster (python3 -m uv_unwrap.batch --help).
"""
from ._uv_unwrap import Cancelled, Result, UnwrapError, unwrap, unwrap_scene

__all__ = ["unwrap", "unwrap_scene", "Result", "UnwrapError", "Cancelled"]
