#!/usr/bin/env python3
"""Refreshes the generated blocks of docs/results/*.md from the files a demonstration wrote.

A generated block is

    <!-- output: PATH [match=REGEX] [head=N] -->
    ...replaced...
    <!-- end output -->

PATH is relative to the demonstration's OUT_DIR. The block becomes a fenced text block holding
the file's lines (only those matching REGEX, at most N of them, when given). A missing file or
an unterminated block is an error (exit 1): a document never keeps a stale block silently.

Usage: python3 scripts/render_results.py OUT_DIR FILE.md [FILE.md ...]
"""
import re
import shlex
import sys
from pathlib import Path

BEGIN = re.compile(r"^<!-- output: (.*?) -->$")
END = "<!-- end output -->"


def render_block(out_dir: Path, spec: str) -> list[str]:
    words = shlex.split(spec)
    if not words:
        raise ValueError("empty output marker")
    path, options = out_dir / words[0], dict(w.split("=", 1) for w in words[1:])
    unknown = set(options) - {"match", "head"}
    if unknown:
        raise ValueError(f"unknown option(s) {sorted(unknown)} in marker '{spec}'")
    if not path.is_file():
        raise FileNotFoundError(f"{path} (named by marker '{spec}') does not exist: run the demonstration first")
    lines = path.read_text().splitlines()
    if "match" in options:
        pattern = re.compile(options["match"])
        lines = [line for line in lines if pattern.search(line)]
    if "head" in options:
        lines = lines[: int(options["head"])]
    if not lines:
        raise ValueError(f"marker '{spec}' selects no line of {path}")
    return ["```text", *lines, "```"]


def render(out_dir: Path, doc: Path) -> int:
    text = doc.read_text().splitlines()
    out, i, blocks = [], 0, 0
    while i < len(text):
        m = BEGIN.match(text[i])
        out.append(text[i])
        i += 1
        if not m:
            continue
        end = next((j for j in range(i, len(text)) if text[j] == END), None)
        if end is None:
            raise ValueError(f"{doc}: marker '{m.group(1)}' has no '{END}'")
        out.extend(render_block(out_dir, m.group(1)))
        out.append(END)
        i = end + 1
        blocks += 1
    doc.write_text("\n".join(out) + "\n")
    return blocks


def main(argv: list[str]) -> int:
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2
    out_dir = Path(argv[1])
    try:
        for doc in map(Path, argv[2:]):
            print(f"render_results: {doc}: {render(out_dir, doc)} generated block(s) refreshed")
    except (OSError, ValueError) as e:
        print(f"render_results: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
