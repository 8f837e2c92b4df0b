# Building Blender objects from the hairstyle files (hdf5_files.py): hair curves with
# attributes, the body mesh, frames of a simulation. Everything is read and checked
# before the first object is made, and what was made is removed again if making the rest
# fails, so a refused file leaves the scene as it was.
#
# Axes: the pipeline's files are metres with +Y up (as OBJ and MakeHuman); Blender's up
# is +Z, so a point (x, y, z) becomes (x, -z, y), as Blender's own OBJ importer turns it.

import os

import numpy as np

from . import hdf5_files
from .hdf5_files import HairstyleFileError

try:
    import bpy
except ImportError:
    bpy = None

# Custom properties of an object whose points follow a frames.h5 from frame to frame.
FRAMES_PATH_PROPERTY = "hairstyle_frames_path"
FRAMES_FIRST_PROPERTY = "hairstyle_frames_first"
FRAMES_COUNT_PROPERTY = "hairstyle_frames_count"
# ...and of a body that moves with the head of a frames.h5 (its path).
FRAMES_BODY_PROPERTY = "hairstyle_frames_body_of"

# Blender's axes from the files': (x, y, z) -> (x, -z, y).
AXES = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def to_blender_axes(points):
    """(x, y, z), +Y up, to Blender's (x, -z, y), +Z up."""
    points = np.asarray(points, dtype=np.float32)
    return np.stack([points[:, 0], -points[:, 2], points[:, 1]], axis=1)


def _require_blender():
    if bpy is None:
        raise HairstyleFileError("these functions run inside Blender (blender -b --python ...)")


def head_matrix(rotation_wxyz, translation_m):
    """The 4 x 4 world-from-rest matrix of a head pose (a unit quaternion w, x, y, z and a
    translation, in the files' axes), in Blender's axes: A [R t] A^T."""
    w, x, y, z = (float(v) for v in rotation_wxyz)
    rotation = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])
    matrix = np.eye(4)
    matrix[:3, :3] = AXES @ rotation @ AXES.T
    matrix[:3, 3] = AXES @ np.asarray(translation_m, dtype=np.float64)
    return matrix


def _blender_matrix(matrix):
    from mathutils import Matrix
    return Matrix([[float(v) for v in row] for row in matrix])


def _curves_object(name, points, offsets):
    """A hair curves object (Blender's Curves type) with one curve per strand, made as
    poly splines and converted, since Blender 3.4's Python cannot size a Curves."""
    curve = bpy.data.curves.new(name, type="CURVE")
    curve.dimensions = "3D"
    blender_points = to_blender_axes(points)
    homogeneous = np.ones((len(blender_points), 4), dtype=np.float32)
    homogeneous[:, :3] = blender_points
    for s in range(len(offsets) - 1):
        first, end = int(offsets[s]), int(offsets[s + 1])
        spline = curve.splines.new("POLY")
        spline.points.add(end - first - 1)
        spline.points.foreach_set("co", homogeneous[first:end].ravel())
    legacy = bpy.data.objects.new(name, curve)
    bpy.context.scene.collection.objects.link(legacy)
    for other in bpy.context.scene.objects:
        if other is not None:
            other.select_set(False)
    legacy.select_set(True)
    bpy.context.view_layer.objects.active = legacy
    bpy.ops.object.convert(target="CURVES")
    converted = bpy.context.view_layer.objects.active
    if converted is None or converted.type != "CURVES":
        raise HairstyleFileError(f"{name}: Blender did not convert the strands to hair curves")
    converted.name = name
    if curve.users == 0:
        bpy.data.curves.remove(curve)
    return converted


def _set_curve_attribute(curves, name, kind, values):
    attribute = curves.attributes.new(name, kind, "CURVE")
    field = "color" if kind == "FLOAT_COLOR" else "value"
    attribute.data.foreach_set(field, np.asarray(values).ravel())


def _removing_on_failure(made, build):
    """Runs build(made), which appends what it creates to `made`; on an exception removes
    them all and raises again."""
    try:
        return build(made)
    except BaseException:
        for item in reversed(made):
            try:
                if isinstance(item, bpy.types.Object):
                    bpy.data.objects.remove(item, do_unlink=True)
                elif isinstance(item, bpy.types.Mesh):
                    bpy.data.meshes.remove(item)
                elif isinstance(item, bpy.types.Curves):
                    bpy.data.hair_curves.remove(item)
            except ReferenceError:
                pass
        raise


def _style_attributes(curves_object, strand_cluster, cluster_style):
    curves = curves_object.data
    _set_curve_attribute(curves, "cluster", "INT", strand_cluster.astype(np.int32))
    if cluster_style is None:
        return
    valid = (strand_cluster >= 0) & (strand_cluster < len(cluster_style))
    style = np.where(valid, cluster_style[np.clip(strand_cluster, 0, len(cluster_style) - 1)], -1)
    _set_curve_attribute(curves, "style", "INT", style.astype(np.int32))
    colours = np.array([hdf5_files.STYLE_COLOURS[int(s)] + (1.0,) for s in style],
                       dtype=np.float32)
    _set_curve_attribute(curves, "style_colour", "FLOAT_COLOR", colours)


def import_body(extract_path, name="body"):
    """The body of extract.h5 as a mesh object."""
    _require_blender()
    vertices, triangles = hdf5_files.read_body(extract_path)

    def build(made):
        mesh = bpy.data.meshes.new(name)
        made.append(mesh)
        mesh.from_pydata(to_blender_axes(vertices).tolist(), [], triangles.tolist())
        mesh.update()
        body = bpy.data.objects.new(name, mesh)
        made.append(body)
        bpy.context.scene.collection.objects.link(body)
        return body

    return _removing_on_failure([], build)


