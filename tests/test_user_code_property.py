"""User code on every target (issue 31 item 3): a property test of the user-file scheme.

Each cycle applies a random model edit (add / remove / rename a component, a port or a
property: tests/user_code_models.py builds the XMI) and a random user edit (text inserted into
a user file: a class written once, a tuned-values file), then regenerates into the same folder,
as a user does for months. After every cycle: every byte the user wrote is still there; every
user file is still part of the build (CMakeLists.txt compiles each user source, a generated
file includes or loads each other one). When robomda refuses a run (OUT003: the component of a
user file was renamed or removed) nothing may have changed on disk; the simulated user then
does what the message says (moves the code to the file it names, or takes the file out) and
the next run goes on.

Cheap cycles: one compiled chain (the API's engine) and a pool of models: a random walk of
POOL single edits of every kind from a first model (seeded, so every run and engine sees the
same pool; each edit kind occurs, which the test checks). A cycle's model edit moves to any
model of the pool: a neighbour is one edit away, any other several at once, as when a user
changes a model a lot between two generations. The file set of each (target, model) is made
once; only the writer runs every cycle. ``ROBOMDA_USER_CYCLES`` (default 340 per target) and
``ROBOMDA_USER_POOL`` (default 16) ask for more.
"""

from __future__ import annotations

import os
import random
import re
import shutil
import tempfile
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

from robomda.api import generate
from robomda.diagnostics import RobomdaError
from robomda.output import write_fileset
from user_code_models import Comp, Port, xmi

FS = "{urn:robomda:fileset:1}"
TARGETS = ["orocos", "ros1", "ros2"]
CYCLES = int(os.environ.get("ROBOMDA_USER_CYCLES", "340"))  # per target: 1,020 in all
STEPS = 20  # cycles per example (one output folder lives through them)
POOL = int(os.environ.get("ROBOMDA_USER_POOL", "16"))
COMP_NAMES = ["Arm", "Camera", "Planner", "Gripper"]
PORT_NAMES = ["cmd", "state", "pose"]
PROP_NAMES = ["gain", "limit"]
_FILESETS: dict[tuple[str, str], etree._Element] = {}
_COUNTS = {"cycles": 0, "runs": 0, "refused": 0}

# ------------------------------------------------------------------ edits
FIRST = (Comp("1", "Arm", (Port("1", "cmd", "in"), Port("2", "state", "out")), (("1", "gain"),)),)


def model_pool(size: int, seed: int = 31) -> tuple[list[tuple[Comp, ...]], set[str]]:
    """A random walk of ``size`` models from FIRST, each one edit (one that changes it) from the last,
    and the kinds of edit made."""
    draw = random.Random(seed)
    pool, kinds = [FIRST], set()
    while len(pool) < size:
        edit = _random_edit(draw, sorted(set(EDIT_KINDS) - kinds))
        after = edit_model(pool[-1], edit)
        if after != pool[-1] and after not in pool:
            pool.append(after)
            kinds.add(edit[0])
    return pool, kinds


EDIT_KINDS = ["add-comp", "remove-comp", "rename-comp", "add-port", "remove-port", "rename-port",
              "add-prop", "remove-prop", "rename-prop"]


def _random_edit(draw: random.Random, missing: list[str]) -> tuple:
    """A random edit; half of the time one of a kind the walk has not made yet."""
    kind = draw.choice(missing if missing and draw.random() < 0.5 else EDIT_KINDS)
    return (kind, draw.randrange(4), draw.randrange(4) if kind == "rename-comp" else draw.randrange(3),
            draw.randrange(3) if kind == "rename-port" else draw.choice(["in", "out"]))


user_edits = st.one_of(st.none(), st.tuples(st.integers(0, 50), st.floats(0, 1),
                                            st.text(st.characters(codec="utf-8", exclude_characters="\r\x00"),
                                                    min_size=1, max_size=30)))
cycles = st.lists(st.tuples(st.one_of(st.none(), st.integers(0, POOL - 1)), user_edits), min_size=STEPS, max_size=STEPS)


