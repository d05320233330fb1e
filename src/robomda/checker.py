"""The checks of a large stage, in another process, while the driver goes on.

Every intermediate model is validated against its XSD and checked by its
rules before its result counts. SaxonC holds Python's GIL through a whole
transform, so a thread cannot check stage N while the driver runs stage
N+1; another process can, on the second core. :class:`Checker` keeps one
such process (``python -m robomda.checker``) for the life of the driver's
process and hands it a stage as a file. It validates the file with libxml2
as it reads it (no lxml tree: at 10,000 components a stage's is 0.6 GiB),
then, when the stage has rules, reads it into its own SaxonC and runs them
there as the driver runs a large stage's rules (robomda.rules), locating
each finding by the xmi:id it stands for in that tree. It answers whether
the model is valid and, per rule set, its findings; the driver locates them
in the XMI and counts them as if it had checked the stage itself. It
explains an invalid model itself (the rare path: xmlschema), and checks a
stage itself when the process cannot answer (it died, or raised).

The protocol, one JSON object a line each way, in order: a request
``{"job": N, "file": PATH, "schema": XSD or null (known valid), "checks":
[[SCH, PHASE], ...]}``; the answer ``{"job": N, "valid": BOOL, "findings":
[[[CODE, SEVERITY, MESSAGE, XMI_ID], ...], ...], "seconds": S, "peak":
BYTES}`` (its peak resident memory so far) or ``{"job": N, "error":
TEXT}``. The process removes each file once
read, and its folder when its input ends (the driver exited, or was
killed). Its standard error goes nowhere: whatever befalls it, the driver
validates the stage itself, and the user sees no traceback of it.
"""

from __future__ import annotations

import atexit
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from robomda.rules import Finding

__all__ = ["Checker", "Job", "Answer", "checker", "ENABLED"]

# ROBOMDA_CHECKER=0 checks every stage in the driver's own process (tests
# compare both ways)
ENABLED = os.environ.get("ROBOMDA_CHECKER", "1") != "0"


@dataclass(frozen=True)
class Answer:
    """Whether a stage is valid and, when it is, per rule set asked for, its findings."""

    valid: bool
    findings: tuple[tuple[Finding, ...], ...]


class Job:
    """A stage handed to the checker; :meth:`Checker.answer` waits for its answer."""

    __slots__ = ("number",)

    def __init__(self, number: int) -> None:
        self.number = number


class Checker:
    """One checker process, started on first use."""

    def __init__(self) -> None:
        self._proc: subprocess.Popen | None = None
        self._folder: Path | None = None
        self._next = 0
        self._answers: dict[int, dict] = {}
        # the highest peak resident memory a checker process reported (bench/run.py adds it to the
        # driver's own)
        self.peak_bytes = 0

    def submit(self, text: str, schema: Path | None, checks: list[tuple[Path, str | None]] = ()) -> Job | None:
        """Hand ``text`` (a stage) to the checker, to validate against ``schema`` (None: known valid),
        then to check by ``checks`` (rule sets and phases). None when no checker process can be had (the
        caller checks it)."""
        try:
            proc = self._process()
            self._next += 1
            path = self._folder / f"{self._next}.xml"
            path.write_bytes(text.encode("utf-8"))
            request = {"job": self._next, "file": str(path), "schema": schema and str(schema),
                       "checks": [[str(rules), phase] for rules, phase in checks]}
            proc.stdin.write(json.dumps(request) + "\n")
            proc.stdin.flush()
        except OSError:
            self.close()
            return None
        return Job(self._next)

    def answer(self, job: Job) -> Answer | None:
        """What the checker found in the stage of ``job``; None when it could not tell (the caller checks
        the stage itself)."""
        while job.number not in self._answers:
            line = self._proc.stdout.readline() if self._proc is not None else ""
            if not line:  # the process died: every job still out is the driver's again
                self.close()
                return None
            try:
                reply = json.loads(line)
                self._answers[reply["job"]] = reply
            except (ValueError, KeyError, TypeError):  # not the checker's answer: it is no longer trusted
                self.close()
                return None
            self.peak_bytes = max(self.peak_bytes, reply.get("peak", 0))
        reply = self._answers.pop(job.number)
        if "error" in reply:
            return None
        return Answer(reply["valid"], tuple(tuple(Finding(*f) for f in found) for found in reply["findings"]))

    def _process(self) -> subprocess.Popen:
        if self._proc is None or self._proc.poll() is not None:
            self._folder = Path(tempfile.mkdtemp(prefix="robomda-checker-"))
            # this robomda, whether installed or run from a source tree
            env = dict(os.environ, PYTHONPATH=os.pathsep.join(
                [str(Path(__file__).resolve().parent.parent), *filter(None, [os.environ.get("PYTHONPATH")])]))
            self._proc = subprocess.Popen([sys.executable, "-m", "robomda.checker", str(self._folder)],
                                          stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                          stderr=subprocess.DEVNULL, text=True, env=env)
            self._answers = {}
        return self._proc

    def close(self) -> None:
        """End the process (it ends by itself when this one does) and remove its folder."""
        if self._proc is not None:
            try:
                self._proc.stdin.close()
            except OSError:
                pass
            try:
                self._proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.wait()
            self._proc = None
        if self._folder is not None:
            shutil.rmtree(self._folder, ignore_errors=True)
            self._folder = None


_CHECKER: Checker | None = None
_OWNER = 0


def checker() -> Checker:
    """The driver process's one checker (a process forked from the driver makes its own: the pipes
    of the driver's are not its to use)."""
    global _CHECKER, _OWNER
    if _CHECKER is None or _OWNER != os.getpid():
        _CHECKER, _OWNER = Checker(), os.getpid()
        atexit.register(_CHECKER.close)
    return _CHECKER


# --------------------------------------------------------------- the process

_ENGINE = None


def _check(request: dict) -> dict:
    from robomda.rules import findings
    from robomda.validate import schema_of, streams_valid

    global _ENGINE
    started = time.perf_counter()
    path = Path(request["file"])
    found: list[list[list[str | None]]] = []
    try:
        valid = not request["schema"] or streams_valid(path, schema_of(Path(request["schema"])))
        if valid and request["checks"]:
            if _ENGINE is None:
                from robomda.engine import Engine

                _ENGINE = Engine()
            source = _ENGINE.parse(path)
            found = [[[f.code, f.severity, f.message, f.xmi_id]
                      for f in findings(Path(rules), phase, None, source=source, engine=_ENGINE, in_saxon=True)]
                     for rules, phase in request["checks"]]
    finally:
        path.unlink(missing_ok=True)
    return {"valid": valid, "findings": found, "seconds": time.perf_counter() - started, "peak": _peak()}


def _peak() -> int:
    """This process's peak resident memory: VmHWM, which starts again at exec (getrusage's maxrss
    keeps the forked driver's)."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def main(folder: str) -> int:
    """Answer requests on standard input until it ends."""
    try:
        for line in sys.stdin:
            request = json.loads(line)
            try:
                reply = _check(request)
            except Exception as exc:  # the driver checks the stage itself
                reply = {"error": f"{type(exc).__name__}: {exc}"}
            reply["job"] = request["job"]
            sys.stdout.write(json.dumps(reply) + "\n")
            sys.stdout.flush()
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
