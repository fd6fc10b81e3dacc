#!/usr/bin/env bash
# Parse time of the largest POV-Ray example scenes: snell --parse-only against POV-Ray 3.7's own "Parse
# Time" statistic (rendered at 8x8 so that render time stays out), median of 3 runs each, as a ratio.
# Both are CPU seconds: POV-Ray's parse wall time includes seconds in which its parser thread waits
# (0.25 CPU-s of parsing shows as 3-12 s on a busy machine), so wall times are printed but not compared.
# snell's CPU time is that of the whole --parse-only process (start-up and scene building included).
# Usage: tools/parse-time.sh [--bin build/snell] [--runs 3] [scene.pov...]
set -euo pipefail
bin=build/snell runs=3 include=/usr/share/povray-3.7/include examples=/usr/share/doc/povray/examples
# The 5 example scenes POV-Ray spends the most parse CPU time on (measured over all 396; see
# docs/parse-speed.md), then the two heaviest that snell parsed when this list was made.
scenes=(advanced/wallstucco.pov bsp/Tango.pov incdemo/shapes.pov advanced/benchmark/benchmark.pov
  advanced/abyss.pov incdemo/math.pov advanced/sombrero.pov)
while (($#)); do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    -*) echo "usage: $0 [--bin PATH] [--runs N] [scene.pov...]" >&2; exit 2 ;;
    *) scenes=("$@"); break ;;
  esac
done
[[ -x $bin ]] || { echo "parse-time: no snell binary at $bin" >&2; exit 2; }
command -v povray >/dev/null || { echo "parse-time: POV-Ray (povray) is not installed" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$examples" "$work/examples"
find "$work/examples" -name '*.gz' -exec gunzip -q {} + 2>/dev/null || true

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

printf '%-34s %12s %12s %8s   %s\n' scene "snell cpu-s" "povray cpu-s" ratio "(wall: snell / povray)"
for scene in "${scenes[@]}"; do
  path=$scene
  [[ -f $path ]] || path=$work/examples/$scene
  [[ -f $path ]] || { echo "parse-time: no scene $scene" >&2; exit 2; }
  dir=$(cd "$(dirname "$path")" && pwd) file=$(basename "$path")
  : >"$work/snell" && : >"$work/snell_wall" && : >"$work/pov" && : >"$work/pov_wall"
  if ! (cd "$dir" && "$bin" --parse-only "+I$file" "+L$include" +W8 +H8 --quiet >/dev/null 2>&1); then
    printf '%-34s %12s\n' "$scene" "(snell cannot parse it yet)"
    continue
  fi
  for ((i = 0; i < runs; i++)); do
    out=$(cd "$dir" && /usr/bin/time -f 'cpu %U %S' "$bin" --parse-only "+I$file" "+L$include" +W8 +H8 2>&1)
    awk '/^cpu /{print $2 + $3}' <<<"$out" >>"$work/snell"
    grep -o 'parse [0-9.]*s' <<<"$out" | tr -d 'parse s' >>"$work/snell_wall"
    out=$(cd "$dir" && povray "+I$file" -F +W8 +H8 -D +WT1 "+L$include" 2>&1 </dev/null)
    stats=$(grep -A1 'Parse Time' <<<"$out" | tr -s ' \n' ' ')
    sed -E 's/.* with ([0-9.]+) CPU-seconds.*/\1/' <<<"$stats" >>"$work/pov"
    sed -E 's/.*\(([0-9.]+) seconds\).*/\1/' <<<"$stats" >>"$work/pov_wall"
  done
  s=$(median <"$work/snell") p=$(median <"$work/pov")
  printf '%-34s %12.3f %12.3f %8s   (%s / %s)\n' "$scene" "$s" "$p" \
    "$(awk -v s="$s" -v p="$p" 'BEGIN { if (p > 0) printf "%.2f", s / p; else print "-" }')" \
    "$(median <"$work/snell_wall")" "$(median <"$work/pov_wall")"
done
echo "ratio = snell / POV-Ray CPU seconds (median of $runs); below 1 means snell parses faster"
