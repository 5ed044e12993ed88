#!/usr/bin/env bash
# Kingston's Fig. 23 redone (issue 14's report): the light volume mesh's build
# time on the GPU against its resolution, 32² to 1024² cells per map (a cube's
# six faces each), in one airlight bench run at 128×96 (the build does not
# depend on the image; the crossing and bounds passes, which do, stay small).
# light_volume builds the texel mesh (2R² + 4R triangles a spot, 12R² a cube),
# sv_march the shell (4R² + 8R, 24R²); each method's `volume_s` and
# `volume_triangles` are in the CSV's stats column. Scenes: teapot_spot (one
# spot), toth_hall (one point light: a cube), three_lights (a spot, a point
# light and a directional light). Maps at 1024², so R = 1024 is a vertex per
# texel. bench/light_volume_build.py prints the table.
# Writes bench/results/light_volume_build.csv. References come from the
# default cache (README "Benchmarking").
# usage: bench/light_volume_build.sh   (builds first)
source "$(dirname "$0")/prologue.sh"
build_airlight
$airlight bench --warmup 1 --frames 3 \
  --builtin teapot_spot --builtin toth_hall --builtin three_lights --sizes 128x96 \
  --methods light_volume,sv_march \
  --sweep light_volume.volume_resolution=32,64,128,256,512,1024 \
  --sweep sv_march.volume_resolution=32,64,128,256,512,1024 \
  --csv "$results/light_volume_build.csv"
python3 bench/light_volume_build.py "$results/light_volume_build.csv"
