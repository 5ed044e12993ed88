#!/usr/bin/env python3
"""The README's "Latest output" section from bench/results/ (bench/sweeps.sh's
machine.txt and equal-quality CSVs), as Markdown on stdout.

usage: bench/equal_quality_table.py
"""
import csv
import pathlib

results = pathlib.Path(__file__).resolve().parent / "results"


def short(settings, method):
    keep = {'raymarch': ['sampling', 'steps'], 'interleaved': ['sampling', 'steps'], 'planes': ['sampling', 'planes'],
            'analytic': ['F']}[method]
    kv = dict(x.split('=') for x in settings.split())
    return ' '.join(f'{k}={kv[k]}' for k in keep if k in kv)
def ratio(text):
    return f'{float(text):.2f}' if text else ''


machine = open(results / 'machine.txt').read().split('\n')
out = []
out.append('### Latest output\n')
out.append(f'`bench/sweeps.sh` (E = 0.05), run {machine[0]} on {machine[2]}, {machine[3]}, {machine[1]}; '
           'OpenGL on Mesa llvmpipe (no GPU), with other jobs sharing the cores. Frame times are medians of 2 '
           'frames after 1 warm-up; `time / brute force` is the frame time over the cheapest `raymarch` run with '
           'uniform steps and no jitter that reaches rRMSE ≤ E (the documents\' baseline), `time / best raymarch` '
           'over the cheapest `raymarch` run of any settings that does. Every CSV and plot is in '
           '`bench/results/`. An empty `time / brute force`: no such run reaches E (uniform steps up to N = 128 '
           'stay above it beside the lights).\n')
out.append('![error against time, stage 256×192](bench/results/seeds-stage-256x192.png)\n')
out.append('| scene | size | method | cheapest setting with rRMSE ≤ 0.05 | frame s | rRMSE | time / brute force | '
           'time / best raymarch |')
out.append('|---|---|---|---|---|---|---|---|')
for f in ['seeds', 'analytic']:
    for r in csv.DictReader(open(results / f'{f}-equal-quality.csv')):
        size = f"{r['width']}×{r['height']}"
        if not r['settings']:  # no run of the method reaches E
            out.append(f"| {r['scene']} | {size} | {r['method']} | {r['note']} | | | | |")
        else:
            out.append(f"| {r['scene']} | {size} | {r['method']} | {short(r['settings'], r['method'])} | "
                       f"{float(r['frame_median_s']):.3g} | {float(r['rel_rmse']):.2g} | {ratio(r['time_ratio'])} | "
                       f"{ratio(r['time_ratio_best'])} |")
print('\n'.join(out))
