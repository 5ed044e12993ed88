#!/usr/bin/env python3
"""The error reduced resolution adds at edges (issue 28): rRMSE against the
reference over the pixels at an edge of L_air, over the rest, and over all.

usage: reduced_edges.py REFERENCE.pfm IMAGE.pfm...   (one line per image)

An edge pixel is one whose 3×3 neighbourhood in the reference holds, in some
channel, a value below 0.75 of the greatest: a shadow's or a cone's edge, a
gobo's stripe, and a silhouette, where the distance and with it L_air jump
(the contrast the bilateral upsampling's own test uses, docs/decisions.md
"Reduced resolution"). Every rRMSE is relative to the whole reference's mean,
so that the edge and the rest add up to the whole: rmse² = f·edge² + (1−f)·rest²
for the edge fraction f.
"""
import math
import sys

from pfm_error import read_pfm

CONTRAST = 0.25


def edge_mask(width, height, values):
    def at(x, y, c):
        return values[3 * (y * width + x) + c]

    mask = []
    for y in range(height):
        for x in range(width):
            edge = False
            for c in range(3):
                window = [at(i, j, c) for j in range(max(y - 1, 0), min(y + 2, height))
                          for i in range(max(x - 1, 0), min(x + 2, width))]
                if min(window) < (1.0 - CONTRAST) * max(window):
                    edge = True
            mask.append(edge)
    return mask


def main():
    width, height, reference = read_pfm(sys.argv[1])
    mean = sum(reference) / len(reference)
    mask = edge_mask(width, height, reference)
    fraction = sum(mask) / len(mask)
    for path in sys.argv[2:]:
        image = read_pfm(path)[2]
        sums = {True: 0.0, False: 0.0}
        counts = {True: 0, False: 0}
        for p, edge in enumerate(mask):
            sums[edge] += sum((image[3 * p + c] - reference[3 * p + c]) ** 2 for c in range(3))
            counts[edge] += 3
        rel = {k: math.sqrt(sums[k] / counts[k]) / mean if counts[k] else 0.0 for k in sums}
        whole = math.sqrt((sums[True] + sums[False]) / len(reference)) / mean
        print(f"{path}\tedge_fraction={fraction:.3f}\trel_rmse={whole:.4f}\tedges={rel[True]:.4f}\trest={rel[False]:.4f}")


if __name__ == "__main__":
    main()
