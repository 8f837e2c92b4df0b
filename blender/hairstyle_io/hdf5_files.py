# Reading the hairstyle pipeline's HDF5 files with h5py, without Blender: each reader
# checks the file's schema and version (schemas/*.json) and the shapes it needs, and
# raises HairstyleFileError with one line naming the file otherwise.

import os

import numpy as np

# The schema versions this add-on reads (schemas/*.json; a test keeps them equal).
SCHEMA_VERSIONS = {
    "hairstyle.extract": 3,
    "hairstyle.strands": 2,
    "hairstyle.styles": 5,
    "hairstyle.frames": 1,
    "hairstyle.guides": 1,
}

# The style enum of styles.h5 and frames.h5, and the paper's colours (Figure 9), RGB 0-1.
STYLE_NAMES = {-1: "none", 0: "normal", 1: "fixed", 2: "short", 3: "braided"}
STYLE_COLOURS = {
    -1: (0.59, 0.59, 0.59),
    0: (0.94, 0.82, 0.16),  # normal: yellow
    1: (0.55, 0.29, 0.12),  # fixed: brown
    2: (0.24, 0.71, 0.24),  # short: green
    3: (0.12, 0.43, 0.86),  # braided: blue
}


class HairstyleFileError(Exception):
    """A file the add-on cannot read: one line, naming the file."""


def _h5py():
    try:
        import h5py
    except ImportError as error:
        raise HairstyleFileError(
            "h5py is not importable in this Python (Debian: apt install python3-h5py): "
            + str(error)) from error
    return h5py


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def _open(path, expected_schema):
    h5py = _h5py()
    if not os.path.exists(path):
        raise HairstyleFileError(f"{path}: no such file")
    try:
        file = h5py.File(path, "r")
    except OSError as error:
        raise HairstyleFileError(f"{path}: not an HDF5 file ({error})") from error
    schema = _text(file.attrs.get("schema", ""))
    version = int(file.attrs.get("schema_version", -1))
    if schema != expected_schema:
        file.close()
        raise HairstyleFileError(
            f"{path}: schema '{schema or 'none'}', expected {expected_schema}")
    if version != SCHEMA_VERSIONS[expected_schema]:
        file.close()
        raise HairstyleFileError(
            f"{path}: {schema} version {version}, this add-on reads version "
            f"{SCHEMA_VERSIONS[expected_schema]} (rerun the stage, or update the add-on)")
    return file


def _dataset(file, path, name, ndim, columns=None):
    if name not in file:
        raise HairstyleFileError(f"{path}: no dataset {name}")
    data = file[name][()]
    if data.ndim != ndim or (columns is not None and data.shape[-1] != columns):
        raise HairstyleFileError(f"{path}: {name} has shape {data.shape}")
    return data


def schema_of(path):
    """The schema attribute of an HDF5 file, or '' when it has none."""
    h5py = _h5py()
    if not os.path.exists(path):
        raise HairstyleFileError(f"{path}: no such file")
    try:
        with h5py.File(path, "r") as file:
            return _text(file.attrs.get("schema", ""))
    except OSError as error:
        raise HairstyleFileError(f"{path}: not an HDF5 file ({error})") from error


def _check_offsets(path, offsets, point_count):
    if (len(offsets) < 1 or offsets[0] != 0 or offsets[-1] != point_count
            or np.any(np.diff(offsets) < 1)):
        raise HairstyleFileError(f"{path}: /strands/offsets do not split the points into strands")


def read_strands(path):
    """strands.h5: points (n x 3, metres, +Y up), offsets (strands + 1) and each strand's
    cluster."""
    with _open(path, "hairstyle.strands") as file:
        points = _dataset(file, path, "/strands/points", 2, 3).astype(np.float32)
        offsets = _dataset(file, path, "/strands/offsets", 1).astype(np.int64)
        cluster = _dataset(file, path, "/strands/strand_attributes/cluster", 1).astype(np.int32)
    _check_offsets(path, offsets, len(points))
    if len(cluster) != len(offsets) - 1:
        raise HairstyleFileError(f"{path}: a cluster for {len(cluster)} of "
                                 f"{len(offsets) - 1} strands")
    return points, offsets, cluster


