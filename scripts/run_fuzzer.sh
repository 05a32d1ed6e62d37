#!/usr/bin/env bash
# Fuzzes the tools' input path (fuzz/fuzz_input.cpp) for a bounded time.
#
#   scripts/run_fuzzer.sh [SECONDS] [extra libFuzzer options...]
#
# SECONDS defaults to 60. Builds the libFuzzer target with clang in
# build-fuzz/ (FUZZ_BUILD_DIR), then runs it on a working corpus kept in
# build-fuzz/fuzz-corpus, seeded from fuzz/corpus and fuzz/regressions.
# Crashing, timing-out and out-of-memory inputs are saved in fuzz/crashes/
# (git-ignored); once fixed, copy them to fuzz/regressions/, which the CTest
# test fuzz_regressions replays. Prints libFuzzer's final statistics; exits
# non-zero if an input crashed.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
seconds="${1:-60}"
shift || true
build="${FUZZ_BUILD_DIR:-build-fuzz}"
cxx="${FUZZ_CXX:-clang++}"
jobs="${JOBS:-2}"

if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "run_fuzzer: $cxx not found (libFuzzer needs clang; set FUZZ_CXX)" >&2
  exit 1
fi

mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
  -DBUILD_TESTING=OFF -DCUT_PARAM_BUILD_FUZZER=ON \
  -DCUT_PARAM_BUILD_EXAMPLES=OFF -DCUT_PARAM_BUILD_BENCHMARK=OFF > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 1; }
cmake --build "$build" --target fuzz_input -j "$jobs"

corpus="$build/fuzz-corpus"
mkdir -p "$corpus" fuzz/crashes
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

echo "run_fuzzer: ${seconds}s, corpus $corpus (+ fuzz/corpus, fuzz/regressions), crashes in fuzz/crashes/"
# -max_len: a few hundred faces in ASCII; -timeout: seconds per input
# (slow unit = hang); -rss_limit_mb: also caps single allocations.
"$build/bin/fuzz_input" \
  -max_total_time="$seconds" -max_len=8192 -timeout=20 -rss_limit_mb=2048 \
  -artifact_prefix=fuzz/crashes/ -print_final_stats=1 \
  "$@" "$corpus" fuzz/corpus fuzz/regressions
