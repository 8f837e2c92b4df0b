# Run inside Debian's Blender, headless, by tests/stage/test_interpolate_cli.cpp
# (InterpolateCli.BlenderImportsEveryStrandPointAndFrame):
#
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/check_import.py \
#     -- ADDON_DIR STRANDS_H5 STYLES_H5 EXTRACT_H5 FRAMES_H5 OBJ_FILE GUIDES_H5
#
# Imports the files through the hairstyle_io add-on and Blender's own OBJ importer and
# checks every strand and point against the HDF5 files read with h5py; refused files
# must leave the scene as it was. Prints "check: ..." lines; any failure raises (exit 1).

import os
import sys

import bpy
import numpy as np

arguments = sys.argv[sys.argv.index("--") + 1:]
addon_dir, strands_path, styles_path, extract_path, frames_path, obj_path, guides_path = arguments
sys.path.insert(0, addon_dir)

import h5py  # noqa: E402
import hairstyle_io  # noqa: E402
from hairstyle_io import hdf5_files, scene  # noqa: E402


def check(condition, message):
    if not condition:
        raise AssertionError(message)
    print("check:", message)


def curve_points(curves_object):
    curves = curves_object.data
    points = np.empty(len(curves.points) * 3, dtype=np.float32)
    curves.position_data.foreach_get("vector", points)
    offsets = np.empty(len(curves.curves) + 1, dtype=np.int32)
    curves.curve_offset_data.foreach_get("value", offsets)
    return points.reshape(-1, 3), offsets


def attribute(curves_object, name):
    data = curves_object.data.attributes[name].data
    values = np.empty(len(data), dtype=np.int32)
    data.foreach_get("value", values)
    return values


# The schema versions the add-on reads are the repository's.
import json  # noqa: E402
for schema, version in hdf5_files.SCHEMA_VERSIONS.items():
    name = schema.split(".")[1]
    with open(os.path.join(addon_dir, "..", "schemas", name + ".json")) as text:
        declared = json.load(text)
    check(declared["name"] == schema and declared["version"] == version,
          f"the add-on reads {schema} version {version}, as schemas/{name}.json says")

for obj in list(bpy.data.objects):  # an empty scene (the factory one has a cube)
    bpy.data.objects.remove(obj, do_unlink=True)

# strands.h5, with styles.h5 and extract.h5.
with h5py.File(strands_path, "r") as file:
    points = file["/strands/points"][()]
    offsets = file["/strands/offsets"][()]
    cluster = file["/strands/strand_attributes/cluster"][()]
with h5py.File(styles_path, "r") as file:
    cluster_style = file["/clusters/style"][()].astype(np.int32)
strands = hairstyle_io.import_strands(strands_path, styles_path, extract_path, name="strands")
got, got_offsets = curve_points(strands)
check(strands.type == "CURVES", "strands.h5 becomes a hair curves object")
check(np.array_equal(got_offsets, offsets), f"{len(offsets) - 1} strands, each with its points")
check(np.array_equal(got, scene.to_blender_axes(points)),
      f"all {len(points)} points where strands.h5 has them (+Y up to +Z up)")
check(np.array_equal(attribute(strands, "cluster"), cluster), "every strand's cluster")
check(np.array_equal(attribute(strands, "style"), cluster_style[cluster]),
      "every strand's style, its cluster's in styles.h5")
body = bpy.data.objects.get("strands body")
with h5py.File(extract_path, "r") as file:
    body_vertices = file["/body/vertices"].shape[0]
check(body is not None and len(body.data.vertices) == body_vertices,
      f"the body from extract.h5, {body_vertices} vertices")

# Refused files leave the scene as it was.
before = (len(bpy.data.objects), len(bpy.data.hair_curves), len(bpy.data.meshes),
          len(bpy.data.curves))
for bad, why in [(styles_path, "a styles.h5 given as strands"),
                 (os.path.join(os.path.dirname(strands_path), "missing.h5"), "a missing file")]:
    try:
        hairstyle_io.import_strands(bad)
        raise AssertionError(f"{why} was imported")
    except hdf5_files.HairstyleFileError as error:
        check("\n" not in str(error) and (bad in str(error)), f"{why}: refused in one line ({error})")
after = (len(bpy.data.objects), len(bpy.data.hair_curves), len(bpy.data.meshes),
         len(bpy.data.curves))
check(before == after, "nothing half-built in the scene after the refusals")

# frames.h5: frame 0, then the third frame through the frame handler; the body with the
# head.
frames = hairstyle_io.import_frames(frames_path, 0, 3, name="frames", extract_path=extract_path)
with h5py.File(frames_path, "r") as file:
    frame_points = [file["/frames/points"][k] for k in range(3)]
    head_rotation = file["/frames/head_rotation"][()]
    head_translation = file["/frames/head_translation_m"][()]
got, _ = curve_points(frames)
check(np.array_equal(got, scene.to_blender_axes(frame_points[0])), "frames.h5: frame 0's points")
bpy.context.scene.frame_set(3)
got, _ = curve_points(frames)
check(np.array_equal(got, scene.to_blender_axes(frame_points[2])),
      "frames.h5: Blender frame 3 shows the simulation's frame 2")
from mathutils import Matrix, Quaternion  # noqa: E402
axes = Matrix(((1, 0, 0), (0, 0, -1), (0, 1, 0)))
expected = (axes @ Quaternion(head_rotation[2].tolist()).to_matrix() @ axes.transposed()).to_4x4()
expected.translation = axes @ Matrix.Translation(head_translation[2].tolist()).translation
moved = bpy.data.objects["frames body"].matrix_world
check(all(abs(moved[i][j] - expected[i][j]) < 1e-6 for i in range(4) for j in range(4)),
      "the body moves with the head of the simulation's frame 2")

# guides.h5: the simulated guides, each with its points, at frame 1 of the file.
guides = hairstyle_io.import_frames(guides_path, 1, 2, name="guides")
with h5py.File(guides_path, "r") as file:
    guide_offsets = file["/guides/offsets"][()]
    guide_points = file["/frames/guide_points"][1]
got, got_offsets = curve_points(guides)
check(np.array_equal(got_offsets, guide_offsets) and
      np.array_equal(got, scene.to_blender_axes(guide_points)),
      f"guides.h5: {len(guide_offsets) - 1} guides with every point of its frame 1")

# Blender's own OBJ importer on hair-export's OBJ: every point, a strand's segments joined.
bpy.ops.object.select_all(action="DESELECT")
if hasattr(bpy.ops.wm, "obj_import"):
    bpy.ops.wm.obj_import(filepath=obj_path)
else:
    bpy.ops.import_scene.obj(filepath=obj_path)
imported = bpy.context.selected_objects
check(len(imported) == 1 and imported[0].type == "MESH", "the OBJ export imports as one mesh")
mesh = imported[0].data
with h5py.File(frames_path, "r") as file:
    obj_points = file["/frames/points"][0]
    strand_count = file["/strands/offsets"].shape[0] - 1
check(len(mesh.vertices) == len(obj_points),
      f"Blender's OBJ importer keeps all {len(obj_points)} points")
check(len(mesh.edges) == len(obj_points) - strand_count,
      f"and every segment: {len(obj_points) - strand_count} edges")
vertices = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
mesh.vertices.foreach_get("co", vertices)
check(np.allclose(vertices.reshape(-1, 3) @ np.array(imported[0].matrix_world)[:3, :3].T,
                  scene.to_blender_axes(obj_points), atol=1e-6),
      "at the positions frames.h5 has (float tolerance)")
print("check: all passed")
