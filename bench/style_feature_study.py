#!/usr/bin/env python3
"""Why the raw features beat the paper's on our data (issue 6): a Markdown report.

    python3 bench/style_feature_study.py TABLES_DIR [--repeats N] [-o OUT.md]

TABLES_DIR is what `hair-train-style --tables` wrote (features_{paper,extended,raw}.tsv;
bench/train_style_models.sh keeps it in WORK_DIR/tables). Every figure is the accuracy of
scikit-learn's random forest (100 trees, sqrt(d) features per split, as OpenCV's RTrees
in hair-train-style) on those tables, in four studies:

1. the learning curve: random subsets of whole models, from about the paper's size (159
   clusters of 46 models) to all, each cross-validated by 10 stratified folds;
2. one design held out: every synthetic preset in turn (all its models), and every real
   mesh in turn, is classified by a forest trained on everything else, so the forest has
   never seen that hairstyle's design (the paper's 46 models were 46 designs);
3. the raw features' kinds: each kind alone, and all kinds but it;
4. the raw features without absolute positions (the mean positions and the average
   strand), which on one body could tell presets apart by where their hair lies.

Needs python3-numpy and python3-sklearn (Debian). A bench, not a CI test: about five
minutes on two cores with the default repeats.
"""
import argparse
import csv
import datetime
import re
import sys

import numpy as np
from sklearn.ensemble import RandomForestClassifier
from sklearn.model_selection import StratifiedKFold

SETS = ("paper", "extended", "raw")
STYLES = ("normal", "fixed", "short", "braided")


def load(path):
    with open(path) as f:
        rows = list(csv.reader(f, delimiter="\t"))
    header, rows = rows[0], rows[1:]
    # The metadata columns end with label_purity, or with strands in tables written since
    # the leave-one-model-out report (issue 26).
    last_meta = "strands" if "strands" in header else "label_purity"
    first_feature = header.index(last_meta) + 1
    return {
        "names": header[first_feature:],
        "X": np.array([[float(v) for v in row[first_feature:]] for row in rows]),
        "label": np.array([row[header.index("label")] for row in rows]),
        "model": np.array([row[header.index("model")] for row in rows]),
        "real": np.array([row[header.index("real_mesh")] == "1" for row in rows]),
    }


def design_of(model, real):
    """A synthetic model's preset (hair-synth corpus names models <preset>_<index>); a
    real mesh is a design of its own."""
    stem = model.rstrip("/").split("/")[-1]
    return "real: " + stem if real else re.sub(r"_\d+$", "", stem)


def forest(seed):
    return RandomForestClassifier(n_estimators=100, max_features="sqrt", random_state=seed, n_jobs=-1)


def cross_validated(X, y, seed):
    predicted = np.empty(len(y), dtype=object)
    folds = min(10, min(np.sum(y == s) for s in set(y)))
    for train, test in StratifiedKFold(folds, shuffle=True, random_state=seed).split(X, y):
        predicted[test] = forest(seed).fit(X[train], y[train]).predict(X[test])
    return predicted


def held_out_by(X, y, keys, seed=0):
    predicted = np.empty(len(y), dtype=object)
    for key in sorted(set(keys)):
        test = keys == key
        predicted[test] = forest(seed).fit(X[~test], y[~test]).predict(X[test])
    return predicted


