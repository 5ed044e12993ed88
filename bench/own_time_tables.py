#!/usr/bin/env python3
"""Equal-quality tables by own time (issue 28), as Markdown on stdout: per
scene, size and method the cheapest run by `own_median_s` whose rRMSE ≤ E,
for each E, with its own time over the cheapest raymarch run of the same CSV
(any settings and scale) and, given an old build's CSV of raymarch runs at
full scale, the speed-up over the cheapest of those (its own time over this one's).

usage: bench/own_time_tables.py NEW.csv [--old OLD.csv] [--e 0.01,0.02,0.05]
"""
import argparse
import csv
from bench_csv import own, settings

SHOWN = ('steps', 'sampling', 'scale', 'planes', 'F')


def short(row):
    return ' '.join(f'{k}={v}' for k, v in settings(row).items() if k in SHOWN)


def cheapest(rows, e):
    ok = [r for r in rows if own(r) is not None and float(r['rel_rmse']) <= e]
    return min(ok, key=own) if ok else None


def main():
    p = argparse.ArgumentParser()
    p.add_argument('new')
    p.add_argument('--old')
    p.add_argument('--e', default='0.01,0.02,0.05')
    a = p.parse_args()
    rows = list(csv.DictReader(open(a.new)))
    old = list(csv.DictReader(open(a.old))) if a.old else []
    cases = list(dict.fromkeys((r['scene'], r['width'], r['height']) for r in rows))
    methods = list(dict.fromkeys(r['method'] for r in rows))
    for e in (float(x) for x in a.e.split(',')):
        print(f'\n**rRMSE ≤ {e:g}**, by own time (ms)\n')
        print('| scene | size | method | cheapest settings | own ms | frame ms | rRMSE | / best raymarch |'
              + (' old raymarch / own |' if old else ''))
        print('|---|---|---|---|---|---|---|---|' + ('---|' if old else ''))
        for scene, w, h in cases:
            group = [r for r in rows if (r['scene'], r['width'], r['height']) == (scene, w, h)]
            best = cheapest([r for r in group if r['method'] == 'raymarch'], e)
            before = cheapest([r for r in old if (r['scene'], r['width'], r['height']) == (scene, w, h)
                               and r['method'] == 'raymarch'], e)
            for m in methods:
                r = cheapest([r for r in group if r['method'] == m], e)
                if not r:
                    print(f'| {scene} | {w}×{h} | {m} | no run reaches it | | | | |' + (' |' if old else ''))
                    continue
                line = (f'| {scene} | {w}×{h} | {m} | {short(r)} | {own(r) * 1e3:.1f} | '
                        f'{float(r["frame_median_s"]) * 1e3:.1f} | {float(r["rel_rmse"]):.3g} | ')
                line += f'{own(r) / own(best):.2f} |' if best else ' |'
                if old:
                    line += f' {own(before) / own(r):.2f} |' if before else ' |'
                print(line)


main()
