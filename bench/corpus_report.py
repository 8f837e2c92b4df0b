#!/usr/bin/python3
"""Writes docs/measured/corpus.md from bench/corpus.sh's work folder: a table per half of
the corpus (tune, check), the targets each half meets, and the contact sheets.

    corpus_report.py MANIFEST WORK REPORT --command C --machine M --commit C

MANIFEST: the prepared corpus's manifest.tsv (bench/corpus/README.md). WORK: a folder per
mesh with row.txt (hair-grow-report's row, or "failed: ..."), ms.txt, extract.h5,
strands.h5, styles.h5, strands.png and mesh.png. Needs python3-h5py and numpy (Debian).
"""
import argparse
import csv
import datetime
import os
import subprocess

import h5py
import numpy

CLEAR_COHERENCE = 0.3      # hair::kClearFlowCoherence: paint that decides a face's flow
TEXTURE_DECIDES = 0.5      # the texture decides the flow where at least this share of
                           # the hair's area has clear paint
TARGET_ALONG = 85.0        # grown along flow, %, on 90% of the meshes the texture decides
TARGET_COVERAGE_H = 0.02   # coverage mean, H, on all
TARGET_KINKED = 1.0        # kinked strands, %, on all
TARGET_CURL = 0.30         # curly meshes: grown curvature within 30% of the cards'

COLUMNS = ["model", "strands", "points", "coverage", "fidelity", "inside", "root", "worst",
           "input_along", "grown_along", "followed", "clusters", "kinked", "curvature"]


def cells(row):
    return [c.strip() for c in row.strip().strip("|").split("|")]


def percent(text):
    return float(text.split("%")[0]) if text not in ("-", "") else None


def first_float(text):
    return float(text.split("/")[0].split("(")[0].split(":")[-1])


def clear_paint_share(extract_path):
    with h5py.File(extract_path, "r") as f:
        v = f["/mesh/vertices"][:].astype(float)
        offsets = f["/mesh/face_offsets"][:]
        corners = f["/mesh/face_vertices"][:]
        coherence = f["/mesh/face_flow_coherence"][:]
    area = numpy.zeros(len(offsets) - 1)
    for k in range(2, int(numpy.max(numpy.diff(offsets))) + 1):
        faces = numpy.nonzero(numpy.diff(offsets) >= k + 1)[0]
        a = v[corners[offsets[faces]]]
        b = v[corners[offsets[faces] + k - 1]]
        c = v[corners[offsets[faces] + k]]
        area[faces] += 0.5 * numpy.linalg.norm(numpy.cross(b - a, c - a), axis=1)
    return float(area[coherence >= CLEAR_COHERENCE].sum() / max(area.sum(), 1e-30))


def styles_by_strands(styles_path, strands_path):
    with h5py.File(styles_path, "r") as f:
        dataset = f["/clusters/style"]
        names = {v: k for k, v in h5py.check_enum_dtype(dataset.dtype).items()}
        styles = [names[int(s)] for s in dataset[:]]
    with h5py.File(strands_path, "r") as f:
        counts = f["/clusters/strand_count"][:]
    total = {}
    for style, count in zip(styles, counts):
        if style != "none":
            total[style] = total.get(style, 0) + int(count)
    return ", ".join(f"{s} {n}" for s, n in sorted(total.items(), key=lambda x: -x[1]))


def measure(entry, work):
    name = entry["name"]
    folder = os.path.join(work, name)
    row_path = os.path.join(folder, "row.txt")
    result = dict(entry)
    if not os.path.isfile(row_path):
        result["failed"] = "not run"
        return result
    row = open(row_path).read().strip()
    if row.startswith("failed"):
        result["failed"] = row[len("failed: "):]
        return result
    c = dict(zip(COLUMNS, cells(row)))
    result.update(
        strands=int(c["strands"]), coverage=first_float(c["coverage"]),
        fidelity=first_float(c["fidelity"]),
        worst=float(c["worst"].split(":")[-1]) if c["worst"] != "-" else None,
        input_along=percent(c["input_along"]), grown_along=percent(c["grown_along"]),
        kinked=percent(c["kinked"]), kinked_text=c["kinked"],
        curvature_text=c["curvature"],
        paint=clear_paint_share(os.path.join(folder, "extract.h5")),
        styles=styles_by_strands(os.path.join(folder, "styles.h5"), os.path.join(folder, "strands.h5")),
        seconds=int(open(os.path.join(folder, "ms.txt")).read()) / 1000)
    grown_k, card_k = (float(x) for x in c["curvature"].split("(")[0].split("/"))
    result["curl_ratio"] = grown_k / card_k if card_k > 0 else None
    return result


def fmt(value, pattern, missing="-"):
    return missing if value is None else pattern % value


