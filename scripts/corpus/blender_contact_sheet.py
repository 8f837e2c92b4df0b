# Puts PNG pictures side by side in pairs, a pair a row (the mesh with its texture, then
# its grown strands), into one PNG: the corpus's contact sheets (bench/corpus.sh).
#
#   blender --background --factory-startup --python scripts/corpus/blender_contact_sheet.py -- \
#       LIST OUT_PNG
#
# LIST: a file of picture paths, one a line, in pairs; a missing picture leaves its cell
# white. Each row is as tall as its taller picture; pictures keep their pixels.
import os
import sys

import bpy
import numpy


def load(path):
    if not os.path.isfile(path):
        return None
    image = bpy.data.images.load(path)
    w, h = image.size
    pixels = numpy.empty(w * h * 4, dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(h, w, 4)


def main():
    listing, out_path = sys.argv[sys.argv.index("--") + 1:][:2]
    paths = [line.strip() for line in open(listing) if line.strip()]
    rows = []
    for k in range(0, len(paths), 2):
        pair = [load(p) for p in paths[k:k + 2]]
        height = max([p.shape[0] for p in pair if p is not None] or [8])
        cells = []
        for p, default_width in zip(pair, (600, 600)):
            cell = numpy.ones((height, p.shape[1] if p is not None else default_width, 4), numpy.float32)
            if p is not None:
                cell[height - p.shape[0]:, :, :] = p  # Blender's rows run bottom up
            cells.append(cell)
        rows.append(numpy.concatenate(cells, axis=1))
    width = max(r.shape[1] for r in rows)
    rows = [numpy.pad(r, ((0, 0), (0, width - r.shape[1]), (0, 0)), constant_values=1) for r in rows]
    sheet = numpy.concatenate(rows[::-1], axis=0)  # first row at the top
    image = bpy.data.images.new("sheet", width=sheet.shape[1], height=sheet.shape[0], alpha=True)
    image.pixels.foreach_set(sheet.ravel())
    # 8-bit RGB, as compressed as PNG goes: a sheet of 20 rows stays near 1 MB.
    settings = bpy.context.scene.render.image_settings
    settings.file_format, settings.color_mode, settings.color_depth = "PNG", "RGB", "8"
    settings.compression = 100
    image.save_render(out_path + ".part.png", scene=bpy.context.scene)
    os.replace(out_path + ".part.png", out_path)


main()
