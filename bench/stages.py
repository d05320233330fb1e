"""Time each stylesheet of a chain alone (no validation, no writing; each
stage includes writing its result as text, as the pipeline does), by model size.

    python bench/stages.py 500 1000 2000      # sizes of bench/synth.py models

A quick profile for stylesheet work: if a stage's time does not double when
the model doubles, that stage has a super-linear step. Stylesheets are
compiled before timing.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "src"))

from synth import write_model  # noqa: E402

from robomda import pipeline  # noqa: E402
from robomda.engine import Engine  # noqa: E402
from robomda.resources import pipeline_path  # noqa: E402


def main(sizes: list[int], target: str = "orocos") -> None:
    engine = Engine()
    chain = pipeline.load(pipeline_path(target))
    context = {"model-file-name": "synth.xmi", "model-dir-from-output": ".", "package-name": ""}
    for step in chain.steps:
        engine.compile(step.stylesheet)
    with tempfile.TemporaryDirectory() as tmp:
        for size in sizes:
            model = write_model(size, Path(tmp) / f"synth-{size}.xmi")
            source: object = model
            row = []
            for index, step in enumerate(chain.steps):
                params = {p.name: p.value if p.value is not None else context.get(p.source or "", "")
                          for p in step.params}
                started = time.perf_counter()
                # as the pipeline does: each stage's tree is the next one's source
                text, tree = engine.run(step.stylesheet, params, source, keep_tree=index < len(chain.steps) - 1)
                source = tree if tree is not None else text
                row.append(f"{step.name} {time.perf_counter() - started:.2f}s ({len(text) // 1024} KiB)")
            print(f"{size:>6}: " + ", ".join(row), flush=True)


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [500, 1000, 2000])
