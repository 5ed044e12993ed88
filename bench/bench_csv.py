"""What the bench/*.py tables read from an `airlight bench` CSV row."""

# The shared frame's passes (app/bench_timing.cpp: frame_pass); every other pass is the method's own.
FRAME_PASSES = {'gbuffer', 'shadow', 'surface', 'depth', 'engine', 'readback'}


def stat(row, name):
    """A method's counter from the row's `stats` column ("key=value ..."), or None."""
    for kv in row['stats'].split():
        key, value = kv.split('=')
        if key == name:
            return float(value)
    return None


def settings(row):
    """The row's settings as a dict, in the CSV's order."""
    return dict(kv.split('=', 1) for kv in row['settings'].split())


def own(row):
    """The method's own time, `own_median_s` (None for a run without own passes); in a CSV from
    before that column, the sum of its own passes' medians (all but the shared frame's)."""
    if 'own_median_s' in row:
        return float(row['own_median_s']) if row['own_median_s'] else None
    return sum(float(v) for k, v in row.items()
               if k.endswith('_median_s') and k != 'frame_median_s' and k[:-len('_median_s')] not in FRAME_PASSES and v)