def _pick(items: tuple, i: int):
    return items[i % len(items)] if items else None


def _fresh_key(used: set[str]) -> str:
    return str(1 + max((int(k) for k in used), default=0))


def _edit_comp(comps: tuple[Comp, ...], c: Comp, edit: tuple) -> Comp:
    kind = edit[0]
    if kind == "add-port":
        name = PORT_NAMES[edit[2]]
        if any(p.name == name for p in c.ports):
            return c
        return Comp(c.key, c.name, c.ports + (Port(_fresh_key({p.key for p in c.ports}), name, edit[3]),), c.properties)
    if kind == "remove-port" and c.ports:
        port = _pick(c.ports, edit[2])
        return Comp(c.key, c.name, tuple(p for p in c.ports if p != port), c.properties)
    if kind == "rename-port" and c.ports:
        port, name = _pick(c.ports, edit[2]), PORT_NAMES[edit[3]]
        if any(p.name == name for p in c.ports):
            return c
        return Comp(c.key, c.name, tuple(Port(p.key, name, p.direction) if p == port else p for p in c.ports), c.properties)
    names = [n for _, n in c.properties]
    new = PROP_NAMES[edit[2] % len(PROP_NAMES)]
    if kind == "add-prop" and new not in names:
        return Comp(c.key, c.name, c.ports, c.properties + ((_fresh_key({k for k, _ in c.properties}), new),))
    if kind == "remove-prop" and c.properties:
        gone = _pick(c.properties, edit[2])
        return Comp(c.key, c.name, c.ports, tuple(p for p in c.properties if p != gone))
    if kind == "rename-prop" and c.properties:
        key, name = _pick(c.properties, edit[2])
        other = next(n for n in PROP_NAMES if n != name)
        if other not in names:
            return Comp(c.key, c.name, c.ports, tuple((k, other if k == key else n) for k, n in c.properties))
    return c


def edit_model(comps: tuple[Comp, ...], edit: tuple | None) -> tuple[Comp, ...]:
    """The model after ``edit``; an edit that does not apply leaves it as it is (one component at least)."""
    if edit is None:
        return comps
    kind, names = edit[0], {c.name for c in comps}
    if kind == "add-comp":
        name = COMP_NAMES[edit[1]]
        return comps if name in names else comps + (Comp(_fresh_key({c.key for c in comps}), name, (Port("1", "cmd", "in"),)),)
    if kind == "remove-comp":
        return comps if len(comps) == 1 else tuple(c for c in comps if c != _pick(comps, edit[1]))
    if kind == "rename-comp":
        old, name = _pick(comps, edit[1]), COMP_NAMES[edit[2]]
        return comps if name in names else tuple(Comp(c.key, name, c.ports, c.properties) if c == old else c for c in comps)
    target = _pick(comps, edit[1])
    return tuple(_edit_comp(comps, c, edit) if c == target else c for c in comps)


# ---------------------------------------------------------------- the run
def fileset(target: str, comps: tuple[Comp, ...], folder: Path) -> etree._Element:
    """The file set of ``comps`` for ``target``, made once per model."""
    text = xmi(comps)
    key = (target, text)
    if key not in _FILESETS:
        model = folder / "model.xmi"
        model.write_text(text, encoding="utf-8")
        done = generate(model, None, target, write=False)
        _FILESETS[key] = etree.fromstring(done.stages["text"].encode("utf-8"))
        _COUNTS["runs"] += 1
    return _FILESETS[key]


def _snapshot(out: Path) -> dict[str, bytes]:
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in out.rglob("*") if p.is_file()}


