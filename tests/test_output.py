"""The file-set writer: all or nothing, and never over a file the user owns."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from robomda.diagnostics import RobomdaError
from robomda.output import NEW_SUFFIX, STATE_FILE, write_fileset

FS = "urn:robomda:fileset:1"


def fileset(*files: tuple[str, str, str]) -> etree._Element:
    root = etree.Element(f"{{{FS}}}files", target="test")
    for path, text, mode in files:
        node = etree.SubElement(root, f"{{{FS}}}file", path=path, mode=mode, stylesheet="x.xsl")
        node.text = text
    return root


def test_first_run_writes_everything_and_records_generated_files(tmp_path: Path) -> None:
    report = write_fileset(fileset(("src/a.cpp", "A\n", "generated"), ("src/u.cpp", "U\n", "user")), tmp_path)
    assert sorted(report.written) == ["src/a.cpp", "src/u.cpp"]
    assert (tmp_path / "src/a.cpp").read_text() == "A\n"
    import json
    state = json.loads((tmp_path / STATE_FILE).read_text())
    # generated files by hash; user files only as what they hold (never overwritten, so no hash)
    assert "src/a.cpp" in state["files"] and "src/u.cpp" not in state["files"] and "src/u.cpp" in state["user"]


def test_second_run_rewrites_generated_and_keeps_user_edits(tmp_path: Path) -> None:
    write_fileset(fileset(("a.cpp", "A1\n", "generated"), ("u.cpp", "U1\n", "user")), tmp_path)
    (tmp_path / "u.cpp").write_text("my code\n")
    report = write_fileset(fileset(("a.cpp", "A2\n", "generated"), ("u.cpp", "U2\n", "user")), tmp_path)
    assert (tmp_path / "a.cpp").read_text() == "A2\n"
    assert (tmp_path / "u.cpp").read_text() == "my code\n"
    assert (tmp_path / ("u.cpp" + NEW_SUFFIX)).read_text() == "U2\n"
    assert report.kept_user == ["u.cpp"] and report.fresh_copies == ["u.cpp" + NEW_SUFFIX]


def test_unchanged_files_are_not_rewritten(tmp_path: Path) -> None:
    files = fileset(("a.cpp", "A\n", "generated"))
    write_fileset(files, tmp_path)
    assert write_fileset(files, tmp_path).unchanged == ["a.cpp"]


@pytest.mark.parametrize("how", ["foreign", "edited"])
def test_a_file_robomda_does_not_own_stops_the_run_before_any_write(tmp_path: Path, how: str) -> None:
    if how == "edited":
        write_fileset(fileset(("a.cpp", "A1\n", "generated")), tmp_path)
    (tmp_path / "a.cpp").write_text("the user's own file\n")
    with pytest.raises(RobomdaError) as caught:
        write_fileset(fileset(("b.cpp", "B\n", "generated"), ("a.cpp", "A2\n", "generated")), tmp_path)
    assert caught.value.diagnostics[0].code == "OUT001"
    assert "a.cpp" in caught.value.diagnostics[0].message
    assert (tmp_path / "a.cpp").read_text() == "the user's own file\n"
    assert not (tmp_path / "b.cpp").exists()


def test_stale_generated_files_are_removed_only_when_unedited(tmp_path: Path) -> None:
    write_fileset(fileset(("old.cpp", "O\n", "generated"), ("edited.cpp", "E\n", "generated")), tmp_path)
    (tmp_path / "edited.cpp").write_text("changed\n")
    report = write_fileset(fileset(("new.cpp", "N\n", "generated")), tmp_path)
    assert report.removed == ["old.cpp"] and not (tmp_path / "old.cpp").exists()
    assert report.kept_stale == ["edited.cpp"] and (tmp_path / "edited.cpp").read_text() == "changed\n"


def test_output_that_is_a_file_is_refused(tmp_path: Path) -> None:
    target = tmp_path / "out"
    target.write_text("x")
    with pytest.raises(RobomdaError) as caught:
        write_fileset(fileset(("a.cpp", "A\n", "generated")), target)
    assert caught.value.exit_code == 2


def test_a_failed_write_leaves_the_old_package_whole(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A write error partway (disk full, a read-only file) used to leave half a package and no state."""
    write_fileset(fileset(("a.cpp", "A1\n", "generated"), ("b.cpp", "B1\n", "generated")), tmp_path / "out")
    before = {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir() if p.is_file()}
    calls = {"n": 0}
    real = Path.write_bytes

    def failing(self: Path, data: bytes) -> int:
        calls["n"] += 1
        if calls["n"] == 2:
            raise OSError(28, "No space left on device", str(self))
        return real(self, data)

    monkeypatch.setattr(Path, "write_bytes", failing)
    with pytest.raises(OSError):
        write_fileset(fileset(("a.cpp", "A2\n", "generated"), ("b.cpp", "B2\n", "generated")), tmp_path / "out")
    monkeypatch.undo()
    assert {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir() if p.is_file()} == before
    assert [p.name for p in tmp_path.iterdir()] == ["out"]  # nothing left beside it
    write_fileset(fileset(("a.cpp", "A2\n", "generated"), ("b.cpp", "B2\n", "generated")), tmp_path / "out")
    assert (tmp_path / "out" / "b.cpp").read_text() == "B2\n"


