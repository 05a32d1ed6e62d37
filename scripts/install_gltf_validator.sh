#!/usr/bin/env bash
# Installs the Khronos glTF-Validator (npm package gltf-validator, a fixed
# version) under PREFIX (default build/gltf-validator), where
# test_gltf_round_trip looks for it (CMake cache variable
# CUT_PARAM_GLTF_VALIDATOR_DIR); installs Debian's nodejs and npm first
# where node or npm is missing. Does nothing when the package is there.
#   scripts/install_gltf_validator.sh [PREFIX]
# Without network access, or to do without the check, configure with
# -DCUT_PARAM_GLTF_VALIDATOR=OFF: the validator test then shows as skipped.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="${1:-$root/build/gltf-validator}"
version=2.0.0-dev.3.10

if [ -d "$prefix/node_modules/gltf-validator" ]; then
  exit 0
fi
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  bash "$root/scripts/install_dependencies.sh" nodejs npm
fi
echo "install_gltf_validator: npm install gltf-validator@$version into $prefix"
npm install --silent --no-audit --no-fund --prefix "$prefix" "gltf-validator@$version"
