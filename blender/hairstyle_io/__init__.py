# hairstyle_io: a Blender add-on that opens the hairstyle pipeline's HDF5 files.
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
    "name": "hairstyle: strands, styles, frames and the body from HDF5",
    "author": "hairstyle",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > hairstyle strands (.h5)",
    "description": "Imports the hairstyle pipeline's strands.h5, styles.h5, frames.h5 and "
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

    def register():
        bpy.utils.register_class(IMPORT_OT_hairstyle_strands)
        bpy.types.TOPBAR_MT_file_import.append(menu_import)

    def unregister():
        bpy.types.TOPBAR_MT_file_import.remove(menu_import)
        bpy.utils.unregister_class(IMPORT_OT_hairstyle_strands)
