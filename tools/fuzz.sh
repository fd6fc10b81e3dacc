#!/usr/bin/env bash
# Builds one libFuzzer target (clang, ASan+UBSan) and runs it.
# Usage: tools/fuzz.sh [TARGET=parse] [SECONDS=600] [--jobs N] [--build DIR]
# TARGET: parse (the scene language), png (height field and image map PNG readers), image (TGA, PPM, GIF
# and JPEG through the OpenImageIO plugin), resume (resume files), df3 (density files), mesh (model files
# through io::import_mesh: Assimp and the binary PLY reader). See docs/fuzzing.md.
# New inputs go to build-fuzz/corpus[-TARGET] (fuzz/corpus holds the seeds and stays untouched); crashes,
# leaks, timeouts and out-of-memory inputs are written to build-fuzz/artifacts[-TARGET]/. Add each
# reproducer to the target's regressions/ folder once fixed: tests/fuzz replays it in every build.
set -euo pipefail
target=parse seconds=600 jobs=1 build=build-fuzz
while (($#)); do
  case $1 in
    parse | png | image | resume | df3 | mesh) target=$1; shift ;;
    --jobs) jobs=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    [0-9]*) seconds=$1; shift ;;
    *) echo "usage: $0 [parse|png|image|resume|df3|mesh] [SECONDS] [--jobs N] [--build DIR]" >&2; exit 2 ;;
  esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=/usr/bin/clang++ \
  -DSNELL_FUZZ=ON -DSNELL_BUILD_TESTS=OFF -DSNELL_WERROR=ON >/dev/null
cmake --build "$build" -j2 --target "snell_${target}_fuzzer"
if [[ $target == parse ]]; then
  corpus=$build/corpus artifacts=$build/artifacts seeds=fuzz/corpus options=(-dict=fuzz/sdl.dict -max_len=8192)
else
  corpus=$build/corpus-$target artifacts=$build/artifacts-$target seeds=fuzz/corpus/$target options=(-max_len=65536)
  # Leaks inside Debian's OpenImageIO are suppressed (fuzz/lsan.supp); matching them needs full stacks.
  export LSAN_OPTIONS=suppressions=$root/fuzz/lsan.supp ASAN_OPTIONS=fast_unwind_on_malloc=0
fi
mkdir -p "$corpus" "$artifacts"
# -timeout and -rss_limit_mb are backstops: the parser's limits (fuzz_parse_options) should stop any input
# well inside them. Leak detection is on (ASan's default).
parallel=()
((jobs > 1)) && parallel=(-jobs="$jobs" -workers="$jobs")  # each job logs to fuzz-N.log
exec "$build/fuzz/snell_${target}_fuzzer" "$corpus" "$seeds" "${options[@]}" \
  -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 "${parallel[@]}" \
  -artifact_prefix="$artifacts/" -print_final_stats=1
