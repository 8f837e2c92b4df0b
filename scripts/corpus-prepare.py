#!/usr/bin/python3
"""Prepares the corpus of hair meshes (bench/corpus/README.md) for bench/corpus.sh: gets
every mesh of bench/corpus/manifest.tsv at its pinned commit, turns it into the
pipeline's input (OUT/<name>/hair/<name>.obj with its MTL and textures, and the body it
was made on, OUT/<name>/body.obj: decimetres, +Y up, the face towards +Z), and writes
OUT/manifest.tsv: the manifest's rows that could be prepared, with the half each belongs
to (tune or check).

    scripts/corpus-prepare.py [--mirror DIR] [--shared DIR] [--only REGEX] [-j N] [OUT]

Files come from DIR/<owner>+<name>/repo or DIR/<owner>+<name> (bare git copies of the
repositories, e.g. made with `git clone --mirror`) when --mirror is given and has the
repository; otherwise from raw.githubusercontent.com at the pinned commit. A mesh whose
files cannot be had is left out with one line saying why. OUT defaults to build/corpus.

Methods (the manifest's `method` column):
  blender    a character file (glTF/GLB/VRM, FBX) split into hair and body by
             scripts/corpus/blender_split.py in Debian's Blender (`hair`, `body` and
             `body_files` columns)
  mhclo      a MakeHuman asset (path: its .mhclo, which names the .obj and .mhmat, or
             the stem of the three) placed on ../shared's MakeHuman body by
             scripts/corpus/fit_mhclo.py, with the texture its .mhmat names or the
             manifest's `texture` (a file beside the asset; `-`: none)
  remesh:V   one of ../shared's MakeHuman meshes re-meshed by scripts/corpus/remesh_obj.py

The halves: within each source, the meshes sorted by the SHA-256 of their names go
alternately to tune and check, so that both halves hold every source and a mesh's half
never depends on which others are present.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import os
import re
import shutil
import subprocess
import sys
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


# The hm08 base mesh with its helper geometry (CC0, MakeHuman): community hairs are fitted
# to its hair helper, whose vertices follow the body's 13,380 (../shared's body.obj is the
# base mesh's body: the same first 13,380 vertices).
HM08_BASE = ("48s97j7ht5-ux/Game-Live-v2", "d8ca07b272fb9decd6057696bf415a400d284290", "models/base.obj")


class Unavailable(Exception):
    pass


def get_file(repo, commit, path, dest, mirror):
    """Writes repo's path at commit to dest."""
    os.makedirs(os.path.dirname(dest), exist_ok=True)
    if mirror:
        for git_dir in (os.path.join(mirror, repo.replace("/", "+"), "repo"),
                        os.path.join(mirror, repo.replace("/", "+"))):
            if os.path.isdir(git_dir):
                for rev in (commit, "HEAD"):
                    done = subprocess.run(["git", "--git-dir", git_dir, "show", f"{rev}:{path}"],
                                          capture_output=True)
                    if done.returncode == 0 and done.stdout:
                        with open(dest, "wb") as f:
                            f.write(done.stdout)
                        return
                raise Unavailable(f"{repo}: {path} is not in {git_dir}")
    url = f"https://raw.githubusercontent.com/{repo}/{commit}/{urllib.parse.quote(path)}"
    try:
        with urllib.request.urlopen(url, timeout=60) as response, open(dest, "wb") as f:
            shutil.copyfileobj(response, f)
    except Exception as e:  # no network, or no such file
        raise Unavailable(f"{url}: {e}")


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        lines = [l for l in (done.stderr + done.stdout).splitlines() if "error" in l.lower()]
        raise Unavailable((lines or (done.stderr + done.stdout).splitlines() or ["failed"])[-1])


def blender(script, *args):
    run([os.environ.get("BLENDER", "blender"), "--background", "--factory-startup", "--python",
         os.path.join(HERE, "corpus", script), "--", *args])


def mhmat_texture(path):
    for line in open(path, errors="replace"):
        w = line.split(None, 1)
        if len(w) == 2 and w[0] == "diffuseTexture":
            return w[1].strip()
    return None


def mhclo_names(path):
    """The obj_file and material lines of a MakeHuman .mhclo file."""
    named = {}
    for line in open(path, errors="replace"):
        w = line.split(None, 1)
        if len(w) == 2 and w[0] in ("obj_file", "material"):
            named.setdefault(w[0], w[1].strip())
    return named