def import_strands(strands_path, styles_path=None, extract_path=None, with_neighbours=False,
                   name=None):
    """strands.h5 as a hair curves object: a curve per strand, the attributes "cluster"
    (per curve) and, with a styles.h5, "style" and "style_colour" (the paper's colours).
    With `with_neighbours`, styles.h5 and extract.h5 in the same folder are used when
    present (the body is added too). Returns the curves object."""
    _require_blender()
    folder = os.path.dirname(os.path.abspath(strands_path))
    if with_neighbours:
        styles_path = styles_path or _if_exists(os.path.join(folder, "styles.h5"))
        extract_path = extract_path or _if_exists(os.path.join(folder, "extract.h5"))
    points, offsets, cluster = hdf5_files.read_strands(strands_path)
    cluster_style = hdf5_files.read_cluster_styles(styles_path)[0] if styles_path else None
    body = hdf5_files.read_body(extract_path) if extract_path else None
    name = name or os.path.basename(folder) or "strands"

    def build(made):
        curves_object = _curves_object(name, points, offsets)
        made.append(curves_object)
        _style_attributes(curves_object, cluster, cluster_style)
        if body is not None:
            made.append(import_body(extract_path, name + " body"))
        return curves_object

    return _removing_on_failure([], build)


def _if_exists(path):
    return path if os.path.exists(path) else None


def import_frames(frames_path, frame_start=0, frame_end=None, name=None, extract_path=None):
    """frames.h5 (or guides.h5) as a hair curves object at its frame `frame_start` (the k-th stored), with
    "cluster", "style" and "style_colour" attributes; its points follow the file from
    Blender frame 1 (= frame_start) to frame_end - frame_start (a frame_change handler
    reads each frame from the file, so nothing is copied into the .blend). With
    `extract_path`, the body too, moving with the head of each frame. Returns the hair
    object."""
    _require_blender()
    body_data = hdf5_files.read_body(extract_path) if extract_path else None
    with hdf5_files.Frames(frames_path) as frames:
        count = len(frames)
        end = count if frame_end is None else frame_end
        if not (0 <= frame_start < end <= count):
            raise HairstyleFileError(
                f"{frames_path}: frames {frame_start} to {end} asked, the file has 0 to {count}")
        points = frames.points(frame_start)
        offsets, cluster, cluster_style = frames.offsets, frames.cluster, frames.cluster_style
        fps = frames.fps
        first_head = head_matrix(frames.head_rotation[frame_start],
                                 frames.head_translation_m[frame_start])
    name = name or os.path.basename(os.path.dirname(os.path.abspath(frames_path))) or "frames"

    def build(made):
        curves_object = _curves_object(name, points, offsets)
        made.append(curves_object)
        _style_attributes(curves_object, cluster, cluster_style)
        curves_object[FRAMES_PATH_PROPERTY] = os.path.abspath(frames_path)
        curves_object[FRAMES_FIRST_PROPERTY] = int(frame_start)
        curves_object[FRAMES_COUNT_PROPERTY] = int(end - frame_start)
        if body_data is not None:
            body = import_body(extract_path, name + " body")
            made.append(body)
            body[FRAMES_BODY_PROPERTY] = os.path.abspath(frames_path)
            body[FRAMES_FIRST_PROPERTY] = int(frame_start)
            body[FRAMES_COUNT_PROPERTY] = int(end - frame_start)
            body.matrix_world = _blender_matrix(first_head)
        scene = bpy.context.scene
        scene.frame_start, scene.frame_end = 1, int(end - frame_start)
        scene.render.fps = max(1, int(round(fps)))
        register_frame_handler()
        return curves_object

    return _removing_on_failure([], build)


def _frame_row(obj, path_property, k):
    """The file and the row of its k-th frame (0 based, held to the range) that an object
    following a frames.h5 or guides.h5 shows; (None, None) for one that follows none."""
    path = obj.get(path_property)
    count = int(obj.get(FRAMES_COUNT_PROPERTY, 0))
    if not path or count == 0:
        return None, None
    return path, int(obj[FRAMES_FIRST_PROPERTY]) + min(max(k, 0), count - 1)


def set_frame_points(curves_object, k):
    """Sets a frames object's points to the k-th frame of its range (0 based)."""
    path, row = _frame_row(curves_object, FRAMES_PATH_PROPERTY, k)
    if path is None:
        return
    with hdf5_files.Frames(path) as frames:
        points = frames.points(row)
    curves_object.data.position_data.foreach_set("vector", to_blender_axes(points).ravel())
    curves_object.data.update_tag()


def set_frame_head(body, k):
    """Moves a body that follows a frames.h5 to the head pose of the k-th frame of its range."""
    path, row = _frame_row(body, FRAMES_BODY_PROPERTY, k)
    if path is None:
        return
    with hdf5_files.Frames(path) as frames:
        matrix = head_matrix(frames.head_rotation[row], frames.head_translation_m[row])
    body.matrix_world = _blender_matrix(matrix)


def _on_frame_change(scene, *args):
    for obj in scene.objects:
        if obj.type == "CURVES" and FRAMES_PATH_PROPERTY in obj:
            set_frame_points(obj, scene.frame_current - 1)
        elif FRAMES_BODY_PROPERTY in obj:
            set_frame_head(obj, scene.frame_current - 1)


def register_frame_handler():
    handlers = bpy.app.handlers.frame_change_pre
    if all(getattr(h, "__name__", "") != _on_frame_change.__name__ for h in handlers):
        handlers.append(_on_frame_change)
