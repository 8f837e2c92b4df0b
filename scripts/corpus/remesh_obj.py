#!/usr/bin/python3
"""Re-meshes a hair OBJ the way other artists' tools write the same hair, keeping its
geometry, texture coordinates and material (the truth is the mesh itself):

    remesh_obj.py IN.obj OUT.obj VARIANT

VARIANT:
  triangulated  every polygon split into triangles, quads along alternating diagonals
                (an exporter that writes triangles, as glTF and game engines do)
  reordered     the cards (connected patches) in a shuffled order, each face's corners
                rotated, and the vertices renumbered in order of first use (an exporter
                that rebuilds the vertex list, as assimp and many DCC tools do)
The shuffle is seeded by the file's name: the same input gives the same output.
Lines other than v, vt, f, usemtl and mtllib are dropped.
"""
import hashlib
import os
import random
import sys


def fail(message):
    print(f"remesh_obj: error: {message}", file=sys.stderr)
    sys.exit(2)


def read(path):
    v, vt, faces, mtllib, material = [], [], [], None, None
    for line in open(path, errors="replace"):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            v.append(w[1:4])
        elif w[0] == "vt":
            vt.append(w[1:3])
        elif w[0] == "f":
            corners = []
            for c in w[1:]:
                parts = c.split("/")
                corners.append((int(parts[0]) - 1, int(parts[1]) - 1 if len(parts) > 1 and parts[1] else -1))
            faces.append((material, corners))
        elif w[0] == "usemtl":
            material = w[1]
        elif w[0] == "mtllib":
            mtllib = line.split(None, 1)[1].strip()
    return v, vt, faces, mtllib


def patches(vertex_count, faces):
    parent = list(range(vertex_count))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for _, corners in faces:
        for c in corners[1:]:
            parent[find(c[0])] = find(corners[0][0])
    groups = {}
    for k, (_, corners) in enumerate(faces):
        groups.setdefault(find(corners[0][0]), []).append(k)
    return list(groups.values())


def main():
    if len(sys.argv) != 4 or sys.argv[3] not in ("triangulated", "reordered"):
        fail("usage: remesh_obj.py IN.obj OUT.obj triangulated|reordered")
    source, out_path, variant = sys.argv[1:]
    if not os.path.isfile(source):
        fail(f"{source}: no such file")
    v, vt, faces, mtllib = read(source)
    if not faces:
        fail(f"{source}: no faces")
    if variant == "triangulated":
        new_faces = []
        for k, (material, corners) in enumerate(faces):
            if len(corners) == 4 and k % 2 == 1:
                corners = corners[1:] + corners[:1]  # the other diagonal
            new_faces += [(material, [corners[0], corners[i], corners[i + 1]])
                          for i in range(1, len(corners) - 1)]
        vertex_order, uv_order = list(range(len(v))), list(range(len(vt)))
    else:
        rng = random.Random(int(hashlib.sha256(os.path.basename(source).encode()).hexdigest()[:8], 16))
        groups = patches(len(v), faces)
        rng.shuffle(groups)
        new_faces = []
        for group in groups:
            for k in group:
                material, corners = faces[k]
                r = rng.randrange(len(corners))
                new_faces.append((material, corners[r:] + corners[:r]))
        vertex_order, uv_order, seen_v, seen_t = [], [], set(), set()
        for _, corners in new_faces:
            for p, t in corners:
                if p not in seen_v:
                    seen_v.add(p)
                    vertex_order.append(p)
                if t >= 0 and t not in seen_t:
                    seen_t.add(t)
                    uv_order.append(t)
    v_number = {p: k + 1 for k, p in enumerate(vertex_order)}
    t_number = {t: k + 1 for k, t in enumerate(uv_order)}
    lines = [f"# {os.path.basename(source)} re-meshed: {variant} (scripts/corpus/remesh_obj.py)\n"]
    if mtllib:
        lines.append(f"mtllib {mtllib}\n")
    lines += [f"v {' '.join(v[p])}\n" for p in vertex_order]
    lines += [f"vt {' '.join(vt[t])}\n" for t in uv_order]
    material = None
    for m, corners in new_faces:
        if m != material and m is not None:
            lines.append(f"usemtl {m}\n")
            material = m
        lines.append("f " + " ".join(f"{v_number[p]}/{t_number[t]}" if t >= 0 else f"{v_number[p]}"
                                     for p, t in corners) + "\n")
    with open(out_path + ".part", "w") as f:
        f.writelines(lines)
    os.replace(out_path + ".part", out_path)


main()
