#!/usr/bin/env bash
# Mesh benchmark (issue 4): generates a 10-million-triangle terrain (tools/make-mesh.py, binary PLY), imports
# it with `mesh { "file" }` and renders it at 640x480, then reports load (parse) time, build and render time,
# peak memory (GNU time's maximum resident set) and bytes per triangle (peak memory over the triangle count,
# so it includes Assimp's temporary copy while loading).
#
# usage: tools/bench-mesh.sh [--bin build/snell] [--triangles N] [--accel embree|bvh] [--keep DIR]
set -euo pipefail
bin=build/snell
triangles=10000000
accel=embree
dir=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --bin) bin=$2; shift 2 ;;
    --triangles) triangles=$2; shift 2 ;;
    --accel) accel=$2; shift 2 ;;
    --keep) dir=$2; shift 2 ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "${dir:-.}"
if [[ -z "$dir" ]]; then
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
fi
mesh="$dir/terrain-$triangles.ply"
[[ -f "$mesh" ]] || /usr/bin/python3 "$here/make-mesh.py" "$mesh" --triangles "$triangles"
cat > "$dir/mesh-bench.pov" <<POV
camera { location <0, 1.2, -2.2> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
mesh { "$(basename "$mesh")" pigment { rgb <0.6, 0.55, 0.4> } }
POV
out="$dir/mesh-bench.png"
/usr/bin/time -v "$bin" +I"$dir/mesh-bench.pov" +O"$out" +W640 +H480 --accel "$accel" 2> "$dir/time.txt" >"$dir/snell.txt" ||
  { cat "$dir/snell.txt" "$dir/time.txt"; exit 1; }
count=$(grep -a -m1 '^element face' "$mesh" | awk '{print $3}')
peak_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$dir/time.txt")
wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$dir/time.txt")
cpu=$(awk -F': ' '/User time/ {u=$2} /System time/ {s=$2} END {printf "%.1fs user + %.1fs system", u, s}' "$dir/time.txt")
echo "triangles: $count ($(du -h "$mesh" | cut -f1) binary PLY)"
grep -ah 'time:' "$dir/snell.txt" "$dir/time.txt" | sed 's/^ *//'
echo "wall: $wall ($cpu; wall times stretch on a busy machine), peak memory: $((peak_kb / 1024)) MiB, bytes per triangle (peak RSS / triangles): $((peak_kb * 1024 / count))"
