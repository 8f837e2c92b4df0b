# The add-on's preferences (Edit > Preferences > Add-ons > hairstyle): the folder of the
# pipeline's binaries (else they are looked for on the PATH), and optionally the style
# model and the folder of parameter files (else those of the source checkout the
# binaries or the add-on come from; binaries.py).

import bpy
from bpy.props import IntProperty, StringProperty

from . import binaries

PACKAGE = __package__


class HAIRSTYLE_AP_preferences(bpy.types.AddonPreferences):
    bl_idname = PACKAGE

    bin_folder: StringProperty(
        name="Binaries", subtype="DIR_PATH",
        description="folder of the pipeline's binaries (extract ... interpolate), e.g. the "
                    "source's build/bin; empty: found on the PATH")
    style_model: StringProperty(
        name="Style model", subtype="FILE_PATH",
        description=f"classify's model (the source's models/{binaries.STYLE_MODEL_NAME}); "
                    "empty: found beside the binaries")
    parameters: StringProperty(
        name="Parameters", subtype="DIR_PATH",
        description="folder of the stages' parameter files (the source's pipelines/default); "
                    "empty: found beside the binaries, else the stages' defaults")
    threads: IntProperty(
        name="Threads", default=0, min=0,
        description="threads per stage (0: all cores)")

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "bin_folder")
        layout.prop(self, "style_model")
        layout.prop(self, "parameters")
        layout.prop(self, "threads")


class Values:
    """The preferences' values, the defaults where the add-on is not enabled (imported
    as a module, as the headless scripts do)."""

    def __init__(self, bin_folder="", style_model="", parameters="", threads=0):
        self.bin_folder = bin_folder
        self.style_model = style_model
        self.parameters = parameters
        self.threads = threads


def values(context):
    addon = context.preferences.addons.get(PACKAGE)
    if addon is None or addon.preferences is None:
        return Values()
    p = addon.preferences
    return Values(bpy.path.abspath(p.bin_folder), bpy.path.abspath(p.style_model),
                  bpy.path.abspath(p.parameters), p.threads)


def tools(context, stages):
    """binaries.Tools for `stages` from the preferences (binaries.MissingTool otherwise)."""
    v = values(context)
    return binaries.tools_for(stages, v.bin_folder, v.style_model, v.parameters), v.threads


CLASSES = (HAIRSTYLE_AP_preferences,)
