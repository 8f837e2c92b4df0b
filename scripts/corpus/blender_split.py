# Splits a character file (glTF/GLB/VRM, FBX, OBJ) into the two meshes the pipeline
# reads: the hair, as an OBJ with its MTL and its painted textures, and the body, as an
# OBJ. Run by scripts/corpus-prepare.sh through Debian's Blender:
#
#   blender --background --factory-startup --python scripts/corpus/blender_split.py -- \
#       INPUT OUT_DIR NAME --hair REGEX [--body REGEX] [--body-file FILE]... [--yaw-deg D]
#       [--scale S]
#
# The hair is every face of INPUT whose mesh object's name matches --hair (a Python
# regular expression, case-insensitive), or whose material's name does: a character
# whose hair cards share one mesh with its body is split by material. The body is every
# other face of INPUT whose object or material matches --body (default: every other
# face), and every mesh of each --body-file. Written in the
# pipeline's convention (data/samples/README.md): decimetres (--scale: the input's
# metres to decimetres, 10 by default), +Y up, the face towards +Z (--yaw-deg turns
# the model about +Y first, e.g. 180 for VRM 0.x avatars, which face -Z). Vertices,
# faces and texture coordinates are kept in the file's own order; objects are
# written in name order, so the output does not depend on the import's order.
#
# OUT_DIR/hair/NAME.obj, OUT_DIR/hair/NAME.mtl, OUT_DIR/hair/textures/NAME_<k>.<ext>
# (the embedded image's own bytes, or a copy of the file it names) and OUT_DIR/body.obj.
# Exits 2 with one line when nothing matches the hair.
import math
import os
import re
import shutil
import sys

import bpy
import numpy

# Debian's Blender 3.4 glTF importer still names numpy.bool, which NumPy 1.24 removed.
if "bool" not in numpy.__dict__:
    numpy.bool = bool


def fail(message):
    print(f"blender_split: error: {message}", file=sys.stderr)
    sys.exit(2)


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    import argparse
    parser = argparse.ArgumentParser(prog="blender_split.py")
    parser.add_argument("input")
    parser.add_argument("out_dir")
    parser.add_argument("name")
    parser.add_argument("--hair", required=True)
    parser.add_argument("--body", default="")
    parser.add_argument("--body-file", action="append", default=[])
    parser.add_argument("--yaw-deg", type=float, default=0.0)
    parser.add_argument("--scale", type=float, default=10.0)
    return parser.parse_args(argv)


def import_file(path, clear=True):
    if clear:
        bpy.ops.wm.read_factory_settings(use_empty=True)
    ext = os.path.splitext(path)[1].lower()
    if ext in (".glb", ".gltf", ".vrm"):
        bpy.ops.import_scene.gltf(filepath=path)
    elif ext == ".fbx":
        bpy.ops.import_scene.fbx(filepath=path)
    elif ext == ".obj":
        bpy.ops.wm.obj_import(filepath=path)
    else:
        fail(f"{path}: unsupported format {ext}")


def face_filter(obj, pattern):
    """Per material slot of obj, whether its faces match `pattern` (by the object's or
    the material's name); None where no face does."""
    rx = re.compile(pattern, re.IGNORECASE)
    slots = [bool(slot.material and rx.search(slot.material.name)) for slot in obj.material_slots]
    if any(slots):
        return slots
    if rx.search(obj.name) or (obj.data and rx.search(obj.data.name)):
        return [True] * max(1, len(obj.material_slots))
    return None


def complement(selected):
    return [not s for s in selected] if selected else None


def image_of(material):
    """The image feeding the material's base colour (through any nodes), or None."""
    if not material or not material.use_nodes:
        return None
    images = [n for n in material.node_tree.nodes if n.type == "TEX_IMAGE" and n.image]
    for node in images:
        for link in node.outputs["Color"].links:
            if link.to_socket.name in ("Base Color", "Color"):
                return node.image
    return images[0].image if images else None


def save_image(image, stem):
    """Writes the image's own bytes (packed or on disk) as stem.<ext>; returns the file name."""
    data = image.packed_file.data if image.packed_file else None
    if data is None:
        source = bpy.path.abspath(image.filepath)
        if not os.path.isfile(source):
            return None
        with open(source, "rb") as f:
            data = f.read()
    ext = ".png" if data[:8] == b"\x89PNG\r\n\x1a\n" else ".jpg" if data[:2] == b"\xff\xd8" else None
    if ext is None:
        return None
    with open(stem + ext, "wb") as f:
        f.write(data)
    return os.path.basename(stem + ext)


def world_to_pipeline(matrix, yaw_deg, scale):
    """Blender world (Z up) to the pipeline's frame (Y up, face +Z), scaled."""
    yaw = math.radians(yaw_deg)
    c, s = math.cos(yaw), math.sin(yaw)

    def convert(co):
        x, y, z = matrix @ co
        gx, gy, gz = x, z, -y  # glTF / OBJ axes: Y up
        return (scale * (c * gx + s * gz), scale * gy, scale * (-s * gx + c * gz))
    return convert