def read_point_clusters(path):
    """strands.h5: the cluster of every point (a strand can run through several)."""
    with _open(path, "hairstyle.strands") as file:
        count = file["/strands/points"].shape[0] if "/strands/points" in file else -1
        cluster = _dataset(file, path, "/strands/point_attributes/cluster", 1).astype(np.int32)
    if len(cluster) != count:
        raise HairstyleFileError(f"{path}: a cluster for {len(cluster)} of {count} points")
    return cluster


def read_cluster_styles(path):
    """styles.h5: the style of every cluster (-1 none) and whether the user pinned it."""
    with _open(path, "hairstyle.styles") as file:
        style = _dataset(file, path, "/clusters/style", 1).astype(np.int32)
        pinned = _dataset(file, path, "/clusters/pinned", 1).astype(np.int32)
    return style, pinned


def read_cluster_table(path):
    """styles.h5: per cluster its style (-1 none), confidence (0 to 1), whether it is
    unsure, pinned, and its strands; a dict of equally long arrays."""
    with _open(path, "hairstyle.styles") as file:
        table = {"style": _dataset(file, path, "/clusters/style", 1).astype(np.int32),
                 "confidence": _dataset(file, path, "/clusters/confidence", 1).astype(np.float64),
                 "unsure": _dataset(file, path, "/clusters/unsure", 1).astype(bool),
                 "pinned": _dataset(file, path, "/clusters/pinned", 1).astype(bool),
                 "strand_count": _dataset(file, path, "/clusters/strand_count", 1).astype(np.int64)}
    if len({len(column) for column in table.values()}) != 1:
        raise HairstyleFileError(f"{path}: the /clusters datasets differ in length")
    return table


def read_body(path):
    """extract.h5: the body's vertices (metres, +Y up) and triangles."""
    with _open(path, "hairstyle.extract") as file:
        vertices = _dataset(file, path, "/body/vertices", 2, 3).astype(np.float32)
        triangles = _dataset(file, path, "/body/triangles", 2, 3).astype(np.int32)
    if len(triangles) and (triangles.min() < 0 or triangles.max() >= len(vertices)):
        raise HairstyleFileError(f"{path}: /body/triangles name missing vertices")
    return vertices, triangles


class Frames:
    """frames.h5 (interpolate: every strand) or guides.h5 (simulate: the guides), opened:
    rest strands, per-strand cluster and the clusters' styles, the head's pose per frame,
    frames read one at a time (each is one compressed chunk)."""

    def __init__(self, path):
        self.path = path
        schema = schema_of(path)
        guides = schema == "hairstyle.guides"
        self.file = _open(path, "hairstyle.guides" if guides else "hairstyle.frames")
        group = "/guides" if guides else "/strands"
        self.offsets = _dataset(self.file, path, group + "/offsets", 1).astype(np.int64)
        self.rest_points = _dataset(self.file, path, group + "/rest_points", 2, 3)
        _check_offsets(path, self.offsets, len(self.rest_points))
        self.cluster = _dataset(self.file, path, group + "/cluster", 1).astype(np.int32)
        self.cluster_style = _dataset(self.file, path, "/clusters/style", 1).astype(np.int32)
        self.time_s = _dataset(self.file, path, "/frames/time_s", 1).astype(np.float64)
        self.points_name = "/frames/guide_points" if guides else "/frames/points"
        self.index = (np.arange(len(self.time_s)) if guides
                      else _dataset(self.file, path, "/frames/index", 1).astype(np.int64))
        points = self.file[self.points_name] if self.points_name in self.file else None
        if points is None or points.ndim != 3 or points.shape[1:] != (len(self.rest_points), 3) \
                or points.shape[0] != len(self.index):
            raise HairstyleFileError(f"{path}: {self.points_name} is not one frame of every "
                                     f"point per time")
        self.fps = float(self.file.attrs.get("fps", 30.0))
        self.head_rotation = _dataset(self.file, path, "/frames/head_rotation", 2, 4)
        self.head_translation_m = _dataset(self.file, path, "/frames/head_translation_m", 2, 3)
        if len(self.head_rotation) != len(self.index) or len(self.head_translation_m) != len(self.index):
            raise HairstyleFileError(f"{path}: a head pose for each of {len(self.index)} frames expected")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        self.file.close()

    def __len__(self):
        return len(self.index)

    def points(self, k):
        """The points of the k-th frame stored (n x 3, metres, +Y up)."""
        return self.file[self.points_name][k].astype(np.float32)
