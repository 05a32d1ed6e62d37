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
