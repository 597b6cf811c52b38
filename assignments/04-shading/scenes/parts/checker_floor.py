#!/usr/bin/env python3
"""Writes checker_floor.ray_trace: a 16 x 16 checkerboard of squares in y = 0, x and z from
-8 to 8, in a BVH, for the stage-04 scenes to `include`. (A surface has one colour, so a
checkerboard is made of squares.) Run it again after changing the numbers below:
    python3 checker_floor.py > checker_floor.ray_trace
"""
N, SIDE = 16, 1.0
LIGHT, DARK = "0.9 0.9 0.85", "0.15 0.15 0.2"
print("# checker_floor.ray_trace: written by checker_floor.py, do not edit by hand.")
print(f"# {N} x {N} squares of side {SIDE} in the plane y = 0, centred on the origin.")
print("BVH {")
h = N * SIDE / 2
for i in range(N):
    for k in range(N):
        x0, z0 = -h + i * SIDE, -h + k * SIDE
        x1, z1 = x0 + SIDE, z0 + SIDE
        colour = LIGHT if (i + k) % 2 == 0 else DARK
        # Counter-clockwise seen from above (+y), so the normal points up.
        print(f"  POLYGON {{ vertices ({x0:g}, 0, {z0:g}) ({x0:g}, 0, {z1:g}) ({x1:g}, 0, {z1:g}) ({x1:g}, 0, {z0:g})"
              f"  color {colour} kdr 0.8 }}")
print("}")
