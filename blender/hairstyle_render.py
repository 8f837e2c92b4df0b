# Renders the pipeline's hair with Blender's Cycles on the CPU, headless (docs/blender.md):
#
#   blender -b --python blender/hairstyle_render.py -- strands OUT/m/strands.h5 OUT/m/render.png
#   blender -b --python blender/hairstyle_render.py -- frames OUT/m/frames.h5 OUT/m/clip.mp4 [--end 30]
#
# The strands as hair curves (the hairstyle_io add-on) shaded with the Principled Hair
# BSDF (dark brown by its melanin, or in the paper's style colours with --styles), each
# strand tapering from `--root-width-mm` at the root to a third of it at the tip, beside
# the body from extract.h5 in a matte grey; three views of the head (front, side, back)
# side by side for a still, the side view for a clip. Settings kept low so that a still
# of a sample renders in under a minute on 2 cores: --samples (16), --size (360 pixels a
# view). A file the add-on refuses: one line on stderr, exit 2.

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Vector  # noqa: E402

import hairstyle_io  # noqa: E402
from hairstyle_io.hdf5_files import HairstyleFileError  # noqa: E402


def parse(argv):
    parser = argparse.ArgumentParser(prog="hairstyle_render.py")
    parser.add_argument("kind", choices=["strands", "frames"])
    parser.add_argument("path", help="strands.h5 or frames.h5 (extract.h5 and styles.h5 beside it)")
    parser.add_argument("output", help="a .png still, or for frames an .mp4 clip")
    parser.add_argument("--samples", type=int, default=16)
    parser.add_argument("--size", type=int, default=360, help="pixels of a view, square")
    parser.add_argument("--root-width-mm", type=float, default=0.5)
    parser.add_argument("--styles", action="store_true",
                        help="colour the hair in the paper's style colours instead of brown")
    parser.add_argument("--first", type=int, default=0, help="frames: the first frame")
    parser.add_argument("--end", type=int, default=None, help="frames: one past the last")
    return parser.parse_args(argv)


def empty_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)


def hair_material(by_style):
    material = bpy.data.materials.new("hair")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    hair = nodes.new("ShaderNodeBsdfHairPrincipled")
    if by_style:
        hair.parametrization = "COLOR"
        colour = nodes.new("ShaderNodeAttribute")
        colour.attribute_name = "style_colour"
        links.new(colour.outputs["Color"], hair.inputs["Color"])
    else:
        hair.parametrization = "MELANIN"
        hair.inputs["Melanin"].default_value = 0.8
        hair.inputs["Melanin Redness"].default_value = 0.4
    hair.inputs["Roughness"].default_value = 0.3
    links.new(hair.outputs["BSDF"], output.inputs["Surface"])
    return material


def body_material():
    material = bpy.data.materials.new("body")
    material.use_nodes = True
    principled = material.node_tree.nodes["Principled BSDF"]
    principled.inputs["Base Color"].default_value = (0.45, 0.43, 0.42, 1)
    principled.inputs["Roughness"].default_value = 0.8
    return material


def taper(curves_object, root_width_m):
    """Per point radius: root_width / 2 at the root down to a third of it at the tip."""
    curves = curves_object.data
    offsets = np.empty(len(curves.curves) + 1, dtype=np.int32)
    curves.curve_offset_data.foreach_get("value", offsets)
    radius = np.empty(len(curves.points), dtype=np.float32)
    for s in range(len(offsets) - 1):
        first, end = offsets[s], offsets[s + 1]
        t = np.linspace(0.0, 1.0, end - first, dtype=np.float32)
        radius[first:end] = 0.5 * root_width_m * (1 - 2 * t / 3)
    attribute = curves.attributes.get("radius") or curves.attributes.new("radius", "FLOAT", "POINT")
    attribute.data.foreach_set("value", radius)


