#!/usr/bin/env python3
"""Converts guides.h5 (and optionally strands.h5, extract.h5) into the plain JSON and OBJ
that bench/blender_hair_dynamics.py reads inside Blender (whose Python may lack h5py).

  bench/blender_hair_input.py GUIDES_H5 -o OUT.json [--strands STRANDS_H5 --count N]
                              [--extract EXTRACT_H5 --body-obj OUT.obj]

OUT.json: {"fps", "substeps", "guide_ms_per_frame", "source", "rotations" [[w,x,y,z]
per frame], "translations" [[x,y,z] per frame], "strands" [[[x,y,z], ...] per hair]},
metres, Y up, frame 0 the rest state. The hairs are guides.h5's /guides/rest_points
polylines (every guide: strands and wisp centres), or with --strands, N grown strands of
strands.h5 taken evenly over its strand order (every len/N-th). --body-obj writes
extract.h5's /body (the body our simulate stage collides with) as an OBJ in metres.
"""
import argparse
import json

import h5py
import numpy as np


def polylines(points, offsets):
    return [points[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("guides")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--strands", help="strands.h5: take --count grown strands instead of the guides")
    ap.add_argument("--count", type=int, default=1000)
    ap.add_argument("--extract", help="extract.h5 whose /body --body-obj writes")
    ap.add_argument("--body-obj")
    a = ap.parse_args()
    with h5py.File(a.guides, "r") as g:
        out = {
            "fps": float(g.attrs["fps"]),
            "substeps": int(g.attrs["substeps"]),
            "guide_ms_per_frame": float(g.attrs.get("guide_ms_per_frame", -1.0)),
            "rotations": g["frames/head_rotation"][:].tolist(),
            "translations": g["frames/head_translation_m"][:].tolist(),
        }
        hairs = polylines(g["guides/rest_points"][:], g["guides/offsets"][:])
        out["source"] = "guides.h5 /guides/rest_points (%d guides)" % len(hairs)
    if a.strands:
        with h5py.File(a.strands, "r") as s:
            all_strands = polylines(s["strands/points"][:], s["strands/offsets"][:])
        pick = np.linspace(0, len(all_strands), a.count, endpoint=False).astype(int)
        hairs = [all_strands[i] for i in pick]
        out["source"] = "strands.h5 /strands/points: %d of %d grown strands, evenly over the strand order" % (
            len(hairs), len(all_strands))
    out["strands"] = [np.asarray(h, dtype=float).round(6).tolist() for h in hairs]
    with open(a.output, "w") as f:
        json.dump(out, f)
    if a.body_obj:
        with h5py.File(a.extract, "r") as e:
            v, t = e["body/vertices"][:], e["body/triangles"][:]
        with open(a.body_obj, "w") as f:
            f.writelines("v %.6f %.6f %.6f\n" % tuple(p) for p in v)
            f.writelines("f %d %d %d\n" % tuple(q + 1) for q in t)


if __name__ == "__main__":
    main()