def test_the_users_own_files_and_folders_survive_a_regeneration(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_fileset(fileset(("src/a.cpp", "A1\n", "generated")), out)
    (out / "build").mkdir()
    (out / "build" / "CMakeCache.txt").write_text("cache\n")
    (out / "build" / "link").symlink_to("CMakeCache.txt")
    (out / "notes.md").write_text("mine\n")
    write_fileset(fileset(("src/a.cpp", "A2\n", "generated")), out)
    assert (out / "build" / "CMakeCache.txt").read_text() == "cache\n"
    assert (out / "build" / "link").is_symlink() and (out / "build" / "link").read_text() == "cache\n"
    assert (out / "notes.md").read_text() == "mine\n" and (out / "src" / "a.cpp").read_text() == "A2\n"


def test_an_interrupted_swap_is_completed_by_the_next_run(tmp_path: Path) -> None:
    """Killed between the two renames of the fallback swap: no OUT, a complete new tree beside it."""
    from robomda.output import recover
    out = tmp_path / "out"
    write_fileset(fileset(("a.cpp", "A1\n", "generated")), out)
    staged = tmp_path / ".out.robomda-new"
    write_fileset(fileset(("a.cpp", "A2\n", "generated")), staged)  # a complete tree, state file included
    out.rename(tmp_path / ".out.robomda-old")
    recover(out)
    assert (out / "a.cpp").read_text() == "A2\n" and [p.name for p in tmp_path.iterdir()] == ["out"]


def _tree(folder: Path) -> dict[str, tuple[bytes, int]]:
    """Every file under ``folder`` (itself included) with its bytes and modification time."""
    return {p.relative_to(folder).as_posix(): (p.read_bytes(), p.stat().st_mtime_ns)
            for p in folder.rglob("*") if p.is_file()}


def test_compare_lists_what_a_run_would_add_change_and_remove_and_writes_nothing(tmp_path: Path) -> None:
    from robomda.output import compare_fileset
    out = tmp_path / "out"
    write_fileset(fileset(("a.cpp", "A1\n", "generated"), ("old.cpp", "O\n", "generated"),
                          ("u.cpp", "U1\n", "user"), ("v.cpp", "V1\n", "user")), out)
    (out / "u.cpp").write_text("my code\n")  # the user's: never drift
    (out / "v.cpp").unlink()  # a missing user file is: the run writes it
    (out / "notes.md").write_text("mine\n")  # not robomda's: never drift
    before = _tree(tmp_path)
    drift = compare_fileset(fileset(("a.cpp", "A2\n", "generated"), ("new.cpp", "N\n", "generated"),
                                    ("u.cpp", "U2\n", "user"), ("v.cpp", "V2\n", "user")), out)
    assert _tree(tmp_path) == before and sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert (drift.added, drift.changed, drift.removed) == (["new.cpp", "v.cpp"], ["a.cpp"], ["old.cpp"])
    assert drift.lines() == ["changed a.cpp", "added   new.cpp", "removed old.cpp", "added   v.cpp"]
    assert drift.diffs["a.cpp"] == "--- a/a.cpp\n+++ b/a.cpp\n@@ -1 +1 @@\n-A1\n+A2\n"
    assert drift.diffs["new.cpp"] == "--- /dev/null\n+++ b/new.cpp\n@@ -0,0 +1 @@\n+N\n"
    assert drift.diffs["old.cpp"] == "--- a/old.cpp\n+++ /dev/null\n@@ -1 +0,0 @@\n-O\n"
    assert drift.diff("m/x.xmi/").startswith("--- a/m/x.xmi/a.cpp\n+++ b/m/x.xmi/a.cpp\n@@ -1 +1 @@\n-A1\n+A2\n")
    same = compare_fileset(fileset(("a.cpp", "A1\n", "generated"), ("old.cpp", "O\n", "generated"),
                                   ("u.cpp", "U2\n", "user")), out)
    assert not same and same.lines() == [] and same.diff() == ""


def test_an_exact_compare_takes_user_files_and_foreign_files_too(tmp_path: Path) -> None:
    """A golden copy (the pytest plugin's expected folder) holds what a fresh run writes, nothing else."""
    from robomda.output import compare_fileset
    out = tmp_path / "golden"
    write_fileset(fileset(("a.cpp", "A\n", "generated"), ("u.cpp", "U1\n", "user")), out)
    (out / "extra.txt").write_text("x\n")
    (out / ("u.cpp" + NEW_SUFFIX)).write_text("fresh\n")
    drift = compare_fileset(fileset(("a.cpp", "A\n", "generated"), ("u.cpp", "U2\n", "user")), out, exact=True)
    assert drift.lines() == ["removed extra.txt", "changed u.cpp"]
    assert "-U1\n+U2\n" in drift.diffs["u.cpp"]
    assert compare_fileset(fileset(("a.cpp", "A\n", "generated")), tmp_path / "none", exact=True).added == ["a.cpp"]
    assert not (tmp_path / "none").exists()
