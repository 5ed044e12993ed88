#!/usr/bin/env python3
"""Writes torus.obj beside this script: a closed ring of quads for obj_point_light.json.

The ring lies in the xy plane (its axis along z), centred on the origin, so that
a light behind it shines through the hole. Quads share their corners, so the
mesh is closed; the OBJ gives no normals and airlight smooths its own.
Run: python3 examples/scenes/meshes/make_torus.py
"""
import math
import pathlib

MAJOR, MINOR = 1.0, 0.3  # ring radius and tube radius, m
AROUND, TUBE = 16, 8     # segments around the ring and around the tube: 256 triangles

lines = [f"# Torus R = {MAJOR}, r = {MINOR}, {AROUND}x{TUBE} quads, written by make_torus.py"]
for i in range(AROUND):
    phi = 2 * math.pi * i / AROUND
    for j in range(TUBE):
        theta = 2 * math.pi * j / TUBE
        radius = MAJOR + MINOR * math.cos(theta)
        lines.append(f"v {radius * math.cos(phi):.6f} {radius * math.sin(phi):.6f} {MINOR * math.sin(theta):.6f}")


def vertex(i, j):  # 1-based OBJ index of ring step i, tube step j
    return (i % AROUND) * TUBE + (j % TUBE) + 1


# Counter-clockwise seen from outside: (i, j) → (i+1, j) → (i+1, j+1) → (i, j+1).
for i in range(AROUND):
    for j in range(TUBE):
        lines.append(f"f {vertex(i, j)} {vertex(i + 1, j)} {vertex(i + 1, j + 1)} {vertex(i, j + 1)}")

(pathlib.Path(__file__).parent / "torus.obj").write_text("\n".join(lines) + "\n")
