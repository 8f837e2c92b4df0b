# Run inside Debian's Blender, headless, by tests/stage/test_blender_addon.cpp
# (BlenderAddon.ConvertsFixesAndBakesFromThePanelsOperators):
#
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/check_addon.py \
#     -- ADDON_DIR BIN_DIR SAMPLES_DIR WORK_DIR
#
# Drives the hairstyle_io add-on's panel operators as a user would, synchronously (no
# window): opens the body and ponytail01's hair cards from their OBJ files, Converts them
# (the stages of BIN_DIR, found through the add-on's preferences) and finds 10,000 strands
# with styles on the cards; pins one cluster's style and sees classify rerun alone (file
# modification times); bakes 11 frames under an animated object's motion and finds them
# on the curves; a Cancel pressed during grow leaves no output and no temporary file; a
# missing binary, and a stage's failure, give one report line. Prints "check: ..." lines
# and the seconds Convert took; any failure raises (exit 1). Writes only under WORK_DIR.

import math
import os
import shutil
import sys
import time

import bpy
import numpy as np

addon_dir, bin_dir, samples_dir, work_dir = sys.argv[sys.argv.index("--") + 1:]
sys.dont_write_bytecode = True  # nothing written into the source tree
sys.path.insert(0, addon_dir)

import addon_utils  # noqa: E402
import h5py  # noqa: E402

addon_utils.enable("hairstyle_io", default_set=True)
from hairstyle_io import hdf5_files, operators, runner, scene, stages  # noqa: E402

CONVERTED = list(stages.CONVERTED)


def check(condition, message):
    if not condition:
        raise AssertionError(message)
    print("check:", message, flush=True)


def preferences():
    return bpy.context.preferences.addons["hairstyle_io"].preferences


def leftovers(folder):
    """Temporary files and work folders anywhere under `folder`."""
    found = []
    for root, folders, files in os.walk(folder):
        found += [os.path.join(root, name) for name in folders + files
                  if name.startswith(runner.WORK_PREFIX) or ".tmp" in name]
    return found


def modification_times(folder):
    return {name: os.stat(os.path.join(folder, name)).st_mtime_ns
            for name in os.listdir(folder) if os.path.isfile(os.path.join(folder, name))}


def curve_values(curves_object, name, kind=np.int32):
    data = curves_object.data.attributes[name].data
    values = np.empty(len(data), dtype=kind)
    data.foreach_get("value", values)
    return values


def curve_points(curves_object):
    points = np.empty(len(curves_object.data.points) * 3, dtype=np.float32)
    curves_object.data.position_data.foreach_get("vector", points)
    return points.reshape(-1, 3)


def import_obj(path):
    bpy.ops.object.select_all(action="DESELECT")
    bpy.ops.wm.obj_import(filepath=path)
    imported = bpy.context.selected_objects
    check(len(imported) == 1 and imported[0].type == "MESH", f"{os.path.basename(path)} opens")
    return imported[0]


def convert():
    """Convert through its operator; its report (an ERROR raises RuntimeError)."""
    return bpy.ops.hairstyle.convert()


def one_report_line(call, why):
    try:
        call()
    except RuntimeError as error:
        text = str(error)
        lines = [line for line in text.splitlines() if line.strip()]
        check(len(lines) == 1 and lines[0].startswith("Error: "),
              f"{why}: one report line ({lines[0] if lines else text!r})")
        return lines[0]
    raise AssertionError(f"{why}: no error reported")


# -- the scene: the body and ponytail01's cards, MakeHuman's decimetres ----------------
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
body = import_obj(os.path.join(samples_dir, "body.obj"))
hair = import_obj(os.path.join(samples_dir, "hair", "ponytail01.obj"))
preferences().bin_folder = bin_dir
settings = bpy.context.scene.hairstyle
settings.hair_mesh, settings.body_mesh = hair, body
settings.unit_scale, settings.strand_count = 0.1, 10000
folder = os.path.join(work_dir, "ponytail01")
settings.folder = folder

# -- Convert ------------------------------------------------------------------------------
started = time.monotonic()
check(convert() == {"FINISHED"}, "Convert finishes")
print(f"convert: ponytail01 took {time.monotonic() - started:.2f} s", flush=True)
check(all(os.path.isfile(os.path.join(folder, name)) for name in CONVERTED) and
      os.path.isfile(os.path.join(folder, stages.HAIR_OBJ)) and
      os.path.isfile(os.path.join(folder, stages.BODY_OBJ)),
      "the folder holds extract.h5 to styles.h5 and the meshes written for extract")
