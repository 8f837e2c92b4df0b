# Writing the hair mesh and the body out of Blender for extract: OBJ through Blender's
# own exporter, with the objects' world transforms and modifiers applied and Blender's
# +Z up turned back to the files' +Y up (the importer's inverse, so a mesh imported from
# an OBJ is written with the coordinates it was read with); the hair with its material
# library and its textures copied beside it (the painted flow extract reads), the body
# without.

import os

import bpy


class ExportError(Exception):
    """A mesh that cannot be written: one line."""


def _export_one(obj, path, with_materials):
    view_layer = bpy.context.view_layer
    if view_layer.objects.get(obj.name) is None:
        raise ExportError(f"hairstyle: {obj.name} is not in the view layer: it cannot be written")
    was_selected = [o for o in view_layer.objects if o.select_get()]
    was_active = view_layer.objects.active
    was_hidden = obj.hide_get()
    try:
        for other in was_selected:
            other.select_set(False)
        obj.hide_set(False)
        obj.select_set(True)
        view_layer.objects.active = obj
        result = bpy.ops.wm.obj_export(
            filepath=path, export_selected_objects=True, apply_modifiers=True,
            export_materials=with_materials, path_mode="COPY" if with_materials else "AUTO",
            export_uv=with_materials, export_normals=False, export_triangulated_mesh=False,
            export_animation=False, forward_axis="NEGATIVE_Z", up_axis="Y", global_scale=1.0)
    except RuntimeError as error:  # the exporter's own error report
        raise ExportError(f"hairstyle: {obj.name}: {' '.join(str(error).split())}") from error
    finally:
        obj.select_set(False)
        obj.hide_set(was_hidden)
        for other in was_selected:
            other.select_set(True)
        view_layer.objects.active = was_active
    if "FINISHED" not in result or not os.path.isfile(path):
        raise ExportError(f"hairstyle: Blender's OBJ exporter did not write {obj.name}")


def write_meshes(hair, body, hair_path, body_path):
    """Writes mesh objects `hair` (with its material and textures) and `body` as OBJ."""
    for obj, role in ((hair, "hair mesh"), (body, "body")):
        if obj is None or obj.type != "MESH":
            raise ExportError(f"hairstyle: choose a {role} (a mesh object) in the hairstyle panel")
        if len(obj.data.polygons) == 0:
            raise ExportError(f"hairstyle: {obj.name} has no faces: it cannot be the {role}")
    if hair == body:
        raise ExportError(f"hairstyle: {hair.name} is chosen as both the hair mesh and the body")
    os.makedirs(os.path.dirname(hair_path), exist_ok=True)
    os.makedirs(os.path.dirname(body_path), exist_ok=True)
    _export_one(hair, hair_path, with_materials=True)
    _export_one(body, body_path, with_materials=False)
