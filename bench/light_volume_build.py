#!/usr/bin/env python3
"""Kingston's Fig. 23 from bench/light_volume_build.sh's CSV, as Markdown: per
scene, per resolution R, each mesh's triangles and build time (`volume_s`, the
median frame's, GPU work bracketed by glFinish on llvmpipe) and the build time
per million triangles; then per scene the growth of the build time from R = 32
to R = 1024 against the triangles' (R² would be 1024×).

usage: bench/light_volume_build.py CSV
"""
import csv
import sys

from bench_csv import stat

rows = list(csv.DictReader(open(sys.argv[1])))
mesh = {'light_volume': 'texel', 'sv_march': 'shell'}
table = {}
for r in rows:
    settings = dict(kv.split('=') for kv in r['settings'].split())
    table[(r['scene'], r['method'], int(settings['volume_resolution']))] = r
scenes = list(dict.fromkeys(r['scene'] for r in rows))
resolutions = sorted({k[2] for k in table})

print('| scene | R | texel triangles | texel build s | shell triangles | shell build s | texel s / M triangles | '
      'shell s / M triangles |')
print('|---|---|---|---|---|---|---|---|')
for s in scenes:
    for n in resolutions:
        t, h = table[(s, 'light_volume', n)], table[(s, 'sv_march', n)]
        tt, ht = stat(t, 'volume_triangles'), stat(h, 'volume_triangles')
        ts, hs = stat(t, 'volume_s'), stat(h, 'volume_s')
        print(f'| {s} | {n} | {int(tt)} | {ts:.3g} | {int(ht)} | {hs:.3g} | {ts / tt * 1e6:.3g} | {hs / ht * 1e6:.3g} |')
print()
for s in scenes:
    lo, hi = resolutions[0], resolutions[-1]
    words = []
    for m in ('light_volume', 'sv_march'):
        a, b = table[(s, m, lo)], table[(s, m, hi)]
        words.append(f"{mesh[m]} {stat(b, 'volume_s') / stat(a, 'volume_s'):.0f}× the time for "
                     f"{stat(b, 'volume_triangles') / stat(a, 'volume_triangles'):.0f}× the triangles")
    print(f'{s}, R = {lo} → {hi}: ' + '; '.join(words) + '.')
