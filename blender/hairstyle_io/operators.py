# The panel's operators: Convert (hair mesh and body to strands with styles), Fix style
# (pin a cluster's style, rerun classify and what follows), Simulate and bake (simulate
# and interpolate under a head motion, the frames on the curves) and Cancel. Each builds a
# chain of stages (stages.py) and runs it in the background (runner.Chain): with a window,
# as a modal operator polling on a timer, the progress on the window manager for the
# panel's bar; headless (blender -b) or without a window, synchronously. One chain runs at
# a time. Errors reach the user as one report line (the stage's own error line, or what
# is missing and how to get it), never a traceback.

import os

import bpy
from bpy.props import EnumProperty, IntProperty

from . import (binaries, hdf5_files, keyframes, mesh_export, overrides, preferences,
               properties, results, runner, stages)

# Functions called with the chain after each poll of a synchronous run (headless), e.g.
# to print progress or, in a test, to press Cancel during a stage.
progress_listeners = []

_job = None  # the running Job


class Job:
    """A chain of stages and what brings its results in: finish(context) -> message."""

    def __init__(self, title, chain, prepare, finish):
        self.title, self.chain, self.prepare, self.finish = title, chain, prepare, finish


def running_job():
    return _job


def cancel_running():
    if _job is not None:
        _job.chain.cancel()


def drop_running():
    """Cancels the running chain and forgets it (its modal operator ends with the file)."""
    global _job
    cancel_running()
    _job = None


# Errors that are the user's to fix, reported in one line.
USER_ERRORS = (binaries.MissingTool, mesh_export.ExportError, hdf5_files.HairstyleFileError,
               overrides.OverridesError, ValueError, OSError)


def one_line(error):
    text = str(error).strip() or type(error).__name__
    return " ".join(text.split("\n"))


# Seconds between two polls of a chain in a window.
POLL_INTERVAL_S = 0.2


def _set_progress(context, fraction, status):
    """The panel's bar and status, written where they changed (to the percent) and shown
    by redrawing the 3D views' sidebars alone: written as ID properties, not through RNA,
    whose update would redraw every editor of the window (the viewport too), costing the
    stages CPU."""
    wm = context.window_manager
    percent = float(int(100.0 * fraction))
    if wm.hairstyle_progress == percent and wm.hairstyle_status == status:
        return
    wm["hairstyle_progress"] = percent
    wm["hairstyle_status"] = status
    screen = context.screen
    for area in (screen.areas if screen is not None else ()):
        if area.type == "VIEW_3D":
            for region in area.regions:
                if region.type == "UI":
                    region.tag_redraw()


class _StageOperator:
    """Runs a Job: modal with a window, synchronously without one."""

    def run(self, context, job):
        global _job
        if _job is not None:
            self.report({"ERROR"}, f"hairstyle: {_job.title} is running: wait for it or cancel it")
            return {"CANCELLED"}
        try:
            job.chain.start(prepare=job.prepare)
        except USER_ERRORS as error:
            self.report({"ERROR"}, one_line(error))
            return {"CANCELLED"}
        _job = job
        if bpy.app.background or context.window is None:
            return self._run_synchronously(context, job)
        _set_progress(context, 0.0, f"{job.title}: {job.chain.describe()}")
        self._job = job
        self._timer = context.window_manager.event_timer_add(POLL_INTERVAL_S, window=context.window)
        context.window_manager.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def _run_synchronously(self, context, job):
        shown = [None]

        def on_progress(chain):
            if chain.stage != shown[0]:
                shown[0] = chain.stage
                print(f"hairstyle: {job.title}: {chain.describe()}", flush=True)
            for listener in list(progress_listeners):
                listener(chain)

        job.chain.wait(on_progress=on_progress)
        return self._end(context, job)

    def modal(self, context, event):
        job = self._job
        if job is not _job:  # dropped (another file was opened)
            context.window_manager.event_timer_remove(self._timer)
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        state = job.chain.poll()
        if state == runner.RUNNING:
            _set_progress(context, job.chain.progress, f"{job.title}: {job.chain.describe()}")
            return {"PASS_THROUGH"}
        context.window_manager.event_timer_remove(self._timer)
        return self._end(context, job)

    def _end(self, context, job):
        global _job
        _job = None
        _set_progress(context, 0.0, "")
        state = job.chain.state
        if state == runner.CANCELLED:
            self.report({"WARNING"}, f"hairstyle: {job.title} cancelled; nothing was written")
            return {"CANCELLED"}
        if state != runner.DONE:
            self.report({"ERROR"}, one_line(job.chain.error))
            return {"CANCELLED"}
        try:
            message = job.finish(context)
        except USER_ERRORS as error:
            self.report({"ERROR"}, one_line(error))
            return {"CANCELLED"}
        self.report({"INFO"}, message)
        return {"FINISHED"}


