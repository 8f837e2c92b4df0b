# The hairstyle_io add-on from the command line, headless (docs/blender.md):
#
#   blender -b --python blender/hairstyle_cli.py -- strands OUT/m/strands.h5 [--save m.blend]
#   blender -b --python blender/hairstyle_cli.py -- frames OUT/m/frames.h5 [--first 0] [--end 30] [--save m.blend]
#   blender -b --python blender/hairstyle_cli.py -- frames OUT/m/guides.h5 ...   (the simulated guides)
#
# strands: strands.h5 with styles.h5 and extract.h5 from the same folder when present;
# frames: frames.h5 from frame --first to --end - 1 (the body from extract.h5 beside it).
# A file the add-on refuses: one line on stderr, exit status 2, nothing saved.

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bpy  # noqa: E402

import hairstyle_io  # noqa: E402
from hairstyle_io.hdf5_files import HairstyleFileError  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(prog="hairstyle_cli.py",
                                     description="Import hairstyle HDF5 files into Blender.")
    parser.add_argument("kind", choices=["strands", "frames"])
    parser.add_argument("path", help="strands.h5, or frames.h5 or guides.h5")
    parser.add_argument("--first", type=int, default=0, help="frames: the first frame")
    parser.add_argument("--end", type=int, default=None, help="frames: one past the last")
    parser.add_argument("--save", help="write the scene to this .blend file")
    parser.add_argument("--keep-default-scene", action="store_true",
                        help="keep the startup file's objects (the cube, camera and light)")
    args = parser.parse_args(argv)
    if not args.keep_default_scene:
        for obj in list(bpy.data.objects):
            if obj.type == "MESH" and obj.name == "Cube":
                bpy.data.objects.remove(obj, do_unlink=True)
    try:
        if args.kind == "strands":
            made = hairstyle_io.import_strands(args.path, with_neighbours=True)
        else:
            extract = os.path.join(os.path.dirname(os.path.abspath(args.path)), "extract.h5")
            made = hairstyle_io.import_frames(args.path, args.first, args.end,
                                              extract_path=extract if os.path.exists(extract) else None)
    except HairstyleFileError as error:
        print(f"hairstyle_cli: error: {error}", file=sys.stderr)
        return 2
    print(f"hairstyle_cli: {made.name}: {len(made.data.curves)} strands, "
          f"{len(made.data.points)} points")
    if args.save:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.save))
    return 0


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    status = main(argv)
    if status:
        sys.exit(status)
