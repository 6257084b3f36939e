#!/usr/bin/env python3
"""Documentation references in the sources point at something that exists.

    python3 scripts/check_doc_refs.py [--self-test] [SOURCE_DIR]

Reads every source, script, scene, CMake, shader and docs file under
SOURCE_DIR (default: the folder above this script) and checks:

- a README section cited in a comment or a message exists as a heading of
  README.md: `README "Heading"`, `README's "Heading"`, `README, Heading`,
  `README.md#anchor`. A citation that names no heading ("see README",
  "(README)", "README: ...", "the README's ... section/table/recipe") fails
  too: the text it meant has moved to docs/ once already.
- every `docs/NAME.md` (and `docs/NAME.md#anchor`) names a file that exists
  and, with an anchor, one of its headings (mkdocs' toc ids);
- every Markdown link between docs pages, and from README.md into docs/,
  lands on an existing page and heading (mkdocs --strict checks the pages,
  Debian's mkdocs 1.4 not the anchors).

CHANGELOG.md and docs/speed-history.md are records of what was: they may
quote the README as it then was (its old sections), so only their links and
docs/ paths are checked (CHANGELOG.md not at all: it records renames).

Exit 0 when every reference resolves, 1 with one line per broken reference
(file:line: what, and where the text lives now if a docs page has that
heading). --self-test first runs the checker on a small planted tree and
fails unless it finds exactly the planted mistakes (ctest docs_references).
"""
import os
import re
import sys
import tempfile
import unicodedata

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".cc", ".py", ".pyi", ".sh", ".sbatch", ".cmake", ".txt",
                   ".toml", ".md", ".yml", ".yaml", ".glsl", ".vert", ".frag", ".in", ".ipynb"}
SKIPPED_DIRS = {".git", "third_party", "site", "output", "__pycache__", ".pytest_cache", "node_modules", "seeds"}
# Histories: their old README sections are quotations, not pointers.
HISTORY_FILES = {"docs/speed-history.md"}
UNCHECKED_FILES = {"CHANGELOG.md"}
THIS_FILE = "scripts/check_doc_refs.py"

README_WORD = re.compile(r"\bREADME\b")
DOCS_PATH = re.compile(r"(?<![\w/.-])docs/((?:[\w-]+/)*[\w.-]+?\.md)(#[\w-]+)?")
MD_LINK = re.compile(r"\]\(([^)\s#]*)(#[^)\s]*)?\)")
# "the README's lollipop section": a section described in words, not named.
DESCRIBED_SECTION = re.compile(
    r"^'s\s+(?:[\w-]+\s+){0,5}?(section|sections|table|row|column|recipe|recipes|number|numbers|command)\b")
# "README.md documents the same values": a claim about its text that names no heading.
CONTENT_CLAIM = re.compile(r"^(?:'s)?\s+(documents|describes|explains|lists|writes|derives)\b")


