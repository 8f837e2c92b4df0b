#!/usr/bin/python3
"""Tables and the time-error plot of bench/time_error.sh's CSV.

    time_error_report.py TIME_ERROR_CSV PLOT_PNG [--title TEXT]

Prints Markdown (one table per model) on stdout and draws PLOT_PNG: per model, the error
(mean over all strand points and frames, as a share of the strand's length) against the
time per frame (simulate + interpolate), the non-dominated variants joined (the front),
the defaults marked with a star."""
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
            for key in ("simulate_ms", "interpolate_ms", "mean_error", "p95_error", "max_error"):
                row[key] = float(row[key])
            row["total_ms"] = row["simulate_ms"] + row["interpolate_ms"]
            models.setdefault(row["model"], []).append(row)
    return models


def front(rows):
    """The rows no other row beats in both time and mean error, by time."""
    kept, best = [], float("inf")
    for row in sorted(rows, key=lambda r: (r["total_ms"], r["mean_error"])):
        if row["mean_error"] < best:
            kept.append(row)
            best = row["mean_error"]
    return kept


def print_tables(models):
    for model, rows in models.items():
        print(f"## {model}\n")
        print("| variant | guides | simulate ms/frame | interpolate ms/frame | total ms/frame "
              "| mean error (% of length) | p95 error | max error |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|")
        for row in rows:
            name = f"**{row['variant']}**" if row["variant"] == "default" else row["variant"]
            print(f"| {name} | {row['guides']} | {row['simulate_ms']:.2f} | {row['interpolate_ms']:.2f} "
                  f"| {row['total_ms']:.2f} | {100 * row['mean_error']:.2f} | {100 * row['p95_error']:.2f} "
                  f"| {100 * row['max_error']:.1f} |")
        on_front = ", ".join(r["variant"] for r in front([r for r in rows if r["variant"] != "reference"]))
        print(f"\nOn the front (nothing both faster and closer): {on_front}.\n")


def plot(models, path, title):
    columns = min(len(models), 2)
    rows_of_plots = (len(models) + columns - 1) // columns
    figure, axes = plt.subplots(rows_of_plots, columns, figsize=(6.5 * columns, 4.6 * rows_of_plots),
                                squeeze=False)
    for axis, (model, rows) in zip(axes.flat, models.items()):
        rows = [r for r in rows if r["variant"] != "reference"]
        for row in rows:
            default = row["variant"] == "default"
            axis.scatter(row["total_ms"], 100 * row["mean_error"], marker="*" if default else "o",
                         s=180 if default else 36, color="tab:red" if default else "tab:blue", zorder=3)
            axis.scatter(row["total_ms"], 100 * row["p95_error"], marker="_", s=60, color="tab:gray", zorder=2)
            axis.annotate(row["variant"], (row["total_ms"], 100 * row["mean_error"]), fontsize=7,
                          xytext=(4, 3), textcoords="offset points")
        line = front(rows)
        axis.plot([r["total_ms"] for r in line], [100 * r["mean_error"] for r in line], color="tab:blue",
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
    plot(models, arguments.png, arguments.title)
    print(f"![time against error]({arguments.png.split('/')[-1]})")


if __name__ == "__main__":
    main()
