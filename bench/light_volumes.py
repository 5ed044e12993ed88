#!/usr/bin/env python3
"""Issue 14's equal-quality tables from bench/light_volumes.sh's CSV, as
Markdown: for each E given, per scene and size, each method's cheapest run with
rRMSE <= E as its frame time over the cheapest raymarch run (any settings) that
reaches E, with the knob it needed. "—": no run of the method reaches E (its
best rRMSE in brackets); with no raymarch run at E, the method's frame time in
seconds instead of a ratio.

usage: bench/light_volumes.py CSV [E ...]   (default E: 0.01 0.03)
"""
import csv
import sys

knobs = {'raymarch': ['sampling', 'steps'], 'interleaved': ['steps'], 'planes': ['planes'],
         'hybrid_clip': ['planes'], 'hybrid': ['planes'], 'light_volume': ['volume_resolution'],
         'sv_march': ['steps']}
rows = list(csv.DictReader(open(sys.argv[1])))
levels = [float(e) for e in sys.argv[2:]] or [0.01, 0.03]
methods = list(dict.fromkeys(r['method'] for r in rows))
cases = list(dict.fromkeys((r['scene'], r['width'], r['height']) for r in rows))


def runs(case, method):
    return [r for r in rows if (r['scene'], r['width'], r['height']) == case and r['method'] == method]


def cheapest(case, method, e):
    good = [r for r in runs(case, method) if float(r['rel_rmse']) <= e]
    return min(good, key=lambda r: float(r['frame_median_s'])) if good else None


def knob(r):
    kv = dict(x.split('=') for x in r['settings'].split())
    return ' '.join(f'{k}={kv[k]}' for k in knobs.get(r['method'], []) if k in kv)


for e in levels:
    print(f'E = {e:g}: frame time over raymarch\'s at rRMSE ≤ E\n')
    print('| scene | size | ' + ' | '.join(methods) + ' |')
    print('|---|---|' + '---|' * len(methods))
    for case in cases:
        base = cheapest(case, 'raymarch', e)
        cells = []
        for m in methods:
            r = cheapest(case, m, e)
            if r is None:
                best = min(float(x['rel_rmse']) for x in runs(case, m))
                cells.append(f'— ({best:.2g})')
                continue
            t = float(r['frame_median_s'])
            value = f'{t / float(base["frame_median_s"]):.2f}' if base else f'{t:.3g} s'
            cells.append(value + (f' ({knob(r)})' if knob(r) else ''))
        print(f'| {case[0]} | {case[1]}×{case[2]} | ' + ' | '.join(cells) + ' |')
    print()
