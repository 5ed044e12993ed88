#!/usr/bin/env python3
"""Nilsson's Table 6.1 from bench/nilsson_table.sh's CSV, as Markdown: per scene
and size, each method's frame time over planes' at dz = 0.5 and 0.1 m (the
same run), its rRMSE and the fragments it shades (the stats column).

usage: bench/nilsson_table.py CSV
"""
import csv
import sys


def stat(row, name):
    for kv in row['stats'].split():
        key, value = kv.split('=')
        if key == name:
            return float(value)
    return None


rows = list(csv.DictReader(open(sys.argv[1])))
planes = {}
for r in rows:
    if r['method'] == 'planes':
        dz = [kv.split('=')[1] for kv in r['settings'].split() if kv.startswith('spacing=')][0]
        planes[(r['scene'], r['width'], dz)] = r
print('| scene | size | method | frame s | / planes dz 0.5 | / planes dz 0.1 | rRMSE | fragments |')
print('|---|---|---|---|---|---|---|---|')
for r in rows:
    if r['method'] == 'reference':
        continue
    key = (r['scene'], r['width'])
    name = r['method'] + (' dz ' + [kv.split('=')[1] for kv in r['settings'].split() if kv.startswith('spacing=')][0]
                          if r['method'] == 'planes' else '')
    t = float(r['frame_median_s'])
    ratios = [t / float(planes[key + (dz,)]['frame_median_s']) for dz in ('0.5', '0.1')]
    fragments = stat(r, 'fragments')
    print(f"| {r['scene']} | {r['width']}² | {name} | {t:.4g} | {ratios[0]:.2f} | {ratios[1]:.2f} | "
          f"{float(r['rel_rmse']):.2g} | {'' if fragments is None else int(fragments)} |")
