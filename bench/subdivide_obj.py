#!/usr/bin/python3
"""Midpoint subdivision of an OBJ mesh, to grow a hair mesh's vertex count for the scaling
bench without changing its shape: each quad becomes four quads (edge midpoints and the
face centre), each triangle four triangles; texture coordinates likewise.

    subdivide_obj.py IN.obj OUT.obj [LEVELS]

Only v, vt and f (v or v/vt) lines are kept, with the material library and each face's
material (mtllib, usemtl), so the painted texture still applies; LEVELS defaults to 1. Used by
bench/pipeline_scaling.sh."""
import sys


def subdivide(positions, uvs, faces, materials):
    """One level: positions and uvs are lists of tuples; faces lists of (v, vt|None) per
    corner, materials each face's material name (or None). Returns the new faces and theirs."""
    edge_point, edge_uv = {}, {}

    def midpoint(table, points, a, b):
        key = (min(a, b), max(a, b))
        if key not in table:
            points.append(tuple((x + y) / 2 for x, y in zip(points[a], points[b])))
            table[key] = len(points) - 1
        return table[key]

    def centre(points, corners):
        points.append(tuple(sum(c) / len(corners) for c in zip(*(points[i] for i in corners))))
        return len(points) - 1

    out, out_materials = [], []
    for face, material in zip(faces, materials):
        out_materials.extend([material] * (4 if len(face) == 3 else len(face)))
        n = len(face)
        vs = [v for v, _ in face]
        ts = [t for _, t in face]
        has_uv = all(t is not None for t in ts)
        mid_v = [midpoint(edge_point, positions, vs[i], vs[(i + 1) % n]) for i in range(n)]
        mid_t = [midpoint(edge_uv, uvs, ts[i], ts[(i + 1) % n]) for i in range(n)] if has_uv else [None] * n
        if n == 3:
            out.append([(vs[0], ts[0]), (mid_v[0], mid_t[0]), (mid_v[2], mid_t[2])])
            out.append([(mid_v[0], mid_t[0]), (vs[1], ts[1]), (mid_v[1], mid_t[1])])
            out.append([(mid_v[2], mid_t[2]), (mid_v[1], mid_t[1]), (vs[2], ts[2])])
            out.append([(mid_v[0], mid_t[0]), (mid_v[1], mid_t[1]), (mid_v[2], mid_t[2])])
            continue
        c_v = centre(positions, vs)
        c_t = centre(uvs, ts) if has_uv else None
        for i in range(n):
            out.append([(vs[i], ts[i]), (mid_v[i], mid_t[i]), (c_v, c_t), (mid_v[i - 1], mid_t[i - 1])])
    return out, out_materials


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    levels = int(sys.argv[3]) if len(sys.argv) == 4 else 1
    positions, uvs, faces, materials, libraries = [], [], [], [], []
    material = None
    with open(sys.argv[1]) as stream:
        for line in stream:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                positions.append(tuple(float(x) for x in words[1:4]))
            elif words[0] == "vt":
                uvs.append(tuple(float(x) for x in words[1:3]))
            elif words[0] == "mtllib":
                libraries.append(line.strip())
            elif words[0] == "usemtl":
                material = line.strip()
            elif words[0] == "f":
                corners = []
                for word in words[1:]:
                    parts = word.split("/")
                    corners.append((int(parts[0]) - 1, int(parts[1]) - 1 if len(parts) > 1 and parts[1] else None))
                faces.append(corners)
                materials.append(material)
    for _ in range(levels):
        faces, materials = subdivide(positions, uvs, faces, materials)
    with open(sys.argv[2], "w") as stream:
        stream.write(f"# {sys.argv[1]} subdivided {levels} times by bench/subdivide_obj.py\n")
        for p in positions:
            stream.write("v {:.6f} {:.6f} {:.6f}\n".format(*p))
        for t in uvs:
            stream.write("vt {:.6f} {:.6f}\n".format(*t))
        for library in libraries:
            stream.write(library + "\n")
        current = None
        for face, material in zip(faces, materials):
            if material != current and material is not None:
                stream.write(material + "\n")
                current = material
            stream.write("f " + " ".join(f"{v + 1}/{t + 1}" if t is not None else f"{v + 1}" for v, t in face) + "\n")


if __name__ == "__main__":
    main()
