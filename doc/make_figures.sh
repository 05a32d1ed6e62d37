#!/usr/bin/env bash
# Regenerates the pictures of doc/fig with the project's own CLI, uv_unwrap
# (its --svg and --png outputs), on meshes of CGAL's data set.
#
#   bash doc/make_figures.sh [BUILD_DIR] [MESH_DIR]
#
# BUILD_DIR (default: build) must hold bin/uv_unwrap
#   (cmake --build BUILD_DIR --target uv_unwrap).
# MESH_DIR (default: BUILD_DIR/data/meshes, which configuring with
#   -DBUILD_TESTING=ON extracts; otherwise extracted here from libcgal-demo's
#   /usr/share/doc/libcgal-dev/data.tar.gz).
# Needs rsvg-convert (Debian: librsvg2-bin) to turn SVG into PNG and to shrink
# the 1024x768 renders below 300 KB. About a minute and a half on two cores.
# Each run prints the numbers that the captions of the manual and of
# README.md quote (E_s, E_d, coverage, border crossings).
set -euo pipefail

doc="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
uv_unwrap="$build/bin/uv_unwrap"
fig="$doc/fig"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

if [ ! -x "$uv_unwrap" ]; then
  echo "make_figures: $uv_unwrap not found; build it: cmake --build $build --target uv_unwrap" >&2
  exit 1
fi
command -v rsvg-convert >/dev/null || { echo "make_figures: rsvg-convert not found (librsvg2-bin)" >&2; exit 1; }

meshes="${2:-$build/data/meshes}"
if [ ! -d "$meshes" ]; then
  archive=/usr/share/doc/libcgal-dev/data.tar.gz
  [ -f "$archive" ] || { echo "make_figures: no mesh directory and no $archive (libcgal-demo)" >&2; exit 1; }
  tar -xzf "$archive" -C "$work" data/meshes
  meshes="$work/data/meshes"
fi

# svg_to_png IN.svg OUT.png: the UV layout at 640 pixels wide.
svg_to_png() { rsvg-convert -w 640 "$1" -o "$2"; }

# shrink_png IN.png OUT.png: a 1024x768 render at 768x576, through an SVG
# wrapper because rsvg-convert is the only image tool required.
shrink_png() {
  local wrapper="$work/wrap.svg"
  printf '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="1024" height="768" viewBox="0 0 1024 768"><image width="1024" height="768" xlink:href="%s"/></svg>\n' \
    "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" > "$wrapper"
  rsvg-convert -w 768 "$wrapper" -o "$2"
}

# unwrap NAME OUT_STEM [uv_unwrap options...]: runs uv_unwrap with pictures.
unwrap() {
  local name="$1" stem="$2"
  shift 2
  "$uv_unwrap" "$meshes/$name.off" -q -o "$work/$stem.obj" --stats "$work/$stem.json" \
    --svg "$work/$stem.svg" --png "$work/$stem.png" "$@"
  echo "$stem: $(tr -d ' \n' < "$work/$stem.json" | grep -o '"charts":[^,]*\|"seam_length":[^,]*\|"distortion":[^,]*\|"border_crossings":[^,]*\|"uv_coverage":[^,]*' | tr '\n' ' ')"
}

mkdir -p "$fig"

# Disk-like mesh, default parameters, then a small and a large seam cost.
unwrap lion-head lion_head
shrink_png "$work/lion_head.png" "$fig/lion_head_checker.png"
svg_to_png "$work/lion_head.svg" "$fig/lion_head_uv.png"
unwrap lion-head lion_head_lambda_0.25 --lambda 0.25
svg_to_png "$work/lion_head_lambda_0.25.svg" "$fig/lion_head_lambda_0.25_uv.png"
unwrap lion-head lion_head_lambda_4 --lambda 4
svg_to_png "$work/lion_head_lambda_4.svg" "$fig/lion_head_lambda_4_uv.png"

# Closed surface of genus 3: initial cut, then the optimized seams.
unwrap elephant elephant
shrink_png "$work/elephant.png" "$fig/elephant_checker.png"

# Texture atlas. Global injectivity: the same elephant without it (two parts
# of its UV border cross) and with it (the default, above).
unwrap elephant elephant_overlaps --allow-overlaps
svg_to_png "$work/elephant_overlaps.svg" "$fig/elephant_overlaps_uv.png"
svg_to_png "$work/elephant.svg" "$fig/elephant_uv.png"
# A mesh of 26 parts (bones.off, also the default input of
# examples/texture_atlas.cpp): the charts packed into the unit square.
unwrap bones bones
svg_to_png "$work/bones.svg" "$fig/bones_atlas_uv.png"
# One chart without a bounding box, and pulled tightly into a 1:1 rectangle
# (compare with lion_head_uv.png: the default, a gentle square).
unwrap lion-head lion_head_no_box --no-box
svg_to_png "$work/lion_head_no_box.svg" "$fig/lion_head_no_box_uv.png"
unwrap lion-head lion_head_box --box 1:1
svg_to_png "$work/lion_head_box.svg" "$fig/lion_head_box_uv.png"

# Seams where nobody looks (the paper's Fig. 8): the field v, measured
# visibility only, then steering the seams with it (--hide-seams 6).
unwrap lion-head lion_head_visible --report-visibility --v-png "$work/lion_head_visible_v.png"
shrink_png "$work/lion_head_visible_v.png" "$fig/lion_head_v.png"
unwrap lion-head lion_head_hidden --hide-seams=6 --v-png "$work/lion_head_hidden_v.png"
shrink_png "$work/lion_head_hidden_v.png" "$fig/lion_head_v_hidden.png"
for stem in lion_head_visible lion_head_hidden; do
  echo "$stem: $(tr -d ' \n' < "$work/$stem.json" | grep -o '"seam_visibility":[^,]*')"
done

ls -l "$fig"

# The Blender add-on's result (README, "Blender add-on"): rendered headless
# by Blender itself, where it is installed, from the add-on's zip.
zip="$build/blender/uv_unwrap_seams.zip"
if command -v blender >/dev/null 2>&1 && [ -f "$zip" ]; then
  BLENDER_USER_SCRIPTS="$work/blender/scripts" BLENDER_USER_CONFIG="$work/blender/config" \
    blender -b --factory-startup --python "$root/doc/render_blender_addon.py" -- \
    "$zip" "$meshes/lion-head.off" "$fig/blender_addon_lion_head.png" y -0.8 >/dev/null
else
  echo "make_figures: no blender or no $zip: blender_addon_lion_head.png not made" >&2
fi
