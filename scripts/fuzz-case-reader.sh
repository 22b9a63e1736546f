#!/usr/bin/env bash
# Fuzzes the case reader (docs/fuzzing.md): builds tests/fuzz/fuzz_case_reader with clang and
# -fsanitize=fuzzer,address,undefined in build-fuzz/ (LIMBER_FUZZ=ON; the normal build/ is not
# touched), then runs it for SECONDS (default 60) from the seed corpus tests/fuzz/corpus/.
# New inputs go to out/fuzz/corpus/ (the seed corpus stays as committed); crashes, aborts,
# sanitizer reports, leaks, timeouts and out-of-memory inputs go to out/fuzz/crashes/.
# Exit status: 0 when nothing was found, libFuzzer's (non-zero) when something was.
# Usage: scripts/fuzz-case-reader.sh [SECONDS]
#   LIMBER_FUZZ_BUILD_DIR  build folder (default build-fuzz)
#   LIMBER_FUZZ_OUT        output folder (default out/fuzz)
#   LIMBER_FUZZ_JOBS       parallel fuzzing processes (default 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build_dir=${LIMBER_FUZZ_BUILD_DIR:-$root/build-fuzz}
out=${LIMBER_FUZZ_OUT:-$root/out/fuzz}
jobs=${LIMBER_FUZZ_JOBS:-1}

"$root/scripts/install-fuzz-deps.sh"
# The build is RelWithDebInfo (-g): ccache then hashes the build folder unless told not to, and a
# second checkout's clang build (148 sanitized objects, slow cold: docs/fuzzing.md) never hits
# the first's entries. Without the folder in the hash, checkouts under ccache's base_dir share them.
export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-true}
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DLIMBER_FUZZ=ON -DLIMBER_BUILD_TESTS=OFF -DLIMBER_BUILD_BENCHMARKS=OFF
fi
cmake --build "$build_dir" -j "$(nproc)" --target fuzz_case_reader

mkdir -p "$out/corpus" "$out/crashes"
parallel=()
# Several processes share the corpus folder; their logs go to fuzz-<n>.log in the current folder.
[ "$jobs" -le 1 ] || parallel=(-jobs="$jobs" -workers="$jobs")
# -max_len: a case file of the corpus fits in 16 KiB; -timeout: one input that takes longer
# than 10 s is a hang (the fuzz target bounds the FE models it reduces: case_input_path.h);
# -rss_limit_mb: memory beyond 2 GiB is a finding too. Leaks are checked at exit only.
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
"$build_dir/tests/fuzz/fuzz_case_reader" \
  -max_total_time="$seconds" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
  "${parallel[@]}" -print_final_stats=1 -dict="$root/tests/fuzz/case.dict" \
  -artifact_prefix="$out/crashes/" \
  "$out/corpus" "$root/tests/fuzz/corpus"