def follow_advice(out: Path, refused: RobomdaError, mine: dict[str, bytes]) -> None:
    """Do what each OUT003 says: move the code to the file it names, or take the file out of the package."""
    codes = {d.code for d in refused.diagnostics}
    assert codes == {"OUT003"}, [d.render() if hasattr(d, "render") else d.message for d in refused.diagnostics]
    # a file whose path another element took is emptied first: another file's code may move there
    for d in sorted(refused.diagnostics, key=lambda d: "its path is now" not in d.message):
        rel = Path(d.file).relative_to(out).as_posix()
        moved = re.search(r"it is now (\S+): move your code there", d.message)
        data = mine.pop(rel)
        (out / rel).unlink()
        if moved:
            dest = out / moved.group(1)
            dest.parent.mkdir(parents=True, exist_ok=True)
            assert not dest.exists(), dest
            dest.write_bytes(data)
            mine[moved.group(1)] = data


def check_kept(out: Path, files: etree._Element, mine: dict[str, bytes]) -> None:
    """Every byte the user wrote is there; every user file is in the build."""
    for rel, data in mine.items():
        assert (out / rel).read_bytes() == data, f"{rel}: the user's bytes changed"
    generated = {n.get("path"): n.text or "" for n in files.iterchildren(f"{FS}file") if n.get("mode") != "user"}
    users = {n.get("path") for n in files.iterchildren(f"{FS}file") if n.get("mode") == "user"}
    assert set(mine) == users, "a user file on disk is not one of the package's, or one is missing"
    cmake = generated["CMakeLists.txt"]
    for rel in users:
        if rel.endswith(".cpp"):
            assert re.search(rf"[ (]{re.escape(rel)}[ )\n]", cmake), f"{rel} is not compiled"
        else:
            name = rel.rsplit("/", 1)[-1]
            assert any(name in text for text in generated.values()), f"no generated file includes or loads {rel}"


def user_edit(out: Path, mine: dict[str, bytes], edit: tuple | None) -> None:
    if edit is None or not mine:
        return
    index, where, text = edit
    rel = sorted(mine)[index % len(mine)]
    data = mine[rel]
    cut = int(where * len(data))
    while 0 < cut < len(data) and (data[cut] & 0xC0) == 0x80:  # not inside a character of several bytes
        cut -= 1
    mine[rel] = data[:cut] + text.encode("utf-8") + data[cut:]
    (out / rel).write_bytes(mine[rel])


def regenerate(out: Path, files: etree._Element, mine: dict[str, bytes]) -> None:
    before = _snapshot(out) if out.exists() else {}
    try:
        write_fileset(files, out)
    except RobomdaError as refused:
        _COUNTS["refused"] += 1
        assert _snapshot(out) == before, "a refused run changed the folder"
        follow_advice(out, refused, mine)
        write_fileset(files, out)
    for node in files.iterchildren(f"{FS}file"):
        if node.get("mode") == "user" and node.get("path") not in mine:
            mine[node.get("path")] = (out / node.get("path")).read_bytes()  # written now: the user's from here on


@pytest.mark.parametrize("target", TARGETS)
def test_user_code_survives_random_model_and_user_edits(target: str, tmp_path: Path) -> None:
    start, before = time.monotonic(), _COUNTS["cycles"]
    pool, kinds = model_pool(POOL)
    assert kinds == set(EDIT_KINDS) or POOL < 16, kinds  # the pool's walk makes every kind of edit
    examples = -(-CYCLES // STEPS)

    @settings(max_examples=examples, deadline=None, database=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(cycles)
    def run(steps: list[tuple]) -> None:
        folder = Path(tempfile.mkdtemp(dir=tmp_path))
        out = folder / "out"
        comps = FIRST
        mine: dict[str, bytes] = {}
        regenerate(out, fileset(target, comps, folder), mine)
        for model_step, user_step in steps:
            comps = comps if model_step is None else pool[model_step]
            user_edit(out, mine, user_step)
            files = fileset(target, comps, folder)
            regenerate(out, files, mine)
            check_kept(out, files, mine)
            _COUNTS["cycles"] += 1
        shutil.rmtree(folder)

    run()
    done = _COUNTS["cycles"] - before
    took = time.monotonic() - start
    print(f"\n{target}: {done} cycles in {took:.1f} s, {_COUNTS['runs']} chain runs so far, "
          f"{_COUNTS['refused']} refused runs so far")
    assert done >= CYCLES
