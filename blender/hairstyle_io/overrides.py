# The pins of classify's --overrides file (docs/classify.md, "Unsure styles and pins"),
# read and written without Blender: Fix style pins a cluster by its id, replacing any pin
# of that cluster and keeping every other pin (by cluster or by point) of the file.
#
#   [[pin]]
#   cluster = 5
#   style = "fixed"

import os

try:
    import tomllib
except ImportError:  # Python before 3.11
    tomllib = None

STYLES = ("normal", "fixed", "short", "braided")


class OverridesError(Exception):
    """An overrides file the add-on cannot read: one line naming it."""


def read_pins(path):
    """The pins of the file at `path` (a list of dicts: cluster or point_m, and style);
    [] when there is no file."""
    if not os.path.exists(path):
        return []
    if tomllib is None:
        raise OverridesError(f"{path}: this Python has no tomllib (Python 3.11 or later)")
    try:
        with open(path, "rb") as file:
            document = tomllib.load(file)
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise OverridesError(f"{path}: {error}") from error
    pins = document.get("pin", [])
    if not isinstance(pins, list) or not all(isinstance(pin, dict) for pin in pins):
        raise OverridesError(f"{path}: 'pin' is not a list of tables ([[pin]])")
    return pins


def pin_cluster(pins, cluster, style):
    """The pins with cluster `cluster` pinned to `style`, or unpinned where style is None
    (classify decides again)."""
    if style is not None and style not in STYLES:
        raise OverridesError(f"style '{style}' is none of {', '.join(STYLES)}")
    kept = [pin for pin in pins if pin.get("cluster") != cluster]
    if style is not None:
        kept.append({"cluster": int(cluster), "style": style})
    return sorted(kept, key=lambda pin: (0, pin["cluster"]) if "cluster" in pin else (1, 0))


def _value(value):
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


def to_toml(pins):
    lines = ["# classify --overrides: the styles pinned in Blender (hairstyle_io, Fix style)",
             "# and any pins written here by hand (docs/classify.md)."]
    for pin in pins:
        lines += ["", "[[pin]]"]
        lines += [f"{key} = {_value(value)}" for key, value in pin.items()]
    return "\n".join(lines) + "\n"


def write_pins(path, pins):
    """Writes the pins to `path` (a temporary name, then a rename)."""
    temporary = os.path.join(os.path.dirname(path) or ".", "." + os.path.basename(path) + ".tmp")
    with open(temporary, "w") as file:
        file.write(to_toml(pins))
    os.replace(temporary, path)


def pinned_clusters(pins):
    """{cluster id: style} of the pins by cluster."""
    return {int(pin["cluster"]): pin.get("style") for pin in pins if "cluster" in pin}
