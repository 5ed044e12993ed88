#!/usr/bin/env python3
"""Times as ratios to a baseline run, from an `airlight bench` CSV, as Markdown:
per scene and size, each run's median frame time and its own passes' time (all
but the shared frame's: bench_csv.own) over the baseline run's in the same
bench run, with its rRMSE. The baseline is the run of BASELINE's method whose
settings include BASELINE's key=value pairs; with --match KEY=BASE_KEY, the one
whose BASE_KEY equals the run's KEY (the run's own BASE_KEY when it has no KEY),
so that `--match planes=steps` sets n planes against N = n steps.

usage: bench/ratios.py CSV 'METHOD [KEY=VALUE ...]' [--match KEY=BASE_KEY] [--keys KEY,...]
  --keys: the settings shown for each run (default: all)
"""
import argparse
import csv

from bench_csv import own, settings

parser = argparse.ArgumentParser()
parser.add_argument('csv')
parser.add_argument('baseline')
parser.add_argument('--match')
parser.add_argument('--keys')
args = parser.parse_args()

rows = list(csv.DictReader(open(args.csv)))
base_method, *base_pairs = args.baseline.split()
base_settings = dict(pair.split('=') for pair in base_pairs)
key, base_key = args.match.split('=') if args.match else (None, None)
shown = args.keys.split(',') if args.keys else None


def case(row):
    return row['scene'], row['width'], row['height']


def baseline(row):
    kv = settings(row)
    found = [b for b in rows if case(b) == case(row) and b['method'] == base_method
             and base_settings.items() <= settings(b).items()
             and (key is None or settings(b).get(base_key) == kv.get(key, kv.get(base_key)))]
    return found[0] if found else None


def ratio(a, b):
    return f'{a / b:.2f}' if b > 0 else ''


print(f'| scene | size | method | settings | frame s | own s | frame / baseline | own / baseline | rRMSE |')
print('|---|---|---|---|---|---|---|---|---|')
for r in rows:
    kv = settings(r)
    words = ' '.join(f'{k}={v}' for k, v in kv.items() if shown is None or k in shown)
    frame, mine, b = float(r['frame_median_s']), own(r), baseline(r)
    print(f"| {r['scene']} | {r['width']}×{r['height']} | {r['method']} | {words} | {frame:.4g} | {mine:.4g} | "
          f"{ratio(frame, float(b['frame_median_s'])) if b else ''} | {ratio(mine, own(b)) if b else ''} | "
          f"{float(r['rel_rmse']):.3g} |")