def prepare(entry, out, args):
    name = entry["name"]
    folder = os.path.join(out, name)
    work = os.path.join(out, ".download", name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(folder, "hair"), exist_ok=True)
    method = entry["method"]
    if method == "blender":
        source = os.path.join(work, os.path.basename(entry["path"]))
        get_file(entry["repo"], entry["commit"], entry["path"], source, args.mirror)
        command = [source, folder, name, "--hair", entry["hair"], "--yaw-deg", entry["yaw_deg"] or "0",
                   "--scale", entry["scale"] or "10"]
        if entry["body"]:
            command += ["--body", entry["body"]]
        for path in filter(None, entry["body_files"].split(";")):
            local = os.path.join(work, os.path.basename(path))
            get_file(entry["repo"], entry["commit"], path, local, args.mirror)
            command += ["--body-file", local]
        blender("blender_split.py", *command)
    elif method == "mhclo":
        # path: the asset's .mhclo, which names its .obj and .mhmat; or the stem the three
        # share.
        if entry["path"].endswith(".mhclo"):
            folder_path = os.path.dirname(entry["path"])
            files = {"mhclo": os.path.join(work, os.path.basename(entry["path"]))}
            get_file(entry["repo"], entry["commit"], entry["path"], files["mhclo"], args.mirror)
            named = mhclo_names(files["mhclo"])
            for ext, key in (("obj", "obj_file"), ("mhmat", "material")):
                if ext == "mhmat" and entry.get("texture"):
                    continue
                if key not in named:
                    raise Unavailable(f"{entry['path']}: no {key} line")
                files[ext] = os.path.join(work, os.path.basename(named[key]))
                get_file(entry["repo"], entry["commit"], f"{folder_path}/{named[key]}", files[ext],
                         args.mirror)
        else:
            stem = entry["path"]
            folder_path = os.path.dirname(stem)
            files = {}
            for ext in ("obj", "mhclo") + (() if entry.get("texture") else ("mhmat",)):
                files[ext] = os.path.join(work, os.path.basename(stem) + "." + ext)
                get_file(entry["repo"], entry["commit"], f"{stem}.{ext}", files[ext], args.mirror)
        # The texture the .mhmat names, or the manifest's `texture` where the repository
        # holds the painted image under another name (or only there: no .mhmat texture).
        texture = entry.get("texture") or mhmat_texture(files["mhmat"])
        mtl = os.path.join(folder, "hair", name + ".mtl")
        with open(mtl, "w") as f:
            f.write(f"newmtl {name}\n")
            if texture and texture != "-":
                local = os.path.join(folder, "hair", "textures", name + os.path.splitext(texture)[1])
                get_file(entry["repo"], entry["commit"], f"{folder_path}/{texture}", local, args.mirror)
                f.write(f"map_Kd textures/{os.path.basename(local)}\n")
        body = os.path.join(args.shared, "data", "makehuman", "body.obj")
        base = os.path.join(work, "base.obj")
        get_file(*HM08_BASE, base, args.mirror)
        run([sys.executable, os.path.join(HERE, "corpus", "fit_mhclo.py"), files["mhclo"], files["obj"], base,
             os.path.join(folder, "hair", name + ".obj"), "--mtllib", name + ".mtl", "--usemtl", name])
        shutil.copy(body, os.path.join(folder, "body.obj"))
    elif method.startswith("remesh:"):
        makehuman = os.path.join(args.shared, "data", "makehuman")
        model = os.path.splitext(os.path.basename(entry["path"]))[0]
        source = os.path.join(makehuman, "hair", model + ".obj")
        if not os.path.isfile(source):
            raise Unavailable(f"{source}: no such file")
        hair = os.path.join(folder, "hair")
        run([sys.executable, os.path.join(HERE, "corpus", "remesh_obj.py"), source,
             os.path.join(hair, name + ".obj"), method.split(":", 1)[1]])
        # The material and texture keep their names: the OBJ's mtllib names the MTL.
        shutil.copy(os.path.join(makehuman, "hair", model + ".mtl"), hair)
        shutil.copytree(os.path.join(makehuman, "hair", "textures"), os.path.join(hair, "textures"),
                        dirs_exist_ok=True)
        shutil.copy(os.path.join(makehuman, "body.obj"), os.path.join(folder, "body.obj"))
    else:
        raise Unavailable(f"unknown method '{method}'")
    return name


def halves(entries):
    by_source = {}
    for e in entries:
        by_source.setdefault(e["source"], []).append(e)
    for members in by_source.values():
        members.sort(key=lambda e: hashlib.sha256(e["name"].encode()).hexdigest())
        for k, e in enumerate(members):
            e["half"] = "tune" if k % 2 == 0 else "check"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out", nargs="?", default=os.path.join(ROOT, "build", "corpus"))
    parser.add_argument("--mirror")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    parser.add_argument("--only", default=".")
    parser.add_argument("-j", type=int, default=1)
    args = parser.parse_args()
    with open(os.path.join(ROOT, "bench", "corpus", "manifest.tsv"), newline="") as f:
        entries = list(csv.DictReader(f, delimiter="\t"))
    halves(entries)
    wanted = [e for e in entries if re.search(args.only, e["name"])]
    os.makedirs(args.out, exist_ok=True)
    prepared = set()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.j) as pool:
        futures = {pool.submit(prepare, e, args.out, args): e for e in wanted}
        for future in concurrent.futures.as_completed(futures):
            e = futures[future]
            try:
                prepared.add(future.result())
                print(f"corpus-prepare: {e['name']}: prepared ({e['source']}, {e['half']})", file=sys.stderr)
            except Unavailable as problem:
                shutil.rmtree(os.path.join(args.out, e["name"]), ignore_errors=True)
                print(f"corpus-prepare: {e['name']}: left out: {problem}", file=sys.stderr)
    shutil.rmtree(os.path.join(args.out, ".download"), ignore_errors=True)
    columns = list(entries[0].keys())
    tmp = os.path.join(args.out, "manifest.tsv.part")
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, delimiter="\t", lineterminator="\n")
        writer.writeheader()
        for e in entries:  # this run's, and those an earlier run prepared
            if os.path.isfile(os.path.join(args.out, e["name"], "hair", e["name"] + ".obj")):
                writer.writerow(e)
    os.replace(tmp, os.path.join(args.out, "manifest.tsv"))
    print(f"corpus-prepare: {len(prepared)} of {len(wanted)} meshes in {args.out}", file=sys.stderr)
    return 0 if prepared else 1


sys.exit(main())
