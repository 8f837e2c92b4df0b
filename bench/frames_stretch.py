#!/usr/bin/env python3
"""Stretched segments of interpolated strands in motion: a line per frames.h5.

    python3 bench/frames_stretch.py FRAMES_H5 [FRAMES_H5 ...] [--ratio R] [--frame N]

For every frames.h5 that `interpolate` wrote: the strands that have a segment longer than
R times its rest length (default 2) in any frame, the most such strands in one frame, the
count at frame N (default 30) and the worst ratio over all frames. A segment held by the
head or carried by one tetrahedron keeps its length; one that stretches past twice its
rest length in a shake is a tear (docs/interpolate.md: braid01's cap strands where they
run into the braid). The rest state is the file's /strands/rest_points.

Needs python3-h5py and python3-numpy (Debian). A bench, not a CI test: a few seconds a
file (braid01: 61 frames of 1.3 million points).
"""

import argparse

import h5py
import numpy as np


def stretch(path, ratio, frame):
    with h5py.File(path, "r") as f:
        offsets = f["strands/offsets"][:]
        rest = f["strands/rest_points"][:]
        rest_length = np.linalg.norm(np.diff(rest, axis=0), axis=1)
        # Segment i joins points i and i + 1; those across two strands do not count.
        inside = np.ones(len(rest_length), bool)
        inside[offsets[1:-1] - 1] = False
        inside &= rest_length > 1e-9
        strand_of = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))[:-1]
        frames = f["frames/points"]
        torn_any = np.zeros(len(offsets) - 1, bool)
        worst, most, at_frame = 1.0, 0, None
        for k in range(frames.shape[0]):
            points = frames[k]
            length = np.linalg.norm(np.diff(points, axis=0), axis=1)
            ratios = np.where(inside, length / np.maximum(rest_length, 1e-12), 1.0)
            worst = max(worst, float(ratios.max()))
            torn = np.unique(strand_of[ratios > ratio])
            torn_any[torn] = True
            most = max(most, len(torn))
            if k == frame:
                at_frame = len(torn)
    return torn_any.sum(), most, at_frame, worst, frames.shape[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("frames", nargs="+", help="frames.h5 files from interpolate")
    parser.add_argument("--ratio", type=float, default=2.0, help="a tear: longer than this times the rest length")
    parser.add_argument("--frame", type=int, default=30, help="the frame to count alone")
    args = parser.parse_args()
    print(f"| frames.h5 | frames | strands torn in any frame | most in one frame | at frame {args.frame} | worst stretch |")
    print("|---|---:|---:|---:|---:|---:|")
    for path in args.frames:
        torn, most, at_frame, worst, count = stretch(path, args.ratio, args.frame)
        shown = "–" if at_frame is None else f"{at_frame:,}"
        print(f"| {path} | {count} | {torn:,} | {most:,} | {shown} | {worst:.2f}× |")


if __name__ == "__main__":
    main()
