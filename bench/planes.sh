#!/usr/bin/env bash
# planes (Dobashi 2000) against raymarch with the same number of samples per ray
# (n planes per light vs N = n uniform steps), at 256×192 and 512×384: the frame
# and airlight-pass times of each planes variant as ratios to raymarch's, measured
# in the same run, and every variant's rRMSE against the reference. Variants:
# sampling=plane (Dobashi's one sample per plane), sampling=lit (the default), and
# Dobashi's 20×20 lattice.
# usage: bench/planes.sh [SCENE]   (default teapot_spot; builds first)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-teapot_spot}
scripts/build release >/dev/null
airlight=build/release/src/app/airlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

times() {  # the report's frame time and its airlight pass's
  python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['timings']; \
print(t['render_s'], sum(p['seconds'] for p in t['passes'] if p['pass']=='airlight'))" "$1"
}

render() {  # name method settings...
  local name=$1 method=$2
  shift 2
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  $airlight render --builtin "$scene" --method "$method" "${sets[@]}" --pass airlight --size "$size" \
    --out "$work/$name.pfm" --report "$work/$name.json"
}

error() { bench/pfm_error.py "$work/ref.pfm" "$work/$1.pfm" | sed 's/.*rel_rmse=\([^\t]*\).*/\1/'; }

printf "size\tn\tvariant\tframe/raymarch\tairlight/raymarch\trel_rmse\n"
for size in 256x192 512x384; do
  $airlight render --builtin "$scene" --method reference --pass airlight --size "$size" --out "$work/ref.pfm"
  for n in 15 30 75 150; do
    render raymarch raymarch "steps=$n"
    render plane planes "planes=$n" sampling=plane
    render lit planes "planes=$n" sampling=lit
    render lattice planes "planes=$n" sampling=plane lattice=20
    read -r f0 a0 < <(times "$work/raymarch.json")
    for v in raymarch plane lit lattice; do
      read -r f a < <(times "$work/$v.json")
      python3 -c "import sys; f,a,f0,a0=map(float,sys.argv[1:5]); \
print('\t'.join(sys.argv[5:8]+['%.2f'%(f/f0),'%.2f'%(a/a0),sys.argv[8]]))" "$f" "$a" "$f0" "$a0" "$size" "$n" "$v" "$(error $v)"
    done
  done
done
