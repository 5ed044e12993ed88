#!/usr/bin/env bash
# planes (Dobashi 2000) against raymarch with the same number of samples per ray
# (n planes per light vs N = n uniform steps), at 256×192 and 512×384: airlight-pass
# and frame time of planes as ratios to raymarch's measured in the same run, and the
# rRMSE of both against the reference. Also planes with ξ on Dobashi's 20×20 lattice.
# usage: bench/planes.sh [SCENE]   (default teapot_spot; builds first)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-teapot_spot}
scripts/build release >/dev/null
airlight=build/release/src/app/airlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() {  # the report's render time and its airlight pass's
  python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['timings']; \
print(t['render_s'], sum(p['seconds'] for p in t['passes'] if p['pass']=='airlight'))" "$1"
}

run() {  # name method settings...
  local name=$1 method=$2
  shift 2
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  $airlight render --builtin "$scene" --method "$method" "${sets[@]}" --pass airlight --size "$size" \
    --out "$work/$name.pfm" --report "$work/$name.json"
}

error() { bench/pfm_error.py "$work/ref.pfm" "$work/$1.pfm" | sed 's/.*rel_rmse=\([^\t]*\).*/\1/'; }

printf "size\tn\tplanes/raymarch airlight\tplanes/raymarch frame\tlattice20/raymarch airlight\trRMSE raymarch\trRMSE planes\trRMSE planes lattice20\n"
for size in 256x192 512x384; do
  $airlight render --builtin "$scene" --method reference --pass airlight --size "$size" --out "$work/ref.pfm"
  for n in 15 30 75 150; do
    run raymarch raymarch "steps=$n"
    run planes planes "planes=$n"
    run lattice planes "planes=$n" lattice=20
    read -r fr ar < <(seconds "$work/raymarch.json")
    read -r fp ap < <(seconds "$work/planes.json")
    read -r _ al < <(seconds "$work/lattice.json")
    python3 -c "import sys; ar,ap,fr,fp,al=map(float,sys.argv[3:8]); \
print('\t'.join([sys.argv[1],sys.argv[2],'%.2f'%(ap/ar),'%.2f'%(fp/fr),'%.2f'%(al/ar)]+sys.argv[8:]))" \
      "$size" "$n" "$ar" "$ap" "$fr" "$fp" "$al" "$(error raymarch)" "$(error planes)" "$(error lattice)"
  done
done
