# The head motion of Simulate and bake: one of simulate's presets, or an object's
# animation in Blender written as simulate's keyframe CSV (docs/simulate.md, "The head
# motion"): a row per Blender frame, the time from the first frame, the object's rotation
# since that frame as yaw, pitch and roll (R = Ry(yaw) Rx(pitch) Rz(roll), in the files'
# axes: +Y up) and its location's change as the offset, in metres. simulate turns the head
# by that rotation about its own pivot (the base of the head), then moves it by the offset.

import math

import numpy as np

# simulate's presets (simulate --help: --motion), with what each does.
PRESETS = (
    ("still", "Still", "no motion: the hair settles under gravity"),
    ("nod", "Nod", "pitch, 20 degrees, 1 Hz"),
    ("shake", "Shake", "yaw, 30 degrees, 1.5 Hz"),
    ("turn", "Turn", "yaw 0 to 60 degrees and back over 4 s"),
    ("walk", "Walk", "forward at 1.2 m/s with bob and sway"),
    ("violent_shake", "Violent shake", "yaw, 45 degrees, 4 Hz"),
)
COLUMNS = ("time_s", "yaw_deg", "pitch_deg", "roll_deg", "offset_x_m", "offset_y_m", "offset_z_m")

# The files' axes from Blender's: Blender (x, y, z) is the files' (x, z, -y)
# (scene.AXES, transposed).
_FROM_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])


def yaw_pitch_roll_deg(rotation):
    """Angles (degrees) with rotation = Ry(yaw) Rx(pitch) Rz(roll), a 3 x 3 rotation."""
    r = np.asarray(rotation, dtype=np.float64)
    pitch = math.asin(max(-1.0, min(1.0, -r[1, 2])))
    yaw = math.atan2(r[0, 2], r[2, 2])
    roll = math.atan2(r[1, 0], r[1, 1])
    return math.degrees(yaw), math.degrees(pitch), math.degrees(roll)


def _rotation_of(matrix):
    """The rotation of a 4 x 4 (or 3 x 3) matrix, its scale divided out (polar part)."""
    m = np.asarray(matrix, dtype=np.float64)[:3, :3]
    u, _, vt = np.linalg.svd(m)
    rotation = u @ vt
    if np.linalg.det(rotation) < 0:
        u[:, -1] = -u[:, -1]
        rotation = u @ vt
    return rotation


def keyframe_rows(times_s, matrices, metres_per_unit=1.0):
    """A keyframe row (COLUMNS) per pose: `matrices` are an object's world matrices
    (Blender's axes, scene units) at `times_s`; each row is the pose since the first."""
    first_rotation = _rotation_of(matrices[0])
    first_location = np.asarray(matrices[0], dtype=np.float64)[:3, 3]
    rows = []
    for time_s, matrix in zip(times_s, matrices):
        turned = _rotation_of(matrix) @ first_rotation.T  # Blender's axes
        rotation = _FROM_BLENDER @ turned @ _FROM_BLENDER.T  # the files' axes
        moved = (np.asarray(matrix, dtype=np.float64)[:3, 3] - first_location) * metres_per_unit
        offset = _FROM_BLENDER @ moved
        rows.append((float(time_s), *yaw_pitch_roll_deg(rotation), *offset.tolist()))
    return rows


def to_csv(rows, source=""):
    lines = [f"# head motion for simulate --keyframes{': ' + source if source else ''}",
             ",".join(COLUMNS)]
    lines += [",".join(f"{value:.9g}" for value in row) for row in rows]
    return "\n".join(lines) + "\n"


def object_matrices(obj, scene, frames):
    """The world matrices of Blender object `obj` at the scene frames `frames`, evaluated
    with its animation, constraints and parents (Blender only)."""
    import bpy
    from . import scene as hair_scene
    matrices = []
    current = scene.frame_current
    with hair_scene.frames_paused():  # setting the frame must not read frames.h5 files
        for frame in frames:
            scene.frame_set(frame)
            evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
            matrices.append(np.array(evaluated.matrix_world, dtype=np.float64))
        scene.frame_set(current)
    return matrices


def object_keyframes(obj, scene, frame_count, fps, metres_per_unit=1.0):
    """The CSV of `obj`'s motion over `frame_count` frames from the scene's first frame,
    one row per frame; None where the object has no animation."""
    animation = obj.animation_data
    animated = animation is not None and (animation.action is not None or len(animation.drivers))
    constrained = len(getattr(obj, "constraints", ())) > 0 or obj.parent is not None
    if not (animated or constrained):
        return None
    frames = [scene.frame_start + k for k in range(frame_count)]
    times = [k / fps for k in range(frame_count)]
    rows = keyframe_rows(times, object_matrices(obj, scene, frames), metres_per_unit)
    return to_csv(rows, f"the animation of {obj.name}, frames {frames[0]} to {frames[-1]}")
