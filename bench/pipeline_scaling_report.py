#!/usr/bin/python3
"""Tables and plots of bench/pipeline_scaling.sh's CSV.

    pipeline_scaling_report.py PIPELINE_CSV PLOT_PNG

Prints Markdown on stdout: the per-stage table, the strand-count and the mesh-size tables
with each stage's growth exponent (the slope of log time against log size from the
smallest to the largest case: 1 is linear). Draws both scalings, log-log, into PLOT_PNG."""
import csv
import math
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STAGES = ["extract", "typeify", "cluster-middle", "cluster-all", "grow", "classify", "simulate", "interpolate"]


def read(path):
    runs = OrderedDict()  # (study, model, vertices, strands) -> {stage: ms}
    with open(path, newline="") as stream:
        for row in csv.DictReader(stream):
            key = (row["study"], row["model"], int(row["vertices"]), int(row["strands"]))
            runs.setdefault(key, {})[row["stage"]] = float(row["ms"])
    return runs


def stages_of(runs):
    present = {stage for times in runs.values() for stage in times}
    return [stage for stage in STAGES if stage in present]


def exponent(points):
    """Slope of log ms against log size between the smallest and largest size."""
    points = sorted(points)
    (x0, y0), (x1, y1) = points[0], points[-1]
    if x1 == x0 or y0 <= 0 or y1 <= 0:
        return float("nan")
    return math.log(y1 / y0) / math.log(x1 / x0)


def table(runs, study, size_index, size_name):
    selected = {key: times for key, times in runs.items() if key[0] == study}
    if not selected:
        return
    stages = stages_of(selected)
    print("| model | " + size_name + " | " + " | ".join(stages) + " | all |")
    print("|---|---:|" + "---:|" * (len(stages) + 1))
    for key, times in selected.items():
        cells = [f"{times[s]:.0f}" if s in times else "" for s in stages]
        print(f"| {key[1]} | {key[size_index]:,} | " + " | ".join(cells) + f" | {sum(times.values()):.0f} |")
    if study == "stages":
        return
    for model in OrderedDict.fromkeys(key[1] for key in selected):
        rows = [(key[size_index], times) for key, times in selected.items() if key[1] == model]
        cells = [f"{exponent([(size, times[s]) for size, times in rows if s in times]):.2f}" for s in stages]
        print(f"| {model}: growth exponent | | " + " | ".join(cells) + " | |")


def plot(runs, path):
    figure, axes = plt.subplots(1, 2, figsize=(13, 5))
    for axis, (study, size_index, label) in zip(axes, (("strands", 3, "grown strands"),
                                                        ("mesh", 2, "hair mesh vertices"))):
        selected = {key: times for key, times in runs.items() if key[0] == study}
        models = list(OrderedDict.fromkeys(key[1] for key in selected))
        styles = ["-", "--", ":", "-."]
        for stage_number, stage in enumerate(stages_of(selected)):
            for model_number, model in enumerate(models):
                rows = sorted((key[size_index], times[stage]) for key, times in selected.items()
                              if key[1] == model and stage in times)
                axis.plot([r[0] for r in rows], [r[1] for r in rows], styles[model_number % len(styles)],
                          marker="o", color=f"C{stage_number}", label=f"{stage} ({model})")
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel(label)
        axis.set_ylabel("wall time per stage, ms")
        axis.grid(True, which="both", alpha=0.3)
        axis.legend(fontsize=6, ncol=2)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    runs = read(sys.argv[1])
    print("## Each stage, ms (10,000 grown strands)\n")
    table(runs, "stages", 2, "mesh vertices")
    print("\n## Strand count: ms per stage\n")
    table(runs, "strands", 3, "strands")
    print("\n## Mesh size: ms per stage (meshes subdivided, 10,000 grown strands)\n")
    table(runs, "mesh", 2, "vertices")
    plot(runs, sys.argv[2])
    print(f"\n![pipeline scaling]({sys.argv[2].split('/')[-1]})")


if __name__ == "__main__":
    main()
