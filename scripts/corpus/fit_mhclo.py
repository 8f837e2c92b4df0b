#!/usr/bin/python3
"""Places a MakeHuman hair asset on the body it was made for: every vertex of the hair
OBJ becomes the weighted sum of three base-mesh vertices plus an offset scaled by the
body's proportions, as the asset's .mhclo file says (MakeHuman's clothes fitting). Every
other line of the OBJ (texture coordinates, faces, materials) is kept as it is, so the
vertex order and the faces are the artist's.

    fit_mhclo.py ASSET.mhclo ASSET.obj BODY.obj OUT.obj [--mtllib NAME] [--usemtl NAME]

BODY.obj: the hm08 base mesh, whose vertices are numbered as the base mesh's: its body
alone (data/makehuman/body.obj in ../shared, the base mesh's first 13,380 vertices) for
assets fitted to the body, or the whole base mesh with its helpers (base.obj) for assets
fitted to the hair helper. --mtllib replaces the OBJ's mtllib line (or adds
one); --usemtl puts every face under that material (MakeHuman's OBJs name none: their
material is the .mhclo's .mhmat). Exits 2 with one line on a file it cannot use.
"""
import argparse
import os
import sys


def fail(message):
    print(f"fit_mhclo: error: {message}", file=sys.stderr)
    sys.exit(2)


def obj_vertices(path):
    return [tuple(float(x) for x in line.split()[1:4]) for line in open(path, errors="replace")
            if line.startswith("v ")]


def read_mhclo(path):
    scales, shears, refs, reading = {}, {}, [], False
    for number, line in enumerate(open(path, errors="replace"), 1):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] in ("x_scale", "y_scale", "z_scale"):
            scales[words[0][0]] = (int(words[1]), int(words[2]), float(words[3]))
        elif words[0] in ("l_shear_x", "l_shear_y", "l_shear_z"):
            # MakeClothes 1's form: the two base vertices and their coordinates on the
            # base mesh along that axis; the factor is the same ratio as x_scale's.
            shears[words[0][-1]] = (int(words[1]), int(words[2]), abs(float(words[3]) - float(words[4])))
        elif words[0] == "verts":
            reading = True
        elif reading and words[0][0].isdigit():
            if len(words) == 1:
                refs.append(((int(words[0]), 0, 0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
            elif len(words) >= 9:
                refs.append((tuple(int(w) for w in words[0:3]), tuple(float(w) for w in words[3:6]),
                             tuple(float(w) for w in words[6:9])))
            else:
                fail(f"{path}:{number}: a vertex line needs 1 or 9 numbers")
        elif reading:
            reading = False
    for axis in "xyz":
        if axis not in scales and axis in shears:
            scales[axis] = shears[axis]
    if set(scales) != {"x", "y", "z"}:
        fail(f"{path}: x_scale, y_scale and z_scale (or l_shear_x, _y, _z) are required")
    return scales, refs


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mhclo")
    parser.add_argument("obj")
    parser.add_argument("body")
    parser.add_argument("out")
    parser.add_argument("--mtllib")
    parser.add_argument("--usemtl")
    args = parser.parse_args()
    for path in (args.mhclo, args.obj, args.body):
        if not os.path.isfile(path):
            fail(f"{path}: no such file")
    scales, refs = read_mhclo(args.mhclo)
    body = obj_vertices(args.body)
    hair_count = len(obj_vertices(args.obj))
    if len(refs) != hair_count:
        fail(f"{args.mhclo}: {len(refs)} fitted vertices for the {hair_count} of {args.obj}")
    top = max(max(r[0]) for r in refs)
    top = max(top, *(max(s[0], s[1]) for s in scales.values()))
    if top >= len(body):
        fail(f"{args.mhclo}: base vertex {top} is beyond the {len(body)} of {args.body}")
    scale = [abs(body[scales[a][0]][k] - body[scales[a][1]][k]) / scales[a][2]
             for k, a in enumerate("xyz")]
    fitted = []
    for (ids, weights, offset) in refs:
        fitted.append(tuple(sum(w * body[i][k] for i, w in zip(ids, weights)) + offset[k] * scale[k]
                            for k in range(3)))
    out, k, wrote_mtllib, wrote_usemtl = [], 0, False, False
    for line in open(args.obj, errors="replace"):
        if line.startswith("v "):
            out.append("v %.6f %.6f %.6f\n" % fitted[k])
            k += 1
        elif line.startswith("vn "):
            continue  # normals of the unfitted mesh; extract computes its own
        elif line.startswith("usemtl") and args.usemtl:
            continue  # one material for the whole asset, written before its first face
        elif line.startswith("f ") and args.usemtl and not wrote_usemtl:
            out += [f"usemtl {args.usemtl}\n", line]
            wrote_usemtl = True
        elif line.startswith("mtllib") and args.mtllib:
            out.append(f"mtllib {args.mtllib}\n")
            wrote_mtllib = True
        else:
            out.append(line)
    if args.mtllib and not wrote_mtllib:
        out.insert(0, f"mtllib {args.mtllib}\n")
    with open(args.out + ".part", "w") as f:
        f.writelines(out)
    os.replace(args.out + ".part", args.out)


main()
