#!/usr/bin/env bash
# Installs what is missing, builds everything with the tests (Release, in
# build/, shared with setup.sh) and runs them all.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_dependencies.sh

# CGAL's CMake files default BUILD_TESTING to OFF: turn it on explicitly.
# Configuring with tests also extracts CGAL's data set into build/data.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON
cmake --build build -j "$jobs"
cd build
ctest --output-on-failure -j "$jobs"
