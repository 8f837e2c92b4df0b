#!/usr/bin/env python3
"""Which of hair-synth's true root cards typeify types root, against the truth.

    bench/typeify_vs_truth.py [--types NAME] OUT TRUTH [OUT TRUTH ...]

OUT is a pipeline output folder (Makefile.pipeline's OUT: OUT/<model>/types.h5, or the
file NAME given with --types, for example one written with other parameters) and TRUTH
the folder of the models' <model>.truth.h5 (hair-synth writes them beside the meshes,
DATA/hair). A card counts as typed root when typeify says root_free or root_connected,
and as truly root when the truth's /patches/group_type says so (hair-synth makes one
patch per group). Prints, per preset (the model name without its _NNN number): true root
cards typed root, true root cards missed, other cards typed root (false roots), and the
rest; then the sums. Models whose types.h5 has another number of groups than the truth
has patches are listed and left out. Needs h5py and numpy (Debian: python3-h5py).
"""
import collections
import glob
import os
import re
import sys

import h5py
import numpy as np


def main(argv):
    types_name = "types.h5"
    if len(argv) >= 2 and argv[0] == "--types":
        types_name, argv = argv[1], argv[2:]
    if len(argv) < 2 or len(argv) % 2:
        sys.exit(__doc__)
    counts = collections.defaultdict(lambda: np.zeros(4, dtype=np.int64))
    for out, truth_dir in zip(argv[0::2], argv[1::2]):
        for path in sorted(glob.glob(os.path.join(out, "*", types_name))):
            model = os.path.basename(os.path.dirname(path))
            truth_path = os.path.join(truth_dir, model + ".truth.h5")
            if not os.path.exists(truth_path):
                continue
            with h5py.File(truth_path, "r") as truth_file, h5py.File(path, "r") as types_file:
                truth = truth_file["patches/group_type"][:]
                found = types_file["groups/type"][:]
            if len(truth) != len(found):
                print(f"left out: {model} ({len(found)} groups, {len(truth)} patches)")
                continue
            true_root, found_root = truth <= 1, found <= 1
            counts[re.sub(r"_\d+$", "", model)] += [
                np.sum(true_root & found_root), np.sum(true_root & ~found_root),
                np.sum(~true_root & found_root), np.sum(~true_root & ~found_root)]
    print("| preset | true root cards | typed root | missed | false roots | other cards |")
    print("|---|---:|---:|---:|---:|---:|")
    total = np.zeros(4, dtype=np.int64)
    for preset in sorted(counts):
        c = counts[preset]
        total += c
        print(f"| {preset} | {c[0] + c[1]} | {c[0]} | {c[1]} | {c[2]} | {c[3]} |")
    print(f"| all | {total[0] + total[1]} | {total[0]} | {total[1]} | {total[2]} | {total[3]} |")


if __name__ == "__main__":
    main(sys.argv[1:])
