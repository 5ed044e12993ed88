#!/usr/bin/env bash
# planes (Dobashi 2000) against raymarch with the same number of samples per ray
# (n planes per light vs N = n uniform steps), at 256×192 and 512×384, in one
# airlight bench run: the frame and own-pass times of each planes variant as
# ratios to raymarch's with N = n, and every run's rRMSE against the reference.
# Variants, for n = 15, 30, 75, 150: sampling=plane (Dobashi's one sample per
# plane) and sampling=lit (the default), each with ξ per fragment and on
# Dobashi's 20×20 lattice. Writes bench/results/planes.csv; references come
# from the default cache (README "Benchmarking").
# usage: bench/planes.sh [SCENE]   (default teapot_spot; builds first)
source "$(dirname "$0")/prologue.sh"
scene=${1:-teapot_spot}
build_airlight
$airlight bench --warmup 1 --frames 3 --builtin "$scene" --sizes 256x192,512x384 \
  --methods raymarch,planes --set raymarch.sampling=uniform --sweep raymarch.steps=15,30,75,150 \
  --sweep planes.planes=15,30,75,150 --sweep planes.sampling=plane,lit --sweep planes.lattice=0,20 \
  --csv "$results/planes.csv"
python3 bench/ratios.py "$results/planes.csv" raymarch --match planes=steps --keys steps,planes,sampling,lattice
