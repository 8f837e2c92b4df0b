# Building Blender objects from the hairstyle files (hdf5_files.py): hair curves with
# attributes, the body mesh, frames of a simulation. Everything is read and checked
# before the first object is made, and what was made is removed again if making the rest
# fails, so a refused file leaves the scene as it was.
#
# Axes: the pipeline's files are metres with +Y up (as OBJ and MakeHuman); Blender's up
# is +Z, so a point (x, y, z) becomes (x, -z, y), as Blender's own OBJ importer turns it.

import contextlib
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


def _set_attribute(curves, name, kind, domain, values):
    attribute = curves.attributes.new(name, kind, domain)
    field = "color" if kind == "FLOAT_COLOR" else "value"
    attribute.data.foreach_set(field, np.asarray(values).ravel())


def _set_curve_attribute(curves, name, kind, values):
    _set_attribute(curves, name, kind, "CURVE", values)


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


def _colours(style, unsure=None):
    """RGBA in the paper's colours of `style` (-1 to 3), paler where `unsure`."""
    table = np.array([hdf5_files.STYLE_COLOURS[k] + (1.0,) for k in range(-1, 4)],
                     dtype=np.float32)
    colours = table[np.clip(style, -1, 3) + 1]
    if unsure is not None:
        colours[unsure, :3] = 0.5 * colours[unsure, :3] + 0.5  # pale, as hair-render draws them
    return colours


def _per_cluster(values, cluster, missing):
    """values[cluster], `missing` where the cluster is out of range."""
    valid = (cluster >= 0) & (cluster < len(values))
    return np.where(valid, np.asarray(values)[np.clip(cluster, 0, max(len(values) - 1, 0))],
                    missing)


def set_style_attributes(curves_object, strand_cluster, cluster_style, cluster_unsure=None,
                         point_cluster=None):
    """The curve attributes "cluster" and, with the clusters' styles, "style" (a strand's
    root cluster's); "style_colour" in the paper's colours, per point by the point's own
    cluster where `point_cluster` is given (a ponytail's cap fixed, its tail normal; the
    point attribute "point_cluster" keeps them), else per strand; the clusters that
    `cluster_unsure` marks pale and in the attribute "unsure". Replaces any that are there."""
    curves = curves_object.data
    for name in ("cluster", "style", "style_colour", "unsure", "point_cluster"):
        if name in curves.attributes:
            curves.attributes.remove(curves.attributes[name])
    _set_curve_attribute(curves, "cluster", "INT", strand_cluster.astype(np.int32))
    if point_cluster is not None:
        _set_attribute(curves, "point_cluster", "INT", "POINT", point_cluster.astype(np.int32))
    if cluster_style is None:
        return
    style = _per_cluster(cluster_style, strand_cluster, -1)
    _set_curve_attribute(curves, "style", "INT", style.astype(np.int32))
    unsure = None
    if cluster_unsure is not None:
        unsure = _per_cluster(cluster_unsure, strand_cluster, 0) != 0
        _set_curve_attribute(curves, "unsure", "INT", unsure.astype(np.int32))
    if point_cluster is None:
        _set_curve_attribute(curves, "style_colour", "FLOAT_COLOR", _colours(style, unsure))
        return
    point_unsure = None if cluster_unsure is None else \
        _per_cluster(cluster_unsure, point_cluster, 0) != 0
    _set_attribute(curves, "style_colour", "FLOAT_COLOR", "POINT",
                   _colours(_per_cluster(cluster_style, point_cluster, -1), point_unsure))


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
    (per curve), "point_cluster" (per point) and, with a styles.h5, "style" (per curve)
    and "style_colour" (per point, the paper's colour of the point's cluster's style).
    With `with_neighbours`, styles.h5 and extract.h5 in the same folder are used when
    present (the body is added too). Returns the curves object."""
    _require_blender()
    folder = os.path.dirname(os.path.abspath(strands_path))
    if with_neighbours:
        styles_path = styles_path or _if_exists(os.path.join(folder, "styles.h5"))
        extract_path = extract_path or _if_exists(os.path.join(folder, "extract.h5"))
    points, offsets, cluster = hdf5_files.read_strands(strands_path)
    point_cluster = hdf5_files.read_point_clusters(strands_path)
    cluster_style = hdf5_files.read_cluster_styles(styles_path)[0] if styles_path else None
    body = hdf5_files.read_body(extract_path) if extract_path else None
    name = name or os.path.basename(folder) or "strands"

    def build(made):
        curves_object = _curves_object(name, points, offsets)
        made.append(curves_object)
        set_style_attributes(curves_object, cluster, cluster_style, point_cluster=point_cluster)
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
        set_style_attributes(curves_object, cluster, cluster_style)
        body = None
        if body_data is not None:
            body = import_body(extract_path, name + " body")
            made.append(body)
        attach_frames(curves_object, frames_path, frame_start, end, fps, body, first_head)
        return curves_object

    return _removing_on_failure([], build)


def attach_frames(curves_object, frames_path, frame_start, frame_end, fps, body=None,
                  first_head=None):
    """Makes `curves_object` (whose strands are those of frames.h5) follow the file's
    frames frame_start to frame_end - 1 from Blender frame 1, and `body` the head of each
    frame (at `first_head`, a 4 x 4 matrix, now); sets the scene's frame range and frame
    rate to them and registers the frame handler."""
    curves_object[FRAMES_PATH_PROPERTY] = os.path.abspath(frames_path)
    curves_object[FRAMES_FIRST_PROPERTY] = int(frame_start)
    curves_object[FRAMES_COUNT_PROPERTY] = int(frame_end - frame_start)
    if body is not None:
        body[FRAMES_BODY_PROPERTY] = os.path.abspath(frames_path)
        body[FRAMES_FIRST_PROPERTY] = int(frame_start)
        body[FRAMES_COUNT_PROPERTY] = int(frame_end - frame_start)
        if first_head is not None:
            body.matrix_basis = _blender_matrix(first_head)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, int(frame_end - frame_start)
    scene.render.fps, scene.render.fps_base = max(1, int(round(fps))), 1.0
    register_frame_handler()


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
    body.matrix_basis = _blender_matrix(matrix)  # under a parent too (the add-on's results)


_paused = False  # frames_paused()


def _on_frame_change(scene, *args):
    if _paused:
        return
    for obj in scene.objects:
        if obj.type == "CURVES" and FRAMES_PATH_PROPERTY in obj:
            set_frame_points(obj, scene.frame_current - 1)
        elif FRAMES_BODY_PROPERTY in obj:
            set_frame_head(obj, scene.frame_current - 1)


@contextlib.contextmanager
def frames_paused():
    """A `with` block in which changing the frame moves no object along its frames.h5."""
    global _paused
    was, _paused = _paused, True
    try:
        yield
    finally:
        _paused = was


def register_frame_handler():
    handlers = bpy.app.handlers.frame_change_pre
    if all(getattr(h, "__name__", "") != _on_frame_change.__name__ for h in handlers):
        handlers.append(_on_frame_change)
