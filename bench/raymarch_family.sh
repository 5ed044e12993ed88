#!/usr/bin/env bash
# raymarch (N = 16/64/256) and interleaved 4×4 against the reference on one scene,
# at 256×192 and 512×384: frame time and airlight-pass time as ratios to raymarch
# N = 64 measured in the same run, and rRMSE of the airlight pass.
# usage: bench/raymarch_family.sh [SCENE]   (default teapot_spot; builds first)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-teapot_spot}
scripts/build release >/dev/null
airlight=build/release/src/app/airlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

variants=(
  "raymarch steps=16"
  "raymarch steps=64"
  "raymarch steps=256"
  "raymarch steps=64 sampling=equiangular"
  "interleaved steps=64 block=4"
  "interleaved steps=256 block=4"
  "interleaved steps=64 block=4 sampling=equiangular"
  "interleaved steps=64 block=4 sampling=equiangular depth_aware=false"
)

seconds() {  # the report's render time, its airlight passes' time and its gather pass's
  python3 -c "import json,sys; r=json.load(open(sys.argv[1])); t=r['timings']; \
a=sum(p['seconds'] for p in t['passes'] if p['pass'] in ('airlight','march','gather')); \
g=sum(p['seconds'] for p in t['passes'] if p['pass']=='gather'); \
print(t['render_s'], a, g)" "$1"
}

printf "size\tmethod\tsettings\tframe_s\tairlight_s\tgather_s\tframe/raymarch64\tairlight/raymarch64\trel_rmse\n"
for size in 256x192 512x384; do
  $airlight render --builtin "$scene" --method reference --pass airlight --size "$size" --out "$work/ref.pfm"
  declare -A frame=() air=() gather=()
  for i in "${!variants[@]}"; do
    read -r method settings <<<"${variants[$i]}"
    sets=()
    for s in $settings; do sets+=(--set "$s"); done
    $airlight render --builtin "$scene" --method "$method" "${sets[@]}" --pass airlight --size "$size" \
      --out "$work/$i.pfm" --report "$work/$i.json"
    read -r frame[$i] air[$i] gather[$i] < <(seconds "$work/$i.json")
  done
  for i in "${!variants[@]}"; do
    read -r method settings <<<"${variants[$i]}"
    error=$(bench/pfm_error.py "$work/ref.pfm" "$work/$i.pfm" | sed 's/.*rel_rmse=\([^\t]*\).*/\1/')
    python3 -c "import sys; f,a,g,f0,a0=map(float,sys.argv[1:6]); \
print('\t'.join(sys.argv[6:9]+['%.3f'%f,'%.3f'%a,'%.4f'%g,'%.2f'%(f/f0),'%.2f'%(a/a0),sys.argv[9]]))" \
      "${frame[$i]}" "${air[$i]}" "${gather[$i]}" "${frame[1]}" "${air[1]}" "$size" "$method" "${settings// /,}" "$error"
  done
done
