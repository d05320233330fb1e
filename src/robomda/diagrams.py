"""Render the diagram stage's PlantUML files to SVG, where PlantUML is installed.

The diagram stage (``pipelines/diagrams.xml``, ``xslt/m2t/diagrams/``) writes
PlantUML sources (``.puml``) into the file set. :func:`add_svgs` runs
PlantUML once on all of them and adds each SVG to the same file set, as a
generated file beside its source, so the writer writes and tracks both
(state.json) all or nothing. PlantUML runs headless (no ``DISPLAY``: the
Debian wrapper then passes ``-Djava.awt.headless=true``), without the
source embedded in the SVG (``-nometadata``: the same bytes on every run)
and on files that include nothing, so it reads no other file and reaches no
network. Without PlantUML the ``.puml`` files are written alone, with a
note (DIA001); a diagram PlantUML cannot render is a warning (DIA002).
"""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import tempfile
from pathlib import Path

from lxml import etree

from robomda.diagnostics import Diagnostic

__all__ = ["plantuml_command", "add_svgs", "PLANTUML_ENV"]

PLANTUML_ENV = "ROBOMDA_PLANTUML"  # the PlantUML command line to run; "none" (or empty): render nothing
_FS = "{urn:robomda:fileset:1}"
_TIMEOUT = 600  # seconds for one PlantUML run on all of a model's diagrams
_ERROR_MARKS = ("Syntax Error", "An error has occured", "An error has occurred")


def plantuml_command() -> list[str] | None:
    """The PlantUML command: ``$ROBOMDA_PLANTUML`` when set, else ``plantuml`` on PATH; None: none."""
    value = os.environ.get(PLANTUML_ENV)
    if value is not None:
        return shlex.split(value) if value.strip() not in ("", "none") else None
    found = shutil.which("plantuml")
    return [found] if found else None


def add_svgs(files: etree._Element, model: str) -> list[Diagnostic]:
    """Add ``X.svg`` beside each ``X.puml`` of file set ``files``, rendered by PlantUML.

    Returns the note that PlantUML is missing (DIA001), or a warning for
    each diagram it could not render (DIA002): the ``.puml`` is written all
    the same.
    """
    sources = [n for n in files.iterchildren(f"{_FS}file") if (n.get("path") or "").endswith(".puml")]
    if not sources:
        return []
    command = plantuml_command()
    if command is None:
        return [Diagnostic("info", "DIA001", "PlantUML not found (install the plantuml package, or set "
                           f"{PLANTUML_ENV}): the diagrams are written as .puml only; render them with "
                           "plantuml -tsvg", file=model)]
    with tempfile.TemporaryDirectory(prefix="robomda-plantuml-") as tmp:
        names = [f"diagram{i}.puml" for i in range(len(sources))]
        for name, node in zip(names, sources):
            (Path(tmp) / name).write_text(node.text or "", encoding="utf-8")
        failed = _run(command, names, Path(tmp))
        found: list[Diagnostic] = []
        for name, node in zip(names, sources):
            svg = Path(tmp) / (name[:-len(".puml")] + ".svg")
            text = svg.read_text(encoding="utf-8") if svg.is_file() else ""
            if failed or not text or any(mark in text for mark in _ERROR_MARKS):
                reason = failed or ("PlantUML reports an error in it" if text else "PlantUML wrote no SVG")
                found.append(Diagnostic("warning", "DIA002", f"PlantUML could not render {node.get('path')}: "
                                        f"{reason}; the .puml is written, not the .svg", file=model))
                continue
            svg_node = etree.SubElement(files, f"{_FS}file", path=node.get("path")[:-len(".puml")] + ".svg",
                                        mode="generated", stylesheet="plantuml -tsvg")
            svg_node.text = text
    return found


def _run(command: list[str], names: list[str], folder: Path) -> str:
    """Run PlantUML on ``names`` in ``folder``, headless; "" when it ran, else why it did not."""
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    try:
        done = subprocess.run(command + ["-tsvg", "-nometadata", "-charset", "UTF-8", *names], cwd=folder, env=env,
                              stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=_TIMEOUT)
    except (OSError, subprocess.SubprocessError) as exc:
        return f"{shlex.join(command)} did not run ({exc})"
    if done.returncode == 0:
        return ""
    # exit code 200 with an error image: the files' own check names which one; anything else fails them all
    errors = [line for line in done.stderr.splitlines() if line.strip() and not line.startswith(("code1=", "this1="))]
    return "" if done.returncode == 200 else f"exit code {done.returncode}: {' '.join(errors)[:300]}"
