#!/usr/bin/env bash
# Renders every conformance scene (../shared/conformance/scenes.tsv, POV-Ray's examples) to EXR and checks
# that no value is NaN or infinite (issue 12). tests/cli/conformance_finite_test.cpp does the same at 40x30
# in ctest; this script takes any size and anti-aliasing.
# Usage: tools/check-finite.sh [--bin build/snell] [--size WxH] [--aa T] [NAME ...]
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/snell size=40x30 aa=() names=()
while (($#)); do
  case $1 in
    --bin) bin=$(cd "$(dirname "$2")" && pwd)/$(basename "$2"); shift 2 ;;
    --size) size=$2; shift 2 ;;
    --aa) aa=("+A$2"); shift 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
examples=/usr/share/doc/povray/examples include=/usr/share/povray-3.7/include
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
finite=0 bad=0
while IFS=$'\t' read -r name scene _rest; do
  [[ $name == name ]] && continue
  if ((${#names[@]})) && [[ " ${names[*]} " != *" $name "* ]]; then continue; fi
  mkdir -p "$work/$name" && cp "$examples/$scene" "$work/$name/"
  start=$SECONDS
  (cd "$work/$name" && "$bin" "+I$(basename "$scene")" "+O$work/$name.exr" "+W${size%x*}" "+H${size#*x}" \
    "${aa[@]}" -D "+L$examples/$(dirname "$scene")" "+L$include" --quiet >"$work/$name.log" 2>&1)
  code=$?
  if ((code != 0)); then
    echo "$name: exit $code: $(head -1 "$work/$name.log")"; bad=$((bad + 1)); continue
  fi
  count=$(oiiotool --stats "$work/$name.exr" 2>/dev/null | awk '/NaN|Inf/ {print}' | tr -s ' ' | head -2 | tr '\n' ' ')
  if [[ $count =~ [1-9] ]]; then
    echo "$name: NOT FINITE ($count)"; bad=$((bad + 1))
  else
    echo "$name: finite ($((SECONDS - start)) s)"; finite=$((finite + 1))
  fi
done <"$root/../shared/conformance/scenes.tsv"
echo "check-finite: $finite finite, $bad failed"
((bad == 0))