def frame_the_head(curves_object, views, size):
    """Cameras looking at the hair's bounding box from the front, side and back."""
    points = np.empty(len(curves_object.data.points) * 3, dtype=np.float32)
    curves_object.data.position_data.foreach_get("vector", points)
    points = points.reshape(-1, 3)
    low, high = points.min(axis=0), points.max(axis=0)
    centre = Vector(((low + high) / 2).tolist())
    extent = float(np.max(high - low)) * 1.15
    cameras = []
    for name, azimuth in views:
        data = bpy.data.cameras.new(name)
        data.type = "ORTHO"
        data.ortho_scale = extent
        camera = bpy.data.objects.new(name, data)
        bpy.context.scene.collection.objects.link(camera)
        # Front: looking along +Y (Blender's -Y is the face's side after the axis turn).
        direction = Vector((math.sin(azimuth), -math.cos(azimuth), 0.0))
        camera.location = centre + direction * (3 * extent)
        camera.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
        cameras.append(camera)
    return cameras, centre, extent


def lights(centre, extent):
    for name, offset, energy in [("key", (1.0, -1.5, 1.5), 25.0), ("fill", (-1.5, -0.5, 0.5), 8.0),
                                 ("rim", (0.0, 1.5, 1.0), 30.0)]:
        data = bpy.data.lights.new(name, "AREA")
        data.energy = energy * extent * extent / 0.04
        data.size = extent
        light = bpy.data.objects.new(name, data)
        light.location = centre + Vector(offset) * (2 * extent)
        light.rotation_euler = (centre - light.location).to_track_quat("-Z", "Y").to_euler()
        bpy.context.scene.collection.objects.link(light)
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1, 1, 1, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
    bpy.context.scene.world = world


def cycles(scene, samples, size):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.cycles.max_bounces = 6
    scene.cycles.transparent_max_bounces = 4
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.threads_mode = "AUTO"


def render_still(cameras, output, size):
    scene = bpy.context.scene
    views = []
    for camera in cameras:
        scene.camera = camera
        path = output + f".{camera.name}.png"
        scene.render.filepath = path
        scene.render.image_settings.file_format = "PNG"
        bpy.ops.render.render(write_still=True)
        views.append(path)
    # Side by side into one PNG.
    images = [bpy.data.images.load(path) for path in views]
    width = sum(image.size[0] for image in images)
    height = max(image.size[1] for image in images)
    pixels = np.ones((height, width, 4), dtype=np.float32)
    x = 0
    for image in images:
        w, h = image.size
        data = np.array(image.pixels[:], dtype=np.float32).reshape(h, w, 4)
        pixels[:h, x:x + w] = data
        x += w
    combined = bpy.data.images.new("combined", width, height, alpha=True)
    combined.pixels = pixels.ravel()
    combined.filepath_raw = output
    combined.file_format = "PNG"
    combined.save()
    for path in views:
        os.remove(path)


def main(argv):
    args = parse(argv)
    empty_scene()
    folder = os.path.dirname(os.path.abspath(args.path))
    extract = os.path.join(folder, "extract.h5")
    try:
        if args.kind == "strands":
            hair = hairstyle_io.import_strands(args.path, with_neighbours=True, name="hair")
        else:
            hair = hairstyle_io.import_frames(args.path, args.first, args.end, name="hair",
                                              extract_path=extract if os.path.exists(extract) else None)
    except HairstyleFileError as error:
        print(f"hairstyle_render: error: {error}", file=sys.stderr)
        return 2
    if args.styles and "style_colour" not in hair.data.attributes:
        print("hairstyle_render: error: --styles needs styles.h5 beside the strands", file=sys.stderr)
        return 2
    taper(hair, args.root_width_mm / 1000)
    hair.data.materials.append(hair_material(args.styles))
    body = bpy.data.objects.get("hair body")
    if body is not None:
        body.data.materials.append(body_material())
    scene = bpy.context.scene
    cycles(scene, args.samples, args.size)
    if args.kind == "strands":
        cameras, centre, extent = frame_the_head(
            hair, [("front", 0.0), ("side", math.pi / 2), ("back", math.pi)], args.size)
        lights(centre, extent)
        render_still(cameras, os.path.abspath(args.output), args.size)
    else:
        cameras, centre, extent = frame_the_head(hair, [("side", math.pi / 2)], args.size)
        lights(centre, extent)
        scene.camera = cameras[0]
        scene.render.image_settings.file_format = "FFMPEG"
        scene.render.ffmpeg.format = "MPEG4"
        scene.render.ffmpeg.codec = "H264"
        scene.render.filepath = os.path.abspath(args.output)
        bpy.ops.render.render(animation=True)
    print(f"hairstyle_render: wrote {args.output}")
    return 0


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    status = main(argv)
    if status:
        sys.exit(status)
