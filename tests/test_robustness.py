"""Damaged models never crash robomda: each run ends with files or with located diagnostics.

Seeded random mutations of the fixture models (an attribute or element
removed, a reference pointed elsewhere, odd names, a duplicated id) through
every target. A run may succeed or report model errors (exit 1 or 2); an
internal error (exit 3) or any other exception is a bug.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, targets
from robomda.diagnostics import RobomdaError

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted((ROOT / "fixtures" / "cases").glob("*/model*.xmi"))
XMI_IDS = ("{http://www.omg.org/spec/XMI/20131001}id", "{http://schema.omg.org/spec/XMI/2.1}id")
REFERENCES = ("type", "supplier", "client", "general", "realizingClassifier", "role", "partWithPort",
              "deployedArtifact", "utilizedElement", "contract", "base_Component", "base_Class")
NAMES = ("class", "my name", "Ünïcode", "123abc", "", "x" * 300, "new", "a-b.c")


def _xmi_id(element: etree._Element) -> str | None:
    return next((element.get(k) for k in XMI_IDS if element.get(k)), None)


def _mutate(rng: random.Random, tree: etree._ElementTree) -> str:
    elements = [e for e in tree.getroot().iter() if isinstance(e.tag, str)][1:]
    target = rng.choice(elements)
    kind = rng.choice(["drop-attribute", "drop-element", "retarget-reference", "rename", "duplicate-id"])
    if kind == "drop-attribute" and target.attrib:
        del target.attrib[rng.choice(sorted(target.attrib))]
    elif kind == "drop-element" and target.getparent() is not None:
        target.getparent().remove(target)
    elif kind == "retarget-reference":
        refs = [(e, k) for e in elements for k in e.attrib if k in REFERENCES]
        if refs:
            element, key = rng.choice(refs)
            element.set(key, _xmi_id(rng.choice(elements)) or "nowhere")
    elif kind == "rename" and target.get("name") is not None:
        target.set("name", rng.choice(NAMES))
    elif kind == "duplicate-id":
        with_ids = [e for e in elements if _xmi_id(e)]
        key = next(k for k in XMI_IDS if with_ids[0].get(k))
        with_ids[0].set(key, _xmi_id(rng.choice(with_ids[1:])))
    return kind


@pytest.mark.parametrize("seed", [*range(24), 387])
def test_a_damaged_model_gets_files_or_diagnostics_never_a_crash(seed: int, tmp_path: Path) -> None:
    rng = random.Random(seed)
    source = rng.choice(CASES)
    tree = etree.parse(str(source))
    kind = _mutate(rng, tree)
    model = tmp_path / source.name
    tree.write(str(model), xml_declaration=True, encoding="UTF-8")
    for target in targets():
        try:
            generate(model, tmp_path / "out", target, write=False)
        except RobomdaError as exc:
            assert exc.exit_code in (1, 2), f"{kind} on {source.name}, {target}: {exc}"
            assert all(d.code and d.message for d in exc.diagnostics)
