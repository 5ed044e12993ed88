#!/usr/bin/env bash
# Times two builds of airlight side by side: `bench/compare_builds.sh OLD NEW
# BENCH-ARGS...` runs `airlight bench BENCH-ARGS` with each binary in turn
# (512x384, 1 warm-up, 5 frames) and prints, per run, the median seconds of the
# method's own passes (all but the shared frame's) for both, their ratio and
# both errors. Build the old one from a worktree: git worktree add /tmp/old REV,
# then cmake --preset release && cmake --build build/release --target airlight there.
source "$(dirname "$0")/prologue.sh"
old=$(given_binary "$1") new=$(given_binary "$2")
shift 2
for build in old new; do  # from the caller's directory, where BENCH-ARGS' paths are relative to
  (cd "$caller_dir" && "${!build}" bench "$@" --sizes 512x384 --warmup 1 --frames 5 --csv "$work/$build.csv" >/dev/null 2>&1)
done
PYTHONPATH=bench python3 - "$work/old.csv" "$work/new.csv" <<'PY'
import csv, sys
from bench_csv import own
old, new = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
for a, b in zip(old, new):
    keys = ' '.join(x for x in a['settings'].split() if x.startswith(('steps', 'sampling', 'F=', 'planes=')))
    print(f"{a['scene']} {a['method']} {keys}: old {own(a):.4f} s, new {own(b):.4f} s, "
          f"speed-up {own(a) / own(b):.2f}, rRMSE {a['rel_rmse']} / {b['rel_rmse']}")
PY
