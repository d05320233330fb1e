"""Nothing dropped in silence, over every model we have (issue 11).

For each model - the fixtures (fixtures/cases/*/model*.xmi), the broken
corpus (fixtures/broken/*/model.xmi), the hand-made import models
(tests/data/import/**), and the real-tool samples of ../shared/xmi-samples
(skipped with the reason when absent) - the import runs through the driver
and every element of a kind robomda understands (tests/xmi_invariant.py:
components, classes, interfaces, ports, properties, operations, connectors,
dependencies, nodes, devices, execution environments, artifacts,
deployments, communication paths, stereotype applications) must be
recorded in the PIM by its xmi:id, or be named by a warning whose code is
listed in docs/errors.md. A run refused with an error generates nothing, and
says so: the invariant is about what a successful run leaves out. A
benchmark model (bench/synth.py) and the random models of
tests/test_import_generative.py are checked the same way.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

from xmi_invariant import dropped, import_run

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = Path(os.environ.get("ROBOMDA_SHARED", ROOT.parent / "shared")) / "xmi-samples"
DOCUMENTED = set(re.findall(r"^\| ([A-Z]{2,5}[0-9]{3}|NOTE) \|", (ROOT / "docs" / "errors.md").read_text(encoding="utf-8"),
                            re.M))

OWN = sorted(
    [p for p in (ROOT / "fixtures" / "cases").glob("*/model*.xmi")]
    + [p for p in (ROOT / "fixtures" / "broken").glob("*/model.xmi")]
    + [p for p in (ROOT / "tests" / "data" / "import").rglob("*") if p.suffix in (".xmi", ".uml", ".xml")])


def _check(model: Path) -> None:
    code, pim, messages = import_run(model)
    assert code in (0, 1, 2), "\n".join(messages)
    codes = {m.split(":", 1)[0] for m in messages}
    assert codes <= DOCUMENTED, f"codes missing from docs/errors.md: {codes - DOCUMENTED}"
    if code != 0:
        assert messages, "a refused model must say why"
        return
    lost = dropped(model, pim, messages)
    assert not lost, f"{model}: dropped in silence (xmi:id -> metaclass): {lost}"


@pytest.mark.parametrize("model", OWN, ids=[p.relative_to(ROOT).as_posix() for p in OWN])
def test_nothing_is_dropped_in_silence(model: Path) -> None:
    _check(model)


def _samples() -> list[Path]:
    if not SAMPLES.is_dir():
        return []
    return sorted(p for p in SAMPLES.rglob("*") if p.suffix in (".xmi", ".uml", ".xml"))


@pytest.mark.parametrize("model", _samples() or [None], ids=lambda p: p.name if p else "absent")
def test_nothing_is_dropped_in_silence_in_real_samples(model: Path | None) -> None:
    if model is None:
        pytest.skip(f"shared samples absent: {SAMPLES}")
    _check(model)


@pytest.mark.parametrize("shape", ["ring", "composite", "nested", "datatypes", "deployment", "calls"])
def test_nothing_is_dropped_in_silence_in_a_benchmark_model(tmp_path: Path, shape: str) -> None:
    """The generated models of bench/synth.py (one of 50 components), in each shape the bench draws."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("synth", ROOT / "bench" / "synth.py")
    synth = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(synth)
    assert shape in synth.SHAPES
    _check(synth.write_model(50, tmp_path / "synth-50.xmi", shape))


def test_the_invariant_can_fail(tmp_path: Path) -> None:
    """A PIM that lacks an element and no warning naming it is caught."""
    model = ROOT / "tests" / "data" / "import" / "classes" / "vp-owners.xmi"
    code, pim, messages = import_run(model)
    assert code == 0
    assert dropped(model, pim, messages) == {}
    assert dropped(model, pim, [m for m in messages if "vpLoose" not in m]) == {"vpLoose": "Connector"}
    assert "vpWheel" in dropped(model, pim.replace('id="vpWheel"', 'id="other"'), messages)
