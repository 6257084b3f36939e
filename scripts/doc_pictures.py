#!/usr/bin/env python3
"""The README's and docs' pictures, made by the commands the text shows.

Each picture `![alt](path.png)` in README.md and docs/*.md whose line is
preceded (blank lines between at most) by a fenced code block is made by
that block: its lines, a trailing backslash joining a line to the next, run
with bash from the repository root. The block must name the picture's path
(from the repository root) without its extension, as the file it writes.

  python3 scripts/doc_pictures.py              # regenerate every picture in place
  python3 scripts/doc_pictures.py --check       # render each into a temporary folder and compare
  python3 scripts/doc_pictures.py --check --only lollipop-strobe-figure --rollspin build/rollspin
  python3 scripts/doc_pictures.py --list        # each picture and its command
  python3 scripts/doc_pictures.py --self-test   # the parser on planted pages, then --list

--check runs the same commands in a scratch folder (scenes/ and build/rollspin
linked into it), with the picture's path swapped for a scratch one, and
compares the result with the committed picture by `rollspin compare` at
the cross-machine policy of docs/rendering.md (--max-delta 16
--max-pixels 1% --mean-delta 0.6): exit 1 when a picture no longer matches
its command, 2 when a picture has no command or the command fails.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TOLERANCE = ["--max-delta", "16", "--max-pixels", "1%", "--mean-delta", "0.6"]
# Pictures of measurements, not of a command's pixels: their commands time
# the machine, so no two runs draw the same picture.
# A screenshot of a page in a browser is the browser's pixels, made by a
# script of its own from the command the text shows.
MEASUREMENTS = {
    "docs/report/errors.png": "a measurement: run times (rollspin report errors; docs/solver.md)",
    "docs/viewer.png": "a browser's screenshot of the page the command above it writes (scripts/viewer_screenshot.sh)",
}
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+\.png)\)")


def pictures_of(page, text):
    """(picture path from the root, command text, page:line) for each picture of a page."""
    lines = text.splitlines()
    found = []
    for number, line in enumerate(lines):
        for match in IMAGE.finditer(line):
            if "://" in match.group(1):
                continue
            picture = os.path.normpath(os.path.join(os.path.dirname(page), match.group(1)))
            found.append((picture, command_above(lines, number), f"{page}:{number + 1}"))
    return found


def command_above(lines, number):
    """The fenced block that ends just above line `number` (blank lines between), or None."""
    k = number - 1
    while k >= 0 and not lines[k].strip():
        k -= 1
    if k < 0 or not lines[k].startswith("```"):
        return None
    end = k
    k -= 1
    while k >= 0 and not lines[k].startswith("```"):
        k -= 1
    return "\n".join(lines[k + 1:end]) if k >= 0 else None


def all_pictures():
    pages = sorted((ROOT / "docs").glob("*.md"))
    pages.insert(0, ROOT / "README.md")
    by_path = {}
    for page in pages:
        for picture, command, where in pictures_of(str(page.relative_to(ROOT)), page.read_text()):
            by_path.setdefault(picture, []).append((command, where))
    return by_path


def chosen_commands(by_path):
    """Each picture's command (the first page that shows one); a list of problems."""
    chosen, problems = {}, []
    for picture, uses in sorted(by_path.items()):
        if picture in MEASUREMENTS:
            continue
        commands = [c for c, _ in uses if c is not None]
        if not commands:
            problems.append(f"{picture}: no command above it ({', '.join(w for _, w in uses)})")
            continue
        stem = os.path.splitext(picture)[0]
        if stem not in commands[0]:
            where = next(w for c, w in uses if c is not None)
            problems.append(f"{picture}: the command above it at {where} does not write {stem}.*")
            continue
        if any(c != commands[0] for c in commands):
            problems.append(f"{picture}: the pages show different commands for it")
            continue
        chosen[picture] = commands[0]
    return chosen, problems


def run(command, cwd, rollspin):
    env = dict(os.environ, LP_NUM_THREADS=os.environ.get("LP_NUM_THREADS", "0"))
    script = command.replace("build/rollspin", str(rollspin))
    return subprocess.run(["bash", "-euo", "pipefail", "-c", script], cwd=cwd, env=env,
                          capture_output=True, text=True)


def check(chosen, rollspin, only):
    failed = 0
    for picture, command in chosen.items():
        if only and not any(o in picture for o in only):
            continue
        with tempfile.TemporaryDirectory(prefix="doc-pictures-") as scratch:
            (Path(scratch) / "scenes").symlink_to(ROOT / "scenes")
            (Path(scratch) / "output").mkdir()  # as in a clone
            stem = os.path.splitext(picture)[0]
            fresh = Path(scratch) / "picture"
            result = run(command.replace(stem, str(fresh)), scratch, rollspin)
            if result.returncode != 0:
                print(f"{picture}: its command failed ({result.returncode}):\n{result.stderr}", file=sys.stderr)
                return 2
            compared = subprocess.run([str(rollspin), "compare", str(fresh) + ".png", str(ROOT / picture)] + TOLERANCE,
                                      capture_output=True, text=True)
            verdict = "matches" if compared.returncode == 0 else "differs from"
            print(f"{picture}: {verdict} its command\n{compared.stdout.strip()}")
            if compared.returncode == 2:
                print(compared.stderr, file=sys.stderr)
                return 2
            failed += compared.returncode != 0
    return 1 if failed else 0


def self_test():
    page = "docs/" + "example.md"  # a made-up page: only the parser sees it
    text = "```sh\nbuild/rollspin render a --still \\\n  -o docs/p/a.png\n```\n\n![a](p/a.png)\n\ntext\n![b](p/b.png)\n"
    found = pictures_of(page, text)
    assert [p for p, _, _ in found] == ["docs/p/a.png", "docs/p/b.png"], found
    assert found[0][1] == "build/rollspin render a --still \\\n  -o docs/p/a.png" and found[1][1] is None, found
    chosen, problems = chosen_commands({"docs/p/a.png": [(found[0][1], "x")], "docs/p/b.png": [(None, "y")]})
    assert list(chosen) == ["docs/p/a.png"] and len(problems) == 1 and "no command" in problems[0], problems
    _, problems = chosen_commands({"docs/p/c.png": [("build/rollspin render c -o output/c.png", "z")]})
    assert len(problems) == 1 and "does not write" in problems[0], problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("--only", action="append", default=[], help="pictures whose path contains this")
    parser.add_argument("--rollspin", default=str(ROOT / "build" / "rollspin"))
    args = parser.parse_args()
    if args.self_test:  # the parser on planted pages first, so the check cannot pass vacuously
        self_test()
        args.list = not args.check
    chosen, problems = chosen_commands(all_pictures())
    for problem in problems:
        print(problem, file=sys.stderr)
    if args.list:
        for picture, command in chosen.items():
            print(f"{picture}:\n  {command}")
        for picture, why in MEASUREMENTS.items():
            print(f"{picture}: not checked, {why}")
        return 2 if problems else 0
    if problems:
        return 2
    rollspin = Path(args.rollspin).resolve()
    if args.check:
        return check(chosen, rollspin, args.only)
    for picture, command in chosen.items():
        if args.only and not any(o in picture for o in args.only):
            continue
        result = run(command, ROOT, rollspin)
        print(f"{picture}: {'written' if result.returncode == 0 else 'FAILED'}")
        if result.returncode != 0:
            print(result.stderr, file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
