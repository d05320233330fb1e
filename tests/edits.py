"""Edits of model files in the tests: one exact, unique replacement per call; variants of a fixture."""

from __future__ import annotations

from pathlib import Path


def edit(path: Path, old: str, new: str) -> None:
    """Replace the one occurrence of ``old`` in ``path`` by ``new`` (fails if it is not there exactly once)."""
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new), encoding="utf-8")


def distributed_variant(tmp: Path, *edits: tuple[str, str, int], name: str = "model.xmi") -> Path:
    """The distributed fixture (seed 002) edited (old, new, how many times old occurs) in
    TMP/cases/distributed/NAME, beside a link to its library's case (../headlamp/atomic)."""
    cases = Path(__file__).resolve().parent.parent / "fixtures" / "cases"
    folder = tmp / "cases" / "distributed"
    folder.mkdir(parents=True, exist_ok=True)
    if not (tmp / "cases" / "headlamp").exists():
        (tmp / "cases" / "headlamp").symlink_to(cases / "headlamp")
    text = (cases / "distributed" / "model.xmi").read_text(encoding="utf-8")
    for old, new, count in edits:
        assert text.count(old) == count, old
        text = text.replace(old, new)
    model = folder / name
    model.write_text(text, encoding="utf-8")
    return model
