#!/usr/bin/env bash
# "Nothing changes an image" (issue 27): renders every built-in scene × every
# method at 128×96 with two builds of airlight, L_air as a PFM (linear float),
# and compares the two builds' images; the surface (PFM too) per scene from the
# reference and from the first GPU method listed, since every GPU method reads
# its surface from the kit's one shared frame. The reference (CPU,
# its sums in a fixed order) must be bit-identical. A GPU method may move by
# rounding when shader text moves, so its images must agree within 1e-6
# relative, per pixel and channel: |a − b| ≤ 1e-6 · max(|a|, m), m the mean |a|
# of the old image. Per pixel, because a bound relative to the image's maximum
# would let a lamp in view (stage: 10³ × the shafts) hide a change in the
# shafts; the floor m, because a pixel near zero (deep shadow, a cancelled sum)
# moves by more than 1e-6 of itself when only the rounding of its terms moves.
# Prints a line per scene × method, then a summary with the run time; exits 1
# on any difference (an image, a render failing in one build only, the lists of
# scenes or methods), 0 when there is none.
# usage: bench/same_images.sh OLD_BINARY NEW_BINARY
#   SAME_IMAGES_SCENES, SAME_IMAGES_METHODS: only these (space-separated; default
#   all that NEW lists); SAME_IMAGES_JOBS: renders at once (default 2).
source "$(dirname "$0")/prologue.sh"
if [[ $# -ne 2 ]]; then
  echo "usage: bench/same_images.sh OLD_BINARY NEW_BINARY" >&2
  exit 2
fi
old=$(given_binary "$1") new=$(given_binary "$2")
start=$SECONDS

names() { "$1" list "$2" | awk -F '\t' '/^[^ ]/ { print $1 }'; }  # method lines start unindented
listed=0
for what in scenes methods; do
  if [[ "$(names "$old" $what)" != "$(names "$new" $what)" ]]; then
    echo "the builds list different $what:"
    diff <(names "$old" $what) <(names "$new" $what) || true
    listed=1
  fi
done
read -r -a scenes <<<"${SAME_IMAGES_SCENES:-$(names "$new" scenes | tr '\n' ' ')}"
read -r -a methods <<<"${SAME_IMAGES_METHODS:-$(names "$new" methods | tr '\n' ' ')}"

# One render: BINARY TAG SCENE METHOD PASS into $work/SCENE.METHOD.PASS.TAG.pfm;
# a failure leaves its exit status and message in .TAG.failed instead.
render() {
  local out="$work/$3.$4.$5.$2"
  "$1" render --builtin "$3" --method "$4" --pass "$5" --size 128x96 --out "$out.pfm" 2>"$out.err" ||
    { echo "exit $?: $(tail -n 1 "$out.err")" >"$out.failed"; }
}
export -f render
export work
gpu_surface=$(printf '%s\n' "${methods[@]}" | grep -vxm1 reference || true)
for scene in "${scenes[@]}"; do
  for method in "${methods[@]}"; do
    passes=(airlight)
    [[ $method == reference || $method == "$gpu_surface" ]] && passes+=(surface)
    for pass in "${passes[@]}"; do
      echo "$old old $scene $method $pass"
      echo "$new new $scene $method $pass"
    done
  done
done | xargs -P "${SAME_IMAGES_JOBS:-2}" -n 5 bash -c 'render "$@"' _

PYTHONPATH=bench python3 - "$work" "$((SECONDS - start))" "${#scenes[@]}" "${scenes[@]}" "${methods[@]}" <<'PY' || exit 1
import math, os, sys

from pfm_error import read_pfm

work, seconds, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
scenes, methods = sys.argv[4:4 + count], sys.argv[4 + count:]
tolerance = 1e-6


def compare(base, method):
    """'identical', 'within' or 'differs', and the words for the line."""
    failed = [os.path.exists(f'{base}.{tag}.failed') for tag in ('old', 'new')]
    if any(failed):
        notes = [open(f'{base}.{tag}.failed').read().strip() if f else 'ok' for tag, f in zip(('old', 'new'), failed)]
        return ('identical' if notes[0] == notes[1] else 'differs'), f'old {notes[0]}, new {notes[1]}'
    with open(f'{base}.old.pfm', 'rb') as a, open(f'{base}.new.pfm', 'rb') as b:
        if a.read() == b.read():
            return 'identical', 'identical'
    if method == 'reference':
        return 'differs', 'not bit-identical'
    (width, height, a), (*size_b, b) = read_pfm(f'{base}.old.pfm'), read_pfm(f'{base}.new.pfm')
    if [width, height] != size_b:
        return 'differs', f'{width}x{height} against {size_b[0]}x{size_b[1]}'
    floor = sum(map(abs, a)) / len(a)
    worst, where = 0.0, 0
    for i, (x, y) in enumerate(zip(a, b)):
        if math.isnan(x) or math.isnan(y):
            error = 0.0 if math.isnan(x) and math.isnan(y) else math.inf
        else:
            scale = max(abs(x), floor)
            error = abs(x - y) / scale if scale > 0 else (0.0 if x == y else math.inf)
        if error > worst:
            worst, where = error, i
    pixel = f'pixel ({where // 3 % width}, {height - 1 - where // 3 // width})'  # PFM rows run bottom up
    if worst <= tolerance:
        return 'within', f'within {tolerance:g} (at most {worst:.2g}, {pixel})'
    return 'differs', f'{worst:.3g} relative at {pixel}'


totals = {'identical': 0, 'within': 0, 'differs': 0}
for scene in scenes:
    for method in methods:
        results = {p: compare(f'{work}/{scene}.{method}.{p}', method) for p in ('airlight', 'surface')
                   if p == 'airlight' or os.path.exists(f'{work}/{scene}.{method}.{p}.old.err')}
        kinds = [kind for kind, _ in results.values()]
        kind = 'differs' if 'differs' in kinds else 'within' if 'within' in kinds else 'identical'
        totals[kind] += 1
        notes = [w for _, w in results.values()]
        words = 'identical' if notes == ['identical'] * len(notes) else ', '.join(f'{p} {w}' for p, w in zip(results, notes))
        print(f"{scene} {method}: {'DIFFERS: ' if kind == 'differs' else ''}{words}")
print(f"{sum(totals.values())} scene × method pairs at 128x96: {totals['identical']} "
      f"bit-identical, {totals['within']} within {tolerance:g}, {totals['differs']} different; {seconds} s")
sys.exit(1 if totals['differs'] else 0)
PY
exit "$listed"
