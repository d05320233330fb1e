"""The XSLT engine: one SaxonC-HE processor per process, each stylesheet compiled once.

Saxon writes its own error reports and ``xsl:message`` output to the process's
standard error; robomda reports errors itself (with locations), so that
stream is captured while Saxon works and handed back with the failure.
"""

from __future__ import annotations

import os
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from saxonche import PySaxonApiError, PySaxonProcessor

__all__ = ["Engine", "TransformError", "Tree", "shared"]

# writes a kept result tree as its text (see Engine.run)
_SERIALIZER = """<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
<xsl:output method="xml" indent="no" encoding="UTF-8"/>
<xsl:template match="/"><xsl:sequence select="."/></xsl:template>
</xsl:stylesheet>"""


class Tree:
    """A result tree held by Saxon, to be the source of the next stage."""

    __slots__ = ("node",)

    def __init__(self, node: object) -> None:
        self.node = node


class TransformError(Exception):
    """Saxon failed: ``message`` is Saxon's description, ``detail`` its report."""

    def __init__(self, stylesheet: Path, message: str, detail: str) -> None:
        super().__init__(message)
        self.stylesheet = stylesheet
        self.message = message
        self.detail = detail


@contextmanager
def _captured_stderr() -> Iterator[list[str]]:
    """Redirect file descriptor 2 (where Saxon writes) into a buffer."""
    out: list[str] = []
    with tempfile.TemporaryFile(mode="w+b") as sink:
        saved = os.dup(2)
        os.dup2(sink.fileno(), 2)
        try:
            yield out
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            out.append(sink.read().decode("utf-8", errors="replace"))


# Saxon's XML parser, for the models and every document a stylesheet reads:
# no external entities (a model must not pull /etc/passwd into the output)
# and no external DTD (EA's XMI 1.1 names UML_EA.dtd, which nobody has; a
# DTD could also be fetched over the network)
_SAFE_PARSER = {
    f"http://saxon.sf.net/feature/parserFeature?uri={feature}": "false"
    for feature in ("http%3A//xml.org/sax/features/external-general-entities",
                    "http%3A//xml.org/sax/features/external-parameter-entities",
                    "http%3A//apache.org/xml/features/nonvalidating/load-external-dtd")
} | {
    # and no cap on the text that character and predefined entity references make: SaxonC-HE 13's
    # parser stops at 100,000 characters from them in a document, which an EA model's escaped HTML
    # notes (`&lt;p&gt;`) pass, and so does the PSM of 10,000 components with data types
    # (`std::vector&lt;double&gt;`). Entity expansions stay limited (jdk.xml.entityExpansionLimit,
    # 2,500 here: a "billion laughs" DTD is still refused, tests/test_xxe.py)
    f"http://saxon.sf.net/feature/parserProperty?uri=jdk.xml.{limit}": "0"
    for limit in ("maxGeneralEntitySizeLimit", "totalEntitySizeLimit")
}

# the trees the stylesheets build (the import's normalised copy of the XMI,
# every stage's result) keep each distinct attribute value and text once:
# a model repeats the same library types, metaclasses, visibilities and
# defaults thousands of times. Peak memory of the import of 10,000
# components with calls, alone: 1,304 -> 1,015 MiB; of the whole Orocos
# chain (bench/run.py --one 10000 --shape calls): 1,742 -> 1,447 MiB with
# the checker's. The cost is in building: the Orocos PSM of 4,000
# components alone, 3.03 -> 3.36 s (the least of six runs); the import's
# difference was within the machine's noise. Trees parsed from files (the
# XMI) are not affected.
_TREES = {"http://saxon.sf.net/feature/treeModelName": "tinyTreeCondensed"}


