#!/usr/bin/env python3
"""Nilsson's Table 6.1 from bench/nilsson_table.sh's CSV, as Markdown: per scene
and size, each method's frame time over planes' at the same dz (the same run;
the exact methods, which have no dz, over planes' at 0.5 and 0.1 m), its rRMSE
and the fragments it shades (the stats column).

usage: bench/nilsson_table.py CSV
"""
import csv
import sys

from bench_csv import stat


def spacing(row):
    found = [kv.split('=')[1] for kv in row['settings'].split() if kv.startswith('spacing=')]
    return found[0] if found else None


rows = [r for r in csv.DictReader(open(sys.argv[1])) if r['method'] != 'reference']
planes = {(r['scene'], r['width'], spacing(r)): float(r['frame_median_s']) for r in rows if r['method'] == 'planes'}
print('| scene | size | method | dz | frame s | / planes dz 0.5 | / planes dz 0.1 | rRMSE | fragments |')
print('|---|---|---|---|---|---|---|---|---|')
for r in rows:
    key, dz, t = (r['scene'], r['width']), spacing(r), float(r['frame_median_s'])
    ratio = {d: f"{t / planes[key + (d,)]:.2f}" if dz in (None, d) else '' for d in ('0.5', '0.1')}
    fragments = stat(r, 'fragments')
    print(f"| {r['scene']} | {r['width']}² | {r['method']} | {dz or ''} | {t:.4g} | {ratio['0.5']} | {ratio['0.1']} | "
          f"{float(r['rel_rmse']):.2g} | {'' if fragments is None else int(fragments)} |")
