#!/usr/bin/env bash
# Isosurface and blob speed against POV-Ray 3.7, same flags, same run: renders POV-Ray's example scenes
# objects/isosurfaces.pov and objects/blob.pov (320x240) and snell's scenes/noisy_isosurfaces.pov
# (640x480, several noise-displaced isosurfaces) with snell and with povray, alternating, --runs times
# each, and prints the median wall times and CPU times (user + system, which a loaded machine distorts
# less), their ratios (povray / snell: above 1 means snell is faster) and the SSIM of snell's image
# against POV-Ray's. With --out FILE it also writes that table as markdown.
# Usage (from the project root):
#   tools/bench-shapes.sh [--bin build/snell] [--runs N] [--scale F] [--out docs/benchmark-shapes.md]
# --scale multiplies every image size (0.5 for a quick look).
set -eu
bin=build/snell runs=3 scale=1 out=
while (($#)); do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --scale) scale=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "bench-shapes: unknown argument $1" >&2; exit 2 ;;
  esac
done
examples=/usr/share/doc/povray/examples include=/usr/share/povray-3.7/include
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# scene file, width, height
scenes=("$examples/objects/isosurfaces.pov 320 240" "$examples/objects/blob.pov 320 240"
  "$root/scenes/noisy_isosurfaces.pov 640 480")

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# "wall cpu" seconds of one run; the CPU time is the child's user + system time from wait4.
seconds() {
  /usr/bin/python3 -c 'import os, subprocess, sys, time
start = time.monotonic()
child = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, _, usage = os.wait4(child.pid, 0)
print(time.monotonic() - start, usage.ru_utime + usage.ru_stime)' "$@"
}

rows=()
printf '%-18s %9s %8s %8s %7s %8s %8s %7s %7s\n' scene size snell_s povray_s ratio snell_cpu pov_cpu ratio ssim
for entry in "${scenes[@]}"; do
  read -r scene w h <<<"$entry"
  w=$(printf '%.0f' "$(echo "$w * $scale" | bc -l)") h=$(printf '%.0f' "$(echo "$h * $scale" | bc -l)")
  name=$(basename "$scene" .pov)
  zcat -f "$scene" >"$work/$name.pov"
  flags=(+W"$w" +H"$h" +A0.3 -D +WT2 +L"$include" +L"$(dirname "$scene")")
  snell_wall=() snell_cpu=() pov_wall=() pov_cpu=()
  for ((i = 0; i < runs; i++)); do
    read -r wall cpu < <(seconds "$bin" +I"$work/$name.pov" +O"$work/$name-snell.png" "${flags[@]}")
    snell_wall+=("$wall") snell_cpu+=("$cpu")
    read -r wall cpu < <(seconds povray +I"$work/$name.pov" +O"$work/$name-pov.png" "${flags[@]}")
    pov_wall+=("$wall") pov_cpu+=("$cpu")
  done
  s=$(median "${snell_wall[@]}") p=$(median "${pov_wall[@]}")
  sc=$(median "${snell_cpu[@]}") pc=$(median "${pov_cpu[@]}")
  ssim=$(/usr/bin/python3 "$root/../shared/tools/imgdiff" "$work/$name-snell.png" "$work/$name-pov.png" --json |
    /usr/bin/python3 -c 'import json, sys; print(round(json.load(sys.stdin)["ssim"], 4))')
  ratio=$(printf '%.2f' "$(echo "$p / $s" | bc -l)") cpu_ratio=$(printf '%.2f' "$(echo "$pc / $sc" | bc -l)")
  printf '%-18s %9s %8.3f %8.3f %6sx %8.3f %8.3f %6sx %7s\n' "$name" "${w}x$h" "$s" "$p" "$ratio" "$sc" "$pc" \
    "$cpu_ratio" "$ssim"
  rows+=("| $name | ${w}x$h | $(printf '%.3f | %.3f' "$s" "$p") | ${ratio}x | $(printf '%.3f | %.3f' "$sc" "$pc") | ${cpu_ratio}x | $ssim |")
done

if [[ -n $out ]]; then
  {
    echo "# Isosurface and blob speed against POV-Ray 3.7"
    echo
    echo "Written by \`tools/bench-shapes.sh --runs $runs\` on $(date -u +%Y-%m-%d) ($(nproc) cores;"
    echo "\`+A0.3 -D +WT2\`, snell and povray alternating in one run, medians of $runs runs; ratio = povray / snell"
    echo "time, above 1 means snell is faster; CPU = user + system seconds of the process, less distorted than wall"
    echo "time when other work shares the cores; SSIM of snell's image against POV-Ray's)."
    echo
    echo "| scene | size | snell wall s | povray wall s | ratio | snell CPU s | povray CPU s | CPU ratio | SSIM |"
    echo "|---|---|---|---|---|---|---|---|---|"
    printf '%s\n' "${rows[@]}"
  } >"$out"
fi
