"""Time each stylesheet of a chain alone (no validation, no writing; each
stage includes writing its result as text, as the pipeline does), by model
shape and size.

    python bench/stages.py 2000 4000                        # every shape, Orocos chain
    python bench/stages.py 2000 4000 --shapes composite nested --target ros2
    python bench/stages.py 2000 4000 --shapes composite deployment --target openrtm

A quick profile for stylesheet work: for each shape of bench/synth.py, each
stage's time at each size, then the ratio of each stage's time between
consecutive sizes beside the ratio of the sizes. A stage whose ratio is
well above the sizes' (issue 35: t(4,000) / t(2,000) <= 2.2) has a
super-linear step on that shape. Each size is measured in a fresh process
(its stylesheets compiled before timing), as bench/run.py measures the
whole chain: in one process serving both sizes, the larger one ran on the
heap the smaller one had left, and the same stage grew more (the Orocos
text stage on the nested shape from 2,000 to 4,000: 2.49 in one process,
1.93 in fresh ones, the stylesheet and inputs the same). The times are the
measuring process's CPU seconds (SaxonC runs in it), which other work on a
shared machine stretches less than wall time (--wall: wall time);
--repeat runs each stage that many times and keeps the least time (other
work on a shared machine only ever adds). The sizes' processes take turns,
one run of the chain each, so that a slow spell of the machine falls on
every size alike. Here, the import of the ring at 4,000 took 5.2 s at one
time and 6.8 to 8.1 s a quarter of an hour later, the stylesheet the same;
at 2,000, four runs in one process went from 3.80 down to 2.43 s. A ratio
of two figures measured minutes apart is the machine's as much as the
stage's. Beside each ratio, that
of the identity transform of the stage's input in the same processes: what
the engine's own growth (its garbage collector on a larger heap) adds
whatever the stylesheet does. --target times another target's
chain (ros1, ros2, openrtm), on models deployed on its middleware.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Callable

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "src"))

from synth import SHAPES, write_model  # noqa: E402

from robomda import pipeline  # noqa: E402
from robomda.engine import Engine  # noqa: E402
from robomda.resources import pipeline_path  # noqa: E402

MIDDLEWARE = {"orocos": "OROCOS", "ros1": "ROS", "ros2": "ROS2", "openrtm": "OPENRTM"}
LIMIT = 2.2  # issue 35: t(4,000) / t(2,000) on every stage


_IDENTITY = """<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
<xsl:mode on-no-match="shallow-copy"/></xsl:stylesheet>"""


def chain(target: str) -> pipeline.Pipeline:
    """``target``'s chain as a model without a product-line configuration runs it (no configure step)."""
    return pipeline.for_context(pipeline.load(pipeline_path(target)), {}, model_may_ask=False)


def stage_params(step: pipeline.Step, model: Path) -> dict[str, str]:
    """The parameters ``step`` runs with on ``model``, as a command generating into the model's folder sets
    them."""
    context = {"model-file-name": model.name, "model-dir-from-output": ".", "package-name": ""}
    return {p.name: p.value if p.value is not None else context.get(p.source or "", "") for p in step.params}


def _time_stages(engine: Engine, chain: pipeline.Pipeline, model: Path, clock,
                 identity: Path) -> list[tuple[str, float, int, float]]:
    """Each step's name, seconds on ``clock``, output size and the seconds of the identity transform of its input
    on ``model``, as the pipeline hands trees on."""
    source: object = model
    row = []
    for index, step in enumerate(chain.steps):
        params = stage_params(step, model)
        started = clock()
        engine.run(identity, {}, source, keep_tree=False)
        floor = clock() - started
        started = clock()
        text, tree = engine.run(step.stylesheet, params, source, keep_tree=index < len(chain.steps) - 1)
        row.append((step.name, clock() - started, len(text), floor))
        source = tree if tree is not None else text
    return row


def _fastest(runs: list[list[tuple[str, float, int, float]]]) -> list[tuple[str, float, int, float]]:
    """Per stage, the least seconds of ``runs`` (and, apart, the least of its identity's): other work on a
    shared machine only ever adds time, to any one run."""
    return [(name, min(run[j][1] for run in runs), size, min(run[j][3] for run in runs))
            for j, (name, _, size, _) in enumerate(runs[0])]


def _serve(shape: str, size: int, target: str, wall: bool) -> None:
    """One size of ``shape`` in this process (its own engine and heap, the stylesheets compiled first): "ready"
    on stdout, then for each line on stdin one run of the chain, each stage's seconds (with the identity of its
    input) as a line of JSON, until stdin ends."""
    clock = time.perf_counter if wall else time.process_time
    engine = Engine()
    steps = chain(target)
    for step in steps.steps:
        engine.compile(step.stylesheet)
    with tempfile.TemporaryDirectory() as tmp:
        identity = Path(tmp) / "identity.xsl"
        identity.write_text(_IDENTITY)
        engine.compile(identity)
        model = write_model(size, Path(tmp) / f"{shape}-{size}.xmi", shape, MIDDLEWARE[target])
        print("ready", flush=True)
        for _ in sys.stdin:
            print(json.dumps(_time_stages(engine, steps, model, clock, identity)), flush=True)