def percent(values):
    return "%.1f%%" % (100 * np.mean(values))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tables")
    parser.add_argument("--repeats", type=int, default=5, help="random subsets per size")
    parser.add_argument("-o", "--output", help="write the report here (default: stdout)")
    args = parser.parse_args()

    tables = {name: load("%s/features_%s.tsv" % (args.tables, name)) for name in SETS}
    first = tables["paper"]
    for name in SETS[1:]:
        if not (np.array_equal(tables[name]["model"], first["model"])
                and np.array_equal(tables[name]["label"], first["label"])):
            sys.exit("style_feature_study: the tables of %s do not list the same clusters" % args.tables)
    y, models, real = first["label"], first["model"], first["real"]
    heads = " | ".join("%s (%d)" % (name, tables[name]["X"].shape[1]) for name in SETS)
    designs = np.array([design_of(m, r) for m, r in zip(models, real)])
    out = []
    say = out.append

    say("# Style features: the paper's, ours and the raw ones")
    say("")
    say("Written by `python3 bench/style_feature_study.py %s --repeats %d` on %s: scikit-learn's "
        "random forest (100 trees, sqrt(d) features per split) on the feature tables of "
        "`hair-train-style` (%d clusters, %d of them from %d real meshes, %d synthetic models "
        "of %d presets)." % (args.tables, args.repeats, datetime.date.today().isoformat(), len(y),
                             real.sum(), len(set(models[real])), len(set(models[~real])),
                             len(set(designs[~real]))))
    say("")

    # 1. Learning curve.
    unique_models = np.array(sorted(set(models)))
    say("## 1. Learning curve")
    say("")
    say("Random subsets of whole models (%d draws per size), each cross-validated by 10 "
        "stratified folds of clusters; mean and standard deviation over the draws. The paper: "
        "159 clusters of 46 models, random forest 86.7%% with its features, 72.4%% with the raw "
        "ones." % args.repeats)
    say("")
    say("| models | clusters | %s |" % heads)
    say("|---:|---:|---:|---:|---:|")
    sizes = [n for n in (25, 46, 80) if n < len(unique_models)] + [len(unique_models)]
    for size in sizes:
        draws = 1 if size == len(unique_models) else args.repeats
        scores, counts = {name: [] for name in SETS}, []
        for draw in range(draws):
            chosen = np.random.RandomState(draw).choice(unique_models, size, replace=False)
            rows = np.isin(models, chosen)
            counts.append(rows.sum())
            for name in SETS:
                predicted = cross_validated(tables[name]["X"][rows], y[rows], draw)
                scores[name].append(np.mean(predicted == y[rows]))
        cells = ["%.1f%% ± %.1f" % (100 * np.mean(s), 100 * np.std(s)) if draws > 1
                 else "%.1f%%" % (100 * s[0]) for s in scores.values()]
        say("| %d | %.0f | %s |" % (size, np.mean(counts), " | ".join(cells)))
    say("")

    # 2. One design held out.
    say("## 2. One design held out")
    say("")
    say("Every synthetic preset (all its models at once) and every real mesh is classified by "
        "a forest trained on all other rows: the forest has seen no model of that design.")
    say("")
    held = {name: held_out_by(tables[name]["X"], y, designs) for name in SETS}
    say("| held out | clusters | styles | %s |" % heads)
    say("|---|---:|---|---:|---:|---:|")
    for design in sorted(set(designs), key=lambda d: (d.startswith("real"), d)):
        rows = designs == design
        styles = ", ".join("%s %d" % (s, np.sum(y[rows] == s)) for s in STYLES if np.any(y[rows] == s))
        say("| %s | %d | %s | %s |" % (design, rows.sum(), styles,
                                         " | ".join(percent(held[n][rows] == y[rows]) for n in SETS)))
    for label, rows in (("**synthetic presets**", ~real), ("**real meshes**", real),
                        ("**all**", np.ones(len(y), bool))):
        say("| %s | %d | | %s |" % (label, rows.sum(),
                                     " | ".join(percent(held[n][rows] == y[rows]) for n in SETS)))
    say("")

    # 3 and 4. The raw features' kinds.
    raw = tables["raw"]

    def kind_of(name):
        name = re.sub(r"_\d+$", "", name)
        if name.startswith("average_strand_") and name[-1] in "xyz" and name[-2] == "_":
            return "average_strand (x, y, z)"
        return name

    kinds = np.array([kind_of(n) for n in raw["names"]])
    say("## 3. The raw features' kinds")
    say("")
    say("10-fold cross-validation (folds of clusters) on one kind alone, and on all kinds but "
        "that one.")
    say("")
    say("| kind | dimensions | alone | all but it |")
    say("|---|---:|---:|---:|")
    for kind in sorted(set(kinds), key=lambda k: list(kinds).index(k)):
        alone = cross_validated(raw["X"][:, kinds == kind], y, 0)
        without = cross_validated(raw["X"][:, kinds != kind], y, 0)
        say("| %s | %d | %s | %s |" % (kind, np.sum(kinds == kind), percent(alone == y),
                                       percent(without == y)))
    say("")
    positional = np.array([k.startswith("position_mean") or k.startswith("average_strand (")
                           for k in kinds])
    say("## 4. Without absolute positions")
    say("")
    say("| features | dimensions | 10-fold | one design held out | real meshes held out |")
    say("|---|---:|---:|---:|---:|")
    for label, X in (("paper", tables["paper"]["X"]), ("extended", tables["extended"]["X"]),
                     ("raw", raw["X"]),
                     ("raw without the mean positions and the average strand", raw["X"][:, ~positional])):
        folds = cross_validated(X, y, 0)
        designs_out = held_out_by(X, y, designs)
        say("| %s | %d | %s | %s | %s |" % (label, X.shape[1], percent(folds == y),
                                             percent(designs_out == y),
                                             percent(designs_out[real] == y[real])))
    say("")

    text = "\n".join(out) + "\n"
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