def _settings(context):
    return context.scene.hairstyle


def _environment():
    environment = dict(os.environ)
    # Stages share the cores with Blender: a waiting OpenMP thread sleeps (Makefile.pipeline).
    environment.setdefault("OMP_WAIT_POLICY", "passive")
    return environment


def _hair_and_body(context, settings):
    hair = settings.hair_mesh
    if hair is None:
        active = context.active_object
        if active is not None and active.type == "MESH" and active != settings.body_mesh:
            hair = active
    return hair, settings.body_mesh


class HAIRSTYLE_OT_convert(_StageOperator, bpy.types.Operator):
    """Convert the hair mesh (its cards, material and texture) and the body to strands with styles: extract, typeify, cluster-middle, cluster-all, grow and classify in the background"""

    bl_idname = "hairstyle.convert"
    bl_label = "Convert"
    bl_options = {"REGISTER"}

    @classmethod
    def poll(cls, context):
        return _job is None

    def execute(self, context):
        settings = _settings(context)
        hair, body = _hair_and_body(context, settings)
        try:
            if hair is None:
                raise mesh_export.ExportError(
                    "hairstyle: choose a hair mesh in the hairstyle panel (or make it active)")
            tools, threads = preferences.tools(context, stages.CONVERT_STAGES)
        except USER_ERRORS as error:
            self.report({"ERROR"}, one_line(error))
            return {"CANCELLED"}
        folder = properties.output_folder(settings, hair.name)
        unit_scale, hair_name = settings.unit_scale, hair.name
        chain = runner.Chain(
            stages.convert_steps(tools, unit_scale, settings.strand_count, threads), folder,
            keep=[*stages.CONVERTED, stages.MESH_FOLDER],
            remove=[*stages.BAKED, stages.OVERRIDES, stages.KEYFRAMES],
            environment=_environment())

        def prepare(work):
            mesh_export.write_meshes(hair, body, os.path.join(work, stages.HAIR_OBJ),
                                     os.path.join(work, stages.BODY_OBJ))

        def finish(context):
            settings.baked_first = settings.baked_end = -1
            curves = results.bring_in(context, settings, folder, hair_name, unit_scale)
            unsure = sum(item.unsure for item in settings.clusters)
            return (f"hairstyle: {hair_name}: {len(curves.data.curves)} strands in "
                    f"{len(settings.clusters)} clusters ({unsure} unsure) from {folder}")

        return self.run(context, Job("Convert", chain, prepare, finish))


class HAIRSTYLE_OT_fix_style(_StageOperator, bpy.types.Operator):
    """Pin the chosen cluster's style (classify's overrides file in the results folder) and rerun classify, and simulate and interpolate if there is a bake"""

    bl_idname = "hairstyle.fix_style"
    bl_label = "Fix style"
    bl_options = {"REGISTER"}

    cluster: IntProperty(name="Cluster", default=-1, min=-1,
                         description="the cluster to pin (-1: the one chosen in the list)")
    style: EnumProperty(name="Style", items=properties.FIX_ITEMS,
                        description="the style to pin it to")

    @classmethod
    def poll(cls, context):
        settings = _settings(context)
        return _job is None and bool(settings.result_folder) and len(settings.clusters) > 0

    def execute(self, context):
        settings = _settings(context)
        folder = settings.result_folder
        cluster = self.cluster
        if cluster < 0 and 0 <= settings.cluster_index < len(settings.clusters):
            cluster = settings.clusters[settings.cluster_index].cluster
        style = None if self.style == "classified" else self.style
        bake = _last_bake(settings, folder)
        try:
            if not stages.converted(folder):
                raise hdf5_files.HairstyleFileError(f"hairstyle: {folder}: no conversion there: "
                                                    f"convert first")
            if not 0 <= cluster < len(settings.clusters):
                raise ValueError(f"hairstyle: no cluster {cluster} (0 to {len(settings.clusters) - 1})")
            pins = overrides.pin_cluster(
                overrides.read_pins(os.path.join(folder, stages.OVERRIDES)), cluster, style)
            names = stages.CONVERT_STAGES[-1:] + (stages.BAKE_STAGES if bake else ())
            tools, threads = preferences.tools(context, names)
        except USER_ERRORS as error:
            self.report({"ERROR"}, one_line(error))
            return {"CANCELLED"}
        keep = ["styles.h5", stages.OVERRIDES] + (list(stages.BAKED) if bake else [])
        chain = runner.Chain(stages.fix_steps(tools, folder, bake, threads), folder, keep,
                             environment=_environment())

        def prepare(work):
            overrides.write_pins(os.path.join(work, stages.OVERRIDES), pins)

        def finish(context):
            results.restyle(settings, folder)
            if bake is not None:
                results.attach_bake(context, settings, folder, bake.first, bake.end)
            now = settings.clusters[cluster].style
            what = f"pinned {style}" if style else f"unpinned: {now}"
            return (f"hairstyle: cluster {cluster} {what}; classify"
                    f"{', simulate and interpolate' if bake else ''} reran")

        return self.run(context, Job("Fix style", chain, prepare, finish))


