#!/usr/bin/env python3
"""Writes room.yaml + room.pgm: the rostests' world, a 10 m x 6 m free room
(x in [-2, 8], y in [-3, 3]) closed by 0.5 m of wall, at 5 cm (map_server trinary PGM)."""
import os

RES, X0, Y0, W, H = 0.05, -2.5, -3.5, 220, 140  # 11 m x 7 m
here = os.path.dirname(os.path.abspath(__file__))
rows = []
for row in range(H):  # PGM row 0 is the top (largest y)
    y = Y0 + (H - 1 - row + 0.5) * RES
    line = bytearray()
    for col in range(W):
        x = X0 + (col + 0.5) * RES
        line.append(254 if (-2.0 < x < 8.0 and -3.0 < y < 3.0) else 0)
    rows.append(bytes(line))
with open(os.path.join(here, "room.pgm"), "wb") as f:
    f.write(b"P5\n%d %d\n255\n" % (W, H) + b"".join(rows))
with open(os.path.join(here, "room.yaml"), "w") as f:
    f.write("image: room.pgm\nresolution: %.2f\norigin: [%.1f, %.1f, 0.0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" % (RES, X0, Y0))
