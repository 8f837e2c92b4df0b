"""Blender's hair dynamics on our guide strands under our head motion: ms per frame.

Run inside Blender (3.x), headless:
  blender -b --factory-startup -noaudio -t THREADS --python-exit-code 1 \
      -P bench/blender_hair_dynamics.py -- --input guides.json [--frames N] [--keys K] \
      [--body body.obj] [--output result.json] [--export shapes.json]

--input is bench/blender_hair_input.py's JSON (hairs at rest in metres, Y up, and the head
rotation/translation per frame, frame 0 the rest state). The scene: an emitter mesh (one
1 mm triangle at each hair's root) with a hair particle system of one hair per input
polyline, each resampled by arc length to K keys (one key count for all, as Blender
requires) and written with HairKey.co_object_set; hair dynamics on (Blender's cloth-based
implicit hair solver) with the settings below; gravity 9.81 m/s^2 along -Y as in our
simulate stage; with --body, the body mesh as a collision object parented to the emitter.
The emitter is keyed with the head transform per frame (x = R x_rest + t), Blender frame
f + 1 = input frame f (looped when --frames exceeds the input's frames). Frames are
stepped in order with scene.frame_set; each is timed with time.perf_counter, except frame
1 (the rest state, where the cache starts). The check: at frame 1 the hair keys must be
the resampled rest shapes; where the head is turned furthest and at the last frame the
roots (ParticleSystem.co_hair, the path Blender draws) must follow the head; and by the
last frame the tips must have moved relative to the head (dynamics ran, not a rigid
copy). Prints and writes the result as JSON.
"""
import argparse
import json
import math
import statistics
import sys
import time

import bpy
from mathutils import Matrix, Quaternion, Vector
from mathutils.bvhtree import BVHTree

# Hair dynamics settings (ClothSettings of the hair system): Blender 3.4's defaults, set
# explicitly so that the run does not depend on them.
SETTINGS = {
    "quality": 5,                # solver steps per frame (Blender's default 5; ours: 2 substeps)
    "mass": 0.3,                 # Blender's default vertex mass (kg); the look depends on ratios
    "bending_stiffness": 0.5,    # Blender's default hair bending
    "tension_stiffness": 15.0,   # Blender's default (the UI's "stiffness" of hair structure)
    "air_damping": 1.0,          # Blender's default
    "internal_friction": 0.0,    # hair-hair friction through the volume grid: off
    "pin_stiffness": 0.0,        # pull of the keys to their rest shape (0: off; roots are pinned regardless)
}
# With --body: hair kept this far off it (collision distance_min and the body's outer
# thickness; Blender's defaults 0.015 and 0.02 m are for scenes in larger units), as our
# body_clearance_h = 0.004 H (about 1 mm for MakeHuman's 0.24 m head).
BODY_CLEARANCE_M = 0.001


def parse():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="blender_hair_dynamics.py")
    ap.add_argument("--input", required=True)
    ap.add_argument("--frames", type=int, default=0, help="frames to step after the rest frame; 0: the input's")
    ap.add_argument("--keys", type=int, default=16, help="keys per hair (all hairs share one count)")
    ap.add_argument("--body", help="body OBJ (metres, Y up) as a collision object")
    ap.add_argument("--quality", type=int, default=SETTINGS["quality"])
    ap.add_argument("--output", help="write the result JSON here too")
    ap.add_argument("--export", help="write the hairs (world space) at frame 1, where the head is turned furthest and the last frame here")
    return ap.parse_args(argv)


def resample(poly, k):
    """k points evenly by arc length along the polyline."""
    pts = [Vector(p) for p in poly]
    acc = [0.0]
    for a, b in zip(pts, pts[1:]):
        acc.append(acc[-1] + (b - a).length)
    out, seg = [], 0
    for i in range(k):
        s = acc[-1] * i / (k - 1)
        while seg < len(pts) - 2 and acc[seg + 1] < s:
            seg += 1
        span = acc[seg + 1] - acc[seg]
        u = 0.0 if span == 0 else min(max((s - acc[seg]) / span, 0.0), 1.0)
        out.append(pts[seg].lerp(pts[seg + 1], u))
    return out


