# Bringing a run's results into the scene: the grown strands as hair curves coloured by
# their cluster's style (a material reading the "style_colour" attribute; unsure clusters
# pale), the body of extract.h5, both under an empty scaled back to the scene's units so
# that they lie on the hair mesh they came from; the clusters' styles and confidences for
# the panel's list; after Fix style the new styles on the same curves; after a bake the
# curves and the body following frames.h5 (scene.attach_frames: the file is read as the
# frame changes).

import os

import bpy
import numpy as np

from . import hdf5_files, scene

# Custom property on the objects a conversion made: the output folder they show.
RESULT_PROPERTY = "hairstyle_result_of"
MATERIAL_NAME = "hairstyle styles"


def style_material():
    """A material colouring hair curves by their "style_colour" attribute (Cycles and
    EEVEE; Solid shading draws the attribute with Color: Attribute)."""
    material = bpy.data.materials.get(MATERIAL_NAME)
    if material is not None:
        return material
    material = bpy.data.materials.new(MATERIAL_NAME)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    shader = nodes.new("ShaderNodeBsdfPrincipled")
    colour = nodes.new("ShaderNodeAttribute")
    colour.attribute_name = "style_colour"
    shader.inputs["Roughness"].default_value = 0.5
    links.new(colour.outputs["Color"], shader.inputs["Base Color"])
    links.new(shader.outputs["BSDF"], output.inputs["Surface"])
    colour.location, shader.location, output.location = (-300, 0), (0, 0), (300, 0)
    material.diffuse_color = hdf5_files.STYLE_COLOURS[0] + (1.0,)
    return material


def remove_results(settings):
    """Removes the objects (and their data) of the scene's last conversion."""
    root = settings.result_root
    objects = [settings.result_hair, settings.result_body, root]
    if root is not None:
        objects += list(root.children)
    for obj in {o for o in objects if o is not None}:
        data = obj.data
        bpy.data.objects.remove(obj, do_unlink=True)
        if isinstance(data, bpy.types.Curves) and data.users == 0:
            bpy.data.hair_curves.remove(data)
        elif isinstance(data, bpy.types.Mesh) and data.users == 0:
            bpy.data.meshes.remove(data)
    settings.result_root = settings.result_hair = settings.result_body = None


def _cluster_table(folder):
    return hdf5_files.read_cluster_table(os.path.join(folder, "styles.h5"))


def fill_clusters(settings, table):
    """The panel's cluster list from styles.h5's table, keeping the active row."""
    active = settings.cluster_index
    settings.clusters.clear()
    for cluster in range(len(table["style"])):
        item = settings.clusters.add()
        item.cluster = cluster
        item.style = hdf5_files.STYLE_NAMES.get(int(table["style"][cluster]), "none")
        item.confidence = float(table["confidence"][cluster])
        item.unsure = bool(table["unsure"][cluster])
        item.pinned = bool(table["pinned"][cluster])
        item.strand_count = int(table["strand_count"][cluster])
    settings.cluster_index = min(max(active, 0), max(len(settings.clusters) - 1, 0))


def _int_attribute(curves_object, name):
    attribute = curves_object.data.attributes.get(name)
    if attribute is None:
        return None
    values = np.empty(len(attribute.data), dtype=np.int32)
    attribute.data.foreach_get("value", values)
    return values


def _restyle(hair, table):
    scene.set_style_attributes(hair, _int_attribute(hair, "cluster"), table["style"],
                               table["unsure"], _int_attribute(hair, "point_cluster"))


def bring_in(context, settings, folder, name, unit_scale):
    """The strands, styles and body of `folder` under an empty named after `name` (the
    hair mesh), scaled 1 / unit_scale; they replace the objects of the scene's last
    conversion where it was into the same folder (another hair mesh's stay)."""
    if settings.result_folder == folder:
        remove_results(settings)
    table = _cluster_table(folder)
    hair = scene.import_strands(os.path.join(folder, "strands.h5"), name=f"{name} strands")
    try:
        body = scene.import_body(os.path.join(folder, "extract.h5"), name=f"{name} body")
    except BaseException:
        bpy.data.objects.remove(hair, do_unlink=True)
        raise
    root = bpy.data.objects.new(f"{name} hairstyle", None)
    context.scene.collection.objects.link(root)
    root.empty_display_type = "PLAIN_AXES"
    root.empty_display_size = 0.05
    root.scale = (1.0 / unit_scale,) * 3
    for obj in (root, hair, body):
        obj[RESULT_PROPERTY] = folder
    hair.parent = body.parent = root
    hair.data.materials.append(style_material())
    _restyle(hair, table)  # the styles, with the unsure clusters pale
    settings.result_root, settings.result_hair, settings.result_body = root, hair, body
    settings.result_folder = folder
    fill_clusters(settings, table)
    return hair


def restyle(settings, folder):
    """The styles of `folder`'s styles.h5 on the converted curves and in the list."""
    table = _cluster_table(folder)
    hair = settings.result_hair
    if hair is not None:
        _restyle(hair, table)
        hair.data.update_tag()
    fill_clusters(settings, table)


def attach_bake(context, settings, folder, first, end):
    """The converted curves and body follow `folder`'s frames.h5 (its frames first to
    end - 1) from Blender frame 1; shows frame 1."""
    frames_path = os.path.join(folder, "frames.h5")
    hair, body = settings.result_hair, settings.result_body
    if hair is None:
        raise hdf5_files.HairstyleFileError(
            f"hairstyle: the converted strands of {folder} are no longer in the scene: "
            f"convert again")
    with hdf5_files.Frames(frames_path) as frames:
        count, fps = len(frames), frames.fps
        same_strands = len(frames.rest_points) == len(hair.data.points) \
            and len(frames.offsets) - 1 == len(hair.data.curves)
    if not same_strands:
        raise hdf5_files.HairstyleFileError(
            f"{frames_path}: its strands are not the converted ones (convert again)")
    scene.attach_frames(hair, frames_path, 0, count, fps, body)
    settings.baked_first, settings.baked_end = first, end
    context.scene.frame_set(1)

