# Screenshots of the hairstyle panel for docs/blender.md, taken from Blender's own window
# on a virtual display (no screen needed):
#
#   xvfb-run -a -s '-screen 0 1600x1000x24' blender --factory-startup --enable-event-simulate \
#     --python blender/hairstyle_panel_shots.py -- SAMPLES_DIR BIN_DIR WORK_DIR IMAGE_PREFIX
#
# Opens SAMPLES_DIR's body and braid01's cards, presses Convert (modal: the progress bar
# and Cancel while grow runs: IMAGE_PREFIX_convert.png), shows the strands coloured by style
# with the cluster list (classify's unsure_below raised to 0.9 in a parameter folder of
# WORK_DIR, so that clusters at confidence 0.88 are listed unsure: IMAGE_PREFIX_clusters.png)
# and bakes 45 frames of the shake preset (IMAGE_PREFIX_bake.png, at frame 30). Each
# step runs from a timer, as a user's clicks would, then Blender quits.

import os
import shutil
import sys

import bpy
from mathutils import Euler, Vector

samples_dir, bin_dir, work_dir, prefix = sys.argv[sys.argv.index("--") + 1:]
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import addon_utils  # noqa: E402

addon_utils.enable("hairstyle_io", default_set=True)
from hairstyle_io import operators  # noqa: E402

MODEL = "braid01"


def view3d():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    sidebar = next(r for r in area.regions if r.type == "UI")
    return window, area, region, sidebar


def shot(name):
    window, area, region, _ = view3d()
    path = f"{prefix}_{name}.png"
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.screen.screenshot_area(filepath=path)
    print("panel shot:", path, flush=True)


def parameter_folder():
    """pipelines/default with classify's unsure_below at 0.9."""
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pipelines", "default")
    folder = os.path.join(work_dir, "params")
    shutil.copytree(source, folder, dirs_exist_ok=True)
    path = os.path.join(folder, "classify.toml")
    with open(path) as file:
        text = file.read()
    with open(path, "w") as file:
        file.write(text.replace("unsure_below = 0.6", "unsure_below = 0.9"))
    return folder


def open_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    imported = []
    for path in (os.path.join(samples_dir, "body.obj"),
                 os.path.join(samples_dir, "hair", MODEL + ".obj")):
        bpy.ops.wm.obj_import(filepath=path)
        imported.append(bpy.context.selected_objects[0])
    body, hair = imported
    preferences = bpy.context.preferences.addons["hairstyle_io"].preferences
    preferences.bin_folder, preferences.parameters = bin_dir, parameter_folder()
    settings = bpy.context.scene.hairstyle
    settings.hair_mesh, settings.body_mesh, settings.unit_scale = hair, body, 0.1
    settings.folder = os.path.join(work_dir, MODEL)
    settings.bake_end = 45
    window, area, region, sidebar = view3d()
    bpy.context.preferences.view.show_splash = False
    bpy.context.preferences.system.use_region_overlap = False  # the sidebar's edge: its own
    space = area.spaces[0]
    space.show_region_ui = True
    space.shading.type = "SOLID"
    space.shading.color_type = "TEXTURE"
    space.overlay.show_floor = space.overlay.show_axis_x = space.overlay.show_axis_y = False
    x, y = sidebar.x + sidebar.width // 2, sidebar.y + sidebar.height // 2
    window.event_simulate(type="ESC", value="PRESS", x=x, y=y)  # the splash
    window.event_simulate(type="ESC", value="RELEASE", x=x, y=y)
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    for _ in range(3):  # Item, Tool, View, then Hairstyle: Ctrl+wheel steps the sidebar's tabs
        window.event_simulate(type="WHEELDOWNMOUSE", value="PRESS", ctrl=True, x=x, y=y)
    corners = [hair.matrix_world @ Vector(corner) for corner in hair.bound_box]
    low = Vector([min(c[i] for c in corners) for i in range(3)])
    high = Vector([max(c[i] for c in corners) for i in range(3)])
    view = space.region_3d
    view.view_location = (low + high) / 2
    view.view_distance = 1.3 * max(high - low)
    view.view_rotation = Euler((1.45, 0.0, 2.3)).to_quaternion()
    body.select_set(False)
    hair.select_set(False)


def press(operator):
    window, area, region, _ = view3d()
    with bpy.context.temp_override(window=window, area=area, region=region):
        getattr(bpy.ops.hairstyle, operator)("INVOKE_DEFAULT")


STEPS = []


def step(function):
    STEPS.append(function)
    return function


@step
def start():
    open_scene()
    return True


def _drag(kind, value, dx):
    """One event of dragging the sidebar's edge (one a tick: the window handles each)."""
    window, _, _, sidebar = view3d()
    edge, y = sidebar.x + 1, sidebar.y + sidebar.height // 2
    window.event_simulate(type=kind, value=value, x=edge + dx, y=y)
    print("drag", kind, value, edge + dx, y, sidebar.width, flush=True)
    return True


for _event in (("MOUSEMOVE", "NOTHING", 0), ("LEFTMOUSE", "PRESS", 0),
               ("MOUSEMOVE", "NOTHING", -100), ("MOUSEMOVE", "NOTHING", -200),
               ("LEFTMOUSE", "RELEASE", -200)):  # a sidebar wide enough for the list
    step(lambda event=_event: _drag(*event))


@step
def convert():
    window, _, _, sidebar = view3d()
    print("sidebar width", sidebar.width, flush=True)
    window.event_simulate(type="MOUSEMOVE", value="NOTHING", x=200, y=200)
    press("convert")
    return True


@step
def during_grow():
    job = operators.running_job()
    if job is None or job.chain.stage != "grow":
        return False
    bpy.context.scene.hairstyle.hair_mesh.hide_set(False)
    return "shoot"


@step
def shoot_convert():
    shot("convert")
    return True


@step
def converted():
    if operators.running_job() is not None:
        return False
    settings = bpy.context.scene.hairstyle
    settings.hair_mesh.hide_set(True)  # the cards, over the strands
    _, area, _, _ = view3d()
    area.spaces[0].shading.color_type = "MATERIAL"
    area.spaces[0].shading.type = "MATERIAL"
    settings.cluster_index = 1
    settings.result_hair.select_set(False)
    return "render"


@step
def shoot_clusters():
    shot("clusters")
    bpy.context.scene.hairstyle.motion = "shake"
    press("bake")
    return True


@step
def baked():
    if operators.running_job() is not None:
        return False
    bpy.context.scene.frame_set(30)
    bpy.context.scene.hairstyle.result_hair.select_set(False)
    return "render"


@step
def shoot_bake():
    shot("bake")
    bpy.ops.wm.quit_blender()
    return True


_state = {"step": 0, "wait": 0}


def tick():
    """Runs the current step; "shoot" waits two ticks for the window to redraw first,
    "render" twenty (EEVEE compiles its shaders)."""
    if _state["wait"]:
        _state["wait"] -= 1
        return 0.5
    done = STEPS[_state["step"]]()
    if done:
        _state["step"] += 1
        _state["wait"] = {"shoot": 2, "render": 20}.get(done, 0)
    return 0.25 if _state["step"] < len(STEPS) else None


bpy.app.timers.register(tick, first_interval=2.0)
