#!/usr/bin/env bash
# The Python module and the Blender add-on on the benchmark meshes (read from
# ../shared/meshes, never copied): unwrap() against uv_unwrap on the 19 meshes,
# Smart UV Project against the add-on in Blender on the 15 disk meshes, the
# outputs measured by ../shared/tools/uv_metrics.py; prints the tables of
# doc/python_and_blender.md. Needs the build (uv_unwrap, the module, the
# add-on's zip: scripts/setup.sh), Debian's python3 with numpy, and blender.
#   benchmark/python_blender/run.sh [BUILD_DIR] [OUT_DIR]
# uv_unwrap loads OpenBLAS's AVX2 / AVX-512 kernels where Debian's OpenBLAS
# does not know the processor (tools/blas_setup.h); Python cannot once numpy
# has loaded OpenBLAS. To compare the same kernels (the same last bits from
# 8,000 faces, where CHOLMOD's supernodal factorization runs), run this with
# OPENBLAS_CORETYPE=SkylakeX (AVX-512) or Haswell (AVX2) on such processors.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
out="${2:-$build/python_blender_benchmark}"
shared="$root/../shared"
python="$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")"
here="$root/benchmark/python_blender"
mkdir -p "$out"
PYTHONPATH="$build/python" "$python" "$here/module_vs_cli.py" "$build/bin/uv_unwrap" "$shared/meshes" "$out/module.csv"
blender -b --factory-startup --python-exit-code 1 --python "$here/blender_side_by_side.py" -- \
  "$build/blender/uv_unwrap_seams.zip" "$shared/meshes" "$out" | grep '^ROW ' || true
"$python" "$shared/tools/uv_metrics.py" "$out"/*_smart_uv.obj "$out"/*_addon.obj > "$out/uv_metrics.txt"
"$python" "$here/tables.py" "$out"
