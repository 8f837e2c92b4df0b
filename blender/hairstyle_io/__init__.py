# hairstyle_io: a Blender add-on that opens the hairstyle pipeline's HDF5 files and runs
# the pipeline from Blender.
#
# The panel (3D viewport, N sidebar > Hairstyle) converts a hair mesh and the body into
# strands by the pipeline's installed binaries in the background (Convert, with a
# progress bar and Cancel), lists each cluster's style and confidence, pins a style (Fix
# style: classify reruns) and simulates under a head motion (Simulate and bake), the
# frames playing on the curves. Modules: panel, operators (the chains' driver), runner
# (subprocesses), stages (the command lines), binaries and preferences (where the
# binaries are), mesh_export, overrides, keyframes, results (what the scene gets),
# properties; scene and hdf5_files read the files.
#
# File > Import > hairstyle strands (.h5) reads strands.h5 (grow) as a hair curves
# object, with each strand's cluster and the cluster's style (from styles.h5 beside it)
# as curve attributes and a colour attribute in the paper's colours; frames.h5
# (interpolate) or guides.h5 (simulate) as the strands or guides at one frame or animated
# over a frame range, the body moving with the head; and the body from extract.h5.
# Headless:
#
#   blender -b --python blender/hairstyle_cli.py -- strands OUT/m/strands.h5 --save m.blend
#
# The files are read with h5py (Debian's blender runs on the system Python: apt install
# python3-h5py). A file of the wrong schema, or a missing one, is refused with one
# message and nothing is added to the scene. Install: docs/blender.md.

bl_info = {
    "name": "hairstyle: hair cards to strands, styles and frames",
    "author": "hairstyle",
    "version": (1, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Hairstyle; File > Import > hairstyle strands (.h5)",
    "description": "Converts hair cards to strands with styles and simulates them with the "
                   "hairstyle pipeline; imports its strands.h5, styles.h5, frames.h5 and "
                   "extract.h5 as hair curves and a body mesh",
    "category": "Import-Export",
}

import os  # noqa: E402

from . import hdf5_files  # noqa: E402
from .scene import import_body, import_frames, import_strands  # noqa: E402

__all__ = ["import_body", "import_frames", "import_strands", "hdf5_files"]

try:
    import bpy
    from bpy.props import IntProperty, StringProperty
    from bpy_extras.io_utils import ImportHelper
except ImportError:  # imported outside Blender (the readers alone)
    bpy = None

if bpy is not None:

    class IMPORT_OT_hairstyle_strands(bpy.types.Operator, ImportHelper):
        """Import the hairstyle pipeline's strands.h5 (with styles.h5 and extract.h5 beside it), frames.h5 or guides.h5"""

        bl_idname = "import_curves.hairstyle_strands"
        bl_label = "Import hairstyle strands"
        bl_options = {"REGISTER", "UNDO"}
        filename_ext = ".h5"
        filter_glob: StringProperty(default="*.h5", options={"HIDDEN"})
        frame_start: IntProperty(name="First frame", default=0, min=0,
                                 description="frames.h5, guides.h5: the first frame to animate")
        frame_end: IntProperty(name="End frame", default=-1,
                               description="frames.h5, guides.h5: one past the last frame (-1: all)")

        def execute(self, context):
            try:
                if hdf5_files.schema_of(self.filepath) in ("hairstyle.frames", "hairstyle.guides"):
                    extract = os.path.join(os.path.dirname(self.filepath), "extract.h5")
                    import_frames(self.filepath, self.frame_start,
                                  None if self.frame_end < 0 else self.frame_end,
                                  extract_path=extract if os.path.exists(extract) else None)
                else:
                    import_strands(self.filepath, with_neighbours=True)
            except hdf5_files.HairstyleFileError as error:
                self.report({"ERROR"}, str(error))
                return {"CANCELLED"}
            return {"FINISHED"}

    def menu_import(self, context):
        self.layout.operator(IMPORT_OT_hairstyle_strands.bl_idname,
                             text="hairstyle strands (.h5)")

    from bpy.app.handlers import persistent

    from . import operators, panel, preferences, properties, runner, scene

    @persistent
    def _cancel_on_load(*args):
        operators.drop_running()  # another file: the running chain's results have no scene

    @persistent
    def _follow_frames_on_load(*args):
        """A saved file's curves play their frames.h5 again."""
        if any(scene.FRAMES_PATH_PROPERTY in obj for obj in bpy.data.objects):
            scene.register_frame_handler()

    _CLASSES = (IMPORT_OT_hairstyle_strands, *preferences.CLASSES, *operators.CLASSES,
                *panel.CLASSES)

    def register():
        properties.register()
        for cls in _CLASSES:
            bpy.utils.register_class(cls)
        bpy.types.TOPBAR_MT_file_import.append(menu_import)
        bpy.app.handlers.load_pre.append(_cancel_on_load)
        bpy.app.handlers.load_post.append(_follow_frames_on_load)

    def unregister():
        operators.drop_running()
        runner.cancel_all()
        if _cancel_on_load in bpy.app.handlers.load_pre:
            bpy.app.handlers.load_pre.remove(_cancel_on_load)
        if _follow_frames_on_load in bpy.app.handlers.load_post:
            bpy.app.handlers.load_post.remove(_follow_frames_on_load)
        bpy.types.TOPBAR_MT_file_import.remove(menu_import)
        for cls in reversed(_CLASSES):
            bpy.utils.unregister_class(cls)
        properties.unregister()
