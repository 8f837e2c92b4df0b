# Renders a hair mesh with its painted texture over its body, as an artist sees it in a
# viewport: front, side and back views side by side in one PNG, framed on the hair.
# Cycles on the CPU, few samples: a picture to look at, not a final render.
#
#   blender --background --factory-startup --python scripts/corpus/blender_mesh_views.py -- \
#       HAIR_OBJ BODY_OBJ OUT_PNG [--size PX] [--samples N]
#
# The OBJ files are in the pipeline's convention (+Y up, the face towards +Z); a
# material's image alpha is its coverage, as extract reads it (map_d, or the alpha of
# map_Kd). The views match hair-render's: front (from +Z), side (from +X), back (from -Z).
import argparse
import math
import os
import sys

import bpy
import numpy
from mathutils import Vector


def fail(message):
    print(f"blender_mesh_views: error: {message}", file=sys.stderr)
    sys.exit(2)


def arguments():
    parser = argparse.ArgumentParser(prog="blender_mesh_views.py")
    parser.add_argument("hair")
    parser.add_argument("body")
    parser.add_argument("out")
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--samples", type=int, default=8)
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])


def import_obj(path):
    before = set(bpy.data.objects)
    bpy.ops.wm.obj_import(filepath=path)
    return [o for o in bpy.data.objects if o not in before]


def use_texture_alpha(objects):
    """Every hair material shows its image's alpha as coverage, both sides drawn."""
    for obj in objects:
        for slot in obj.material_slots:
            material = slot.material
            if not material or not material.use_nodes:
                continue
            nodes, links = material.node_tree.nodes, material.node_tree.links
            bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
            image = next((n for n in nodes if n.type == "TEX_IMAGE" and n.image), None)
            if bsdf and image and not bsdf.inputs["Alpha"].is_linked:
                links.new(image.outputs["Alpha"], bsdf.inputs["Alpha"])
            if bsdf:
                bsdf.inputs["Specular"].default_value = 0.1
            material.blend_method = "HASHED"
            material.use_backface_culling = False


def grey_body(objects):
    material = bpy.data.materials.new("body grey")
    material.diffuse_color = (0.55, 0.55, 0.55, 1)
    material.use_nodes = True
    bsdf = material.node_tree.nodes.get("Principled BSDF")
    bsdf.inputs["Base Color"].default_value = (0.55, 0.55, 0.55, 1)
    for obj in objects:
        obj.data.materials.clear()
        obj.data.materials.append(material)


def bounds(objects):
    corners = [obj.matrix_world @ Vector(c) for obj in objects for c in obj.bound_box]
    lo = Vector((min(c[i] for c in corners) for i in range(3)))
    hi = Vector((max(c[i] for c in corners) for i in range(3)))
    return lo, hi


def render_view(scene, camera, centre, extent, direction, size, path):
    # direction: where the camera stands, in Blender axes (Z up; the face looks -Y).
    camera.location = centre + direction * 10
    camera.rotation_euler = direction.to_track_quat("Z", "Y").to_euler()
    camera.data.ortho_scale = extent
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = numpy.array(image.pixels[:], dtype=numpy.float32).reshape(size, size, 4)
    bpy.data.images.remove(image)
    os.remove(path)
    return pixels


def main():
    args = arguments()
    for path in (args.hair, args.body):
        if not os.path.isfile(path):
            fail(f"{path}: no such file")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    hair = import_obj(args.hair)
    body = import_obj(args.body)
    use_texture_alpha(hair)
    grey_body(body)

    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args.samples
    scene.cycles.use_denoising = False
    scene.cycles.max_bounces = 4
    scene.cycles.transparent_max_bounces = 32
    scene.render.resolution_x = scene.render.resolution_y = args.size
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"
    scene.world = bpy.data.worlds.new("white")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (1, 1, 1, 1)
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    sun.data.energy = 2.0
    sun.rotation_euler = (math.radians(40), 0, math.radians(-30))
    scene.collection.objects.link(sun)
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.data.type = "ORTHO"
    scene.collection.objects.link(camera)
    scene.camera = camera

    lo, hi = bounds(hair)
    centre = (lo + hi) / 2
    extent = max(hi - lo) * 1.16
    views = [Vector((0, -1, 0)), Vector((1, 0, 0)), Vector((0, 1, 0))]  # front, side, back
    tmp = args.out + ".view.png"
    tiles = [render_view(scene, camera, centre, extent, v, args.size, tmp) for v in views]
    sheet = numpy.concatenate(tiles, axis=1)
    out = bpy.data.images.new("views", width=sheet.shape[1], height=sheet.shape[0], alpha=True)
    out.pixels.foreach_set(sheet.ravel())
    out.filepath_raw = args.out + ".part.png"
    out.file_format = "PNG"
    out.save()
    os.replace(args.out + ".part.png", args.out)


main()
