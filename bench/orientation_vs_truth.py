#!/usr/bin/env python3
"""Which of extract's strand groups run root to tip, against hair-synth's truth.

    bench/orientation_vs_truth.py OUT TRUTH [OUT TRUTH ...]

OUT is a pipeline output folder (Makefile.pipeline's OUT: OUT/<model>/extract.h5) and
TRUTH the folder of the models' <model>.truth.h5 (hair-synth writes them beside the
meshes, DATA/hair). Prints, per preset (the model name without its _NNN number), the
groups and how many run backwards: a group runs backwards when most of its strands do,
and a strand when most of its segments run against the true strand nearest them among
the true strands of the group's own stream (patches/stream in the truth: hair-synth
makes one patch per group). Judging by the own stream's strands keeps a braid's pieces,
whose locks cross one another, from being judged by another lock's direction.

Models whose extract.h5 has another number of groups than the truth has patches are
listed and left out. Needs h5py, numpy and scipy (Debian: python3-h5py, python3-scipy).
"""
import glob
import os
import re
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree


def unit_tangents(points, offsets):
    tangents = np.zeros_like(points)
    for a, b in zip(offsets[:-1], offsets[1:]):
        if b - a < 2:
            continue
        d = np.gradient(points[a:b], axis=0)
        tangents[a:b] = d / np.maximum(np.linalg.norm(d, axis=1), 1e-12)[:, None]
    return tangents


def backward_groups(extract_path, truth_path):
    """(groups judged, groups running backwards), or None if the groups do not match."""
    with h5py.File(truth_path, "r") as truth, h5py.File(extract_path, "r") as extract:
        true_points = truth["strands/points"][:]
        true_offsets = truth["strands/offsets"][:]
        true_stream = np.repeat(truth["strands/strand_attributes/stream"][:], np.diff(true_offsets))
        patch_stream = truth["patches/stream"][:]
        if len(patch_stream) != len(extract["groups/face_count"]):
            return None
        tangents = unit_tangents(true_points, true_offsets)
        by_stream = {}
        for stream in np.unique(true_stream):
            mask = true_stream == stream
            by_stream[stream] = (cKDTree(true_points[mask]), tangents[mask])
        points = extract["strands/points"][:]
        offsets = extract["strands/offsets"][:]
        groups = extract["strands/strand_attributes/group"][:]
    backwards = {}
    for s, (a, b) in enumerate(zip(offsets[:-1], offsets[1:])):
        g = groups[s]
        if b - a < 2 or patch_stream[g] not in by_stream:
            continue
        tree, true_tangents = by_stream[patch_stream[g]]
        strand = points[a:b]
        segments = strand[1:] - strand[:-1]
        _, nearest = tree.query(0.5 * (strand[1:] + strand[:-1]))
        against = np.sign((segments * true_tangents[nearest]).sum(axis=1)).sum() < 0
        backwards.setdefault(g, []).append(against)
    return len(backwards), sum(np.mean(v) > 0.5 for v in backwards.values())


def main(argv):
    if len(argv) < 2 or len(argv) % 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    per_preset = {}
    for out, truth in zip(argv[0::2], argv[1::2]):
        for extract_path in sorted(glob.glob(os.path.join(out, "*", "extract.h5"))):
            model = os.path.basename(os.path.dirname(extract_path))
            truth_path = os.path.join(truth, model + ".truth.h5")
            if not os.path.exists(truth_path):
                continue
            counts = backward_groups(extract_path, truth_path)
            if counts is None:
                print(f"left out {model}: groups do not match the truth's patches", file=sys.stderr)
                continue
            preset = re.sub(r"_\d+$", "", model)
            total = per_preset.setdefault(preset, [0, 0, 0])
            total[0] += 1
            total[1] += counts[0]
            total[2] += counts[1]
    print("| preset | models | groups | running backwards |")
    print("|---|---:|---:|---:|")
    models = groups = backwards = 0
    for preset in sorted(per_preset):
        m, g, b = per_preset[preset]
        models, groups, backwards = models + m, groups + g, backwards + b
        print(f"| {preset} | {m} | {g} | {b} |")
    share = 100.0 * backwards / groups if groups else float("nan")
    print(f"| **all** | {models} | {groups} | {backwards} ({share:.1f}%) |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
