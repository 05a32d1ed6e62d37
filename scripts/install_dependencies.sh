#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those missing.
# Used by setup.sh and test.sh; safe to run again (does nothing then).
# Arguments, if any: the packages to install instead of the project's (as
# scripts/install_gltf_validator.sh does for nodejs and npm).
# libcli11-dev, nlohmann-json3-dev, libtinygltf-dev, libgtest-dev: command lines,
# JSON, glTF, tests.
# libopenblas0-pthread: the BLAS behind CHOLMOD on large meshes (Debian's
# reference BLAS would make its supernodal factorization several times slower).
# python3-dev, python3-pybind11, python3-numpy, python3-pytest: the Python
# module uv_unwrap (python/) and its tests; python3-distributed (Dask) and
# python3-tqdm (its progress bar): the batch, python3 -m uv_unwrap.batch.
# --with-blender (scripts/test.sh): also Debian's blender, for the add-on's
# test (blender/; measured: 165 packages, 167 MB downloaded, 632 MB on disk),
# and xvfb, a virtual X server for the test of its modal path (4 packages, 6 MB).
set -euo pipefail

packages=(cmake make g++ libcgal-dev libeigen3-dev libboost-dev libsuitesparse-dev libmetis-dev libtbb-dev
          libopenblas0-pthread libcgal-demo libstb-dev doxygen libcli11-dev nlohmann-json3-dev libgtest-dev
          libtinygltf-dev python3-dev python3-pybind11 python3-numpy python3-pytest python3-distributed
          python3-tqdm)
if [ "${1:-}" = "--with-blender" ]; then
  packages+=(blender xvfb xauth)
elif [ $# -gt 0 ]; then
  packages=("$@")
fi

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "install_dependencies: not a Debian-like system; install these yourself: ${packages[*]}" >&2
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install_dependencies: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi

echo "install_dependencies: installing ${missing[*]}"
"${sudo[@]}" apt-get update
# No recommends: libcgal-demo would pull the whole Qt5 stack.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