def _ask(child: subprocess.Popen, err, shape: str, size: int, request: str | None) -> str:
    """Send ``request`` (a line; None: nothing) to ``child`` and read its answer line (``err``: the file its
    stderr goes to, read back when it has ended)."""
    if request is not None:
        try:
            child.stdin.write(request + "\n")
            child.stdin.flush()
        except BrokenPipeError:  # it has ended: its report is on stderr
            pass
    answer = child.stdout.readline()
    if not answer:
        child.wait()
        err.seek(0)
        raise RuntimeError(f"bench/stages.py on {shape} at {size} failed:\n{err.read()}")
    return answer


def measure(shape: str, sizes: list[int], target: str = "orocos", wall: bool = False,
            log: Callable[[str], None] = print, repeat: int = 1) -> dict[str, object]:
    """Each stage's seconds at each size of ``shape`` (with the identity transform of its input), each size in a
    fresh process of its own (:func:`_serve`), the least of ``repeat`` runs, the sizes taking turns run by run;
    ``log`` gets a line per size. The result: sizes, stage names, seconds per size (``seconds[i][j]``: size i,
    stage j) and the identity's likewise."""
    unit = "" if wall else " CPU"
    # each child's stderr in a file, not a pipe: a pipe nobody reads until the end would stop a child that
    # wrote more than its buffer holds
    errs = [tempfile.TemporaryFile("w+", encoding="utf-8") for _ in sizes]
    children = [subprocess.Popen([sys.executable, __file__, str(size), "--serve", "--shapes", shape,
                                  "--target", target] + (["--wall"] if wall else []),
                                 stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err, text=True)
                for size, err in zip(sizes, errs)]
    try:
        for child, err, size in zip(children, errs, sizes):
            _ask(child, err, shape, size, None)  # "ready": compiled, model written
        runs: list[list[list[tuple[str, float, int, float]]]] = [[] for _ in sizes]
        for _ in range(max(1, repeat)):
            for i, (child, err, size) in enumerate(zip(children, errs, sizes)):
                runs[i].append([tuple(stage) for stage in json.loads(_ask(child, err, shape, size, "run"))])
    finally:
        for child, err in zip(children, errs):
            try:
                child.stdin.close()  # the end of its runs
            except BrokenPipeError:
                pass
            child.wait()
            err.close()
    rows = [_fastest(size_runs) for size_runs in runs]
    for size, row in zip(sizes, rows):
        log(f"{shape:>10} {size:>6}: " + ", ".join(f"{name} {t:.2f}s{unit} ({n // 1024} KiB)"
                                                 for name, t, n, _ in row))
    return {"shape": shape, "sizes": sizes, "stages": [name for name, _, _, _ in rows[0]] if rows else [],
            "seconds": [[t for _, t, _, _ in row] for row in rows],
            "identity": [[f for _, _, _, f in row] for row in rows]}


def ratios(measured: dict[str, object]) -> list[tuple[int, int, list[float], list[float]]]:
    """Per pair of consecutive sizes (small, large): each stage's t(large) / t(small) and the identity's."""
    sizes, seconds, identity = measured["sizes"], measured["seconds"], measured["identity"]
    return [(small, large, [b / max(a, 1e-3) for a, b in zip(seconds[i], seconds[i + 1])],
             [b / max(a, 1e-3) for a, b in zip(identity[i], identity[i + 1])])
            for i, (small, large) in enumerate(zip(sizes, sizes[1:]))]


def worst_doubling(measured: dict[str, object]) -> tuple[float, str] | None:
    """The highest stage ratio over a doubling of the size, and its stage; None without a doubling."""
    found = [(r, name) for small, large, stage, _ in ratios(measured) if large == 2 * small
             for r, name in zip(stage, measured["stages"])]
    return max(found) if found else None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sizes", type=int, nargs="*", default=[500, 1000, 2000])
    parser.add_argument("--shapes", nargs="+", choices=SHAPES, default=list(SHAPES))
    parser.add_argument("--target", choices=sorted(MIDDLEWARE), default="orocos")
    parser.add_argument("--wall", action="store_true",
                        help="wall time instead of this process's CPU time (SaxonC runs in it): CPU time is what "
                             "a busy shared machine leaves steady")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each stage at each size: the least time of them is reported (the identity's "
                             "likewise); 2 or 3 on a busy machine")
    parser.add_argument("--json", action="store_true", help="a last line with the measures as JSON (bench/run.py)")
    parser.add_argument("--serve", action="store_true", help=argparse.SUPPRESS)  # a child of measure()
    args = parser.parse_args(argv)
    if args.serve:
        _serve(args.shapes[0], args.sizes[0], args.target, args.wall)
        return 0
    worst = 0.0
    found = []
    for shape in args.shapes:
        measured = measure(shape, args.sizes, args.target, args.wall, lambda line: print(line, flush=True),
                           args.repeat)
        found.append(measured)
        for small, large, stage, identity in ratios(measured):
            print(f"{shape:>10} t({large})/t({small}) (sizes x{large / small:.1f}): "
                  + ", ".join(f"{name} {r:.2f} (identity {f:.2f})"
                              for name, r, f in zip(measured["stages"], stage, identity)), flush=True)
        worst = max(worst, (worst_doubling(measured) or (0.0, ""))[0])
    if worst:
        print(f"worst stage ratio on a doubling: {worst:.2f} (issue 35's limit: {LIMIT})")
    if args.json:
        print(json.dumps(found))
    return 0


if __name__ == "__main__":
    sys.exit(main())
