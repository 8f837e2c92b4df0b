# The stage chains the add-on runs, as Makefile.pipeline calls the stages (the same
# inputs, parameter files and options), without Blender:
#
#   Convert          extract typeify cluster-middle cluster-all grow classify
#   Fix style        classify (--overrides), then simulate and interpolate if a bake exists
#   Simulate, bake   simulate (a preset or --keyframes) and interpolate (--frames A:B)
#
# Every stage runs in the chain's work folder (runner.Chain): the files a chain makes are
# named relative to it, those it reads from an earlier run by their path in the output
# folder. The seconds each stage is expected to take are those of ponytail01 on 2 cores,
# only shares of the progress bar.

import os

from . import runner

# The files of a conversion, in the output folder.
MESH_FOLDER = "mesh"  # hair.obj (with its .mtl and textures) and body.obj
HAIR_OBJ = os.path.join(MESH_FOLDER, "hair.obj")
BODY_OBJ = os.path.join(MESH_FOLDER, "body.obj")
CONVERTED = ("extract.h5", "types.h5", "middle.h5", "clusters.h5", "strands.h5", "styles.h5")
OVERRIDES = "overrides.toml"
KEYFRAMES = "keyframes.csv"
BAKED = ("guides.h5", "frames.h5")

CONVERT_STAGES = ("extract", "typeify", "cluster-middle", "cluster-all", "grow", "classify")
BAKE_STAGES = ("simulate", "interpolate")


class BakeSettings:
    """What Simulate and bake runs with: a motion preset, or a keyframe file (its path, or
    its name in the work folder) that replaces it; the frames first to end - 1 of the
    simulation (simulate runs from time 0 to end / fps); frames per second."""

    def __init__(self, first, end, fps, motion="shake", keyframes=""):
        if not 0 <= first < end:
            raise ValueError(f"hairstyle: frames {first} to {end}: the first must be under the end")
        self.first, self.end, self.fps = int(first), int(end), float(fps)
        self.motion, self.keyframes = motion, keyframes


def _common(threads):
    return ["--threads", str(threads)]


def convert_steps(tools, unit_scale, strand_count, threads=0):
    """extract to classify on the meshes the chain's prepare writes (HAIR_OBJ, BODY_OBJ)."""
    common = _common(threads)
    return [
        runner.Step("extract", tools.command(
            "extract", HAIR_OBJ, "--body", BODY_OBJ, "-o", "extract.h5",
            "--unit_scale", repr(float(unit_scale)), *common), 1.0),
        runner.Step("typeify", tools.command(
            "typeify", "extract.h5", "-o", "types.h5", *common), 0.2),
        runner.Step("cluster-middle", tools.command(
            "cluster-middle", "types.h5", "-o", "middle.h5", *common), 0.2),
        runner.Step("cluster-all", tools.command(
            "cluster-all", "types.h5", "middle.h5", "-o", "clusters.h5", *common), 0.2),
        runner.Step("grow", tools.command(
            "grow", "extract.h5", "types.h5", "clusters.h5", "-o", "strands.h5",
            "--strand_count", str(int(strand_count)), *common), 2.0),
        classify_step(tools, "extract.h5", "clusters.h5", "strands.h5", None, threads),
    ]


def classify_step(tools, extract, clusters, strands, overrides, threads=0):
    """classify, with the pins of `overrides` when given."""
    arguments = [extract, clusters, strands, "--model", tools.style_model]
    if overrides:
        arguments += ["--overrides", overrides]
    return runner.Step("classify", tools.command(
        "classify", *arguments, "-o", "styles.h5", *_common(threads)), 1.0)


def bake_steps(tools, folder, settings, styles=None, threads=0):
    """simulate and interpolate on the output folder's extract.h5 and strands.h5, with
    `styles` (a styles.h5 the same chain makes) or the folder's styles.h5."""
    extract = os.path.join(folder, "extract.h5")
    strands = os.path.join(folder, "strands.h5")
    styles = styles or os.path.join(folder, "styles.h5")
    motion = ["--keyframes", settings.keyframes] if settings.keyframes else ["--motion", settings.motion]
    duration_s = settings.end / settings.fps
    frames = settings.end - settings.first
    return [
        runner.Step("simulate", tools.command(
            "simulate", extract, strands, styles, *motion, "--fps", repr(settings.fps),
            "--duration_s", repr(duration_s), "-o", "guides.h5", *_common(threads)),
            1.0 + 0.05 * frames),
        runner.Step("interpolate", tools.command(
            "interpolate", "guides.h5", strands, styles, "--frames",
            f"{settings.first}:{settings.end}", "-o", "frames.h5", *_common(threads)),
            0.5 + 0.3 * frames),
    ]


def fix_steps(tools, folder, bake=None, threads=0):
    """classify with the work folder's overrides (OVERRIDES), then, with the settings of
    the folder's bake, simulate and interpolate on the new styles."""
    steps = [classify_step(tools, os.path.join(folder, "extract.h5"),
                           os.path.join(folder, "clusters.h5"),
                           os.path.join(folder, "strands.h5"), OVERRIDES, threads)]
    if bake is not None:
        steps += bake_steps(tools, folder, bake, styles="styles.h5", threads=threads)
    return steps


def converted(folder):
    """Whether `folder` holds a conversion's results."""
    return all(os.path.isfile(os.path.join(folder, name)) for name in CONVERTED)


def baked(folder):
    return all(os.path.isfile(os.path.join(folder, name)) for name in BAKED)
