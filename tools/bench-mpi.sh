#!/usr/bin/env bash
# Distributed-render benchmark (docs/distributed.md): wall time of one render with 1, 2 and 3 MPI ranks on this
# machine, and the tile queue's parallel efficiency with ranks of one render thread each. On a 2-core machine
# 3 ranks are oversubscribed: the table says so. Medians of hyperfine runs.
# Usage: tools/bench-mpi.sh [--bin build/snell] [--scene scenes/showcase.pov] [--size 640x480] [--runs 3]
set -eu
bin=build/snell scene=scenes/showcase.pov size=640x480 runs=3
while (($#)); do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: $0 [--bin PATH] [--scene FILE] [--size WxH] [--runs N]" >&2; exit 2 ;;
  esac
done
command -v hyperfine >/dev/null || { echo "bench-mpi: needs hyperfine (Debian package)" >&2; exit 2; }
"$bin" --version | grep -q "with Open MPI" || { echo "bench-mpi: $bin was built without MPI" >&2; exit 2; }
w=${size%x*} h=${size#*x}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mpi="mpirun --allow-run-as-root --oversubscribe"
flags="+I$scene +W$w +H$h +A0.3 --quiet +O$out/o.png"
median() { # hyperfine's median of one command, in seconds
  hyperfine --warmup 1 --runs "$runs" --export-json "$out/h.json" "$1" >/dev/null 2>&1
  /usr/bin/python3 -c "import json;print('%.3f'%json.load(open('$out/h.json'))['results'][0]['median'])"
}
cores=$(nproc)
echo "| ranks | threads per rank | wall s (median of $runs) | note |"
echo "| --- | --- | --- | --- |"
t1=$(median "$bin $flags"); echo "| 1 (no mpirun) | $cores | $t1 | |"
for n in 2 3; do
  note=""; ((n > cores)) && note="oversubscribed: $n ranks on $cores cores"
  tn=$(median "$mpi -n $n $bin $flags"); echo "| $n | $cores | $tn | $note |"
done
# Efficiency of the tile queue alone: the render phase that rank 0 reports (--stats "render Xs": from the
# first tile handed out to the last gathered), single 1-thread process vs 2 ranks of 1 thread (rank 0 renders
# beside its queue, so 2 renderers). Start-up (mpirun, parse and build on every rank) is left out here; the
# table above includes it.
render_median() { # median render-phase seconds of $runs runs
  for _ in $(seq "$runs"); do $1 --stats 2>&1 | sed -nE 's/.*render ([0-9.]+)s.*/\1/p' | tail -1; done |
    sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
s1=$(render_median "$bin $flags --threads 1")
s2=$(render_median "$mpi -n 2 $bin $flags --threads 1")
tiles=$(( ((w + 31) / 32) * ((h + 31) / 32) ))
echo
echo "tile queue, 1-thread ranks, render phase: T(1 process)=${s1}s, T(2 ranks)=${s2}s, efficiency T1/(2*T2) = $(
  /usr/bin/python3 -c "print('%.2f' % ($s1 / (2 * $s2)))")"
echo "tiles: $tiles of 32x32; mean cost per tile (1 thread) = $(
  /usr/bin/python3 -c "print('%.2f ms' % (1000 * $s1 / $tiles))")"
