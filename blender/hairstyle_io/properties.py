# What the hairstyle panel edits and shows, stored with the scene (scene.hairstyle): the
# hair mesh and the body to convert, where the results go, the stages' options, the
# clusters of the last conversion with their styles, and the bake's motion and frames.
# The running chain's progress lives on the window manager (not saved in the file).

import os
import tempfile

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty,
                       IntProperty, PointerProperty, StringProperty)

from . import keyframes, overrides


def _is_mesh(self, obj):
    return obj.type == "MESH"


STYLE_ITEMS = [(style, style.capitalize(), f"pin the cluster's style to {style}")
               for style in overrides.STYLES]
FIX_ITEMS = STYLE_ITEMS + [("classified", "As classified",
                            "remove the cluster's pin: classify decides its style again")]
MOTION_ITEMS = list(keyframes.PRESETS) + [
    ("OBJECT", "Object's animation",
     "the animation of the motion object (or the active object): its rotation turns the head "
     "about the head's pivot, its location moves it")]


class HAIRSTYLE_PG_cluster(bpy.types.PropertyGroup):
    """One cluster of styles.h5."""

    cluster: IntProperty(name="Cluster")
    style: StringProperty(name="Style")
    confidence: FloatProperty(name="Confidence", min=0.0, max=1.0)
    unsure: BoolProperty(name="Unsure")
    pinned: BoolProperty(name="Pinned")
    strand_count: IntProperty(name="Strands")


class HAIRSTYLE_PG_settings(bpy.types.PropertyGroup):
    hair_mesh: PointerProperty(
        name="Hair mesh", type=bpy.types.Object, poll=_is_mesh,
        description="the hair cards to convert (empty: the active object)")
    body_mesh: PointerProperty(
        name="Body", type=bpy.types.Object, poll=_is_mesh,
        description="the body the hair is fitted on")
    folder: StringProperty(
        name="Folder", subtype="DIR_PATH",
        description="where the results go (empty: 'hairstyle/<hair mesh>' beside the .blend "
                    "file, or in the system's temporary folder for an unsaved file)")
    unit_scale: FloatProperty(
        name="Unit scale", default=1.0, min=1e-6, soft_max=100.0, precision=4,
        description="metres per Blender unit of the meshes (MakeHuman's OBJ files imported "
                    "as they are: 0.1, decimetres)")
    strand_count: IntProperty(
        name="Strands", default=10000, min=1, max=1000000,
        description="strands grow grows over the scalp")
    # The last conversion.
    result_root: PointerProperty(type=bpy.types.Object)
    result_hair: PointerProperty(type=bpy.types.Object)
    result_body: PointerProperty(type=bpy.types.Object)
    result_folder: StringProperty(name="Results", subtype="DIR_PATH")
    clusters: CollectionProperty(type=HAIRSTYLE_PG_cluster)
    cluster_index: IntProperty(name="Cluster", default=0)
    fix_style: EnumProperty(name="Style", items=FIX_ITEMS, default="normal",
                            description="the style to pin the chosen cluster to")
    # Simulate and bake.
    motion: EnumProperty(name="Motion", items=MOTION_ITEMS, default="shake",
                         description="the head's motion: a preset of simulate, or an object's "
                                     "animation written as keyframes")
    motion_object: PointerProperty(
        name="Motion object", type=bpy.types.Object,
        description="the object whose animation moves the head (empty: the active object)")
    bake_first: IntProperty(name="First frame", default=0, min=0,
                            description="the first simulation frame brought in")
    bake_end: IntProperty(name="End frame", default=60, min=1,
                          description="one past the last simulation frame: the simulation "
                                      "runs to it (End / fps seconds)")
    # The last bake (Fix style reruns it on the new styles).
    baked_first: IntProperty(default=-1)
    baked_end: IntProperty(default=-1)
    baked_fps: FloatProperty(default=30.0)
    baked_motion: StringProperty(default="")


def output_folder(settings, hair_name):
    """The folder a conversion of `hair_name` writes to."""
    if settings.folder:
        return os.path.abspath(bpy.path.abspath(settings.folder))
    safe = bpy.path.clean_name(hair_name) or "hair"
    if bpy.data.filepath:
        return os.path.join(os.path.dirname(bpy.data.filepath), "hairstyle", safe)
    return os.path.join(tempfile.gettempdir(), "hairstyle", safe)


CLASSES = (HAIRSTYLE_PG_cluster, HAIRSTYLE_PG_settings)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.hairstyle = PointerProperty(type=HAIRSTYLE_PG_settings)
    bpy.types.WindowManager.hairstyle_progress = FloatProperty(
        name="Progress", subtype="PERCENTAGE", min=0.0, max=100.0, precision=0)
    bpy.types.WindowManager.hairstyle_status = StringProperty(name="Status")


def unregister():
    del bpy.types.WindowManager.hairstyle_status
    del bpy.types.WindowManager.hairstyle_progress
    del bpy.types.Scene.hairstyle
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
