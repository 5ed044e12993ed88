#!/usr/bin/env bash
# Issue 14's equal-quality table: every GPU method on teapot_spot (a spot over
# a teapot), three_lights (a spot, a point light, a directional light) and
# toth_hall (Tóth's hall, 66 308 triangles under one point light) at 256×192,
# 512×384 and 1024×768, each method's accuracy knob swept, in one airlight
# bench run; --equal-quality E (default 0.01) picks per scene, size and method
# the cheapest run with rRMSE <= E, and its time over the cheapest raymarch run
# (any settings) that reaches E is the CSV's time_ratio_best.
# bench/light_volumes.py prints the tables at E and at 3%. The exact methods run at their
# defaults; analytic (no volumetric shadows) is there to show it cannot.
# Writes bench/results/light_volumes.csv and -equal-quality.csv. References
# come from the default cache (README "Benchmarking"); the first run renders
# them (toth_hall at 1024×768 takes the CPU reference a few minutes).
# usage: bench/light_volumes.sh [E]   (builds first)
source "$(dirname "$0")/prologue.sh"
quality=${1:-0.01}
build_airlight
$airlight bench --warmup 1 --frames 2 --equal-quality "$quality" \
  --builtin teapot_spot --builtin three_lights --builtin toth_hall --sizes 256x192,512x384,1024x768 \
  --methods raymarch,interleaved,planes,hybrid_clip,hybrid,analytic,shadow_planes,beam_volumes,light_volume,sv_march \
  --sweep raymarch.sampling=uniform,equiangular --sweep raymarch.steps=16,32,64,128,256 \
  --sweep interleaved.steps=32,64,128,256 \
  --sweep planes.planes=30,75,150,300 --sweep hybrid_clip.planes=30,75,150,300 --sweep hybrid.planes=30,75,150,300 \
  --sweep light_volume.volume_resolution=256,1024 \
  --sweep sv_march.sampling=uniform,equiangular --sweep sv_march.steps=4,8,16,32,64,128,256 \
  --csv "$results/light_volumes.csv"
python3 bench/light_volumes.py "$results/light_volumes.csv" 0.01 0.03
