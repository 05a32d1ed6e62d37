#!/usr/bin/env bash
# From a fresh clone to a first result: installs what is missing, builds
# uv_unwrap (Release) in build/, and unwraps the default mesh into build/output/.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_dependencies.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target uv_unwrap -j "$jobs"

# The Python module uv_unwrap and the Blender add-on's zip (python/, blender/;
# CMake leaves them out, with a message, when pybind11 is missing), and a
# .pth file that puts build/python on the path of the python3 they are built
# for (Debian's /usr/bin/python3, whose site folder Debian's Blender shares).
targets="$(cmake --build build --target help)" # (grep -q on a pipe would end it early: pipefail)
if grep -q blender_addon <<<"$targets"; then
  cmake --build build --target uv_unwrap_python blender_addon -j "$jobs"
  python="$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)"
  site="$("$python" -c 'import site; print(site.getsitepackages()[0])')"
  pth="$site/cut_parameterization_uv_unwrap.pth"
  if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo); else sudo=(false); fi
  if "${sudo[@]}" mkdir -p "$site" && echo "$root/build/python" | "${sudo[@]}" tee "$pth" >/dev/null; then
    echo "setup: $python imports uv_unwrap from $root/build/python ($pth)"
  else
    echo "setup: could not write $pth: use PYTHONPATH=$root/build/python" >&2
  fi
  echo "setup: Blender add-on: $root/build/blender/uv_unwrap_seams.zip"
fi

# uv_unwrap's default mesh (mushroom.off, z up) comes from CGAL's data set
# (libcgal-demo), which it looks for in build/data when CGAL_DATA_DIR is not
# set. Configuring with tests extracts it; without them, do it here.
archive=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -d build/data/meshes ] && [ -f "$archive" ]; then
  echo "setup: extracting CGAL's data set into build/data"
  tar -xzf "$archive" -C build
fi

out=build/output
mkdir -p "$out"
cd "$out"
"$root/build/bin/uv_unwrap" -o default_uv.obj --stats default_stats.json \
  --svg default_uv_layout.svg --png default_checker.png --up z --v-field default_v_field.ply
echo
echo "setup: results in $root/$out:"
ls -1 | sed 's/^/  /'
