"""Diagnostics that point at the user's XMI: file, line, column, element.

Every failure robomda reports - an XML parse error, a schema violation of an
intermediate model, an ``error()`` raised by a stylesheet - becomes a
:class:`Diagnostic`. Stylesheets raise errors as ``CODE: MESSAGE [xmi:id=ID]``
(see ``xslt/common/errors.xsl``); :class:`XmiLocator` maps ID back to the line
of the XMI element that carries it.
"""

from __future__ import annotations

import dataclasses
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote

from lxml import etree

from robomda.sandbox import Sandbox

__all__ = [
    "Diagnostic",
    "RobomdaError",
    "XmiLocator",
    "EXIT_OK",
    "EXIT_FINDINGS",
    "EXIT_INPUT",
    "EXIT_INTERNAL",
    "file_ref_path",
    "parse_stylesheet_error",
    "parse_stylesheet_warning",
    "parse_stylesheet_message",
    "model_element_id",
    "as_error",
    "format_all",
]

EXIT_OK = 0
EXIT_FINDINGS = 1  # the model has errors
EXIT_INPUT = 2  # usage error, unreadable or unsupported input
EXIT_INTERNAL = 3  # a bug in robomda (never a traceback: reported like this)

# Codes that mean "this input cannot be read at all" rather than "this model
# has an error": they exit with EXIT_INPUT.
INPUT_CODES = frozenset({"XML001", "IO001", "IMP001", "IMP002"})

# Saxon may follow the description with its own trace ("During lazy
# evaluation of ..."), depending on how the transform was called
_STYLESHEET_ERROR = re.compile(r"(?P<code>[A-Z]{2,5}[0-9]{3}): (?P<message>.*?) \[xmi:id=(?P<id>[^\]]*)\](?=\.?(?:\s|$))", re.S)


@dataclass(frozen=True)
class Diagnostic:
    """One finding, located in the user's model where possible."""

    severity: str
    code: str
    message: str
    file: str | None = None
    line: int | None = None
    column: int | None = None
    element_kind: str | None = None
    element_name: str | None = None
    xmi_id: str | None = None
    step: str | None = None
    qualified_name: str | None = None  # the element's UML qualified name (Package::Component::port)

    def format(self) -> str:
        """``FILE:LINE:COL: severity: [CODE] message (kind 'name', xmi:id)``."""
        where = ""
        if self.file:
            where = self.file
            if self.line:
                where += f":{self.line}"
                if self.column:
                    where += f":{self.column}"
            where += ": "
        text = f"{where}{self.severity}: [{self.code}] {self.message}"
        if self.xmi_id or self.element_kind:
            parts = []
            if self.element_kind:
                name = self.element_name or ""
                if len(name) > 80:  # a name as long as a file: its start says enough
                    name = name[:60] + "..."
                parts.append(f"{self.element_kind} '{name}'")
            if self.xmi_id:
                parts.append(self.xmi_id)
            text += f" ({', '.join(parts)})"
        return text


_QUOTED = re.compile(r"('[^']*')")


def _variants(d: Diagnostic) -> list[tuple[tuple[str, ...], str]]:
    """For each quoted name in ``d``'s message: (the key of the message with that name left out, the name)."""
    parts = _QUOTED.split(d.message)  # odd indexes are the quoted names
    return [((d.severity, d.code, str(i), *parts[:i], *parts[i + 1:]), parts[i]) for i in range(1, len(parts), 2)]


def _groups(diagnostics: list[Diagnostic]) -> list[list[tuple[Diagnostic, str]]]:
    """``diagnostics`` in order, those saying the same thing about different elements together.

    Two diagnostics say the same thing when they have the same severity and
    code and their messages differ in one quoted name only, at the same
    place. Each diagnostic joins the largest such group (the earliest
    name's on a tie); a group stands where its first member stood.
    """
    sizes: dict[tuple[str, ...], int] = {}
    for d in diagnostics:
        for key, _ in _variants(d):
            sizes[key] = sizes.get(key, 0) + 1
    groups: dict[object, list[tuple[Diagnostic, str]]] = {}
    for n, d in enumerate(diagnostics):
        best = max(_variants(d), key=lambda v: sizes[v[0]], default=None)
        key: object = best[0] if best is not None and sizes[best[0]] > 1 else n
        groups.setdefault(key, []).append((d, best[1] if best is not None else ""))
    return list(groups.values())