class Engine:
    """Compiles stylesheets once and runs them on strings or files."""

    def __init__(self) -> None:
        self._proc = PySaxonProcessor(license=False)
        for name, value in (_SAFE_PARSER | _TREES).items():
            self._proc.set_configuration_property(name, value)
        self._xslt = self._proc.new_xslt30_processor()
        self._compiled: dict[Path, object] = {}
        self._serializer: object | None = None
        # the xsl:message texts of the last transform (warnings travel this way)
        self.messages: list[str] = []

    @property
    def version(self) -> str:
        return str(self._proc.version)

    def compile(self, stylesheet: Path, text: str | None = None) -> object:
        """The compiled form of ``stylesheet`` (compiled on first use), read from its file or, for a
        stylesheet made in memory (the Schematron rules compiled to XSLT), from ``text``."""
        stylesheet = stylesheet.resolve()
        executable = self._compiled.get(stylesheet)
        if executable is None:
            source = {"stylesheet_file": str(stylesheet)} if text is None else {"stylesheet_text": text}
            with _captured_stderr() as err:
                try:
                    executable = self._xslt.compile_stylesheet(**source)
                except PySaxonApiError as exc:
                    failure = exc
                else:
                    failure = None
            if failure is not None or executable is None:
                raise TransformError(stylesheet, str(failure or "compilation failed").strip(), "".join(err))
            self._compiled[stylesheet] = executable
        return executable

    def parse(self, text: str) -> Tree:
        """A tree of ``text`` (robomda's own XML: an earlier stage's result) to run stylesheets on."""
        return Tree(self._proc.parse_xml(xml_text=text))

    def transform(self, stylesheet: Path, params: dict[str, str], *,
                  source_file: Path | None = None, source_text: str | None = None) -> str:
        """Run ``stylesheet`` on a file or a string; return the serialized result."""
        source = source_file.resolve() if source_file is not None else source_text
        return self.run(stylesheet, params, source, keep_tree=False)[0]

    def run(self, stylesheet: Path, params: dict[str, str], source: Path | str | Tree, *,
            keep_tree: bool) -> tuple[str, Tree | None]:
        """Run ``stylesheet`` on a file, a string or a tree from an earlier run.

        Returns the serialized result and, with ``keep_tree``, the result
        tree itself, which the next stage of a chain takes as its source
        without parsing the text again (about a tenth of a stage's time on
        large models). A kept tree is serialized as plain XML (UTF-8, no
        indentation), which is what every intermediate stage declares.
        """
        # a clone for this run: an executable keeps its global context item,
        # so the compiled one would hold each stage's source tree in Saxon's
        # heap for the rest of the process (peak memory 1,040 -> 901 MiB at
        # 4,000 components); the clone shares the compiled stylesheet
        executable = self.compile(stylesheet).clone()
        executable.set_save_xsl_message(True, None)
        self.messages = []
        for name, value in params.items():
            executable.set_parameter(name, self._proc.make_atomic_value("untypedAtomic", value))
        failure: PySaxonApiError | None = None
        text: str | None = None
        tree: Tree | None = None
        with _captured_stderr() as err:
            try:
                if isinstance(source, Tree):
                    node = source.node
                elif isinstance(source, Path):
                    node = self._proc.parse_xml(xml_file_name=str(source))
                else:
                    node = self._proc.parse_xml(xml_text=source)
                # as Saxon's command line does with -s: the source is both the
                # global context item and the initial match selection
                executable.set_global_context_item(xdm_item=node)
                if keep_tree:
                    value = executable.apply_templates_returning_value(xdm_value=node)
                    if value is not None and value.size == 1 and value.head.is_node:
                        tree = Tree(value.head.get_node_value())
                    value = None
                else:
                    text = _returning_text(executable, node)
            except PySaxonApiError as exc:
                failure = exc
        saved = executable.get_xsl_messages()
        if saved is not None:
            self.messages = [str(saved.item_at(i).string_value) for i in range(saved.size)]
        # the source (the executable holds it as its global context item)
        # let go before the kept tree is serialized: Saxon may reclaim it
        # then (peak memory of the import of 10,000 components with calls:
        # 1,478 -> 1,391 MiB)
        executable = node = saved = None
        if tree is not None and failure is None:
            with _captured_stderr() as err:
                try:
                    text = self._serialize(tree)
                except PySaxonApiError as exc:
                    failure = exc
        if failure is not None or text is None:
            raise TransformError(stylesheet, str(failure or "no result").strip(), "".join(err))
        return text, tree

    def strings(self, tree: Tree, expression: str, namespaces: dict[str, str]) -> list[str]:
        """The string values of the XPath ``expression`` on ``tree`` (a look-up in a kept tree, with
        no lxml tree of the model)."""
        xpath = self._proc.new_xpath_processor()
        for prefix, uri in namespaces.items():
            xpath.declare_namespace(prefix, uri)
        xpath.set_context(xdm_item=tree.node)
        found = xpath.evaluate(expression)
        return [] if found is None else [str(found.item_at(i).string_value) for i in range(found.size)]

    def _serialize(self, tree: Tree) -> str:
        if self._serializer is None:
            self._serializer = self._xslt.compile_stylesheet(stylesheet_text=_SERIALIZER)
        serializer = self._serializer.clone()  # as in run: the compiled one must not hold the tree
        serializer.set_global_context_item(xdm_item=tree.node)
        # through a file, as a stage's text is: 0.66 against 0.85 s for a bound PIM of 35 MB (4,000 components
        # with calls), the same bytes
        return _returning_text(serializer, tree.node)


def _returning_text(executable: object, node: object) -> str:
    """The result of ``executable`` on ``node``, serialized as its xsl:output says, through a temporary file:
    Saxon's own string of a large result cost more than writing and reading it (the Orocos text stage of 4,000
    components: 4.96 against 4.33 s of CPU, twice the time at 2,000 against 2.1 times; same bytes)."""
    handle, name = tempfile.mkstemp(prefix="robomda-stage-", suffix=".xml")
    os.close(handle)
    try:
        executable.apply_templates_returning_file(xdm_value=node, output_file=name)
        with open(name, encoding="utf-8", newline="") as result:
            return result.read()
    finally:
        os.unlink(name)


_SHARED: Engine | None = None


def shared() -> Engine:
    """The process's one Saxon engine: every stylesheet it compiles stays compiled across runs."""
    global _SHARED
    if _SHARED is None:
        _SHARED = Engine()
    return _SHARED
