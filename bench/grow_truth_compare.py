#!/usr/bin/python3
"""Grown strands of two runs of the pipeline on hair-synth models, against the models' truth.

    bench/grow_truth_compare.py DATA_DIR OUT_BEFORE OUT_AFTER

DATA_DIR holds hair/<model>.obj and hair/<model>.truth.h5 (hair-synth corpus or presets);
OUT_BEFORE and OUT_AFTER are Makefile.pipeline OUT trees with <model>/strands.h5. For the
models whose grown points differ, per preset (the model name before its last "_"), the
means over its models of: fidelity (from each grown point to the nearest true point),
coverage (from every fifth true point to the nearest grown point), both in head heights
H, and the median grown strand's length over the median true strand's. A Markdown table
on stdout. Needs h5py, NumPy and SciPy (Debian: python3-h5py python3-scipy).
"""
import collections
import glob
import os
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree


def strand_lengths(points, offsets):
    segment = np.linalg.norm(np.diff(points, axis=0), axis=1)
    segment[offsets[1:-1] - 1] = 0  # between one strand's tip and the next one's root
    walked = np.concatenate([[0], np.cumsum(segment)])
    return walked[offsets[1:] - 1] - walked[offsets[:-1]]


def measures(strands, truth_points, truth_median_m):
    points = strands["strands/points"][:]
    offsets = strands["strands/offsets"][:]
    h = strands.attrs["head_height_m"]
    fidelity = cKDTree(truth_points).query(points)[0].mean() / h
    coverage = cKDTree(points).query(truth_points[::5])[0].mean() / h
    return fidelity, coverage, np.median(strand_lengths(points, offsets)) / truth_median_m


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    data, before, after = sys.argv[1:]
    rows = collections.defaultdict(list)
    for path in sorted(glob.glob(os.path.join(after, "*", "strands.h5"))):
        model = os.path.basename(os.path.dirname(path))
        truth_path = os.path.join(data, "hair", model + ".truth.h5")
        old_path = os.path.join(before, model, "strands.h5")
        if not (os.path.exists(truth_path) and os.path.exists(old_path)):
            continue
        with h5py.File(old_path) as old, h5py.File(path) as new, h5py.File(truth_path) as truth:
            old_points, new_points = old["strands/points"][:], new["strands/points"][:]
            if old_points.shape == new_points.shape and (old_points == new_points).all():
                continue
            truth_points = truth["strands/points"][:]
            truth_median = np.median(strand_lengths(truth_points, truth["strands/offsets"][:]))
            rows[model.rsplit("_", 1)[0]].append(
                (measures(old, truth_points, truth_median), measures(new, truth_points, truth_median)))
    print("| preset (models changed) | fidelity mean (H) | coverage mean (H) | median length / true |")
    print("|---|---|---|---|")
    for preset, pairs in sorted(rows.items()):
        r = np.array(pairs)  # models x (before, after) x 3
        cells = [f"{r[:, 0, k].mean():.{p}f} → {r[:, 1, k].mean():.{p}f}" for k, p in ((0, 4), (1, 4), (2, 3))]
        print(f"| {preset} ({len(pairs)}) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
