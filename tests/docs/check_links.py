#!/usr/bin/env python3
"""Checks that every file the documentation cites exists.

In README.md and docs/**/*.md (outside fenced code blocks):
  - every relative link target, [text](path) or ![alt](path), without its #fragment;
  - every repository path in an inline code span: a word that starts with include/, tests/,
    tools/, scripts/, docs/, examples/ or cmake/ and is not part of a longer path (so
    build/gcc/tools/... and out/... are output paths, not checked). Globs (*), brace lists
    ({a,b}) and placeholders (<area>, read as *) must match at least one file.

Prints each missing target as FILE:LINE: target and exits 1 if there is any.
Usage: python3 tests/docs/check_links.py REPOSITORY_ROOT
"""
import glob
import itertools
import re
import sys
from pathlib import Path

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1", re.S)
REPO_PATH = re.compile(r"(?<![\w./$-])((?:include|tests|tools|scripts|docs|examples|cmake)/[\w./*{},+<>-]*)")


def expand_braces(path: str) -> list[str]:
    """a_{x,y}_{1,2} -> a_x_1, a_x_2, a_y_1, a_y_2."""
    parts = re.split(r"\{([^{}]*)\}", path)
    choices = [[p] if i % 2 == 0 else p.split(",") for i, p in enumerate(parts)]
    return ["".join(c) for c in itertools.product(*choices)]


def exists(root: Path, path: str) -> bool:
    for candidate in expand_braces(path):
        if not (glob.glob(str(root / candidate)) if "*" in candidate else (root / candidate).exists()):
            return False
    return True


def check(root: Path, doc: Path, counted: list[int]) -> list[str]:
    # Fenced code blocks become blank lines (line numbers stay), then links and code spans are
    # found in the whole text, since a span may continue on the next line.
    lines, in_fence = [], False
    for line in doc.read_text().splitlines():
        fence = line.lstrip().startswith("```")
        lines.append("" if in_fence or fence else line)
        in_fence ^= fence
    text = "\n".join(lines)
    missing = []

    def where(offset: int) -> str:
        return f"{doc.relative_to(root)}:{text.count(chr(10), 0, offset) + 1}"

    for m in LINK.finditer(text):
        target = m.group(1)
        if re.match(r"^[a-z]+:", target) or target.startswith("#"):
            continue  # http:, https:, mailto:, an anchor in the same page
        counted[0] += 1
        if not (doc.parent / target.split("#", 1)[0]).exists():
            missing.append(f"{where(m.start())}: link {target}")
    for m in CODE_SPAN.finditer(text):
        for path in REPO_PATH.findall(m.group(2)):
            path = re.sub(r"<[^<>/]*>", "*", path.rstrip(".,:;"))
            counted[0] += 1
            if not exists(root, path):
                missing.append(f"{where(m.start())}: path {path}")
    return missing


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    root = Path(sys.argv[1]).resolve()
    docs = [root / "README.md", *sorted((root / "docs").rglob("*.md"))]
    counted = [0]
    missing = [m for doc in docs for m in check(root, doc, counted)]
    for m in missing:
        print(m)
    print(f"{len(docs)} documents, {counted[0]} links and paths, {len(missing)} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
