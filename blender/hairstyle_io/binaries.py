# Where the add-on finds the pipeline's installed binaries, the style model classify
# needs and the parameter files of the stages: the folder set in the add-on's preferences
# first, then the PATH (binaries), then the places a source checkout or an installation
# keeps them. A binary that is nowhere is named, with how to get it, in one line.
# No Blender here: the functions take the preference values as arguments.

import os
import shutil

# The stages Convert, Fix style and Simulate and bake run.
STAGES = ("extract", "typeify", "cluster-middle", "cluster-all", "grow", "classify",
          "simulate", "interpolate")
# The style model of the pipeline's default (Makefile.pipeline's STYLE_MODEL).
STYLE_MODEL_NAME = "style_extended.yml"

# The repository holding this add-on, when it runs from a source checkout
# (blender/hairstyle_io/ -> the checkout).
_CHECKOUT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

HOW_TO_GET = ("build the binaries in the hairstyle source with 'make -f Makefile.pipeline "
              "build' and set their folder (build/bin) in Edit > Preferences > Add-ons > "
              "hairstyle, or put that folder on the PATH")


class MissingTool(Exception):
    """A binary, the style model or a parameter folder that is not there: one line."""


def find_binary(name, folder=""):
    """The path of the stage `name`: in `folder` (the preference) if set and there, else on
    the PATH; None where it is in neither."""
    if folder:
        candidate = os.path.join(os.path.expanduser(folder), name)
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return shutil.which(name)


def find_binaries(names, folder=""):
    """{name: path} of every stage in `names`; raises MissingTool naming all that are
    missing, where they were looked for and how to get them."""
    found = {name: find_binary(name, folder) for name in names}
    missing = [name for name, path in found.items() if path is None]
    if missing:
        where = f"in {folder} or on the PATH" if folder else "on the PATH"
        raise MissingTool(f"hairstyle: {', '.join(missing)} not found {where}: {HOW_TO_GET}")
    return found


def _bin_folder(binary_path):
    return os.path.dirname(os.path.realpath(binary_path)) if binary_path else ""


def _preferred(preference, exists, what, kind, setting):
    """The path a preference names (~ expanded); MissingTool naming the preference's
    `setting` where `exists` says there is no such `kind`."""
    path = os.path.expanduser(preference)
    if not exists(path):
        raise MissingTool(f"hairstyle: {what} {path}: no such {kind} (Edit > "
                          f"Preferences > Add-ons > hairstyle > {setting})")
    return path


def find_style_model(preference, classify_path):
    """The style model file: the preference if set, else style_extended.yml in the models/
    folder of the checkout or installation the binaries (or this add-on) come from."""
    if preference:
        return _preferred(preference, os.path.isfile, "style model", "file", "Style model")
    bin_folder = _bin_folder(classify_path)
    candidates = [os.path.join(bin_folder, "..", "..", "models", STYLE_MODEL_NAME),  # build/bin
                  os.path.join(bin_folder, "..", "share", "hairstyle", "models", STYLE_MODEL_NAME),
                  os.path.join(bin_folder, "..", "models", STYLE_MODEL_NAME),
                  os.path.join(_CHECKOUT, "models", STYLE_MODEL_NAME)]
    for candidate in candidates:
        if os.path.isfile(candidate):
            return os.path.normpath(candidate)
    raise MissingTool(f"hairstyle: no style model {STYLE_MODEL_NAME} beside the binaries "
                      f"({bin_folder}): set it (the source's models/{STYLE_MODEL_NAME}) in Edit > "
                      f"Preferences > Add-ons > hairstyle > Style model")


def find_parameters(preference, binary_path):
    """The folder of the stages' parameter files (pipelines/default in a checkout): the
    preference if set, else the checkout's beside the binaries or this add-on; "" when
    there is none (the stages' own defaults, which the default files equal)."""
    if preference:
        return _preferred(preference, os.path.isdir, "parameter folder", "folder", "Parameters")
    for candidate in (os.path.join(_bin_folder(binary_path), "..", "..", "pipelines", "default"),
                      os.path.join(_CHECKOUT, "pipelines", "default")):
        if os.path.isfile(os.path.join(candidate, "extract.toml")):
            return os.path.normpath(candidate)
    return ""


class Tools:
    """The binaries, style model and parameter folder of one run of the stages."""

    def __init__(self, binaries, style_model="", parameters=""):
        self.binaries = binaries
        self.style_model = style_model
        self.parameters = parameters

    def command(self, stage, *arguments):
        """The command line of `stage`: its binary, `arguments`, its parameter file when
        there is one (the arguments given here win over it, as the command line does)."""
        command = [self.binaries[stage], *arguments]
        if self.parameters:
            params = os.path.join(self.parameters, stage + ".toml")
            if os.path.isfile(params):
                command += ["--params", params]
        return command


def tools_for(stages, bin_folder="", style_model="", parameters=""):
    """Tools with every binary of `stages` (MissingTool naming the missing ones), the style
    model when classify is among them, and the parameter folder."""
    binaries = find_binaries(stages, bin_folder)
    model = find_style_model(style_model, binaries["classify"]) if "classify" in stages else ""
    params = find_parameters(parameters, next(iter(binaries.values())))
    return Tools(binaries, model, params)
