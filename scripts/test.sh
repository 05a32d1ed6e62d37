#!/usr/bin/env bash
# Installs what is missing (with Debian's blender and xvfb, for the add-on's tests),
# builds everything with the tests (Release, in build/, shared with setup.sh)
# and runs them all.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_dependencies.sh --with-blender

# CGAL's CMake files default BUILD_TESTING to OFF: turn it on explicitly.
# Configuring with tests also extracts CGAL's data set into build/data.
# The test files are compiled a few at a time (CUT_PARAM_UNITY_TESTS, see
# test/README.md): measured on 2 cores, 689 s of compilation for the 19
# files one by one, 344 s by fives.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DCUT_PARAM_UNITY_TESTS=ON
cmake --build build -j "$jobs"

# The Khronos glTF-Validator, which test_gltf_round_trip runs on the glTF
# files uv_unwrap writes (with ../shared/tools/validate_gltf.js): installed
# with npm into build/gltf-validator when npm is there and can reach it;
# otherwise that test checks counts and bounds itself and says so.
if [ ! -d build/gltf-validator/node_modules/gltf-validator ] && command -v npm >/dev/null 2>&1; then
  npm install --silent --prefix build/gltf-validator gltf-validator@2.0.0-dev.3.10 >/dev/null 2>&1 ||
    echo "test.sh: npm could not install gltf-validator: glTF outputs checked without it" >&2
fi
cd build
ctest --output-on-failure -j "$jobs"
