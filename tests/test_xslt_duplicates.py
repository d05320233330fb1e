"""No new repeated blocks of six or more lines under xslt/ (tests/xslt_duplicates.py).

The project's duplicate finder does not read XSLT. The blocks that were
repeated when this check came in are listed in tests/data/xslt-duplicates.txt;
a block that is not listed fails here with its places, to be shared through
xslt/common/ (or accepted on purpose with ``--update``, said in the commit).
"""

from __future__ import annotations

import xslt_duplicates as dup


def test_no_new_repeated_blocks_in_the_stylesheets() -> None:
    blocks = dup.find_blocks()
    new = set(blocks) - dup.baseline()
    assert not new, "repeated blocks of 6+ lines not in tests/data/xslt-duplicates.txt:\n" + "\n".join(
        dup.runs(blocks, new))


def test_the_finder_sees_a_copied_block(tmp_path) -> None:
    body = "\n".join(f'  <xsl:variable name="v{i}" select="string-length($x) + {i}"/>' for i in range(6))
    lines = [f"<xsl:stylesheet> <!-- {n} -->" for n in "ab"]
    for n, head in enumerate(lines):
        (tmp_path / f"s{n}.xsl").write_text(f"{head}\n{body}\n</xsl:stylesheet>\n", encoding="utf-8")
    found = dup.find_blocks(tmp_path)
    assert len(found) == 1
    (places,) = found.values()
    assert [p[1:] for p in places] == [(2, 7), (2, 7)]


def test_closing_tags_short_lines_and_declarations_do_not_make_a_block(tmp_path) -> None:
    body = "\n".join(["</xsl:if>", "</xsl:when>", "</xsl:choose>", "<xsl:otherwise/>", "</xsl:for-each>",
                      "</xsl:template>", "</xsl:if>"] * 2
                     + ['xmlns:xsl="http://www.w3.org/1999/XSL/Transform"', 'xmlns:xs="http://www.w3.org/2001/XMLSchema"',
                        'xmlns:f="urn:robomda:xslt:function"', 'xmlns:fp="urn:robomda:xslt:function:private"',
                        '<xsl:include href="../../common/indent.xsl"/>', '<xsl:include href="../common/naming.xsl"/>',
                        'exclude-result-prefixes="#all">'])
    for n in range(2):
        (tmp_path / f"s{n}.xsl").write_text(body + "\n", encoding="utf-8")
    assert dup.find_blocks(tmp_path) == {}


def test_no_private_function_is_defined_twice_under_xslt() -> None:
    """A helper two stages need lives once (xslt/common/, xslt/m2t/common/): no fp: function is
    declared in two stylesheet modules, even where the two never meet in one transform."""
    import re
    from collections import defaultdict
    from pathlib import Path

    root = Path(__file__).resolve().parents[1] / "xslt"
    where = defaultdict(list)
    for path in sorted(root.rglob("*.xsl")):
        for name in re.findall(r'<xsl:function\s+name="(fp:[^"]+)"', path.read_text(encoding="utf-8")):
            where[name].append(path.relative_to(root).as_posix())
    twice = {name: paths for name, paths in where.items() if len(paths) > 1}
    assert not twice, twice
