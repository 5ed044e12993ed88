#!/usr/bin/env bash
# shadow_planes (Biri 2006) in one airlight bench run (issue 12's report):
#  1. biri_sphere at 256×192, 512×384 and 1024×768: shadow_planes against planes
#     (sampling=lit, 15–150 planes) and raymarch (equiangular, N = 16–256) at
#     equal error (--equal-quality E, default 0.01): time per frame as ratios;
#  2. the silhouette and plane build time per frame (the CSV's stats column,
#     build_s) against the caster's triangle count: bench/scenes/biri_sphere_1k,
#     _10k and _100k.json (a UV sphere of 32, 100 and 316 segments).
# Writes bench/results/shadow_planes.csv (and -equal-quality.csv). References
# come from the default cache (README "Benchmarking").
# usage: bench/shadow_planes.sh [E]   (builds first)
source "$(dirname "$0")/prologue.sh"
quality=${1:-0.01}
build_airlight
$airlight bench --warmup 1 --frames 3 --equal-quality "$quality" \
  --builtin biri_sphere --scene bench/scenes/biri_sphere_1k.json --scene bench/scenes/biri_sphere_10k.json \
  --scene bench/scenes/biri_sphere_100k.json --sizes 256x192,512x384,1024x768 \
  --methods shadow_planes,planes,raymarch \
  --sweep planes.planes=15,30,75,150 --sweep raymarch.sampling=uniform,equiangular \
  --sweep raymarch.steps=16,64,256 --csv "$results/shadow_planes.csv"
