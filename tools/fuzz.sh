#!/usr/bin/env bash
# Builds the libFuzzer target for the scene language (clang, ASan+UBSan over the whole core) and runs it.
# Usage: tools/fuzz.sh [SECONDS=600] [--jobs N] [--build DIR]
# New inputs go to build-fuzz/corpus (fuzz/corpus holds the seeds and stays untouched); crashes, leaks,
# timeouts and out-of-memory inputs are written to build-fuzz/artifacts/. Add each reproducer to
# fuzz/corpus/regressions/ once fixed: tests/fuzz replays that folder in every build.
set -euo pipefail
seconds=600 jobs=1 build=build-fuzz
while (($#)); do
  case $1 in
    --jobs) jobs=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    [0-9]*) seconds=$1; shift ;;
    *) echo "usage: $0 [SECONDS] [--jobs N] [--build DIR]" >&2; exit 2 ;;
  esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=/usr/bin/clang++ \
  -DSNELL_FUZZ=ON -DSNELL_BUILD_TESTS=OFF -DSNELL_WERROR=ON >/dev/null
cmake --build "$build" -j2 --target snell_parse_fuzzer
mkdir -p "$build/corpus" "$build/artifacts"
# -timeout and -rss_limit_mb are backstops: the parser's limits (fuzz_parse_options) should stop any input
# well inside them. Leak detection is on (ASan's default).
parallel=()
((jobs > 1)) && parallel=(-jobs="$jobs" -workers="$jobs")  # each job logs to fuzz-N.log
exec "$build/fuzz/snell_parse_fuzzer" "$build/corpus" fuzz/corpus -dict=fuzz/sdl.dict \
  -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 -max_len=8192 "${parallel[@]}" \
  -artifact_prefix="$build/artifacts/" -print_final_stats=1