check(not leftovers(work_dir), "no temporary file is left")
curves = settings.result_hair
check(curves is not None and curves.type == "CURVES" and len(curves.data.curves) == 10000,
      "10,000 strands as hair curves")
with h5py.File(os.path.join(folder, "strands.h5"), "r") as file:
    points = file["/strands/points"][()]
    strand_cluster = file["/strands/strand_attributes/cluster"][()]
    point_cluster = file["/strands/point_attributes/cluster"][()]
with h5py.File(os.path.join(folder, "styles.h5"), "r") as file:
    cluster_style = file["/clusters/style"][()].astype(np.int32)
    confidence = file["/clusters/confidence"][()]
    unsure = file["/clusters/unsure"][()]
check(np.array_equal(curve_points(curves), scene.to_blender_axes(points)),
      f"every one of the {len(points)} points where strands.h5 has it")
style = curve_values(curves, "style")
check(np.array_equal(style, cluster_style[strand_cluster]) and np.all((style >= 0) & (style <= 3)),
      "every strand has its cluster's style (normal, fixed, short or braided)")
colour = curves.data.attributes["style_colour"]
colours = np.empty(len(colour.data) * 4, dtype=np.float32)
colour.data.foreach_get("color", colours)
paper = np.array([hdf5_files.STYLE_COLOURS[k] for k in range(-1, 4)], dtype=np.float32)
expected = paper[cluster_style[point_cluster] + 1]
pale = unsure[point_cluster] != 0
expected[pale] = 0.5 * expected[pale] + 0.5  # unsure clusters pale
check(colour.domain == "POINT" and np.allclose(colours.reshape(-1, 4)[:, :3], expected) and
      curves.active_material is not None and curves.active_material.name == "hairstyle styles",
      "every point is coloured in the paper's colour of its own cluster's style")
names = {0: "normal", 1: "fixed", 2: "short", 3: "braided"}
listed = [(item.cluster, item.style, round(item.confidence, 5), item.unsure) for item in settings.clusters]
check(listed == [(c, names[int(cluster_style[c])], round(float(confidence[c]), 5), bool(unsure[c]))
                 for c in range(len(cluster_style))],
      f"the panel lists the {len(listed)} clusters with style, confidence and unsure")
# The results lie on the cards they came from: the body in the scene's decimetres.
source = np.array([body.matrix_world @ v.co for v in body.data.vertices])
result = np.array([settings.result_body.matrix_world @ v.co for v in settings.result_body.data.vertices])
check(np.allclose(source.min(axis=0), result.min(axis=0), atol=1e-3) and
      np.allclose(source.max(axis=0), result.max(axis=0), atol=1e-3),
      "the converted body lies on the body it came from (unit scale 0.1)")

# -- Fix style: classify reruns, nothing before it ---------------------------------------
before = modification_times(folder)
cluster = int(np.argmax([item.strand_count for item in settings.clusters]))
old = settings.clusters[cluster].style
new = "braided" if old != "braided" else "normal"
time.sleep(0.01)  # distinct modification times
check(bpy.ops.hairstyle.fix_style(cluster=cluster, style=new) == {"FINISHED"},
      f"Fix style pins cluster {cluster} ({old}) to {new}")
after = modification_times(folder)
changed = sorted(name for name in after if before.get(name) != after[name])
check(changed == ["overrides.toml", "styles.h5"],
      f"only classify reran: of {', '.join(sorted(after))} only the overrides file and "
      f"styles.h5 changed")
with h5py.File(os.path.join(folder, "styles.h5"), "r") as file:
    pinned = file["/clusters/pinned"][()]
    cluster_style = file["/clusters/style"][()].astype(np.int32)
check(pinned[cluster] == 1 and pinned.sum() == 1 and names[int(cluster_style[cluster])] == new,
      f"styles.h5 has cluster {cluster} pinned {new}")
check(settings.clusters[cluster].pinned and settings.clusters[cluster].style == new,
      "the panel lists it pinned, with its new style")
check(np.array_equal(curve_values(curves, "style"), cluster_style[strand_cluster]),
      "the curves show the new styles")

# -- Simulate and bake: 11 frames under an animated object's motion ----------------------
head = bpy.data.objects.new("head motion", None)
bpy.context.scene.collection.objects.link(head)
bpy.context.scene.frame_start = 1
for frame, angle in ((1, 0.0), (12, 20.0)):
    head.rotation_euler = (0.0, 0.0, math.radians(angle))
    head.keyframe_insert("rotation_euler", frame=frame)
