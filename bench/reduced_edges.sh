#!/usr/bin/env bash
# The error reduced resolution adds at shadow edges and silhouettes (issue 28):
# every built-in scene's L_air at 256×192 by the reference and by each of
# METHODS (default raymarch) at scale 1, 1/2 and 1/4, compared by
# bench/reduced_edges.py over the pixels at an edge of L_air and the rest.
# Prints a tab-separated line per scene × method × scale.
# usage: bench/reduced_edges.sh [METHOD...]   (REDUCED_EDGES_SIZE: default 256x192)
source "$(dirname "$0")/prologue.sh"
build_airlight
size=${REDUCED_EDGES_SIZE:-256x192}
methods=("${@:-raymarch}")
scenes=$("$airlight" list scenes | awk -F '\t' '/^[^ ]/ { print $1 }')
for scene in $scenes; do
  "$airlight" render --builtin "$scene" --method reference --size "$size" --pass airlight --out "$work/$scene.pfm" 2>/dev/null
  for method in "${methods[@]}"; do
    images=()
    for scale in 1 1/2 1/4; do
      image="$work/${scene}_${method}_${scale/\//_}.pfm"
      "$airlight" render --builtin "$scene" --method "$method" --set "scale=$scale" --size "$size" --pass airlight \
        --out "$image" 2>/dev/null
      images+=("$image")
    done
    python3 bench/reduced_edges.py "$work/$scene.pfm" "${images[@]}" |
      sed "s|^$work/||; s|\.pfm\t|\t|"
  done
done
