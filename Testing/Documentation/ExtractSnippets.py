"""Extracts the code blocks of README.md and Documentation/*.md, so that the tests run them.

    ExtractSnippets.py ROOT OUTPUT KIND...   write each block of the kinds to OUTPUT/PAGE-N.EXT
    ExtractSnippets.py ROOT --summary        count the blocks of every kind

A block's kind is its fence's info string:

    ```python            VTK's Python with the built package (the VTK stage runs it)
    ```python pvpython   pvpython (the ParaView stage runs it)
    ```cpp               a whole program, compiled against the module and run
    ```python no-run     shown, not run (a fragment); also `cpp no-run`
    ```sh, ```cmake, ```text
                         commands, build code and output: not run here

Runnable blocks take a mesh path as their first argument and run from the repository's root.
An unknown info string is an error, so that no code block escapes the tests unnoticed.
"""
import collections
import glob
import os
import re
import sys

RUNNABLE = {"python": "py", "python pvpython": "py", "cpp": "cxx"}
SHOWN = {"python no-run", "cpp no-run", "sh", "cmake", "text"}
FENCE = re.compile(r"^```([^\n`]*)\n(.*?)^```\s*$", re.S | re.M)


def pages(root):
    yield os.path.join(root, "README.md")
    yield from sorted(glob.glob(os.path.join(root, "Documentation", "*.md")))


def blocks(root):
    """(page stem, index on the page, kind, code) of every fenced block."""
    for page in pages(root):
        stem = os.path.splitext(os.path.basename(page))[0]
        with open(page, encoding="utf-8") as text:
            for index, match in enumerate(FENCE.finditer(text.read()), start=1):
                kind = " ".join(match.group(1).split())
                if kind not in RUNNABLE and kind not in SHOWN:
                    sys.exit(f"{page}: code block {index} has the unknown fence '{kind}'; "
                             f"use one of {sorted(RUNNABLE) + sorted(SHOWN)}")
                yield stem, index, kind, match.group(2)


def main():
    root = sys.argv[1]
    if sys.argv[2:] == ["--summary"]:
        counts = collections.Counter(kind for _, _, kind, _ in blocks(root))
        runs = sum(n for kind, n in counts.items() if kind in RUNNABLE)
        print(f"{sum(counts.values())} code blocks, {runs} run by the tests:",
              ", ".join(f"{n} {kind}" for kind, n in sorted(counts.items())))
        return
    output, kinds = sys.argv[2], set(sys.argv[3:])
    os.makedirs(output, exist_ok=True)
    for stale in glob.glob(os.path.join(output, "*")):
        os.remove(stale)
    for stem, index, kind, code in blocks(root):
        if kind in kinds:
            with open(os.path.join(output, f"{stem}-{index}.{RUNNABLE[kind]}"), "w",
                      encoding="utf-8") as snippet:
                snippet.write(code)


if __name__ == "__main__":
    main()