def _short(name: str) -> str:
    return name if len(name) <= 80 else name[:60] + "...'"


def format_all(diagnostics: list[Diagnostic]) -> list[str]:
    """The text lines of ``diagnostics``: one finding per thing said, located at every element it is about.

    A diagnostic that says the same as others about another element (see
    :func:`_groups`) is one finding: its first line is the first one's
    (:meth:`Diagnostic.format`) ending in ``[N alike: 'a', 'b', ...]``, and
    each other element gets a ``FILE:LINE:COL: note: [CODE] the same for 'b'
    (kind 'name', xmi:id)`` line after it, as compilers locate the other
    places of one finding.
    """
    lines = []
    for group in _groups(diagnostics):
        first, _ = group[0]
        if len(group) == 1:
            lines.append(first.format())
            continue
        names = ", ".join(_short(name) for _, name in group)
        lines.append(f"{first.format()} [{len(group)} alike: {names}]")
        for d, name in group[1:]:
            note = dataclasses.replace(d, severity="note", message=f"the same for {_short(name)}")
            lines.append(note.format())
    return lines


@dataclass
class RobomdaError(Exception):
    """A run failed; ``diagnostics`` say why and where, ``exit_code`` how badly."""

    diagnostics: list[Diagnostic] = field(default_factory=list)
    exit_code: int = EXIT_FINDINGS

    def __str__(self) -> str:
        return "\n".join(d.format() for d in self.diagnostics)


def as_error(exc: Exception, model: str | None) -> RobomdaError:
    """What a run on ``model`` that raised ``exc`` reports: a :class:`RobomdaError` as it is, an OSError
    as IO001 (input that cannot be read or written), anything else as INTERNAL, a bug said in one line
    without a traceback."""
    if isinstance(exc, RobomdaError):
        return exc
    if isinstance(exc, OSError):
        return RobomdaError([Diagnostic("error", "IO001", str(exc), file=exc.filename and str(exc.filename))],
                            EXIT_INPUT)
    return RobomdaError([Diagnostic("error", "INTERNAL", f"{type(exc).__name__}: {exc} (please report it with "
                                    "the model)", file=model or None)], EXIT_INTERNAL)


def parse_stylesheet_warning(text: str) -> tuple[str, str, str] | None:
    """Split a robomda stylesheet warning ("warning: CODE: ...") into (code, message, xmi id)."""
    text = text.strip()
    if not text.startswith("warning: "):
        return None
    return parse_stylesheet_error(text[len("warning: "):])


def parse_stylesheet_message(text: str) -> tuple[str, str, str, str] | None:
    """Split an ``xsl:message`` of a robomda stylesheet into (severity, code, message, xmi id).

    ``warning: CODE: ...`` is a warning, ``error: CODE: ...`` an error the
    stage reports before it stops (f:report-error), anything else a note
    (code NOTE): no message a stylesheet writes is ever dropped.
    """
    stripped = text.strip()
    if not stripped:
        return None
    for severity in ("warning", "error"):
        if stripped.startswith(severity + ": "):
            parsed = parse_stylesheet_error(stripped[len(severity) + 2:])
            if parsed is not None:
                return (severity, *parsed)
    parsed = parse_stylesheet_error(stripped)
    if parsed is not None and stripped.startswith(parsed[0]):
        return ("info", *parsed)
    return "info", "NOTE", " ".join(stripped.split()), ""


def parse_stylesheet_error(text: str) -> tuple[str, str, str] | None:
    """Split a robomda stylesheet error into (code, message, xmi id)."""
    match = _STYLESHEET_ERROR.search(text.strip())
    if not match:
        return None
    return match["code"], " ".join(match["message"].split()), match["id"]


def model_element_id(node: etree._Element | None) -> str | None:
    """The xmi:id an element of a robomda model stands for: its own, else its nearest ancestor's.

    Model elements carry it as ``xmi-id`` or ``id``; a bound component as
    ``component``, a bound data port as ``port``.
    """
    while node is not None:
        for attr in ("xmi-id", "id", "component", "port"):
            value = node.get(attr)
            if value:
                return value
        node = node.getparent()
    return None


