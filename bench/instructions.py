"""Count the instructions each stylesheet of a chain executes, by model shape and size: a measure that does not
depend on what else the machine is doing.

    python bench/instructions.py 500 1000                      # every shape, Orocos chain
    python bench/instructions.py 500 1000 --shapes ring calls --target ros2

bench/stages.py times each stage; on a shared machine the same stage took 5.2 s at one time and 6.8 to 8.1 s a
quarter of an hour later, so a change that saves 3 to 5 % cannot be told from the machine. A count does not depend
on what else the machine does, but it includes the work of SaxonC's garbage collector, and the same run does not
collect at the same points every time, so its count still varies: six counts of a process running the Orocos text
stage on the ring at 1,000 components spread over 0.3 % (10,931 to 10,965 million instructions), four of the import
of calls at 1,000 over 1.1 %, five of the Orocos PSM of calls at 1,000 over 4 % of the process (6 % of the stage:
one count fell 0.4 G below the others). --repeat N counts each run N times and keeps the least, as bench/stages.py
keeps the least time. A count is a difference of two processes' counts, so at a few components, where compiling
dwarfs the stage, the spread is a large part of it: the smallest sizes show that the stages run, not how much they
cost.

For each shape and size it writes the model, runs the chain once to get every stage's input, then for each stage
and for the identity transform of the stage's input runs a fresh process twice under valgrind (cachegrind, no
cache simulation): a first transform of a tiny tree (what the engine's first transform in a process costs, in
every count alike), compiling the stylesheet and parsing the stage's input into a tree as the chain hands one
over (the base); then the same and one run of the stylesheet on that tree, as the chain runs it (a kept tree
serialized too). A count is the second process's minus the base's. It prints each stage's count beside its
identity's and their ratio, then each stage's growth between consecutive sizes beside its identity's: a stage
that grows with the square of the model stands out above that spread (issue 35 asks t(4,000) / t(2,000) <= 2.2
of every stage).

valgrind runs a process about 15 times slower, so the sizes are small (CI counts 10 components of one shape; a
whole run at 500 and 1,000 takes about 7 minutes a shape on two cores with --repeat 1, 12 with --repeat 3).
--jobs runs that many counts at once (default 2). Needs valgrind (Debian package valgrind); without it, it says so
and exits 2.
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "src"))

from stages import _IDENTITY, MIDDLEWARE, chain, stage_params  # noqa: E402
from synth import SHAPES, write_model  # noqa: E402

from robomda.engine import Engine  # noqa: E402

_COUNT = re.compile(r"I\s+refs:\s+([0-9,]+)")


def _inputs(model: Path, target: str, workdir: Path) -> list[tuple[str, Path, Path, dict[str, str], bool]]:
    """Each step of the chain on ``model``: its name, stylesheet, input file (the XMI, then the text of the step
    before), parameters and whether the chain keeps its result as a tree."""
    engine = Engine()
    chain_steps = chain(target).steps
    steps, source = [], model
    for index, step in enumerate(chain_steps):
        keep = index < len(chain_steps) - 1
        params = stage_params(step, model)
        steps.append((step.name, step.stylesheet, source, params, keep))
        if keep:
            text = engine.run(step.stylesheet, params, source, keep_tree=False)[0]
            source = workdir / f"{model.stem}.{step.name}.xml"
            source.write_text(text, encoding="utf-8")
    return steps


def _child(stylesheet: Path, identity: Path, source: Path, params: dict[str, str], keep: bool, run: bool) -> None:
    """In a fresh process (under valgrind): run ``identity`` once on a tiny tree (what any first transform of a
    process costs the engine, in every count alike), compile ``stylesheet``, parse ``source`` into a tree as the
    chain hands one over, then, with ``run``, run the stylesheet on it once."""
    engine = Engine()
    engine.run(identity, {}, engine.parse("<warm/>"), keep_tree=keep)
    engine.compile(stylesheet)
    tree = engine.parse(source.read_text(encoding="utf-8"))
    if run:
        engine.run(stylesheet, params, tree, keep_tree=keep)


def _count(args: list[str]) -> int:
    """The instructions of ``python this-file --child ARGS`` under valgrind."""
    done = subprocess.run(["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null",
                           sys.executable, __file__, "--child", *args], capture_output=True, text=True)
    found = _COUNT.findall(done.stderr)
    if done.returncode != 0 or not found:
        raise RuntimeError(f"bench/instructions.py --child {' '.join(args)} failed:\n{done.stderr[-3000:]}")
    return int(found[-1].replace(",", ""))


def measure(shape: str, sizes: list[int], target: str, jobs: int, workdir: Path,
            repeat: int = 1) -> dict[str, object]:
    """Each stage's instructions at each size of ``shape`` and those of the identity transform of its input:
    ``counts[i][j]`` and ``identity[i][j]`` for size i, stage j; each run counted ``repeat`` times, the least
    kept."""
    identity = workdir / "identity.xsl"
    identity.write_text(_IDENTITY, encoding="utf-8")
    work = []
    for size in sizes:
        model = write_model(size, workdir / f"{shape}-{size}.xmi", shape, MIDDLEWARE[target])
        for name, stylesheet, source, params, keep in _inputs(model, target, workdir):
            keep_flag = "1" if keep else "0"
            work.append((size, name, [[str(xsl), str(identity), str(source), json.dumps(given), keep_flag, run]
                                      for xsl, given in ((stylesheet, params), (identity, {}))
                                      for run in ("0", "1")]))
    # the base once (compiling and parsing vary by 0.2 % at most), each run ``repeat`` times
    with ThreadPoolExecutor(max(1, jobs)) as pool:
        counted = [[[pool.submit(_count, args) for _ in range(1 if args[-1] == "0" else max(1, repeat))]
                    for args in runs] for _, _, runs in work]
        counted = [[min(future.result() for future in futures) for futures in runs] for runs in counted]
    names = list(dict.fromkeys(name for _, name, _ in work))
    counts = [[0] * len(names) for _ in sizes]
    ident = [[0] * len(names) for _ in sizes]
    for (size, name, _), (base, stage, identity_base, same) in zip(work, counted):
        if stage <= base or same <= identity_base:  # a run that did nothing: the measure is broken, not the stage
            raise RuntimeError(f"{shape} at {size}: the run of {name} or of its identity counted no more "
                               f"instructions than its base ({stage - base:,} and {same - identity_base:,})")
        counts[sizes.index(size)][names.index(name)] = stage - base
        ident[sizes.index(size)][names.index(name)] = same - identity_base
    return {"shape": shape, "target": target, "sizes": sizes, "stages": names, "counts": counts, "identity": ident}


def report(measured: dict[str, object]) -> list[str]:
    """Lines: each size's stages (millions of instructions, the identity's, their ratio), then the growth of each
    stage between consecutive sizes beside its identity's."""
    shape, sizes, names = measured["shape"], measured["sizes"], measured["stages"]
    counts, ident = measured["counts"], measured["identity"]
    lines = []
    for i, size in enumerate(sizes):
        stages = ", ".join(f"{name} {c / 1e6:,.0f} M ({c / max(f, 1):.1f} x identity {f / 1e6:,.0f} M)"
                           for name, c, f in zip(names, counts[i], ident[i]))
        lines.append(f"{shape:>10} {size:>6}: {stages}; all {sum(counts[i]) / max(sum(ident[i]), 1):.1f} x")
    for i in range(len(sizes) - 1):
        growth = ", ".join(f"{name} {b / max(a, 1):.2f} (identity {g / max(f, 1):.2f})"
                           for name, a, b, f, g in zip(names, counts[i], counts[i + 1], ident[i], ident[i + 1]))
        pair = f"n({sizes[i + 1]})/n({sizes[i]}) (sizes x{sizes[i + 1] / sizes[i]:.1f})"
        lines.append(f"{shape:>10} {pair}: {growth}")
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sizes", type=int, nargs="*", default=[500, 1000])
    parser.add_argument("--shapes", nargs="+", choices=SHAPES, default=list(SHAPES))
    parser.add_argument("--target", choices=sorted(MIDDLEWARE), default="orocos")
    parser.add_argument("--jobs", type=int, default=2, help="counts run at once (default 2)")
    parser.add_argument("--repeat", type=int, default=1,
                        help="counts of each run, the least kept (SaxonC's garbage collector does not work the "
                             "same in every run: a run's count varies by up to 6 %%; default 1)")
    parser.add_argument("--json", action="store_true", help="a last line with the counts as JSON")
    parser.add_argument("--child", nargs=6, help=argparse.SUPPRESS)  # one count's process (_child)
    args = parser.parse_args(argv)
    if args.child:
        stylesheet, identity, source, params, keep, run = args.child
        _child(Path(stylesheet), Path(identity), Path(source), json.loads(params), keep == "1", run == "1")
        return 0
    if shutil.which("valgrind") is None:
        print("bench/instructions.py: valgrind is not installed (Debian: apt-get install valgrind)",
              file=sys.stderr)
        return 2
    found = []
    with tempfile.TemporaryDirectory(dir="/dev/shm" if Path("/dev/shm").is_dir() else None) as tmp:
        for shape in args.shapes:
            try:
                measured = measure(shape, args.sizes, args.target, args.jobs, Path(tmp), args.repeat)
            except RuntimeError as exc:
                print(f"bench/instructions.py: {exc}", file=sys.stderr)
                return 1
            found.append(measured)
            for line in report(measured):
                print(line, flush=True)
    if args.json:
        print(json.dumps(found))
    return 0


if __name__ == "__main__":
    sys.exit(main())
