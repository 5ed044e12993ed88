#!/usr/bin/env python3
"""Issue 14's equal-quality table from bench/light_volumes.sh's
-equal-quality CSV, as Markdown: per scene and size, each method's cheapest run
with rRMSE <= E as its frame time over the cheapest raymarch run that reaches E
(time_ratio_best), with the knob it needed; "—" where no run of the method
reaches E (the note says how close it came).

usage: bench/light_volumes.py EQUAL_QUALITY_CSV
"""
import csv
import sys

knobs = {'raymarch': ['sampling', 'steps'], 'interleaved': ['steps'], 'planes': ['planes'],
         'hybrid_clip': ['planes'], 'hybrid': ['planes'], 'light_volume': ['volume_resolution'],
         'sv_march': ['steps']}
rows = list(csv.DictReader(open(sys.argv[1])))
methods = list(dict.fromkeys(r['method'] for r in rows))
cases = list(dict.fromkeys((r['scene'], f"{r['width']}×{r['height']}") for r in rows))
cell = {}
for r in rows:
    key = (r['scene'], f"{r['width']}×{r['height']}", r['method'])
    if not r['settings']:
        cell[key] = '—'
        continue
    kv = dict(x.split('=') for x in r['settings'].split())
    knob = ' '.join(f'{k}={kv[k]}' for k in knobs.get(r['method'], []) if k in kv)
    ratio = r['time_ratio_best']
    cell[key] = (f'{float(ratio):.2f}' if ratio else '?') + (f' ({knob})' if knob else '')
print('| scene | size | ' + ' | '.join(methods) + ' |')
print('|---|---|' + '---|' * len(methods))
for scene, size in cases:
    print(f'| {scene} | {size} | ' + ' | '.join(cell.get((scene, size, m), '') for m in methods) + ' |')
print()
print('raymarch s (the 1.00): ' + ', '.join(
    f"{r['scene']} {r['width']}×{r['height']} {float(r['frame_median_s']):.3g}" for r in rows
    if r['method'] == 'raymarch' and r['settings']) + '.')
