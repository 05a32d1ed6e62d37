#!/usr/bin/env bash
# Full run of tools/check_all_meshes: uv_unwrap on every mesh of CGAL's data
# set and of ../shared/meshes (when present), without the face limit of the
# CTest test, each mesh with a time limit. Builds uv_unwrap and the checker
# (Release) in build-rel/ (BUILD_DIR) first. Prints the table and the
# summary; exits non-zero on any crash, hang, NaN, flipped face or broken
# contract.
#
#   scripts/check_all_meshes.sh [check_all_meshes options...]
#   (e.g. --max-faces 30000, --timeout 600, --repeat-faces 0)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"
build="${BUILD_DIR:-build-rel}"

bash scripts/install_dependencies.sh
# BUILD_TESTING=ON extracts CGAL's data set into $build/data.
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 1; }
cmake --build "$build" --target uv_unwrap check_all_meshes -j "$jobs"

dirs=()
[ -d "$build/data/meshes" ] && dirs+=("$build/data/meshes")
[ -d "$root/../shared/meshes" ] && dirs+=("$(cd "$root/../shared/meshes" && pwd)")
if [ ${#dirs[@]} -eq 0 ]; then
  echo "check_all_meshes: no mesh directory found (install libcgal-demo for CGAL's data set)" >&2
  exit 1
fi

exec "$build/bin/check_all_meshes" --uv-unwrap "$build/bin/uv_unwrap" --timeout 1200 --repeat-faces 20000 \
  --work-dir "$build/check_all_meshes_full" "$@" "${dirs[@]}"
