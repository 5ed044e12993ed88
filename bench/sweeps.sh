#!/usr/bin/env bash
# The standard sweeps (issue 6): each method's accuracy knob swept on the seeds'
# built-in scenes at 256×192 and 512×384, 1 warm-up and 2 timed frames per run,
# timed against brute force (raymarch, uniform steps, no jitter) at equal
# quality; and analytic, which has no volumetric shadows, on the one scene where
# it can be exact (bench/scenes/open_fog.json: nothing shadows the lights).
# Writes bench/results/: seeds.csv and analytic.csv (columns in README.md
# "Benchmarking"), their -equal-quality.csv tables, one plot per scene and size
# (seeds-<scene>-<WxH>.png, analytic-open_fog-<WxH>.png) and machine.txt (date,
# kernel, CPU). References come from the default cache (README "Benchmarking").
# Most of its time goes to raymarch N = 128 at 512×384 (run time: docs/decisions.md).
# usage: bench/sweeps.sh [E]   (E: the equal-quality rRMSE, default 0.05; builds first)
source "$(dirname "$0")/prologue.sh"
quality=${1:-0.05}
build_airlight

{
  date -u +"%Y-%m-%d %H:%M UTC"
  uname -srm
  lscpu | sed -n 's/^Model name: *//p'
  echo "$(nproc) cores"
} >"$results/machine.txt"

common=(--sizes 256x192,512x384 --warmup 1 --frames 2 --equal-quality "$quality")

$airlight bench "${common[@]}" \
  --builtin teapot_spot --builtin stage --builtin stained_glass --builtin three_lights \
  --methods raymarch,interleaved,planes \
  --sweep raymarch.sampling=uniform,equiangular --sweep raymarch.steps=16,32,64,128 \
  --sweep interleaved.sampling=uniform,equiangular --sweep interleaved.steps=64,128 \
  --sweep planes.sampling=plane,lit --sweep planes.planes=15,30,75,150 \
  --floor --csv "$results/seeds.csv" --plot "$results/seeds.png"

$airlight bench "${common[@]}" \
  --scene bench/scenes/open_fog.json \
  --methods raymarch,analytic \
  --sweep raymarch.sampling=uniform,equiangular --sweep raymarch.steps=16,32,64,128 \
  --sweep analytic.F=table,shader \
  --csv "$results/analytic.csv" --plot "$results/analytic.png"
