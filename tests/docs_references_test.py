"""Every file and every usvid flag a doc names exists (issue 73: docs that drifted).

Reads the Markdown pages (README.md, docs/) and the comments of the sources (.h, .cc, .py,
CMake), and checks two kinds of reference written in backticks, also across a line break:
- a path in the repository (its first folder one of the tree's top-level folders, e.g.
  `methods/refit/refit.h`, `docs/compare.md#the-real-suite`, `harness/suite.cc:100`): the file
  exists;
- a command line (`usvid identify --method gp --fit-rows 0`): the subcommand exists and each
  --flag appears in its --help.
Output placeholders (`DIR/model.json`, `OUT/summary.md`) are not paths of the tree and are not
checked. Usage: docs_references_test.py ROOT USVID_BINARY. Exit 1 listing each dangling
reference as FILE:LINE: what.
"""
import os
import re
import subprocess
import sys

ROOT, USVID = sys.argv[1], sys.argv[2]
SKIP_DIRS = {".git", ".ci", "build", "node_modules"}
TOP = {d for d in os.listdir(ROOT)
       if os.path.isdir(os.path.join(ROOT, d)) and not d.startswith((".", "build"))}
PATH = re.compile(r"^((?:[A-Za-z0-9_.\-]+/)+[A-Za-z0-9_.\-]+\.(?:h|cc|md|json|sh|py|yaml|in|txt"
                  r"|cmake))(?::[\d-]+|#[\w-]+)?$")
COMMAND = re.compile(r"^usvid ([a-z][a-z-]*)\b(.*)$", re.S)
FLAG = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")


def files():
    for folder, dirs, names in os.walk(ROOT):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
        for name in names:
            if name.endswith((".md", ".h", ".cc", ".py", ".txt", ".in")):
                yield os.path.join(folder, name)


def text_of(path):
    """The file's prose: Markdown whole; in a source, its comments, each line kept (the code
    lines blanked), so that a backtick span broken over two comment lines reads as one."""
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().split("\n")
    if path.endswith(".md"):
        return lines
    marker = "#" if path.endswith((".py", ".txt")) else "//"
    out = []
    for line in lines:
        at = line.find(marker)
        out.append(line[at + len(marker):] if at >= 0 else "")
    return out


HELP = {}


def help_of(sub):
    if sub not in HELP:
        r = subprocess.run([USVID, sub, "--help"], capture_output=True, text=True)
        HELP[sub] = r.stdout + r.stderr if r.returncode == 0 else None
    return HELP[sub]


def spans(lines):
    """(line number, text) of each backtick span, joined across line breaks."""
    joined = "\n".join(lines)
    for m in re.finditer(r"`([^`\n]+(?:\n[^`\n]*)?)`", joined):
        yield joined.count("\n", 0, m.start()) + 1, " ".join(m.group(1).split())


def main():
    bad = []
    for path in files():
        rel = os.path.relpath(path, ROOT)
        if rel == os.path.join("tests", "docs_references_test.py"):
            continue
        for line, span in spans(text_of(path)):
            p = PATH.match(span)
            if p and p.group(1).split("/")[0] in TOP:
                if not os.path.exists(os.path.join(ROOT, p.group(1))):
                    bad.append(f"{rel}:{line}: no file {p.group(1)}")
                continue
            for command in re.split(r"&&|\|\||[|;]", span):  # each command of a pipeline
                c = COMMAND.match(command.strip())
                if not c or c.group(1) == "args":
                    continue
                help_text = help_of(c.group(1))
                if help_text is None:
                    bad.append(f"{rel}:{line}: no subcommand 'usvid {c.group(1)}'")
                    continue
                for flag in FLAG.findall(c.group(2)):
                    if flag not in help_text:
                        bad.append(f"{rel}:{line}: 'usvid {c.group(1)}' has no flag {flag}")
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