def write_obj(parts, path, yaw_deg, scale, mtl_name=None, material_names=None):
    """parts: (object, per-slot flags of the faces to write). Only the vertices those faces
    use are written, in the mesh's own order."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    lines = ["# written by scripts/corpus/blender_split.py\n"]
    if mtl_name:
        lines.append(f"mtllib {mtl_name}\n")
    v_base = vt_base = 1
    for obj, slots in parts:
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        convert = world_to_pipeline(obj.matrix_world, yaw_deg, scale)
        polygons = [p for p in mesh.polygons if slots[min(p.material_index, len(slots) - 1)]]
        used = sorted({mesh.loops[l].vertex_index for p in polygons for l in p.loop_indices})
        number = {v: k for k, v in enumerate(used)}
        lines.append(f"o {obj.name}\n")
        for v in used:
            lines.append("v %.6f %.6f %.6f\n" % convert(mesh.vertices[v].co))
        uv = mesh.uv_layers.active.data if (mtl_name and mesh.uv_layers.active) else None
        loops = [l for p in polygons for l in p.loop_indices]
        loop_number = {l: k for k, l in enumerate(loops)}
        if uv is not None:
            for l in loops:
                u, w = uv[l].uv
                lines.append("vt %.6f %.6f\n" % (u, w))
        current = None
        for poly in polygons:
            if mtl_name:
                slot = obj.material_slots[poly.material_index] if poly.material_index < len(obj.material_slots) else None
                name = material_names.get(slot.material.name if slot and slot.material else "", "none")
                if name != current:
                    lines.append(f"usemtl {name}\n")
                    current = name
            if uv is not None:
                corners = " ".join(f"{number[mesh.loops[l].vertex_index] + v_base}/{loop_number[l] + vt_base}"
                                   for l in poly.loop_indices)
            else:
                corners = " ".join(str(number[mesh.loops[l].vertex_index] + v_base) for l in poly.loop_indices)
            lines.append(f"f {corners}\n")
        v_base += len(used)
        if uv is not None:
            vt_base += len(loops)
        evaluated.to_mesh_clear()
    tmp = path + ".part"
    with open(tmp, "w") as f:
        f.writelines(lines)
    os.replace(tmp, path)


def main():
    args = arguments()
    if not os.path.isfile(args.input):
        fail(f"{args.input}: no such file")
    import_file(args.input)
    meshes = sorted((o for o in bpy.data.objects if o.type == "MESH"), key=lambda o: o.name)
    hair = [(o, f) for o in meshes for f in [face_filter(o, args.hair)] if f]
    if not hair:
        fail(f"{args.input}: no mesh or material matches --hair '{args.hair}' "
             f"(meshes: {', '.join(o.name for o in meshes)})")
    body = []
    for o in meshes:
        rest = complement(dict(hair).get(o)) or [True] * max(1, len(o.material_slots))
        if args.body:
            wanted = face_filter(o, args.body) or [False] * len(rest)
            rest = [a and b for a, b in zip(rest, wanted)]
        if any(rest):
            body.append((o, rest))
    for path in args.body_file:
        if not os.path.isfile(path):
            fail(f"{path}: no such file")
        before = set(bpy.data.objects)
        import_file(path, clear=False)
        body += [(o, [True] * max(1, len(o.material_slots)))
                 for o in sorted(set(bpy.data.objects) - before, key=lambda o: o.name) if o.type == "MESH"]
    if not body:
        fail(f"{args.input}: no body mesh (--body '{args.body}')")

    hair_dir = os.path.join(args.out_dir, "hair")
    textures = os.path.join(hair_dir, "textures")
    os.makedirs(textures, exist_ok=True)
    materials = sorted({s.material.name for o, f in hair for s, keep in zip(o.material_slots, f)
                        if s.material and keep})
    names, mtl = {}, []
    for k, material_name in enumerate(materials):
        material = bpy.data.materials[material_name]
        name = f"{args.name}_{k}"
        names[material_name] = name
        mtl.append(f"newmtl {name}\n")
        image = image_of(material)
        file_name = save_image(image, os.path.join(textures, name)) if image else None
        if file_name:
            mtl.append(f"map_Kd textures/{file_name}\n")
    with open(os.path.join(hair_dir, args.name + ".mtl"), "w") as f:
        f.writelines(mtl)
    write_obj(hair, os.path.join(hair_dir, args.name + ".obj"), args.yaw_deg, args.scale,
              mtl_name=args.name + ".mtl", material_names=names)
    write_obj(body, os.path.join(args.out_dir, "body.obj"), args.yaw_deg, args.scale)
    print(f"blender_split: {args.name}: hair {', '.join(o.name for o, _ in hair)}; "
          f"body {', '.join(o.name for o, _ in body)}")


main()
