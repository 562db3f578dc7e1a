#!/usr/bin/env python3
"""A vessel folder gives the built-in track's rows (issue 72): Esso Osaka's shared runs, linked
into a folder of another name under other file names (every file "trial-" + its name), with the
particulars file as vessel.yaml and the built-in track's own file (harness/tracks/esso-osaka.yaml)
as track.yaml, its runs renamed, run through `usvid compare --suite real --quick`. Every row must
equal the built-in track's, run alone on the shared folder, but for the names that come from the
files (the further runs' names) and the vessel's path.

Usage: vessel_folder_esso_test.py USVID SOURCE_DIR SHARED_DATA_DIR WORK_DIR
Exit 77 (skipped) without the shared data; 1 on a failure.
"""
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77


def make_folder(track_text, shared, source, folder):
    for sub in ("zigzag", "turning", "random"):
        os.makedirs(os.path.join(folder, sub))
        for f in os.listdir(os.path.join(shared, "esso-osaka", sub)):
            os.symlink(os.path.join(shared, "esso-osaka", sub, f),
                       os.path.join(folder, sub, "trial-" + f))
    shutil.copy(os.path.join(source, "docs/vessels/files/esso-osaka.yaml"),
                os.path.join(folder, "vessel.yaml"))
    renamed = re.sub(r"file: (\w+)/", r"file: \1/trial-", track_text)
    if renamed == track_text:
        raise SystemExit("no run named in the track file")
    with open(os.path.join(folder, "track.yaml"), "w") as f:
        f.write(renamed)


def rows(results):
    out = []
    for row in json.load(open(results))["rows"]:
        row = {k: v for k, v in row.items() if k not in ("fit_seconds", "vessel")}
        out.append(row)
    return out


def main():
    usvid, source, shared, work = sys.argv[1:5]
    if not os.path.isdir(os.path.join(shared, "esso-osaka")):
        print("skipped: no esso-osaka/ in " + shared)
        return SKIP
    shutil.rmtree(work, ignore_errors=True)
    track_text = open(os.path.join(source, "harness/tracks/esso-osaka.yaml")).read()
    os.makedirs(os.path.join(work, "builtin"))
    os.symlink(os.path.join(os.path.abspath(shared), "esso-osaka"),
               os.path.join(work, "builtin", "esso-osaka"))
    make_folder(track_text, os.path.abspath(shared), source,
                os.path.join(work, "folders", "my-tanker"))
    for data in ("builtin", "folders"):
        run = subprocess.run([usvid, "compare", "--suite", "real", "--quick", "--threads", "2",
                              "--data-dir", os.path.join(work, data),
                              "--out", os.path.join(work, data + "-out")],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(data + ": exit %d\n%s" % (run.returncode, run.stderr))
            return 1
    builtin = rows(os.path.join(work, "builtin-out", "esso-osaka", "results.json"))
    folder = rows(os.path.join(work, "folders-out", "esso-osaka", "results.json"))
    listed = set(re.findall(r'name: "([^"]+)"', track_text))
    failures = 0
    if len(builtin) != len(folder):
        print("rows: %d built-in, %d from the folder" % (len(builtin), len(folder)))
        return 1
    for a, b in zip(builtin, folder):
        if a["test_maneuver"] not in listed:  # a further run, named by its file
            if "trial-" + a["test_maneuver"] != b["test_maneuver"]:
                print("further run %s against %s" % (a["test_maneuver"], b["test_maneuver"]))
                failures += 1
            a = dict(a, test_maneuver="")
            b = dict(b, test_maneuver="")
        if a != b:
            print("differs:\n  built-in %s\n  folder   %s" % (json.dumps(a)[:400], json.dumps(b)[:400]))
            failures += 1
    print("%d rows compared, %d differ" % (len(builtin), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
