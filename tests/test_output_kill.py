"""Kill robomda's writer at random instants: the output is always the old package or the new one.

A child process writes one of two versions of a large file set into the same
output folder (``write_fileset``, as ``robomda generate`` does) and is killed
(SIGKILL or SIGINT) after a random delay spread over its whole run. After
every kill the folder must hold exactly the old package or the new one,
with the user's own file and the user's edited user file untouched; the next
run must succeed and leave the new package. ROBOMDA_KILL_RUNS sets the
number of kills (200 here; more by hand).
"""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RUNS = int(os.environ.get("ROBOMDA_KILL_RUNS", "200"))
FILES = 80

CHILD = r"""
import sys
from lxml import etree
from robomda.output import write_fileset
FS = "urn:robomda:fileset:1"
version, out = sys.argv[1], sys.argv[2]
root = etree.Element(f"{{{FS}}}files", target="test")
for i in range(%(files)d):
    node = etree.SubElement(root, f"{{{FS}}}file", path=f"src/d{i %% 7}/f{i}.cpp", mode="generated", stylesheet="x")
    node.text = (f"// version {version} file {i}\n" * 100)
if version == "B":  # B drops one file and adds another
    root.remove(root[0])
    extra = etree.SubElement(root, f"{{{FS}}}file", path="src/only_b.cpp", mode="generated", stylesheet="x")
    extra.text = "B only\n"
user = etree.SubElement(root, f"{{{FS}}}file", path="src/User.cpp", mode="user", stylesheet="x")
user.text = f"// fresh user template {version}\n"
write_fileset(root, out)
""" % {"files": FILES}


def _run(version: str, out: Path) -> subprocess.Popen[bytes]:
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    return subprocess.Popen([sys.executable, "-c", CHILD, version, str(out)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def _snapshot(out: Path) -> dict[str, bytes]:
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in out.rglob("*")
            if p.is_file() and ".robomda" not in p.relative_to(out).parts}


def _reference(tmp: Path, version: str) -> dict[str, bytes]:
    out = tmp / f"ref-{version}"
    assert _run(version, out).wait() == 0
    (out / "src/User.cpp").write_text("my controller\n")
    (out / "notes.txt").write_text("my notes\n")
    if version == "B":  # what the user's edited user file leaves beside it
        (out / "src/User.cpp.robomda-new").write_text("// fresh user template B\n")
    return _snapshot(out)


def test_killed_at_any_instant_the_output_is_old_or_new(tmp_path: Path) -> None:
    old, new = _reference(tmp_path, "A"), _reference(tmp_path, "B")
    old_with_side = dict(old, **{"src/User.cpp.robomda-new": b"// fresh user template A\n"})
    out = tmp_path / "out"
    assert _run("A", out).wait() == 0
    (out / "src/User.cpp").write_text("my controller\n")
    (out / "notes.txt").write_text("my notes\n")
    durations = []
    for version in "BA":  # how long a whole run takes here, now: the kills are spread over it
        started = time.monotonic()
        assert _run(version, out).wait() == 0
        durations.append(time.monotonic() - started)
    duration = max(durations)
    rng = random.Random(20261124)
    outcomes = {"old": 0, "new": 0}
    for n in range(RUNS):
        version = "B" if n % 2 == 0 else "A"
        before = _snapshot(out)
        child = _run(version, out)
        time.sleep(rng.uniform(0, duration * 1.2))
        sig = signal.SIGKILL if n % 3 else signal.SIGINT
        child.send_signal(sig)
        child.communicate()
        after = _snapshot(out)
        assert after == before or after == (new if version == "B" else old_with_side), \
            f"kill {n} ({sig.name}) left a package that is neither the old nor the new one"
        outcomes["old" if after == before else "new"] += 1
        assert after["notes.txt"] == b"my notes\n" and after["src/User.cpp"] == b"my controller\n"
        if after == before and before != (new if version == "B" else old_with_side):
            # the next run recovers and completes
            assert _run(version, out).wait() == 0
            assert _snapshot(out) == (new if version == "B" else old_with_side)
    leftovers = [p.name for p in tmp_path.iterdir() if ".robomda-" in p.name]
    assert _run("B", out).wait() == 0 and _snapshot(out) == new
    assert not [p.name for p in tmp_path.iterdir() if ".robomda-" in p.name]
    # the delays must have hit the write phase both ways, or the test proves nothing
    assert min(outcomes.values()) >= min(5, RUNS // 10), (outcomes, leftovers)
