#!/usr/bin/env bash
# Nilsson's Table 6.1 redone (issue 13's report) in one airlight bench run: his
# three scenes (nilsson_parallel, nilsson_toplight, nilsson_multiple) and a spot
# over a table (bench/scenes/under_table.json, where the unlit volume is large)
# at 64² to 1024²; planes and his two hybrids (hybrid_clip: Method 1, hybrid:
# Method 2) with his dz = 0.5 and 0.1 m (spacing, sampling=plane: his one sample
# per plane), beam_volumes and shadow_planes; then each run's frame time as a
# ratio to planes at the same dz, scene and size, with its rRMSE and the
# fragments it shades (bench/nilsson_table.py prints the table).
# Writes bench/results/nilsson.csv. References come from the default cache.
# usage: bench/nilsson_table.sh   (builds first)
source "$(dirname "$0")/prologue.sh"
build_airlight
$airlight bench --warmup 1 --frames 3 \
  --builtin nilsson_parallel --builtin nilsson_toplight --builtin nilsson_multiple --scene bench/scenes/under_table.json \
  --sizes 64x64,128x128,256x256,512x512,1024x1024 \
  --methods planes,hybrid_clip,hybrid,beam_volumes,shadow_planes \
  --set planes.sampling=plane --set hybrid_clip.sampling=plane --set hybrid.sampling=plane \
  --sweep planes.spacing=0.5,0.1 --sweep hybrid_clip.spacing=0.5,0.1 --sweep hybrid.spacing=0.5,0.1 \
  --csv "$results/nilsson.csv"
python3 bench/nilsson_table.py "$results/nilsson.csv"
