#!/usr/bin/env bash
# raymarch (N = 16/64/256, uniform and equiangular) and interleaved 4×4 (N = 64
# and 256, depth-aware gather or not) against the reference on one scene, at
# 256×192 and 512×384, in one airlight bench run: frame and own-pass times as
# ratios to raymarch N = 64 (equiangular, the default) from the same run, and
# each run's rRMSE. Writes bench/results/raymarch_family.csv (its
# gather_median_s: interleaved's gather alone); references come from the
# default cache (README "Benchmarking").
# usage: bench/raymarch_family.sh [SCENE]   (default teapot_spot; builds first)
source "$(dirname "$0")/prologue.sh"
scene=${1:-teapot_spot}
build_airlight
$airlight bench --warmup 1 --frames 3 --builtin "$scene" --sizes 256x192,512x384 \
  --methods raymarch,interleaved \
  --sweep raymarch.sampling=uniform,equiangular --sweep raymarch.steps=16,64,256 \
  --set interleaved.block=4 --sweep interleaved.steps=64,256 --sweep interleaved.depth_aware=true,false \
  --csv "$results/raymarch_family.csv"
python3 bench/ratios.py "$results/raymarch_family.csv" "raymarch steps=64 sampling=equiangular" \
  --keys steps,sampling,block,depth_aware
