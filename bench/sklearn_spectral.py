#!/usr/bin/env python3
"""Our spectral clustering against scikit-learn's on the same graph.

    bench/sklearn_spectral.py [--runs N] [--times TSV] FILE.h5...

Each FILE is a middle.h5 (cluster-middle) or a clusters.h5 (cluster-all). The
script rebuilds the affinity matrix spectral clustering ran on (a scipy.sparse
csr matrix from /graph/edges and /graph/affinity, symmetric, zero diagonal)
over the nodes that were clustered:

  middle.h5    the middle-type groups (/groups/middle_cluster >= 0); our labels
               are /groups/middle_cluster at those groups;
  clusters.h5  the graph nodes (len(/nodes/set)); our label of a node is
               /groups/cluster_before_split at any of its groups (/groups/node).

It runs sklearn.cluster.SpectralClustering(n_clusters=<our cluster_count>,
affinity='precomputed', random_state=0, n_init=10) with assign_labels='kmeans'
and 'discretize' (scikit-learn's default eigensolver, ARPACK in shift-invert
mode), and 'kmeans' once more with eigen_solver='lobpcg' (which scikit-learn
answers with a dense eigh when nodes < 5 k + 1), and prints one Markdown table
row per file, then a legend of the reasons for disagreement: nodes,
edges, connected components (scipy.sparse.csgraph), isolated nodes, our k and
how it was chosen, ARI(ours, components), ARI(ours, sklearn) with
sklearn.metrics.adjusted_rand_score, the median time of RUNS fits
(time.perf_counter) and our time for the stage: from --times (a file of
"PATH<TAB>MILLISECONDS" lines, the median wall time of the stage binary that
wrote PATH, as bench/cluster_compare.sh measures it) and from the file's
provenance attribute wall_time_s (absent from --reproducible runs).

Files with 0 or 1 clustered nodes are skipped with a note; where scikit-learn
refuses (k >= nodes with a sparse matrix: ARPACK cannot find every eigenvector)
the cell says so. scikit-learn warns about disconnected graphs; the warning is
suppressed and the components column shows it instead.

Needs numpy, scipy, h5py and scikit-learn (Debian: python3-sklearn python3-h5py).
scikit-learn's k-means runs on OpenMP threads: on a busy machine a fit can stall
for ~160 ms waiting for them; OMP_NUM_THREADS=1 avoids that on these small graphs.
"""

import argparse
import os
import statistics
import sys
import time
import warnings

import h5py
import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components
from sklearn.cluster import SpectralClustering
from sklearn.metrics import adjusted_rand_score


def attr_str(h5, name):
    value = h5.attrs.get(name)
    if isinstance(value, bytes):
        value = value.decode()
    return value


def load(path):
    """The clustered graph of one file: its stage, our labels per node, the csr
    affinity matrix over those nodes, k and how k was chosen."""
    with h5py.File(path, "r") as h5:
        stage = attr_str(h5, "stage")
        edges = h5["/graph/edges"][()].reshape(-1, 2).astype(np.int64)
        affinity = h5["/graph/affinity"][()].astype(np.float64)
        k = int(h5.attrs["cluster_count"])
        source = attr_str(h5, "cluster_count_source")
        wall = h5.attrs.get("wall_time_s")
        if stage == "cluster-middle":
            middle_cluster = h5["/groups/middle_cluster"][()]
            nodes = np.flatnonzero(middle_cluster >= 0)
            ours = middle_cluster[nodes].astype(np.int64)
            index = np.full(len(middle_cluster), -1, dtype=np.int64)
            index[nodes] = np.arange(len(nodes))
            edges = index[edges] if len(edges) else edges
            if (edges < 0).any():
                raise ValueError(f"{path}: an edge touches a group that is not middle-type")
        elif stage == "cluster-all":
            node = h5["/groups/node"][()].astype(np.int64)
            before_split = h5["/groups/cluster_before_split"][()].astype(np.int64)
            n_nodes = len(h5["/nodes/set"])
            ours = np.full(n_nodes, -1, dtype=np.int64)
            ours[node] = before_split
            if (ours < 0).any():
                raise ValueError(f"{path}: a node without groups")
            if (ours[node] != before_split).any():
                raise ValueError(f"{path}: the groups of a node are in different clusters")
        else:
            raise ValueError(f"{path}: stage {stage!r} is neither cluster-middle nor cluster-all")
    n = len(ours)
    rows = np.concatenate([edges[:, 0], edges[:, 1]])
    cols = np.concatenate([edges[:, 1], edges[:, 0]])
    matrix = sp.csr_matrix((np.concatenate([affinity, affinity]), (rows, cols)), shape=(n, n))
    matrix.sum_duplicates()
    matrix.eliminate_zeros()  # an affinity that underflowed to 0 is no edge
    return {
        "stage": stage,
        "ours": ours,
        "matrix": matrix,
        "edges": len(edges),
        "k": k,
        "source": source,
        "wall_ms": None if wall is None else 1000.0 * float(wall),
    }