def _last_bake(settings, folder):
    """The settings of `folder`'s bake, for Fix style to rerun it; None without one."""
    if settings.baked_end < 0 or not stages.baked(folder):
        return None
    keyframe_file = os.path.join(folder, stages.KEYFRAMES)
    from_object = settings.baked_motion == "OBJECT" and os.path.isfile(keyframe_file)
    return stages.BakeSettings(settings.baked_first, settings.baked_end, settings.baked_fps,
                               motion=settings.baked_motion if not from_object else "",
                               keyframes=keyframe_file if from_object else "")


class HAIRSTYLE_OT_bake(_StageOperator, bpy.types.Operator):
    """Simulate the converted strands under the head motion and interpolate every strand, then play the frames on the curves (read from frames.h5 as the frame changes)"""

    bl_idname = "hairstyle.bake"
    bl_label = "Simulate and bake"
    bl_options = {"REGISTER"}

    @classmethod
    def poll(cls, context):
        settings = _settings(context)
        return _job is None and bool(settings.result_folder) and settings.result_hair is not None

    def execute(self, context):
        settings = _settings(context)
        folder = settings.result_folder
        fps = context.scene.render.fps / context.scene.render.fps_base
        try:
            if not stages.converted(folder):
                raise hdf5_files.HairstyleFileError(f"hairstyle: {folder}: no conversion there: "
                                                    f"convert first")
            csv = self._keyframes(context, settings, fps) if settings.motion == "OBJECT" else None
            bake = stages.BakeSettings(settings.bake_first, settings.bake_end, fps,
                                       motion=settings.motion if csv is None else "",
                                       keyframes=stages.KEYFRAMES if csv is not None else "")
            tools, threads = preferences.tools(context, stages.BAKE_STAGES)
        except USER_ERRORS as error:
            self.report({"ERROR"}, one_line(error))
            return {"CANCELLED"}
        keep = list(stages.BAKED) + ([stages.KEYFRAMES] if csv is not None else [])
        remove = [] if csv is not None else [stages.KEYFRAMES]
        chain = runner.Chain(stages.bake_steps(tools, folder, bake, threads=threads), folder,
                             keep, remove, environment=_environment())

        def prepare(work):
            if csv is not None:
                with open(os.path.join(work, stages.KEYFRAMES), "w") as file:
                    file.write(csv)

        motion = settings.motion

        def finish(context):
            settings.baked_fps, settings.baked_motion = fps, motion
            results.attach_bake(context, settings, folder, bake.first, bake.end)
            return (f"hairstyle: frames {bake.first} to {bake.end - 1} on "
                    f"{settings.result_hair.name}, Blender frames 1 to {bake.end - bake.first}")

        return self.run(context, Job("Simulate and bake", chain, prepare, finish))

    @staticmethod
    def _keyframes(context, settings, fps):
        obj = settings.motion_object or context.active_object
        if obj is None:
            raise ValueError("hairstyle: choose the motion object (or make it active)")
        csv = keyframes.object_keyframes(obj, context.scene, settings.bake_end + 1, fps,
                                         metres_per_unit=settings.unit_scale)
        if csv is None:
            raise ValueError(f"hairstyle: {obj.name} has no animation: animate it, or choose "
                             f"a motion preset")
        return csv


class HAIRSTYLE_OT_cancel(bpy.types.Operator):
    """Cancel the running stage: it is stopped and nothing it was writing is kept"""

    bl_idname = "hairstyle.cancel"
    bl_label = "Cancel"
    bl_options = {"INTERNAL"}

    @classmethod
    def poll(cls, context):
        return _job is not None

    def execute(self, context):
        cancel_running()
        return {"FINISHED"}


CLASSES = (HAIRSTYLE_OT_convert, HAIRSTYLE_OT_fix_style, HAIRSTYLE_OT_bake, HAIRSTYLE_OT_cancel)
