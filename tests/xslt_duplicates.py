"""Find blocks of six or more lines repeated across the stylesheets (``xslt/``).

The project's duplicate finder does not read XSLT, so this small script does
it for ``tests/test_xslt_duplicates.py`` and for developers::

    python tests/xslt_duplicates.py            # list the repeated blocks
    python tests/xslt_duplicates.py --update   # accept today's set as the baseline

A line counts when, stripped of indentation, it says something: blank lines,
lone closing tags (``</xsl:if>``), lines shorter than 12 characters and
declarations (namespace declarations, ``xsl:include`` / ``xsl:import``,
``exclude-result-prefixes``) are passed over, so that six closing tags or the
namespaces every stylesheet declares are not a duplicate. Six
counting lines in a row that stand, to the letter, in another place (another
file, or elsewhere in the same file) are a duplicate block. Each block is
known by the hash of its text; ``tests/data/xslt-duplicates.txt`` lists the
blocks that existed when the check was introduced, to be removed as they are
shared, and the test fails on any block not listed there.
"""

from __future__ import annotations

import hashlib
import re
import sys
from collections import defaultdict
from pathlib import Path

__all__ = ["WINDOW", "find_blocks", "baseline", "runs", "BASELINE"]

ROOT = Path(__file__).resolve().parents[1]
BASELINE = ROOT / "tests" / "data" / "xslt-duplicates.txt"
WINDOW = 6
_TRIVIAL = re.compile(r"^(</[\w:.-]+>|xmlns(:[\w.-]+)?=.*|<xsl:(include|import) .*|exclude-result-prefixes=.*)$")


def _counting_lines(path: Path) -> list[tuple[int, str]]:
    """(line number, stripped text) of the lines of ``path`` that say something."""
    out = []
    for number, raw in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        line = raw.strip()
        if len(line) >= 12 and not _TRIVIAL.match(line):
            out.append((number, line))
    return out


def find_blocks(root: Path = ROOT / "xslt") -> dict[str, list[tuple[str, int, int]]]:
    """Hash of each repeated block -> its places (file, first line, last line)."""
    places: dict[str, list[tuple[str, int, int]]] = defaultdict(list)
    for path in sorted(root.rglob("*.xsl")):
        lines = _counting_lines(path)
        rel = (path.relative_to(ROOT) if path.is_relative_to(ROOT) else path.relative_to(root)).as_posix()
        for i in range(len(lines) - WINDOW + 1):
            window = lines[i:i + WINDOW]
            digest = hashlib.sha256("\n".join(t for _, t in window).encode()).hexdigest()[:16]
            places[digest].append((rel, window[0][0], window[-1][0]))
    repeated = {}
    for digest, where in places.items():
        # two places of one block in one file only count when they do not overlap
        distinct: list[tuple[str, int, int]] = []
        for place in where:
            if not any(p[0] == place[0] and p[2] >= place[1] for p in distinct):
                distinct.append(place)
        if len(distinct) > 1:
            repeated[digest] = distinct
    return repeated


def baseline() -> set[str]:
    if not BASELINE.is_file():
        return set()
    return {line.split()[0] for line in BASELINE.read_text(encoding="utf-8").splitlines()
            if line.strip() and not line.startswith("#")}


def _describe(blocks: dict[str, list[tuple[str, int, int]]], digests: set[str]) -> list[str]:
    return [f"{d}  " + "  ~  ".join(f"{f}:{a}-{b}" for f, a, b in blocks[d])
            for d in sorted(digests, key=lambda d: blocks[d][0])]


def runs(blocks: dict[str, list[tuple[str, int, int]]], digests: set[str]) -> list[str]:
    """The blocks of ``digests`` merged into runs: overlapping blocks in the same files are one run."""
    merged: list[list[tuple[str, int, int]]] = []
    for digest in sorted(digests, key=lambda d: blocks[d]):
        where = blocks[digest]
        last = merged[-1] if merged else None
        if (last is not None and [f for f, _, _ in last] == [f for f, _, _ in where]
                and all(a <= prev_b + 1 for (_, a, _), (_, _, prev_b) in zip(where, last))):
            merged[-1] = [(f, pa, max(pb, b)) for (f, pa, pb), (_, _, b) in zip(last, where)]
        else:
            merged.append(list(where))
    return ["  ~  ".join(f"{f}:{a}-{b}" for f, a, b in run) for run in merged]


def main(argv: list[str]) -> int:
    blocks = find_blocks()
    if "--update" in argv:
        BASELINE.write_text(
            "# Repeated 6-line blocks under xslt/ accepted when the check was introduced (hash, places).\n"
            "# Remove lines as the blocks are shared; tests/test_xslt_duplicates.py fails on any new one.\n"
            + "".join(line + "\n" for line in _describe(blocks, set(blocks))), encoding="utf-8")
        print(f"{len(blocks)} repeated blocks written to {BASELINE.relative_to(ROOT)}")
        return 0
    new = set(blocks) - baseline()
    for line in runs(blocks, new):
        print("new:", line)
    print(f"{len(blocks)} repeated blocks, {len(new)} not in the baseline"
          f" ({len(baseline() - set(blocks))} baseline blocks gone)")
    return 1 if new else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
