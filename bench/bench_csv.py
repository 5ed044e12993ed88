"""What the bench/*.py tables read from an `airlight bench` CSV row."""


def stat(row, name):
    """A method's counter from the row's `stats` column ("key=value ..."), or None."""
    for kv in row['stats'].split():
        key, value = kv.split('=')
        if key == name:
            return float(value)
    return None
