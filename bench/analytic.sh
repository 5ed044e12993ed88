#!/usr/bin/env bash
# analytic (Sun et al. 2005 via Kingston 4.2) at 512×384 on a scene without
# volumetric shadows: the time of F=shader over F=table (Kingston §5.2.1
# measured 14× for the shader alone), and of analytic over raymarch N = 64,
# for the airlight pass and the frame, each the best of 3 runs; with each
# variant's rRMSE against the reference.
# usage: bench/analytic.sh [SCENE.json]   (default bench/scenes/open_fog.json; builds first)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-bench/scenes/open_fog.json}
size=512x384
scripts/build release >/dev/null
airlight=build/release/src/app/airlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

variants=(
  "analytic F=table"
  "analytic F=shader"
  "raymarch steps=64"
)

seconds() {  # the report's render time and its airlight pass's
  python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['timings']; \
print(t['render_s'], sum(p['seconds'] for p in t['passes'] if p['pass']=='airlight'))" "$1"
}

best_of_3() {  # index method settings...: the fastest frame and airlight pass of 3 renders
  local i=$1 method=$2
  shift 2
  local sets=() frame=inf air=inf f a
  for s in "$@"; do sets+=(--set "$s"); done
  for _ in 1 2 3; do
    $airlight render --scene "$scene" --method "$method" "${sets[@]}" --pass airlight --size "$size" \
      --out "$work/$i.pfm" --report "$work/$i.json"
    read -r f a < <(seconds "$work/$i.json")
    frame=$(python3 -c "print(min(float('$frame'), $f))")
    air=$(python3 -c "print(min(float('$air'), $a))")
  done
  echo "$frame $air"
}

error() { bench/pfm_error.py "$work/ref.pfm" "$work/$1.pfm" | sed 's/.*rel_rmse=\([^\t]*\).*/\1/'; }

$airlight render --scene "$scene" --method reference --pass airlight --size "$size" --out "$work/ref.pfm"
frame=() air=()
for i in "${!variants[@]}"; do
  read -r frame[$i] air[$i] < <(best_of_3 "$i" ${variants[$i]})
done

printf "scene %s, %s\n" "$scene" "$size"
printf "variant\tframe_s\tairlight_s\trel_rmse\n"
for i in "${!variants[@]}"; do
  printf "%s\t%.4f\t%.4f\t%s\n" "${variants[$i]}" "${frame[$i]}" "${air[$i]}" "$(error "$i")"
done
python3 - "${frame[@]}" "${air[@]}" <<'PY'
import sys
f_table, f_shader, f_march, a_table, a_shader, a_march = map(float, sys.argv[1:7])
print("ratio\tairlight\tframe")
print("F=shader / F=table\t%.2f\t%.2f" % (a_shader / a_table, f_shader / f_table))
print("analytic F=table / raymarch N=64\t%.3f\t%.3f" % (a_table / a_march, f_table / f_march))
print("analytic F=shader / raymarch N=64\t%.3f\t%.3f" % (a_shader / a_march, f_shader / f_march))
PY