def emitter(hairs):
    """A mesh of one small triangle at each hair's root, across its first segment."""
    verts, faces = [], []
    for h in hairs:
        d = (h[1] - h[0]).normalized()
        side = d.orthogonal().normalized() * 0.001
        r = h[0]
        n = len(verts)
        verts += [r, r + side, r + d.cross(side)]
        faces.append((n, n + 1, n + 2))
    mesh = bpy.data.meshes.new("scalp")
    mesh.from_pydata([tuple(v) for v in verts], [], faces)
    obj = bpy.data.objects.new("head", mesh)
    bpy.context.scene.collection.objects.link(obj)
    obj.rotation_mode = "QUATERNION"
    return obj


def threads():
    """The -t value Blender was started with (0 or absent: all cores)."""
    args = sys.argv[:sys.argv.index("--")] if "--" in sys.argv else sys.argv
    return int(args[args.index("-t") + 1]) if "-t" in args else 0


def inside_share(body, hairs_world):
    """Share of the path points inside the body (behind the nearest triangle's normal)."""
    dg = bpy.context.evaluated_depsgraph_get()
    body_eval = body.evaluated_get(dg)
    tree, to_local = BVHTree.FromObject(body_eval, dg), body_eval.matrix_world.inverted()
    inside = total = 0
    for path in hairs_world:
        for co in path[1:]:
            p = to_local @ Vector(co)
            loc, normal, _, _ = tree.find_nearest(p)
            inside += loc is not None and (p - loc).dot(normal) < 0
            total += 1
    return inside / total


def world_hairs(obj, psys_eval, k_path):
    return [[tuple(psys_eval.co_hair(object=obj, particle_no=i, step=s)) for s in range(k_path + 1)]
            for i in range(len(psys_eval.particles))]