def sklearn_fit(matrix, k, assign_labels, eigen_solver, runs):
    """Labels and median fit time in ms, or an error message."""
    model = SpectralClustering(n_clusters=k, affinity="precomputed", assign_labels=assign_labels,
                               eigen_solver=eigen_solver, random_state=0, n_init=10)
    times = []
    labels = None
    try:
        for _ in range(runs):
            start = time.perf_counter()
            labels = model.fit(matrix).labels_
            times.append(1000.0 * (time.perf_counter() - start))
    except (ValueError, TypeError, RuntimeError, np.linalg.LinAlgError) as error:
        message = str(error).strip()
        message = message.splitlines()[0].split(". ")[0] if message else "(no message)"
        return None, None, f"{type(error).__name__}: {message}"
    return labels, statistics.median(times), None


def fmt(value, digits):
    return "–" if value is None else f"{value:.{digits}f}"


def short_name(path):
    return os.path.join(os.path.basename(os.path.dirname(os.path.abspath(path))),
                        os.path.basename(path))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="+", metavar="FILE.h5", help="middle.h5 or clusters.h5")
    parser.add_argument("--runs", type=int, default=5, help="fits per variant, median time (default 5)")
    parser.add_argument("--times", metavar="TSV",
                        help="PATH<TAB>MS lines: our median stage time for each file")
    args = parser.parse_args()

    our_times = {}
    if args.times:
        with open(args.times) as lines:
            for line in lines:
                if line.strip():
                    path, ms = line.rstrip("\n").split("\t")
                    our_times[os.path.realpath(path)] = float(ms)

    warnings.simplefilter("ignore")  # "Graph is not fully connected": see the components column
    variants = [("kmeans", None), ("discretize", None), ("kmeans", "lobpcg")]
    print("| file | stage | nodes | edges | components | isolated | our k (source) "
          "| ARI ours~components | ARI sklearn kmeans | ARI sklearn discretize | ARI sklearn kmeans, lobpcg "
          "| sklearn kmeans (ms) | sklearn discretize (ms) | ours, stage binary (ms) | ours, wall_time_s (ms) | note |")
    print("|---|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for path in args.files:
        name = short_name(path)
        try:
            graph = load(path)
        except (OSError, KeyError, ValueError) as error:
            print(f"| {name} | | | | | | | | | | | | | | | not read: {error} |")
            continue
        n = len(graph["ours"])
        k = graph["k"]
        ours_ms = our_times.get(os.path.realpath(path))
        head = f"| {name} | {graph['stage']} | {n} | {graph['edges']} |"
        tail = f" {fmt(ours_ms, 1)} | {fmt(graph['wall_ms'], 1)} |"
        if n < 2:
            print(head + f" {n} | {n} | {k} ({graph['source']}) | – | – | – | – | – | – |"
                  + tail + f" skipped: {n} node{'s' if n != 1 else ''}, nothing to compare |")
            continue
        components, component = connected_components(graph["matrix"], directed=False)
        isolated = int((np.diff(graph["matrix"].indptr) == 0).sum())
        notes = []
        refusals = {}
        aris, times = [], []
        for assign_labels, eigen_solver in variants:
            labels, ms, error = sklearn_fit(graph["matrix"], k, assign_labels, eigen_solver, args.runs)
            variant = f"{assign_labels}{', ' + eigen_solver if eigen_solver else ''}"
            if error:
                refusals.setdefault(error, []).append(variant)
                aris.append(None)
            else:
                aris.append(adjusted_rand_score(graph["ours"], labels))
                if len(np.unique(labels)) != k:
                    notes.append(f"{variant}: {len(np.unique(labels))} clusters, not {k}")
            times.append(ms)
        for error, refused in refusals.items():
            why = f"k = {k} >= {n} nodes; " if k >= n else "k = 1; " if k == 1 else ""
            notes.insert(0, f"sklearn refuses ({' and '.join(refused)}): {why}{error}")
        if any(a is not None and a < 0.999 for a in aris):  # why sklearn disagrees
            if components > 1 and isolated:
                notes.append("isolated nodes (a)")
            if components - isolated > 1:
                notes.append(f"eigenvalue 0 of multiplicity {components - isolated} (b)")
        ari_components = adjusted_rand_score(graph["ours"], component)
        print(head + f" {components} | {isolated} | {k} ({graph['source']}) | {ari_components:.3f} | "
              + " | ".join(fmt(a, 3) for a in aris) + f" | {fmt(times[0], 1)} | {fmt(times[1], 1)} |"
              + tail + f" {'; '.join(notes)} |")
    print()
    print("ARI ours~components: 1 where our clusters are exactly the connected components. Where sklearn disagrees:")
    print("(a) isolated nodes: before ARPACK and LOBPCG scikit-learn sets the diagonal of the normalised Laplacian")
    print("    to 1, so an isolated node has eigenvalue 1, not 0 (its own component, as NJW and our stages treat it);")
    print("    its embedding row is ~0 and k-means lumps the isolated nodes together (the dense eigh that")
    print("    eigen_solver='lobpcg' uses for nodes < 5 k + 1 keeps the 0).")
    print("(b) c components give eigenvalue 0 of multiplicity c; ARPACK (Lanczos, shift-invert) may return fewer")
    print("    than c copies and the next eigenvector instead, so k-means may split a component and merge others;")
    print("    scikit-learn's embedding is also not row-normalised as in NJW (it divides by sqrt(degree)).")
    return 0


if __name__ == "__main__":
    sys.exit(main())
