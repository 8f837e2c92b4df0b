#!/usr/bin/python3
"""Tables and the time-error plot of bench/time_error.sh's CSV.

    time_error_report.py TIME_ERROR_CSV PLOT_PNG [--title TEXT]

Prints Markdown (one table per model) on stdout and draws two plots: PLOT_PNG against the
full reference (every strand simulated as normal hair, the style rules off) and
PLOT_PNG with "_by_style" before its suffix against the by-style reference (every strand
a guide, the style rules on). Per model: the error (mean over all strand points and
frames, as a share of the strand's length) against the time per frame (simulate +
interpolate), the non-dominated variants joined (the front), the defaults marked with a
star."""
import argparse
import csv
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    models = OrderedDict()
    with open(path, newline="") as stream:
        for row in csv.DictReader(stream):
            for key in ("simulate_ms", "interpolate_ms", "mean_error", "p95_error", "max_error",
                        "mean_error_by_style", "p95_error_by_style", "max_error_by_style"):
                row[key] = float(row[key])
            row["total_ms"] = row["simulate_ms"] + row["interpolate_ms"]
            models.setdefault(row["model"], []).append(row)
    return models


def front(rows, key="mean_error"):
    """The rows no other row beats in both time and mean error, by time."""
    kept, best = [], float("inf")
    for row in sorted(rows, key=lambda r: (r["total_ms"], r[key])):
        if row[key] < best:
            kept.append(row)
            best = row[key]
    return kept


def is_reference(row):
    return row["variant"].endswith("reference")


def print_tables(models):
    for model, rows in models.items():
        print(f"## {model}\n")
        print("| variant | guides | simulate ms/frame | interpolate ms/frame | total ms/frame "
              "| error, full ref.: mean (% of length) | p95 | error, by-style ref.: mean | p95 |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for row in rows:
            name = f"**{row['variant']}**" if row["variant"] == "default" else row["variant"]
            print(f"| {name} | {row['guides']} | {row['simulate_ms']:.2f} | {row['interpolate_ms']:.2f} "
                  f"| {row['total_ms']:.2f} | {100 * row['mean_error']:.2f} | {100 * row['p95_error']:.2f} "
                  f"| {100 * row['mean_error_by_style']:.2f} | {100 * row['p95_error_by_style']:.2f} |")
        variants = [r for r in rows if not is_reference(r)]
        for key, against in (("mean_error", "full"), ("mean_error_by_style", "by-style")):
            on_front = ", ".join(r["variant"] for r in front(variants, key))
            print(f"\nOn the front against the {against} reference (nothing both faster and closer): {on_front}.")
        print()


def plot(models, path, title, suffix=""):
    mean_key, p95_key = "mean_error" + suffix, "p95_error" + suffix
    columns = min(len(models), 2)
    rows_of_plots = (len(models) + columns - 1) // columns
    figure, axes = plt.subplots(rows_of_plots, columns, figsize=(6.5 * columns, 4.6 * rows_of_plots),
                                squeeze=False)
    for axis, (model, rows) in zip(axes.flat, models.items()):
        rows = [r for r in rows if not is_reference(r)]
        for row in rows:
            default = row["variant"] == "default"
            axis.scatter(row["total_ms"], 100 * row[mean_key], marker="*" if default else "o",
                         s=180 if default else 36, color="tab:red" if default else "tab:blue", zorder=3)
            axis.scatter(row["total_ms"], 100 * row[p95_key], marker="_", s=60, color="tab:gray", zorder=2)
            axis.annotate(row["variant"], (row["total_ms"], 100 * row[mean_key]), fontsize=7,
                          xytext=(4, 3), textcoords="offset points")
        line = front(rows, mean_key)
        axis.plot([r["total_ms"] for r in line], [100 * r[mean_key] for r in line], color="tab:blue",
                  alpha=0.4, zorder=1)
        axis.set_xscale("log")
        axis.set_xlabel("ms per frame (simulate + interpolate)")
        axis.set_ylabel("error, % of strand length (dots mean, dashes p95)")
        axis.set_title(model)
        axis.grid(True, which="both", alpha=0.3)
    for axis in list(axes.flat)[len(models):]:
        axis.set_visible(False)
    figure.suptitle(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    arguments = parser.parse_args()
    models = read_rows(arguments.csv)
    print_tables(models)
    by_style_png = arguments.png[: -len(".png")] + "_by_style.png"
    plot(models, arguments.png, "against the full reference (every strand a guide, the style rules off); "
         + arguments.title)
    plot(models, by_style_png, "against the by-style reference (every strand a guide, the style rules on); "
         + arguments.title, "_by_style")
    for png, against in ((arguments.png, "full"), (by_style_png, "by-style")):
        print(f"![time against error, the {against} reference]({png.split('/')[-1]})\n")


if __name__ == "__main__":
    main()
