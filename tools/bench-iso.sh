#!/usr/bin/env bash
# Isosurface and blob speed against POV-Ray 3.7, same flags, same run: renders POV-Ray's example scenes
# objects/isosurfaces.pov and objects/blob.pov with snell and with povray, three times each, and prints
# the median wall times, their ratio (povray / snell: above 1 means snell is faster) and the SSIM of
# snell's image against POV-Ray's.
# Usage (from the project root): tools/bench-iso.sh [--bin build/snell] [--size WxH] [--runs N]
set -eu
bin=build/snell size=320x240 runs=3
while (($#)); do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "bench-iso: unknown argument $1" >&2; exit 2 ;;
  esac
done
examples=/usr/share/doc/povray/examples include=/usr/share/povray-3.7/include
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
w=${size%x*} h=${size#*x}
flags=(+W"$w" +H"$h" +A0.3 -D +WT2 +L"$include")

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); echo "$t1 - $t0" | bc -l; }

printf '%-12s %9s %9s %7s %7s\n' scene snell_s povray_s ratio ssim
for scene in objects/isosurfaces.pov objects/blob.pov; do
  name=$(basename "$scene" .pov)
  zcat -f "$examples/$scene"* > "$work/$name.pov"
  snell_times=() pov_times=()
  for ((i = 0; i < runs; i++)); do
    snell_times+=("$(seconds "$bin" +I"$work/$name.pov" +O"$work/$name-snell.png" "${flags[@]}")")
    pov_times+=("$(seconds povray +I"$work/$name.pov" +O"$work/$name-pov.png" "${flags[@]}")")
  done
  s=$(median "${snell_times[@]}") p=$(median "${pov_times[@]}")
  ssim=$(/usr/bin/python3 "$root/../shared/tools/imgdiff" "$work/$name-snell.png" "$work/$name-pov.png" --json |
    /usr/bin/python3 -c 'import json, sys; print(round(json.load(sys.stdin)["ssim"], 4))')
  printf '%-12s %9.3f %9.3f %6.2fx %7s\n' "$name" "$s" "$p" "$(echo "$p / $s" | bc -l)" "$ssim"
done
