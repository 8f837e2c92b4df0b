#!/usr/bin/env python3
"""Compares two corpus reports (docs/measured/corpus.md as bench/corpus.sh writes them):
per half, the summary lines side by side, the means of the measures, and the meshes whose
grown along flow moved by more than 0.3 points, coverage by more than 0.0005 H or kinked
strands by more than 0.3 points. Markdown on stdout.

    bench/corpus_compare.py BEFORE.md AFTER.md [--before-name A] [--after-name B]
"""
import argparse
import re
import sys

COLUMNS = {"along": 5, "coverage": 6, "kinks": 8}
TOLERANCE = {"along": 0.3, "coverage": 0.0005, "kinks": 0.3}


def read_report(path):
    half, summaries, rows = None, {}, {}
    with open(path) as report:
        for line in report:
            if line.startswith("## The tune half"):
                half = "tune"
            elif line.startswith("## The check half"):
                half = "check"
            elif half and line.startswith("- "):
                summaries.setdefault(half, []).append(line[2:].strip())
            elif half and line.startswith("| ") and not line.startswith("| mesh"):
                cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
                if len(cells) > max(COLUMNS.values()):
                    rows[cells[0]] = (half, cells)
    if not rows:
        sys.exit(f"corpus_compare: {path} holds no corpus rows")
    return summaries, rows


def number(cell):
    match = re.match(r"([\d.]+)", cell)
    return float(match.group(1)) if match else None


def means(rows, half):
    out = {}
    for measure, column in COLUMNS.items():
        values = [number(cells[column]) for h, cells in rows.values()
                  if h == half and number(cells[column]) is not None
                  and not (measure == "along" and "not deciding" in cells[3])]
        out[measure] = sum(values) / len(values) if values else float("nan")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--before-name", default="before")
    parser.add_argument("--after-name", default="after")
    args = parser.parse_args()
    before_summary, before = read_report(args.before)
    after_summary, after = read_report(args.after)
    for half in ("check", "tune"):
        print(f"## The {half} half\n")
        print(f"| target | {args.before_name} | {args.after_name} |\n|---|---|---|")
        for a, b in zip(before_summary.get(half, []), after_summary.get(half, [])):
            label = a.split(":")[0]
            print(f"| {label} | {a[len(label) + 1:].strip()} | {b[len(label) + 1:].strip()} |")
        mb, ma = means(before, half), means(after, half)
        print(f"| mean grown along flow (meshes whose texture decides) | {mb['along']:.2f}% | {ma['along']:.2f}% |")
        print(f"| mean coverage (H) | {mb['coverage']:.4f} | {ma['coverage']:.4f} |")
        print(f"| mean kinked strands | {mb['kinks']:.2f}% | {ma['kinks']:.2f}% |\n")
        print("| mesh | grown along flow | coverage mean (H) | kinked strands |\n|---|---|---|---|")
        for name in sorted(after):
            if name not in before or after[name][0] != half:
                continue
            b, a = before[name][1], after[name][1]
            moved = any(
                number(b[c]) is not None and number(a[c]) is not None
                and abs(number(b[c]) - number(a[c])) > TOLERANCE[m]
                for m, c in COLUMNS.items())
            if moved:
                print(f"| {name} | {b[5]} → {a[5]} | {b[6]} → {a[6]} | {b[8]} → {a[8]} |")
        print()


if __name__ == "__main__":
    main()
