"""The XSD validation of a large stage, in another process, while the driver goes on.

Every intermediate model is validated against its XSD before its result
counts. SaxonC holds Python's GIL through a whole transform or rule run, so
a thread cannot validate stage N while the driver checks its rules and runs
stage N+1; another process can, on the second core. :class:`Checker` keeps
one such process (``python -m robomda.checker``) for the life of the
driver's process and hands it a stage as a file, which it validates with
libxml2 as it reads it (no tree of it: at 10,000 components a stage's lxml
tree is 0.6 GiB, and the rules need none here: they run in the driver, on
the tree Saxon holds). It answers whether the model is valid; the driver
explains an invalid one itself (the rare path: xmlschema), and validates a
stage itself when the process cannot answer (it died, or raised).

The protocol, one JSON object a line each way, in order: a request
``{"job": N, "file": PATH, "schema": XSD}``; the answer ``{"job": N,
"valid": BOOL, "seconds": S, "peak": BYTES}`` (its peak resident memory so
far) or ``{"job": N, "error": TEXT}``. The process removes each file once
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
from pathlib import Path

__all__ = ["Checker", "Job", "checker", "ENABLED"]

# ROBOMDA_CHECKER=0 validates every stage in the driver's own process (tests
# compare both ways)
ENABLED = os.environ.get("ROBOMDA_CHECKER", "1") != "0"
# characters of a stage encoded at a time as it is written for the process
_PIECE = 1 << 20


class Job:
    """A stage handed to the checker; :meth:`Checker.valid` waits for its answer."""

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

    def submit(self, text: str, schema: Path) -> Job | None:
        """Hand ``text`` (a stage) to the checker, to validate against ``schema``. None when no checker
        process can be had (the caller validates it)."""
        try:
            proc = self._process()
            self._next += 1
            path = self._folder / f"{self._next}.xml"
            # in pieces: the whole text encoded at once was a second copy of
            # the largest stage beside the driver's peak
            with open(path, "w", encoding="utf-8", newline="") as out:
                for start in range(0, len(text), _PIECE):
                    out.write(text[start:start + _PIECE])
            request = {"job": self._next, "file": str(path), "schema": str(schema)}
            proc.stdin.write(json.dumps(request) + "\n")
            proc.stdin.flush()
        except OSError:
            self.close()
            return None
        return Job(self._next)

    def valid(self, job: Job) -> bool | None:
        """Whether the stage of ``job`` is valid; None when the checker could not tell (the caller
        validates it)."""
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
        return self._answers.pop(job.number).get("valid")

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

def _check(request: dict) -> dict:
    from robomda.validate import schema_of, streams_valid

    started = time.perf_counter()
    path = Path(request["file"])
    try:
        valid = streams_valid(path, schema_of(Path(request["schema"])))
    finally:
        path.unlink(missing_ok=True)
    return {"valid": valid, "seconds": time.perf_counter() - started, "peak": _peak()}


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
