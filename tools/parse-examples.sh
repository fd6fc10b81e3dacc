#!/usr/bin/env bash
# Counts how many of POV-Ray's example scenes (Debian's povray-examples) snell parses with --parse-only,
# and lists the most common first errors, so the language work can go where most scenes stop.
# Usage: tools/parse-examples.sh [--bin build/snell] [--list]
set -u
bin=build/snell list=0 examples=/usr/share/doc/povray/examples include=/usr/share/povray-3.7/include
while (($#)); do
  case $1 in
    --bin) bin=$2; shift 2 ;;
    --list) list=1; shift ;;
    *) echo "usage: $0 [--bin PATH] [--list]" >&2; exit 2 ;;
  esac
done
[[ -x $bin ]] || { echo "parse-examples: no snell binary at $bin" >&2; exit 2; }
[[ -d $examples ]] || { echo "parse-examples: install Debian's povray-examples" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$examples" "$work/examples"
find "$work/examples" -name '*.gz' -exec gunzip -q {} + 2>/dev/null
passed=0 total=0
: >"$work/errors"
while IFS= read -r scene; do
  total=$((total + 1))
  dir=$(dirname "$scene") file=$(basename "$scene")
  # A scene's own .ini (same name, naming the scene) supplies its animation frame range, as POV-Ray's
  # users run it (the portfolio scenes need frame_number from theirs); its first frame is parsed.
  ini=()
  if [[ -f $dir/${file%.pov}.ini ]] && grep -qiE "^input_file_name *= *$file" "$dir/${file%.pov}.ini"; then
    ini=("${file%.pov}.ini")
  fi
  if out=$(cd "$dir" && timeout 20 "$bin" --parse-only "${ini[@]}" "+I$file" "+L$include" +W320 +H240 --quiet 2>&1); then
    passed=$((passed + 1))
    ((list)) && echo "ok   ${scene#"$work/examples/"}"
  else
    first=$(grep -m1 'error' <<<"$out" | sed -E 's/^[^ ]*: error: //' | cut -c1-90)
    [[ -n $first ]] || first="(no error line; exit status $?)"
    echo "$first" >>"$work/errors"
    ((list)) && echo "FAIL ${scene#"$work/examples/"}: $first"
  fi
done < <(find "$work/examples" -name '*.pov' | sort)
echo "most common first errors:"
sort "$work/errors" | uniq -c | sort -rn | head -25
echo "parse-examples: $passed of $total scenes parse ($(awk "BEGIN{printf \"%.1f\", 100*$passed/$total}")%)"
