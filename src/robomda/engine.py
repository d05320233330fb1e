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

__all__ = ["Engine", "TransformError"]


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


class Engine:
    """Compiles stylesheets once and runs them on strings or files."""

    def __init__(self) -> None:
        self._proc = PySaxonProcessor(license=False)
        self._xslt = self._proc.new_xslt30_processor()
        self._compiled: dict[Path, object] = {}
        # the xsl:message texts of the last transform (warnings travel this way)
        self.messages: list[str] = []

    @property
    def version(self) -> str:
        return str(self._proc.version)

    def compile(self, stylesheet: Path) -> object:
        """The compiled form of ``stylesheet`` (compiled on first use)."""
        stylesheet = stylesheet.resolve()
        executable = self._compiled.get(stylesheet)
        if executable is None:
            with _captured_stderr() as err:
                try:
                    executable = self._xslt.compile_stylesheet(stylesheet_file=str(stylesheet))
                except PySaxonApiError as exc:
                    failure = exc
                else:
                    failure = None
            if failure is not None or executable is None:
                raise TransformError(stylesheet, str(failure or "compilation failed").strip(), "".join(err))
            self._compiled[stylesheet] = executable
        return executable

    def transform(self, stylesheet: Path, params: dict[str, str], *,
                  source_file: Path | None = None, source_text: str | None = None) -> str:
        """Run ``stylesheet`` on a file or a string; return the serialized result."""
        executable = self.compile(stylesheet)
        executable.clear_parameters()
        executable.clear_xsl_messages()
        executable.set_save_xsl_message(True, None)
        self.messages = []
        for name, value in params.items():
            executable.set_parameter(name, self._proc.make_atomic_value("untypedAtomic", value))
        failure: PySaxonApiError | None = None
        result: str | None = None
        with _captured_stderr() as err:
            try:
                if source_file is not None:
                    node = self._proc.parse_xml(xml_file_name=str(source_file.resolve()))
                else:
                    node = self._proc.parse_xml(xml_text=source_text)
                # as Saxon's command line does with -s: the source is both the
                # global context item and the initial match selection
                executable.set_global_context_item(xdm_item=node)
                result = executable.apply_templates_returning_string(xdm_value=node)
            except PySaxonApiError as exc:
                failure = exc
        saved = executable.get_xsl_messages()
        if saved is not None:
            self.messages = [str(saved.item_at(i).string_value) for i in range(saved.size)]
        if failure is not None or result is None:
            raise TransformError(stylesheet, str(failure or "no result").strip(), "".join(err))
        return result