@dataclass(frozen=True)
class _Where:
    line: int
    column: int
    kind: str
    name: str
    qualified_name: str = ""


# an href to another file: its document part (before "#", or the whole href)
_HREF = re.compile(rb"""\bhref\s*=\s*["']([^"'#]+)["'#]""")
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*:")
_PROFILE = re.compile(r"\.profile\.(uml|xmi)$", re.I)
# a MagicDraw used project (files.xsl, fp:used-project): never read
_USED_PROJECT = re.compile(r"(^|[:/])PROJECT-[0-9A-Za-z_\-]+(\?|$)|\.mdzip$", re.I)


def file_ref_path(ref: str, base: Path) -> Path | None:
    """The file a reference written in a model names, as the import resolves it: a file: URI, or a
    path relative to the folder ``base``; None for a URI of any other scheme (package://, http:)."""
    if ref.lower().startswith("file:"):
        return Path("/") / ref[5:].lstrip("/")
    return None if _SCHEME.match(ref) else base / ref


def linked_files(model: Path, search: tuple[Path, ...] = ()) -> list[Path]:
    """The model files ``model`` references through hrefs, and theirs, each once (breadth first).

    The same files the import reads (xslt/import/files.xsl): relative,
    ``file:`` or ``platform:/resource/`` references (URL-decoded) that are
    not profiles nor MagicDraw used projects, inside the model's sandbox
    (:class:`robomda.sandbox.Sandbox`: its folder, project, the other
    projects of its workspace, the model path ``search``), that exist.
    """
    # targets by path as written, not by real path, as the import resolves
    # URIs (from the model's real path): a library reached through a
    # symlinked folder inside the model's folder is inside it, as it is for
    # the import
    sandbox = Sandbox.of(model, search)
    start = Path(os.path.normpath(model.resolve()))
    seen, order, todo = {start}, [], [start]
    while todo:
        current = todo.pop(0)
        try:
            raw = current.read_bytes()
        except OSError:
            continue
        for ref in dict.fromkeys(unquote(m.group(1).decode("utf-8", "replace")) for m in _HREF.finditer(raw)):
            if _PROFILE.search(ref) or _USED_PROJECT.search(ref):
                continue
            target = sandbox.resolve(ref, current.parent)
            if target is None or target in seen or not target.is_file() or not sandbox.contains(target):
                continue
            seen.add(target)
            order.append(target)
            todo.append(target)
    return order


class XmiLocator:
    """Maps xmi:id values of a model to file, line, column, kind and name.

    The model is its file and the files it references (:func:`linked_files`):
    an id is looked up in the model file first, then in the others. Files
    are read only when a diagnostic needs a location, so a clean run pays
    nothing for it.
    """

    def __init__(self, path: Path, search: tuple[Path, ...] = ()) -> None:
        self.path = path
        self._search = search
        self._index: dict[str, _Where] | None = None
        self._others: list[tuple[Path, dict[str, _Where] | None]] | None = None

    @staticmethod
    def _build(path: Path) -> dict[str, _Where]:
        index: dict[str, _Where] = {}
        try:
            raw = path.read_bytes()
            parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True)
            root = etree.fromstring(raw, parser)
        except (OSError, etree.XMLSyntaxError):
            return index
        lines = raw.decode("utf-8", errors="replace").split("\n")
        for el in root.iter(etree.Element):
            xid = _xmi_id(el)
            if xid is None or xid in index:
                continue
            line = el.sourceline or 0
            index[xid] = _Where(line, _column(lines, line, xid), _kind(el), el.get("name", ""), _qualified_name(el))
        return index

    def find(self, xmi_id: str | None) -> tuple[Path, _Where | None]:
        """The file that holds ``xmi_id`` and where in it (the model file and None when no file does)."""
        if not xmi_id:
            return self.path, None
        if self._index is None:
            self._index = self._build(self.path)
        if xmi_id in self._index:
            return self.path, self._index[xmi_id]
        if "#" in xmi_id:  # an id several files use, qualified by its file (files.xsl): "components/A.uml#_x"
            return self._qualified(xmi_id)
        if self._others is None:
            self._others = [(p, None) for p in linked_files(self.path, self._search)]
        for i, (path, index) in enumerate(self._others):
            if index is None:
                index = self._build(path)
                self._others[i] = (path, index)
            if xmi_id in index:
                return path, index[xmi_id]
        return self.path, None

    def _qualified(self, xmi_id: str) -> tuple[Path, _Where | None]:
        """Where the file-qualified id ``file#id`` is (the file relative to the model's folder)."""
        rel, raw = xmi_id.rsplit("#", 1)
        path = Path(os.path.normpath(self.path.resolve().parent / unquote(rel)))
        where = (_by_path(path) if raw.startswith("@") else self._build(path)).get(raw)
        return (path, where) if where else (self.path, None)

    def _shown(self, path: Path) -> str:
        """A linked file as the user would name it: beside the model file as the user named that."""
        if path == self.path.resolve():
            return str(self.path)
        try:
            return str(self.path.parent / path.relative_to(self.path.resolve().parent))
        except ValueError:
            return str(path)

    def locate(self, xmi_id: str | None) -> _Where | None:
        return self.find(xmi_id)[1]

    def diagnostic(self, code: str, message: str, xmi_id: str | None, *, severity: str = "error",
                   step: str | None = None, line: int | None = None, column: int | None = None) -> Diagnostic:
        """A diagnostic about the element with ``xmi_id`` (or at ``line``)."""
        path, where = self.find(xmi_id)
        return Diagnostic(
            severity=severity,
            code=code,
            message=message,
            file=self._shown(path) if where else str(self.path),
            line=where.line if where else line,
            column=where.column if where else column,
            element_kind=where.kind if where else None,
            element_name=where.name if where else None,
            # a location id of a file that is no XMI (FILE#@/path): FILE:LINE says it, the id is no xmi:id
            xmi_id=None if not xmi_id or "#@" in xmi_id else xmi_id,
            step=step,
            qualified_name=(where.qualified_name or None) if where else None,
        )


