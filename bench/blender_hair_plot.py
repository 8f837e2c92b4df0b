#!/usr/bin/env python3
"""Draws Blender's hairs (bench/blender_hair_dynamics.py --export) and our guides
(the guides.h5 the export's input came from) at rest, where the head is turned furthest
and at the last frame, front and side views, into a PNG.

  bench/blender_hair_plot.py SHAPES_JSON GUIDES_H5 OUT.png

The export's frames must not be looped (--frames at most guides.h5's).
"""
import json
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

shapes_file, guides_file, out = sys.argv[1:4]
shapes = json.load(open(shapes_file))
with h5py.File(guides_file, "r") as g:
    offsets = g["guides/offsets"][:]
    ours = {f: g["frames/guide_points"][f] for f in (shapes["turned_frame"], shapes["last_frame"])}
rows = [(shapes["turned_frame"], shapes["turned"]), (shapes["last_frame"], shapes["last"])]
fig, axes = plt.subplots(2, 2, figsize=(10, 11))
for (frame, blender), row in zip(rows, axes):
    for ax, u, view in ((row[0], 0, "front (x, y)"), (row[1], 2, "side (z, y)")):
        for hairs, colour in ((shapes["frame1"], "0.75"), (blender, "tab:blue")):
            for h in np.array(hairs):
                ax.plot(h[:, u], h[:, 1], color=colour, lw=0.5)
        for i in range(len(offsets) - 1):
            p = ours[frame][offsets[i]:offsets[i + 1]]
            ax.plot(p[:, u], p[:, 1], color="tab:red", lw=0.5)
        ax.set_title("frame %d, %s, metres" % (frame, view))
        ax.set_aspect("equal")
    row[0].plot([], [], color="0.75", label="rest (Blender's frame 1)")
    row[0].plot([], [], color="tab:blue", label="Blender")
    row[0].plot([], [], color="tab:red", label="ours")
    row[0].legend(loc="lower left", fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=80)
