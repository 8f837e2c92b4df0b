#!/usr/bin/python3
"""Error of one interpolated animation against a reference of the same strands.

    time_error_measure.py REFERENCE_FRAMES_H5 VARIANT_FRAMES_H5

Prints "mean,p95,max" of the distance of every strand point to the same point of the
reference, divided by the length of its strand at rest, over every frame (frames.h5's
/frames/points; both files must hold the same strands and frames). Used by
bench/time_error.sh."""
import sys

import h5py
import numpy as np


def strand_length_per_point(frames):
    offsets = frames["/strands/offsets"][:]
    rest = frames["/strands/rest_points"][:].astype(np.float64)
    segment = np.linalg.norm(np.diff(rest, axis=0), axis=1)
    cumulative = np.concatenate([[0.0], np.cumsum(segment)])
    lengths = cumulative[offsets[1:] - 1] - cumulative[offsets[:-1]]
    return np.repeat(lengths, np.diff(offsets))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with h5py.File(sys.argv[1], "r") as reference, h5py.File(sys.argv[2], "r") as variant:
        if not np.array_equal(reference["/strands/offsets"][:], variant["/strands/offsets"][:]):
            sys.exit(f"{sys.argv[2]}: not the strands of {sys.argv[1]}")
        ref_points, var_points = reference["/frames/points"], variant["/frames/points"]
        if ref_points.shape != var_points.shape:
            sys.exit(f"{sys.argv[2]}: frames {var_points.shape} differ from the reference's {ref_points.shape}")
        length = np.maximum(strand_length_per_point(reference), 1e-9)
        errors = np.empty((ref_points.shape[0], ref_points.shape[1]), dtype=np.float64)
        for frame in range(ref_points.shape[0]):
            offset = var_points[frame].astype(np.float64) - ref_points[frame].astype(np.float64)
            errors[frame] = np.linalg.norm(offset, axis=1) / length
    if not np.all(np.isfinite(errors)):
        sys.exit(f"{sys.argv[2]}: non-finite points")
    print(f"{errors.mean():.5f},{np.percentile(errors, 95):.5f},{errors.max():.5f}")


if __name__ == "__main__":
    main()
