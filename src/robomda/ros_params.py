"""The ROS 2 user parameter file of the earlier layout in an output folder (ROS031, ROS032).

A ROS 2 package once had one user parameter file, ``config/params.user.yaml``,
whose keys were node names (``learner:``, ``/atf/driver/fri:``). Under a pushed
namespace those names no longer match the nodes, so each instance now has its
own ``config/<instance>.user.yaml`` keyed ``/**``, given to that node alone.
A package generated before keeps the old file, which no launch file loads any
more: the user's tuned values would stop reaching the robot in silence.

- the old file sets parameters: error ROS031, one per node key, located on its
  line and naming the instance's new file; nothing is written;
- it sets none (the empty mapping robomda wrote, comments): the run removes
  it, warning ROS032 says so and names the new files.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from robomda.diagnostics import Diagnostic

__all__ = ["LEGACY_USER_PARAMS", "Legacy", "legacy_user_params"]

LEGACY_USER_PARAMS = "config/params.user.yaml"
_FS = "urn:robomda:fileset:1"
_KEY = re.compile(r"""^(?P<key>"[^"]*"|'[^']*'|[^\s#:][^#:]*?)\s*:(\s|$)""")


@dataclass
class Legacy:
    """What the writer does with the old file: stop (``errors``), or drop ``drops`` and warn; ``judged``
    holds the path when this module judged it (the writer's OUT003 leaves it alone)."""

    judged: set[str] = field(default_factory=set)
    errors: list[Diagnostic] = field(default_factory=list)
    warnings: list[Diagnostic] = field(default_factory=list)
    drops: set[str] = field(default_factory=set)


def _values(text: str) -> list[tuple[int, str]]:
    """(line, top-level key) of each node the YAML text sets; [] for an empty mapping or comments only."""
    lines = [(n, line) for n, line in enumerate(text.splitlines(), 1)
             if line.strip() and not line.lstrip().startswith("#")]
    if all(re.fullmatch(r"\s*(\{\s*\}|~|null)?\s*(#.*)?", line) for _, line in lines):
        return []
    keys = []
    for n, line in lines:
        match = _KEY.match(line)
        if match:
            keys.append((n, match["key"].strip("\"'")))
    return keys or [(lines[0][0], "")]


def _user_file(key: str, users: set[str]) -> str | None:
    """The instance's new user file for a node key of the old file (``/atf/driver/fri`` -> atf_driver_fri)."""
    rel = f"config/{key.strip('/').replace('/', '_')}.user.yaml"
    return rel if rel in users else None


def legacy_user_params(files: etree._Element, out: Path) -> Legacy:
    """ROS031 / ROS032 for the old ``config/params.user.yaml`` of a ROS 2 package in ``out``."""
    found = Legacy()
    target = Path(out) / LEGACY_USER_PARAMS
    produced = {n.get("path") for n in files.iterchildren(f"{{{_FS}}}file")}
    if files.get("target") != "ros2" or LEGACY_USER_PARAMS in produced or not target.is_file():
        return found
    found.judged.add(LEGACY_USER_PARAMS)
    users = {n.get("path") for n in files.iterchildren(f"{{{_FS}}}file") if n.get("mode") == "user"}
    new = sorted(p for p in users if p.startswith("config/") and p.endswith(".user.yaml"))
    layout = ("ROS 2 parameter files are per instance now, keyed /** so that they apply under a pushed namespace "
              "(config/<instance>.user.yaml)")
    keys = _values(target.read_text(encoding="utf-8", errors="replace"))
    for line, key in keys:
        dest = _user_file(key, users) if key else None
        where = (f"move them under '/**: ros__parameters:' in {dest}" if dest else
                 f"no instance of the new package is node '{key}': move them to the instance they were meant for"
                 if key else f"move each node's values into its file ({', '.join(new) or 'none'})")
        found.errors.append(Diagnostic(
            "error", "ROS031", f"{LEGACY_USER_PARAMS} sets parameters of node '{key or '?'}', which no launch file "
            f"loads any more: {layout}; {where}, then remove {LEGACY_USER_PARAMS}; nothing was written",
            file=str(target), line=line))
    if not keys:
        found.drops.add(LEGACY_USER_PARAMS)
        found.warnings.append(Diagnostic(
            "warning", "ROS032", f"{LEGACY_USER_PARAMS} set no parameter and is removed: {layout}; tune them in "
            f"{', '.join(new) or 'none'}", file=str(target)))
    return found
