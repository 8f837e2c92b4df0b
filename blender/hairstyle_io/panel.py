# The hairstyle panel in the 3D viewport's sidebar (N > Hairstyle): Convert with its
# options and, while a chain of stages runs, its progress bar and Cancel; the clusters of
# the conversion with their style and confidence (unsure and pinned ones marked) and Fix
# style; Simulate and bake with the motion and the frames.

import bpy

from . import operators

# The style's colour in the list, as near as Blender's icons come to the paper's colours.
STYLE_ICONS = {"normal": "COLLECTION_COLOR_03", "fixed": "COLLECTION_COLOR_08",
               "short": "COLLECTION_COLOR_04", "braided": "COLLECTION_COLOR_05",
               "none": "OUTLINER_COLLECTION"}


# Shares of the list's width: id, style, confidence, strands, marks.
COLUMN_WIDTHS = (0.08, 0.26, 0.18, 0.18, 0.3)


def _columns(layout):
    """The cluster list's columns in `layout`, as rows."""
    columns, remaining = [], 1.0
    for width in COLUMN_WIDTHS[:-1]:
        split = layout.split(factor=width / remaining)
        columns.append(split.row())
        layout, remaining = split, remaining - width
    return columns + [layout.row()]


class HAIRSTYLE_UL_clusters(bpy.types.UIList):
    """A cluster a row: id, style (its colour), confidence, strands; unsure and pinned
    marked."""

    def draw_item(self, context, layout, data, item, icon, active_data, active_property,
                  index=0, flt_flag=0):
        cluster, style, confidence, strands, marks = _columns(layout)
        cluster.label(text=f"{item.cluster}")
        style.label(text=item.style, icon=STYLE_ICONS.get(item.style, "QUESTION"))
        confidence.label(text=f"{item.confidence:.2f}")
        strands.label(text=f"{item.strand_count}")
        if item.unsure:
            marks.label(text="unsure", icon="ERROR")
        if item.pinned:
            marks.label(text="pinned", icon="PINNED")


class _Panel:
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Hairstyle"


class HAIRSTYLE_PT_convert(_Panel, bpy.types.Panel):
    bl_idname = "HAIRSTYLE_PT_convert"
    bl_label = "Hairstyle"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.hairstyle
        column = layout.column()
        column.prop(settings, "hair_mesh")
        column.prop(settings, "body_mesh")
        column.prop(settings, "unit_scale")
        column.prop(settings, "strand_count")
        column.prop(settings, "folder")
        job = operators.running_job()
        if job is None:
            layout.operator("hairstyle.convert", icon="OUTLINER_OB_CURVES")
            if settings.result_folder:
                layout.label(text=f"Results: {settings.result_folder}", icon="FILE_FOLDER")
            return
        wm = context.window_manager
        row = layout.row(align=True)
        row.prop(wm, "hairstyle_progress", text=wm.hairstyle_status or job.title, slider=True)
        row.operator("hairstyle.cancel", text="", icon="CANCEL")


class HAIRSTYLE_PT_clusters(_Panel, bpy.types.Panel):
    bl_idname = "HAIRSTYLE_PT_clusters"
    bl_label = "Clusters"
    bl_parent_id = "HAIRSTYLE_PT_convert"

    @classmethod
    def poll(cls, context):
        return len(context.scene.hairstyle.clusters) > 0

    def draw(self, context):
        layout = self.layout
        settings = context.scene.hairstyle
        for column, text in zip(_columns(layout.row()), ("id", "style", "conf.", "strands",
                                                           "")):
            column.label(text=text)
        layout.template_list("HAIRSTYLE_UL_clusters", "", settings, "clusters", settings,
                             "cluster_index", rows=min(max(len(settings.clusters), 3), 10))
        unsure = [item.cluster for item in settings.clusters if item.unsure]
        if unsure:
            layout.label(text="Unsure: " + ", ".join(str(c) for c in unsure) +
                         " (drawn pale): check them", icon="ERROR")
        row = layout.row(align=True)
        row.prop(settings, "fix_style", text="")
        op = row.operator("hairstyle.fix_style", icon="PINNED")
        if 0 <= settings.cluster_index < len(settings.clusters):
            op.cluster = settings.clusters[settings.cluster_index].cluster
        op.style = settings.fix_style


class HAIRSTYLE_PT_bake(_Panel, bpy.types.Panel):
    bl_idname = "HAIRSTYLE_PT_bake"
    bl_label = "Simulate and bake"
    bl_parent_id = "HAIRSTYLE_PT_convert"

    @classmethod
    def poll(cls, context):
        return context.scene.hairstyle.result_hair is not None

    def draw(self, context):
        layout = self.layout
        settings = context.scene.hairstyle
        column = layout.column()
        column.prop(settings, "motion")
        if settings.motion == "OBJECT":
            column.prop(settings, "motion_object")
        row = column.row(align=True)
        row.prop(settings, "bake_first")
        row.prop(settings, "bake_end")
        fps = context.scene.render.fps / context.scene.render.fps_base
        column.label(text=f"{settings.bake_end / fps:.2f} s simulated at {fps:g} fps; "
                          f"{max(settings.bake_end - settings.bake_first, 0)} frames brought in")
        layout.operator("hairstyle.bake", icon="PHYSICS")
        if settings.baked_end >= 0:
            layout.label(text=f"Baked: frames {settings.baked_first} to {settings.baked_end - 1} "
                              f"({settings.baked_motion.lower()})", icon="CHECKMARK")


CLASSES = (HAIRSTYLE_UL_clusters, HAIRSTYLE_PT_convert, HAIRSTYLE_PT_clusters,
           HAIRSTYLE_PT_bake)
