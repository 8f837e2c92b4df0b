# Times Convert from inside Blender (docs/measured/blender_convert.md): opens the body and
# a sample's cards, presses Convert through its operator (synchronously, headless) RUNS
# times, each into a fresh folder under WORK_DIR, and prints per run the seconds from the
# press to the strands in the scene, of which the meshes were written and the stages ran,
# and the results were brought in:
#
#   blender -b --factory-startup --python tests/blender/time_convert.py \
#     -- ADDON_DIR BIN_DIR SAMPLES_DIR WORK_DIR [MODEL] [RUNS]
#
# Without -b, in a window (xvfb-run where there is no screen), Convert is pressed as from
# the panel: the modal operator, its chain polled on a timer; Blender quits after the runs.

import os
import resource
import sys
import time

import bpy

arguments = sys.argv[sys.argv.index("--") + 1:]
addon_dir, bin_dir, samples_dir, work_dir = arguments[:4]
model = arguments[4] if len(arguments) > 4 else "ponytail01"
runs = int(arguments[5]) if len(arguments) > 5 else 1
sys.dont_write_bytecode = True
sys.path.insert(0, addon_dir)

import addon_utils  # noqa: E402

addon_utils.enable("hairstyle_io", default_set=True)
from hairstyle_io import operators, results  # noqa: E402

bpy.context.preferences.addons["hairstyle_io"].preferences.bin_folder = bin_dir
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
opened = []
for path in (os.path.join(samples_dir, "body.obj"), os.path.join(samples_dir, "hair", model + ".obj")):
    bpy.ops.wm.obj_import(filepath=path)
    opened.append(bpy.context.selected_objects[0])
settings = bpy.context.scene.hairstyle
settings.body_mesh, settings.hair_mesh, settings.unit_scale = opened[0], opened[1], 0.1

chain_end = {}
bring_in = results.bring_in


def timed_bring_in(*args, **kwargs):
    chain_end["at"] = time.monotonic()
    return bring_in(*args, **kwargs)


results.bring_in = timed_bring_in


def cpu_s():
    """CPU seconds of Blender itself and of the stages it ran (ended ones)."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime, children.ru_utime + children.ru_stime


def report(run, started, result):
    total = time.monotonic() - started
    stages = chain_end["at"] - started
    own, children = (now - then for now, then in zip(cpu_s(), chain_end["cpu"]))
    print(f"time_convert: run {run + 1}: {total:.2f} s from Convert to the strands in the scene "
          f"({stages:.2f} s writing the meshes and running the stages, {total - stages:.2f} s "
          f"bringing them in; CPU: Blender {own:.2f} s, the stages {children:.2f} s), {result}",
          flush=True)


def press_in_window():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    region = next(r for r in area.regions if r.type == "WINDOW")
    with bpy.context.temp_override(window=window, area=area, region=region):
        return bpy.ops.hairstyle.convert("INVOKE_DEFAULT")


if bpy.app.background:
    for run in range(runs):
        settings.folder = os.path.join(work_dir, f"{model}_{run}")
        started, chain_end["cpu"] = time.monotonic(), cpu_s()
        report(run, started, bpy.ops.hairstyle.convert())
else:
    state = {"run": 0, "started": None}

    def tick():
        """Presses Convert, then polls until its chain and import are done, RUNS times."""
        if state["started"] is None:
            settings.folder = os.path.join(work_dir, f"{model}_{state['run']}")
            state["started"], chain_end["cpu"] = time.monotonic(), cpu_s()
            press_in_window()
            return 0.1
        if operators.running_job() is not None:
            return 0.1
        report(state["run"], state["started"], "modal")
        state["run"], state["started"] = state["run"] + 1, None
        if state["run"] == runs:
            bpy.ops.wm.quit_blender()
            return None
        return 0.5

    bpy.app.timers.register(tick, first_interval=2.0)
