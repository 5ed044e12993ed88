#!/usr/bin/env python3
"""Relative RMSE and max abs error of PFM images against a reference PFM (docs/design.md §6).

usage: pfm_error.py REFERENCE.pfm IMAGE.pfm...   (prints one line per image)
Pure Python so that it needs nothing beyond python3; `airlight compare` is the real tool.
"""
import math
import struct
import sys


def read_pfm(path):
    """Width, height and the RGB values, row by row as the file stores them."""
    with open(path, "rb") as f:
        header = f.readline().split()
        dims = f.readline().split()
        scale = float(f.readline())
        width, height = int(dims[0]), int(dims[1])
        assert header[0] == b"PF", f"{path}: not an RGB PFM"
        endian = "<" if scale < 0 else ">"
        return width, height, struct.unpack(f"{endian}{width * height * 3}f", f.read(width * height * 12))


def main():
    reference = read_pfm(sys.argv[1])[2]
    mean = sum(reference) / len(reference)
    for path in sys.argv[2:]:
        image = read_pfm(path)[2]
        squared = sum((m - r) ** 2 for m, r in zip(image, reference))
        worst = max(abs(m - r) for m, r in zip(image, reference))
        print(f"{path}\trel_rmse={math.sqrt(squared / len(reference)) / mean:.4f}\tmax_abs={worst:.4f}")


if __name__ == "__main__":
    main()
