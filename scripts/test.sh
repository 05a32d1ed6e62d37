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
# files uv_unwrap writes (tools/tests/validate_gltf.js): installed with npm
# into build/gltf-validator (Debian's nodejs and npm first, where missing).
# Without it that test fails; -DCUT_PARAM_GLTF_VALIDATOR=OFF turns it off.
bash scripts/install_gltf_validator.sh build/gltf-validator
cd build
ctest --output-on-failure -j "$jobs"
