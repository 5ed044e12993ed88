#!/usr/bin/env bash
# The beam tree's build time against polygon count (issue 13's report) in one
# airlight bench run: a sphere caster of about 10², 10³, 10⁴ and 10⁵ triangles
# (bench/scenes/biri_sphere_100, _1k, _10k and _100k.json: a UV sphere of 12,
# 32, 100 and 316 segments over a floor box, one spot light in fog) at 256² and
# 512², timing beam_volumes (the beam tree built on the CPU every frame, its
# build_s, beam_tree_nodes and visible_polygons in the CSV's stats column),
# shadow_planes (its silhouette build_s too) and the sampling methods planes
# and raymarch, whose cost does not depend on the triangle count, all at their
# defaults. bench/beam_tree_build.py then prints per scene and size each
# method's frame time as a ratio to planes' in the same run, the absolute
# build_s, and where beam_volumes' frame time (build included) crosses planes'
# and raymarch's.
# Writes bench/results/beam_tree_build.csv. References come from the default
# cache (README "Benchmarking").
# usage: bench/beam_tree_build.sh   (builds first)
source "$(dirname "$0")/prologue.sh"
build_airlight
$airlight bench --warmup 1 --frames 3 \
  --scene bench/scenes/biri_sphere_100.json --scene bench/scenes/biri_sphere_1k.json \
  --scene bench/scenes/biri_sphere_10k.json --scene bench/scenes/biri_sphere_100k.json \
  --sizes 256x256,512x512 --methods beam_volumes,shadow_planes,planes,raymarch \
  --csv "$results/beam_tree_build.csv"
python3 bench/beam_tree_build.py "$results/beam_tree_build.csv"
