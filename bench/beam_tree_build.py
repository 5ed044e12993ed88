#!/usr/bin/env python3
"""The beam tree's build time against polygon count from bench/beam_tree_build.sh's
CSV, as Markdown: per scene and size the casters' triangles (the floor box's 12
included), beam_volumes' build_s (beam tree, conforming set and pyramids, on the
CPU every frame), the tree's nodes and visible polygons, and each method's frame
time as a ratio to planes' in the same run (absolute seconds for beam_volumes
and planes); then per size the triangle count where beam_volumes' frame time
(build included) crosses planes' and raymarch's, interpolated log-log between
the scenes, and each method's range of rRMSE.

usage: bench/beam_tree_build.py CSV
"""
import csv
import math
import sys

from bench_csv import stat


rows = list(csv.DictReader(open(sys.argv[1])))
runs = {}
for r in rows:
    runs[(r['scene'], r['width'] + 'x' + r['height'], r['method'])] = r
triangles = {r['scene']: stat(r, 'caster_triangles') for r in rows if r['method'] == 'shadow_planes'}
scenes = sorted(triangles, key=triangles.get)
sizes = sorted({k[1] for k in runs}, key=lambda s: int(s.split('x')[0]))


def t(scene, size, method):
    return float(runs[(scene, size, method)]['frame_median_s'])


print('| scene | size | triangles | tree build_s | nodes | visible | beam_volumes s | beam_volumes / planes | '
      'shadow_planes / planes | shadow_planes build_s | raymarch / planes | planes s |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|')
for size in sizes:
    for s in scenes:
        bv, sp = runs[(s, size, 'beam_volumes')], runs[(s, size, 'shadow_planes')]
        p = t(s, size, 'planes')
        print(f"| {s} | {size} | {int(triangles[s])} | {stat(bv, 'build_s'):.3g} | "
              f"{int(stat(bv, 'beam_tree_nodes'))} | {int(stat(bv, 'visible_polygons'))} | "
              f"{t(s, size, 'beam_volumes'):.3g} | {t(s, size, 'beam_volumes') / p:.2f} | {t(s, size, 'shadow_planes') / p:.2f} | "
              f"{stat(sp, 'build_s'):.2g} | {t(s, size, 'raymarch') / p:.2f} | {p:.3g} |")
print()
for size in sizes:
    n = [triangles[s] for s in scenes]
    words = []
    for other in ('planes', 'raymarch'):
        ratio = [t(s, size, 'beam_volumes') / t(s, size, other) for s in scenes]
        where = f'above {int(n[-1])} triangles'
        if ratio[0] > 1:
            where = f'below {int(n[0])} triangles (already {ratio[0]:.2f}×)'
        else:
            for i in range(1, len(n)):
                if ratio[i] > 1:
                    f = -math.log(ratio[i - 1]) / (math.log(ratio[i]) - math.log(ratio[i - 1]))
                    x = math.exp(math.log(n[i - 1]) + f * (math.log(n[i]) - math.log(n[i - 1])))
                    where = f'at about {x:.0f} triangles (between {int(n[i - 1])} and {int(n[i])})'
                    break
        words.append(f'{other} {where}')
    print(f"{size}: beam_volumes' frame time exceeds " + '; '.join(words) + '.')
rmse = {}
for r in rows:
    rmse.setdefault(r['method'], []).append(float(r['rel_rmse']))
print('rRMSE: ' + ', '.join(f'{m} {min(v):.2g}–{max(v):.2g}' for m, v in rmse.items()) + '.')