def slugify(text):
    """mkdocs' heading id: Python-Markdown toc's default slugify of the heading's text."""
    text = re.sub(r"`([^`]*)`", r"\1", text)             # code spans keep their text
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links keep their text
    text = re.sub(r"\*{1,2}([^*]+)\*{1,2}", r"\1", text)   # emphasis (an underscore in a word is not)
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    text = re.sub(r"[^\w\s-]", "", text).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def headings(path):
    """(title, id) of each ATX heading outside fenced code, ids made unique as toc does (_1, _2)."""
    found, seen, fence = [], {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            stripped = line.strip()
            marker = re.match(r"(```+|~~~+)", stripped)
            if marker:
                if fence is None:
                    fence = marker.group(1)[:3]
                elif stripped.startswith(fence):
                    fence = None
                continue
            if fence is not None:
                continue
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if not m:
                continue
            title = m.group(1)
            explicit = re.search(r"\{\s*#([\w-]+)[^}]*\}\s*$", title)
            if explicit:
                title = title[:explicit.start()].strip()
            base = explicit.group(1) if explicit else slugify(title)
            ident, n = base, seen.get(base, 0)
            while ident in seen:
                n += 1
                ident = f"{base}_{n}"
            seen[base] = n
            seen[ident] = 0
            found.append((re.sub(r"`", "", title), ident))
    return found


class Tree:
    def __init__(self, root):
        self.root = root
        self.cache = {}

    def headings_of(self, rel):
        if rel not in self.cache:
            path = os.path.join(self.root, rel)
            self.cache[rel] = headings(path) if os.path.isfile(path) else None
        return self.cache[rel]

    def docs_pages_with_title(self, title):
        """docs pages holding a heading titled `title` (case-insensitive): where moved text now lives."""
        docs = os.path.join(self.root, "docs")
        hits = []
        for name in sorted(os.listdir(docs)) if os.path.isdir(docs) else []:
            if name.endswith(".md"):
                for t, ident in self.headings_of("docs/" + name) or []:
                    if t.lower() == title.lower() or t.lower().startswith(title.lower() + " ("):
                        hits.append(f"docs/{name}#{ident}")
        return hits


def source_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = os.path.relpath(dirpath, root)
        dirnames[:] = sorted(
            d for d in dirnames
            if d not in SKIPPED_DIRS and not d.startswith("build")
            and (not d.startswith(".") or d == ".ci")
            and not os.path.exists(os.path.join(dirpath, d, "CMakeCache.txt")))
        for name in sorted(filenames):
            rel = os.path.normpath(os.path.join(rel_dir, name)).replace(os.sep, "/")
            if rel in UNCHECKED_FILES or rel == THIS_FILE:
                continue
            path = os.path.join(dirpath, name)
            suffix = os.path.splitext(name)[1]
            if suffix not in SOURCE_SUFFIXES:
                if suffix or not _has_shebang(path):
                    continue
            yield rel, path


def _has_shebang(path):
    try:
        with open(path, "rb") as f:
            return f.read(2) == b"#!"
    except OSError:
        return False


def flatten(text):
    """The file as one line of prose: comment leaders dropped, lines joined by a space.

    A citation may wrap across comment lines (`(README,` / `// "Render speed")`).
    Returns the prose and, for each of its characters, the line it came from."""
    prose, line_of = [], []
    for number, line in enumerate(text.split("\n"), start=1):
        body = re.sub(r"^\s*(?://+!?|#+|\*+|--|;+)?\s?", "", line)
        body = body.replace('\\"', '"').replace("\\-", "-")
        prose.append(body + " ")
        line_of.extend([number] * (len(body) + 1))
    return "".join(prose), line_of


def leading_quotes(clause):
    """The quoted headings a citation starts with: `"A"`, `("A", "B")`, `, "A" and "B"`."""
    m = re.match(r'^[\s,:(\w\'-]{0,60}?["“]', clause)
    if not m:
        return []
    rest, titles = clause[m.end() - 1:], []
    while True:
        q = re.match(r'^["“]([^"”]{1,80})["”]', rest)
        if not q:
            return titles
        titles.append(q.group(1))
        rest = rest[q.end():]
        joint = re.match(r'^\s*(?:,|and|or|,\s*and)\s*(?=["“])', rest)
        if not joint:
            return titles
        rest = rest[joint.end():]


def check_readme_citations(tree, rel, prose, line_of, problems):
    titles = [t for t, _ in tree.headings_of("README.md") or []]
    ids = {i for _, i in tree.headings_of("README.md") or []}
    lower_titles = {t.lower() for t in titles}

    def moved(title):
        pages = tree.docs_pages_with_title(title)
        return f" (now {', '.join(pages)})" if pages else ""

    for m in README_WORD.finditer(prose):
        line = line_of[m.start()]
        tail = prose[m.end():m.end() + 160].replace("’", "'")
        if tail.startswith(".md#"):
            anchor = re.match(r"\.md#([\w-]+)", tail)
            if anchor and anchor.group(1) not in ids:
                problems.append(f"{rel}:{line}: README.md#{anchor.group(1)}: README.md has no such heading")
            continue
        if tail.startswith(".md"):
            tail = tail[3:]
        before = prose[max(0, m.start() - 12):m.start()].lower().rstrip()
        described = DESCRIBED_SECTION.match(tail)
        if tail.startswith("'s"):
            tail = tail[2:]
        # The clause the citation is in: up to a sentence end or a semicolon.
        clause = re.split(r"(?<=[.;!?])\s", tail, maxsplit=1)[0]
        quotes = leading_quotes(clause)
        if quotes:
            for title in quotes:
                if title.strip().lower() not in lower_titles:
                    problems.append(f'{rel}:{line}: README "{title}": README.md has no such heading{moved(title)}')
            continue
        if described:
            problems.append(f"{rel}:{line}: README's ... {described.group(1)}: name the heading in quotes "
                            f"(README \"Heading\") or point at the docs page that holds the text")
            continue
        claim = CONTENT_CLAIM.match(tail)
        if claim:
            problems.append(f"{rel}:{line}: README {claim.group(1)} ...: say where (README \"Heading\", "
                            f"or the docs page that holds the text)")
            continue
        phrase = re.match(r"^[\s,(]*([A-Z][\w'-]*(?:\s+[\w'-]+){0,6}?)\s*(?=[:;,.)]|$)", clause)
        if phrase:
            title = phrase.group(1)
            if title.lower() not in lower_titles:
                problems.append(f"{rel}:{line}: README {title}: README.md has no such heading{moved(title)}")
            continue
        if re.match(r"^\s*[):]", clause) or before.endswith("see"):
            problems.append(f"{rel}:{line}: a bare README citation: name the heading (README \"Heading\") "
                            f"or point at the docs page that holds the text")


def check_anchor(tree, rel, line, page, anchor, what, problems):
    found = tree.headings_of(page)
    if found is None:
        problems.append(f"{rel}:{line}: {what}: no such file {page}")
        return
    if anchor and anchor not in {i for _, i in found}:
        problems.append(f"{rel}:{line}: {what}: {page} has no heading with id {anchor}")


def check_file(tree, rel, path, problems):
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (UnicodeDecodeError, OSError):
        return
    prose, line_of = flatten(text)
    if rel not in HISTORY_FILES and rel != "README.md":
        check_readme_citations(tree, rel, prose, line_of, problems)
    for m in DOCS_PATH.finditer(prose):
        page, anchor = "docs/" + m.group(1), (m.group(2) or "")[1:]
        check_anchor(tree, rel, line_of[m.start()], page, anchor, m.group(0), problems)
    if rel.endswith(".md"):
        base = os.path.dirname(rel)
        for number, line in enumerate(text.split("\n"), start=1):
            for m in MD_LINK.finditer(line):
                target, anchor = m.group(1), (m.group(2) or "")[1:]
                if re.match(r"^[a-z]+:", target) or (target and not target.endswith(".md")):
                    continue
                page = os.path.normpath(os.path.join(base, target)).replace(os.sep, "/") if target else rel
                if page.startswith("docs/") or page == "README.md" or rel.startswith("docs/"):
                    check_anchor(tree, rel, number, page, anchor, m.group(0)[1:], problems)


def check(root):
    tree = Tree(root)
    problems = []
    for rel, path in source_files(root):
        check_file(tree, rel, path, problems)
    return problems


def self_test():
    """The checker finds the planted mistakes and nothing else."""
    files = {
        "README.md": "# tool\n## Quick start\n```sh\n# not a heading\n```\n## Speed\n",
        "docs/solver.md": "# Solver\n## Notes on the paper\n## Timeline columns\n",
        "docs/other.md": "# Other\nSee [notes](solver.md#notes-on-the-paper), [bad](solver.md#nope).\n",
        "src/good.cpp": "// README \"Quick start\"; docs/solver.md#notes-on-the-paper; README's second \"Quick start\" step\n"
                        "// the README's \"Speed\" table; README.md#quick-start; build/rollspin, as the README promises.\n"
                        "const char* m = \"see docs/solver.md#timeline-columns (README, \\\"Speed\\\").\\n\"\n",
        "src/moved.hpp": "// (README,\n// \"Notes on the paper\") wraps\n",
        "src/pair.sh": "# the README's table (\"Speed\", \"Quality\"): two\n",
        "src/unquoted.cpp": "x.note = \"README, Notes on the paper: the paper keeps\";\n",
        "src/bare.cpp": "// follows from the inside formula (README); see README for more\n",
        "src/described.cpp": "// the README's magnus4-vs-rk45 lollipop section\n// README.md documents the values\n",
        "scripts/anchor.sh": "# docs/solver.md#speed and docs/gone.md\n",
        "scripts/readme_anchor.sh": "# README.md#gallery\n",
        "docs/speed-history.md": "# History\nThe README's \"Render speed\" as it was.\n",
        "CHANGELOG.md": "- docs/old.md is now docs/solver.md\n",
    }
    planted = [
        ("docs/other.md:2:", "solver.md#nope"),
        ("src/moved.hpp:1:", 'README "Notes on the paper": README.md has no such heading '
                             "(now docs/solver.md#notes-on-the-paper)"),
        ("src/pair.sh:1:", 'README "Quality"'),
        ("src/unquoted.cpp:1:", "README Notes on the paper"),
        ("src/bare.cpp:1:", "bare README citation"),
        ("src/bare.cpp:1:", "bare README citation"),
        ("src/described.cpp:1:", "README's ... section"),
        ("src/described.cpp:2:", "README documents"),
        ("scripts/anchor.sh:1:", "docs/solver.md#speed"),
        ("scripts/anchor.sh:1:", "no such file docs/gone.md"),
        ("scripts/readme_anchor.sh:1:", "README.md#gallery"),
    ]
    with tempfile.TemporaryDirectory() as root:
        for rel, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)
        problems = check(root)
    unmatched = list(problems)
    missed = []
    for where, what in planted:
        hit = next((p for p in unmatched if p.startswith(where) and what in p), None)
        if hit is None:
            missed.append(f"{where} {what}")
        else:
            unmatched.remove(hit)
    if missed or unmatched:
        print("check_doc_refs self-test failed:")
        for m in missed:
            print("  missed the planted", m)
        for p in unmatched:
            print("  flagged what is fine:", p)
        return False
    return True


def main(argv):
    args = [a for a in argv if a != "--self-test"]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    if "--self-test" in argv and not self_test():
        return 1
    if not os.path.isfile(os.path.join(root, "README.md")):
        print(f"check_doc_refs: {root} has no README.md", file=sys.stderr)
        return 2
    problems = check(root)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} broken documentation reference(s): point each at the docs/ page "
              "that holds the text (docs/PAGE.md#heading-id)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