def main():
    a = parse()
    data = json.load(open(a.input))
    k = a.keys
    hairs = [resample(h, k) for h in data["strands"]]
    rot, tr = data["rotations"], data["translations"]
    n_in = len(rot) - 1
    frames = a.frames or n_in

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.gravity = (0.0, -9.81, 0.0)
    scene.render.fps = int(round(data["fps"]))
    scene.frame_start, scene.frame_end = 1, frames + 1

    obj = emitter(hairs)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    mod = obj.modifiers.new("hair", "PARTICLE_SYSTEM")
    psys = mod.particle_system
    part = psys.settings
    part.type = "HAIR"
    part.count = len(hairs)
    part.hair_step = k - 1
    part.emit_from = "FACE"
    part.use_emit_random = False
    part.use_even_distribution = False
    part.distribution = "RAND"
    part.hair_length = 0.1
    part.child_type = "NONE"
    part.display_step = max(1, math.ceil(math.log2(k - 1)))

    # Hair keys exist on the original object only once the hair was computed: toggle
    # particle edit mode, then write the keys (object space) through the evaluated system.
    bpy.ops.particle.particle_edit_toggle()
    bpy.ops.particle.particle_edit_toggle()
    dg = bpy.context.evaluated_depsgraph_get()
    obj_eval = obj.evaluated_get(dg)
    mod_eval = obj_eval.modifiers[mod.name]
    psys_eval = mod_eval.particle_system
    assert len(psys.particles) == len(hairs), (len(psys.particles), len(hairs))
    for p, p_eval, h in zip(psys.particles, psys_eval.particles, hairs):
        assert len(p.hair_keys) == k, len(p.hair_keys)
        for key, co in zip(p.hair_keys, h):
            key.co_object_set(obj_eval, mod_eval, p_eval, co)
    # (No edit mode after this: entering it pushes keys off the emitter and alters them.)

    psys.use_hair_dynamics = True
    cs = psys.cloth.settings
    for name, value in SETTINGS.items():
        setattr(cs, name, value)
    cs.quality = a.quality
    psys.point_cache.frame_start, psys.point_cache.frame_end = 1, frames + 1

    body = None
    if a.body:
        bpy.ops.wm.obj_import(filepath=a.body, forward_axis="Y", up_axis="Z")
        body = bpy.context.selected_objects[0]
        body.modifiers.new("collision", "COLLISION")
        body.parent = obj
        body.collision.thickness_outer = BODY_CLEARANCE_M
    # Collisions with collision objects (the body): only with --body.
    psys.cloth.collision_settings.use_collision = bool(a.body)
    psys.cloth.collision_settings.distance_min = BODY_CLEARANCE_M

    for f in range(frames + 1):
        src = f if f <= n_in else 1 + (f - 1) % n_in
        obj.rotation_quaternion = Quaternion(rot[src])
        obj.location = Vector(tr[src])
        obj.keyframe_insert("rotation_quaternion", frame=f + 1)
        obj.keyframe_insert("location", frame=f + 1)

    k_path = 2 ** part.display_step
    times = []
    t0 = time.perf_counter()
    scene.frame_set(1)
    init_ms = (time.perf_counter() - t0) * 1e3
    dg = bpy.context.evaluated_depsgraph_get()
    obj_eval = obj.evaluated_get(dg)
    mod_eval = obj_eval.modifiers[mod.name]
    psys_eval = mod_eval.particle_system
    first = world_hairs(obj_eval, psys_eval, k_path)
    inside_first = inside_share(body, first) if body else None
    key_err = max((Vector(key.co_object(obj_eval, mod_eval, p)) - co).length
                  for p, h in zip(psys_eval.particles, hairs) for key, co in zip(p.hair_keys, h))
    # The input frame where the head is turned furthest from rest (read after its timing).
    src_of = [f if f <= n_in else 1 + (f - 1) % n_in for f in range(frames + 1)]
    turned = max(range(1, frames + 1), key=lambda f: abs(Quaternion(rot[src_of[f]]).angle))
    for f in range(2, frames + 2):
        t0 = time.perf_counter()
        scene.frame_set(f)
        times.append((time.perf_counter() - t0) * 1e3)
        if f == turned + 1:
            dg = bpy.context.evaluated_depsgraph_get()
            oe = obj.evaluated_get(dg)
            mid = world_hairs(oe, oe.modifiers[mod.name].particle_system, k_path)
    dg = bpy.context.evaluated_depsgraph_get()
    last = world_hairs(obj.evaluated_get(dg), obj.evaluated_get(dg).modifiers[mod.name].particle_system, k_path)
    inside_last = inside_share(body, last) if body else None

    # Check: at frame 1 the hair keys are the rest shapes (the drawn path, a spline through
    # the keys, is only reported: it leaves the key polyline on curly hair); at the last
    # frame and where the head is turned furthest the roots follow the head, and at the last
    # frame the tips moved off the rigidly carried rest shape.
    shape_err = 0.0
    for h, path in zip(hairs, first):
        for s, co in enumerate(path):
            u = s * (k - 1) / k_path
            j = min(int(u), k - 2)
            shape_err = max(shape_err, (Vector(co) - h[j].lerp(h[j + 1], u - j)).length)
    def head(f):
        return Matrix.Translation(Vector(tr[src_of[f]])) @ Quaternion(rot[src_of[f]]).to_matrix().to_4x4()
    m = head(frames)
    tip_moves = sorted((Vector(path[-1]) - m @ h[-1]).length for h, path in zip(hairs, last))
    root_err = max((Vector(path[0]) - head(f) @ h[0]).length
                   for f, paths in ((frames, last), (turned, mid)) for h, path in zip(hairs, paths))
    lengths = [sum((b - a_).length for a_, b in zip(h, h[1:])) for h in hairs]
    ok = key_err < 1e-4 and root_err < 0.001 and statistics.median(tip_moves) > 0.002
    result = {
        "blender": bpy.app.version_string, "threads": threads(),
        "hairs": len(hairs), "keys_per_hair": k, "frames_timed": len(times), "fps": data["fps"],
        "source": data.get("source"), "body_collision": bool(a.body), "settings": {**SETTINGS, "quality": a.quality},
        "median_ms_per_frame": statistics.median(times), "mean_ms_per_frame": statistics.fmean(times),
        "init_frame_ms": init_ms, "first_step_ms": times[0], "ms_per_frame": [round(t, 2) for t in times],
        "check": {"passed": ok, "frame1_max_key_error_m": key_err, "frame1_max_path_off_polyline_m": shape_err, "max_root_error_m": root_err, "turned_frame": turned,
                  "turned_angle_deg": math.degrees(abs(Quaternion(rot[src_of[turned]]).angle)),
                  "last_frame_tip_offset_m_median": statistics.median(tip_moves),
                  "last_frame_tip_offset_m_max": tip_moves[-1], "median_hair_length_m": statistics.median(lengths),
                  "frame1_share_inside_body": inside_first, "last_frame_share_inside_body": inside_last},
        "our_guide_ms_per_frame": data.get("guide_ms_per_frame"),
    }
    print("BLENDER_HAIR_RESULT " + json.dumps(result))
    if a.output:
        json.dump(result, open(a.output, "w"), indent=1)
    if a.export:
        json.dump({"frame1": first, "turned_frame": turned, "turned": mid, "last_frame": frames, "last": last, "rest_keys": [[tuple(v) for v in h] for h in hairs]}, open(a.export, "w"))


main()
