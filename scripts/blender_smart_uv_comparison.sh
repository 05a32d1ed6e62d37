#!/usr/bin/env bash
# Seams of uv_unwrap (defaults) against Blender's Smart UV Project (its defaults) on the
# benchmark's hard-surface corpus, both measured by the same independent script
# (uv_metrics.py: E_d, E_s, flips, crossings): one table row per mesh.
#
#   scripts/blender_smart_uv_comparison.sh [BUILD_DIR] [OUT_DIR] [MAX_FACES]
#
# BUILD_DIR: a build with bin/uv_unwrap and bin/benchmark_cut_parameterization (default build);
# OUT_DIR: where the meshes and both tools' OBJ files go (default BUILD_DIR/smart_uv_comparison);
# MAX_FACES: leave out bigger meshes (default 20000). Needs blender (Debian's, run headless) and
# python3 with numpy; UV_METRICS names uv_metrics.py (default ../shared/tools/uv_metrics.py
# relative to the project root). CGAL's meshes come in where CGAL_DATA_DIR or BUILD_DIR/data has them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$build/smart_uv_comparison}
max_faces=${3:-20000}
metrics=${UV_METRICS:-$root/../shared/tools/uv_metrics.py}
python=${PYTHON:-/usr/bin/python3}
mkdir -p "$out/meshes" "$out/ours" "$out/smart_uv"
"$build/bin/benchmark_cut_parameterization" --hard-surface --max-faces "$max_faces" --write-meshes "$out/meshes" >/dev/null

field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p"; }
printf '%-22s %7s | %8s %8s %6s %6s %8s | %8s %8s %6s %6s %8s\n' mesh faces \
  "E_d" "E_s" flips cross "time s" "E_d" "E_s" flips cross "time s"
printf '%-22s %7s | %-42s | %-42s\n' "" "" "uv_unwrap (defaults)" "Smart UV Project (defaults)"
for mesh in "$out"/meshes/*.obj; do
  name=$(basename "$mesh" .obj)
  start=$(date +%s.%N)
  "$build/bin/uv_unwrap" --quiet "$mesh" -o "$out/ours/$name.obj" >/dev/null 2>&1 || true
  ours_time=$(echo "$(date +%s.%N) - $start" | bc)
  smart_time=$(blender -b --factory-startup --python "$root/benchmark/python_blender/smart_uv_project.py" -- \
                 "$mesh" "$out/smart_uv/$name.obj" 2>/dev/null | sed -n 's/^SMART_UV_SECONDS //p')
  ours=$("$python" "$metrics" "$out/ours/$name.obj" 2>/dev/null || echo "")
  smart=$("$python" "$metrics" "$out/smart_uv/$name.obj" 2>/dev/null || echo "")
  printf '%-22s %7s | %8s %8s %6s %6s %8.3f | %8s %8s %6s %6s %8.3f\n' "$name" "$(echo "$ours" | field faces)" \
    "$(echo "$ours" | field E_d)" "$(echo "$ours" | field E_s)" "$(echo "$ours" | field flips)" \
    "$(echo "$ours" | field crossings)" "$ours_time" \
    "$(echo "$smart" | field E_d)" "$(echo "$smart" | field E_s)" "$(echo "$smart" | field flips)" \
    "$(echo "$smart" | field crossings)" "${smart_time:-0}"
done
