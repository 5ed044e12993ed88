#!/usr/bin/env bash
# analytic (Sun et al. 2005 via Kingston 4.2) at 512×384 on a scene without
# volumetric shadows, in one airlight bench run: the time of F=shader over
# F=table (Kingston §5.2.1 measured 14× for the shader alone), and of analytic
# over raymarch N = 64, for the frame and the method's own passes, medians of 3
# frames after a warm-up; with each run's rRMSE against the reference. Writes
# bench/results/analytic_F.csv; references come from the default cache
# (README "Benchmarking").
# usage: bench/analytic.sh [SCENE.json]   (default bench/scenes/open_fog.json; builds first)
source "$(dirname "$0")/prologue.sh"
scene=${1:-bench/scenes/open_fog.json}
build_airlight
$airlight bench --warmup 1 --frames 3 --scene "$scene" --sizes 512x384 \
  --methods analytic,raymarch --sweep analytic.F=table,shader --set raymarch.steps=64 \
  --csv "$results/analytic_F.csv"
echo "Over analytic F=table:"
python3 bench/ratios.py "$results/analytic_F.csv" "analytic F=table" --keys F,steps
echo
echo "Over raymarch N = 64:"
python3 bench/ratios.py "$results/analytic_F.csv" raymarch --keys F,steps
