"""The rules give the same findings run in SaxonC (large models) as on libxslt (small ones).

robomda.rules runs a stage's rules in SaxonC, on the tree Saxon holds, when
the stage is large (rules.SAXON_FROM characters), and on libxslt otherwise.
The goldens (test_broken.py) and the rule cases (test_rules.py) are small
models, so they run on libxslt; here the same models go through the Saxon
path, finding for finding, message and location included.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from robomda import pipeline
from robomda.api import check
from robomda.diagnostics import RobomdaError
from robomda.engine import shared
from robomda.rules import findings
from test_broken import BROKEN, CORPUS, ROOT
from test_rules import CASES_BY_RULE, _edited


@pytest.mark.parametrize("rule", sorted(CASES_BY_RULE))
def test_each_rule_case_finds_the_same_on_both_engines(rule: str) -> None:
    rules, phase, _, _ = CASES_BY_RULE[rule]
    text = _edited(rule)
    tree = etree.fromstring(text.encode("utf-8"))
    on_libxslt = findings(rules, phase, tree)
    assert on_libxslt
    assert findings(rules, phase, tree, source=shared().parse(text)) == on_libxslt


def _diagnostics(case: str) -> tuple[int, list[str]]:
    args = (BROKEN / case / "args").read_text(encoding="utf-8").split()
    target = args[args.index("--target") + 1] if "--target" in args else None
    replace = [args[i + 1] for i, a in enumerate(args) if a == "--replace"]
    try:
        done = check(Path("fixtures/broken") / case / "model.xmi", target, replace=replace)
    except RobomdaError as exc:  # input that cannot be read: the same either way, checked all the same
        return exc.exit_code, [d.format() for d in exc.diagnostics]
    return done.exit_code, [d.format() for d in done.diagnostics]


@pytest.mark.parametrize("case", CORPUS)
def test_the_broken_corpus_checks_the_same_with_every_rule_on_saxon(case: str,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    args = (BROKEN / case / "args").read_text(encoding="utf-8").split()
    if any(a not in ("--target", "orocos", "ros1", "ros2", "openrtm", "--replace") and "=" not in a for a in args):
        pytest.skip(f"options beyond --target: {args}")
    on_libxslt = _diagnostics(case)
    monkeypatch.setattr(pipeline, "SAXON_FROM", 0)
    assert _diagnostics(case) == on_libxslt