settings.motion, settings.motion_object = "OBJECT", head
settings.bake_first, settings.bake_end = 0, 11
before = modification_times(folder)
check(bpy.ops.hairstyle.bake() == {"FINISHED"}, "Simulate and bake finishes")
after = modification_times(folder)
check(sorted(name for name in after if before.get(name) != after[name]) ==
      ["frames.h5", "guides.h5", "keyframes.csv"],
      "it wrote guides.h5, frames.h5 and the motion's keyframes, nothing else")
frames_path = os.path.join(folder, "frames.h5")
with h5py.File(frames_path, "r") as file:
    frame_points = file["/frames/points"]
    check(frame_points.shape[0] == 11, "frames.h5 holds 11 frames")
    fifth = frame_points[5]
    head_rotation = file["/frames/head_rotation"][()]
    head_translation = file["/frames/head_translation_m"][()]
check(curves.get(scene.FRAMES_PATH_PROPERTY) == os.path.abspath(frames_path) and
      curves.get(scene.FRAMES_COUNT_PROPERTY) == 11 and
      (bpy.context.scene.frame_start, bpy.context.scene.frame_end) == (1, 11),
      "the curves play the 11 frames, Blender frames 1 to 11")
bpy.context.scene.frame_set(6)
check(np.array_equal(curve_points(curves), scene.to_blender_axes(fifth)),
      "Blender frame 6 shows the simulation's frame 5 on the curves")
expected = scene.head_matrix(head_rotation[5], head_translation[5])
check(np.allclose(np.array(settings.result_body.matrix_basis), expected, atol=1e-6),
      "the converted body moves with the head of frame 5")
from mathutils import Quaternion  # noqa: E402
turned = np.array(Quaternion(head_rotation[10].tolist()).to_matrix())
yaw = math.degrees(math.atan2(turned[0, 2], turned[2, 2]))
keyed = head.animation_data.action.fcurves.find("rotation_euler", index=2)
expected_yaw = math.degrees(keyed.evaluate(11))  # Blender frame 11 is the simulation's 10
check(expected_yaw > 10.0 and abs(yaw - expected_yaw) < 1e-3,
      f"the head turned with the object: yaw {yaw:.3f} degrees at frame 10 (the object's "
      f"{expected_yaw:.3f})")

# -- Cancel during grow: no output, no temporary file, no stage left running -------------
cancelled_folder = os.path.join(work_dir, "cancelled")
settings.folder = cancelled_folder
seen = {}


def cancel_in_grow(chain):
    if chain.stage == "grow" and "pid" not in seen:
        seen["pid"] = chain._process.pid
        bpy.ops.hairstyle.cancel()


operators.progress_listeners.append(cancel_in_grow)
try:
    check(convert() == {"CANCELLED"}, "Convert cancelled during grow")
finally:
    operators.progress_listeners.remove(cancel_in_grow)
check("pid" in seen, "Cancel was pressed while grow ran")
check(not os.path.exists(cancelled_folder), "no output: the folder it was writing is gone")
check(not leftovers(work_dir), "no temporary file anywhere")
try:
    os.kill(seen["pid"], 0)
    raise AssertionError("grow still runs after Cancel")
except ProcessLookupError:
    check(True, "grow was stopped")
check(settings.result_hair == curves and settings.result_folder == folder,
      "the scene keeps the last conversion")

# -- Errors: one report line -------------------------------------------------------------
partial = os.path.join(work_dir, "bin_without_grow")
os.makedirs(partial)
for name in os.listdir(bin_dir):
    if name != "grow":
        os.symlink(os.path.join(bin_dir, name), os.path.join(partial, name))
preferences().bin_folder = partial
os.environ["PATH"] = os.pathsep.join(p for p in os.environ.get("PATH", "").split(os.pathsep)
                                     if not os.path.exists(os.path.join(p, "grow")))
settings.folder = os.path.join(work_dir, "no_grow")
line = one_report_line(convert, "a missing binary")
check(" grow " in line and "extract" not in line and "make -f Makefile.pipeline build" in line,
      "it names the missing grow and how to build it")
check(not os.path.exists(settings.folder), "and writes nothing")

preferences().bin_folder = bin_dir
bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.0))
settings.hair_mesh = bpy.context.active_object
settings.folder = os.path.join(work_dir, "cube")
line = one_report_line(convert, "a stage's failure (a cube as the hair)")
check(line.startswith("Error: grow: error: ") and "scalp" in line,
      "it is the stage's own error line")
check(not os.path.exists(settings.folder) and not leftovers(work_dir), "and nothing is left")
shutil.rmtree(partial)
print("check: all passed")