def table(rows):
    lines = ["| mesh | source | a person calls it | clear paint (area) | input along paint | "
             "grown along flow | coverage mean / worst patch (H) | fidelity mean (H) | kinked "
             "strands (hairpins / air chords) | curvature grown / cards (rad/m) | styles by strands "
             "| chain (s) |",
             "|---|---|---|---:|---:|---:|---|---:|---|---|---|---:|"]
    for r in rows:
        if "failed" in r:
            lines.append(f"| {r['name']} | {r['source']} | {r['style']} | failed: {r['failed']} "
                         "| | | | | | | | |")
            continue
        decides = r["paint"] >= TEXTURE_DECIDES
        lines.append(
            f"| {r['name']} | {r['source']} | {r['style']}{' (curly)' if r['curly'] == 'yes' else ''} "
            f"| {100 * r['paint']:.0f}%{'' if decides else ' (not deciding)'} "
            f"| {fmt(r['input_along'], '%.1f%%')} | {fmt(r['grown_along'], '%.1f%%')} "
            f"| {r['coverage']:.4f} / {fmt(r['worst'], '%.4f')} | {r['fidelity']:.4f} "
            f"| {r['kinked_text']} | {r['curvature_text']} | {r['styles']} | {r['seconds']:.1f} |")
    return "\n".join(lines)


def targets(rows):
    done = [r for r in rows if "failed" not in r]
    decided = [r for r in done if r["paint"] >= TEXTURE_DECIDES and r["grown_along"] is not None]
    along = [r for r in decided if r["grown_along"] >= TARGET_ALONG]
    covered = [r for r in done if r["coverage"] <= TARGET_COVERAGE_H]
    unkinked = [r for r in done if r["kinked"] is not None and r["kinked"] < TARGET_KINKED]
    curly = [r for r in done if r["curly"] == "yes"]
    curls = [r for r in curly if r["curl_ratio"] is not None and abs(r["curl_ratio"] - 1) <= TARGET_CURL]
    failed = [r["name"] for r in rows if "failed" in r]

    def share(part, whole):
        return f"{len(part)} of {len(whole)}" + (f" ({100 * len(part) / len(whole):.0f}%)" if whole else "")
    return "\n".join([
        f"- meshes run: {len(done)} of {len(rows)}" + (f" (failed: {', '.join(failed)})" if failed else ""),
        f"- texture decides the flow (clear paint on at least {100 * TEXTURE_DECIDES:.0f}% of the area): "
        f"{len(decided)}; of them grown along flow >= {TARGET_ALONG:.0f}%: {share(along, decided)} (target: 90%)",
        f"- coverage mean <= {TARGET_COVERAGE_H} H: {share(covered, done)} (target: all)",
        f"- kinked strands under {TARGET_KINKED:.0f}%: {share(unkinked, done)} (target: all)",
        f"- curly meshes whose grown curvature is within {100 * TARGET_CURL:.0f}% of the cards': "
        f"{share(curls, curly)} (target: all)",
    ])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("manifest")
    parser.add_argument("work")
    parser.add_argument("report")
    parser.add_argument("--command", required=True)
    parser.add_argument("--machine", required=True)
    parser.add_argument("--commit", required=True)
    args = parser.parse_args()
    with open(args.manifest, newline="") as f:
        entries = list(csv.DictReader(f, delimiter="\t"))
    entries = [e for e in entries if os.path.isdir(os.path.join(args.work, e["name"]))]
    rows = [measure(e, args.work) for e in entries]
    folder = os.path.dirname(os.path.abspath(args.report))
    stem = os.path.splitext(os.path.basename(args.report))[0]
    out = [f"# The corpus: the chain on hair meshes from many artists",
           "",
           f"Measured {datetime.date.today().isoformat()} at commit {args.commit} on {args.machine}, by",
           f"`{args.command}` (bench/corpus/README.md says what the corpus holds, where each",
           "mesh comes from and how the halves are drawn). Distances in head heights H; the",
           "columns are hair-grow-report's (docs/grow.md, \"Figures\").",
           ""]
    for half in ("tune", "check"):
        part = [r for r in rows if r["half"] == half]
        if not part:
            continue
        sources = sorted({r["source"] for r in part})
        out += [f"## The {half} half: {len(part)} meshes from {len(sources)} sources", "",
                targets(part), "", table(part), ""]
        sheet = f"{stem}_{half}.png"
        cells = []
        for r in part:
            for picture in ("mesh.png", "strands.png"):
                cells.append(os.path.join(args.work, r["name"], picture))
        listing = os.path.join(args.work, f"sheet_{half}.txt")
        with open(listing, "w") as f:
            f.write("\n".join(cells) + "\n")
        blender = os.environ.get("BLENDER", "blender")
        try:
            done = subprocess.run([blender, "--background", "--factory-startup", "--python",
                                   "scripts/corpus/blender_contact_sheet.py", "--", listing,
                                   os.path.join(folder, sheet)], capture_output=True, text=True)
        except OSError as e:  # no Blender
            done = subprocess.CompletedProcess([], 1, "", f"{blender}: {e.strerror}")
        if done.returncode == 0:
            out += [f"Each row: the mesh with its texture (front, side, back; Cycles) and the grown "
                    f"strands coloured by cluster.", "", f"![{half} half]({sheet})", ""]
        else:
            out += [f"(no contact sheet: {done.stderr.strip().splitlines()[-1] if done.stderr.strip() else 'Blender failed'})", ""]
    tmp = args.report + ".part"
    with open(tmp, "w") as f:
        f.write("\n".join(out))
    os.replace(tmp, args.report)


main()