def _by_path(path: Path) -> dict[str, _Where]:
    """The elements of a file that is no XMI (a feature model, a configuration, a resolution model) by
    the location id f:where gives them (xslt/m2m/variability/features.xsl): "@/name.N/name.N", each
    step an element's local name and its position among its same-named siblings."""
    try:
        root = etree.parse(str(path), etree.XMLParser(resolve_entities=False, no_network=True)).getroot()
    except (OSError, etree.XMLSyntaxError):
        return {}
    index: dict[str, _Where] = {}
    steps: dict[etree._Element, str] = {}
    for el in root.iter(etree.Element):
        parent = el.getparent()
        same = [s for s in (parent if parent is not None else [el]) if isinstance(s.tag, str) and s.tag == el.tag]
        steps[el] = (steps[parent] if parent is not None else "@") + f"/{etree.QName(el).localname}.{same.index(el) + 1}"
        name = el.get("name") or next(iter(el.attrib.values()), "") or (el.text or "").strip()
        index[steps[el]] = _Where(el.sourceline or 0, 1, etree.QName(el).localname, name)
    return index


def _qualified_name(el: etree._Element) -> str:
    """UML's qualified name: the names of the element and its named owners, outermost first, joined by ::."""
    names = [a.get("name") for a in [el, *el.iterancestors()] if a.get("name")]
    return "::".join(reversed(names))


def _xmi_id(el: etree._Element) -> str | None:
    for key, value in el.attrib.items():
        if key.startswith("{") and key.endswith("}id") and "xmi" in key.lower():
            return value
        if key == "xmi.id":
            return value
    return None


_XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"


def _kind(el: etree._Element) -> str:
    for key, value in el.attrib.items():
        if key.startswith("{") and key.endswith("}type") and "xmi" in key.lower():
            return value
    if el.get(_XSI_TYPE):  # EMF and GenMyModel may write xsi:type instead
        return el.get(_XSI_TYPE, "")
    qname = etree.QName(el)
    prefix = el.prefix
    return f"{prefix}:{qname.localname}" if prefix else qname.localname


def _column(lines: list[str], line: int, xid: str) -> int:
    """1-based column of the start tag that carries ``xid`` on ``line``."""
    if not 0 < line <= len(lines):
        return 1
    text = lines[line - 1]
    at = text.find(f'"{xid}"')
    if at < 0:
        at = text.find(f"'{xid}'")
    start = text.rfind("<", 0, at if at >= 0 else len(text))
    return start + 1 if start >= 0 else 1
