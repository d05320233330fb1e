"""The stylesheets give the same bytes under SaxonC-HE, Saxon-HE Java and SaxonJS.

For every fixture case, each other engine runs
- every stage stylesheet alone, on the golden input of that stage, and must
  write the golden (or, for the text step, SaxonC's file set) byte for byte;
- the pure-XSLT runner (xslt/util/run-pipeline.xsl, fn:transform) on the
  import manifest, which must write the golden bound PIM, and on the Orocos
  manifest, which must write exactly the golden package files.

The engines come from the registries (tests/run.sh installs them): Saxon-HE
Java from Debian's libsaxonhe-java, SaxonJS from npm's xslt3
(tests/engines/package.json). Without them these tests skip and say why.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from saxonche import PySaxonProcessor

from robomda import pipeline
from robomda.api import diagram, generate, targets

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted(p.parent for p in (ROOT / "fixtures" / "cases").glob("*/model.xmi"))
SAXON_JAR = Path(os.environ.get("ROBOMDA_SAXON_JAR", "/usr/share/java/Saxon-HE.jar"))
XSLT3 = Path(os.environ.get("ROBOMDA_XSLT3", ROOT / "tests" / "engines" / "node_modules" / "xslt3" / "xslt3.js"))
CONTEXT = {"model-file-name": "model.xmi", "model-dir-from-output": "..", "package-name": "", "type-map": "",
           "package-version": "", "maintainer-name": "", "maintainer-email": "", "license": "", "copyright-year": "", "model-path": "",
           "replace": ""}


def _stages() -> dict[str, tuple[Path, str, str | None, dict[str, str], str]]:
    """Every step of every target's manifest, with its golden input and output.

    Goldens: import -> expected/import.xml, bind -> expected/bind.xml,
    psm -> expected/<target>/psm.xml; the text step's file set is compared
    with SaxonC's (its files are the goldens). The diagram chain
    (pipelines/diagrams.xml, not a target) runs its text step on the bound PIM too.
    """
    stages: dict[str, tuple[Path, str, str | None, dict[str, str], str]] = {}
    for manifest in sorted((ROOT / "pipelines").glob("*.xml")):
        target = manifest.stem
        if target == "import":
            continue
        previous = "model.xmi"
        for step in pipeline.load(manifest).steps:
            if step.when:  # a step for a product line's configuration: test_configure_stage_writes_the_same_bytes
                continue
            shared = step.name in ("import", "bind")
            golden = (f"expected/{step.name}.xml" if shared
                      # the swaps' and the jobs' checks write the bound PIM they read, unchanged
                      else "expected/bind.xml" if step.name in ("substitute", "jobs")
                      else f"expected/{target}/{step.name}.xml" if step.name != "text" else None)
            params = {p.name: p.value if p.value is not None else CONTEXT[p.source or ""] for p in step.params}
            stages[step.name if shared else f"{target}-{step.name}"] = (step.stylesheet, previous, golden, params, target)
            previous = golden or previous
    return stages


STAGES = _stages()
# the one-target fixtures (fixtures/<target>/<case>: models the other targets refuse yet) run that target's steps
ONE_TARGET = [p.parent for p in sorted((ROOT / "fixtures" / "orocos").glob("*/model.xmi"))]
# the ROS-only fixtures (fixtures/ros: e.g. managed lifecycle nodes) keep PSM goldens only: their text steps
ROS_ONLY = [p.parent for p in sorted((ROOT / "fixtures" / "ros").glob("*/model.xmi"))]
# the dialect fixtures (components drawn as classes in the tools' own profiles, issue 51): what is theirs
# alone is the import's and bind's reading of each profile; their PSM and text stages run the generators
# every other case runs, so the engines compare their import and bind (every engine) and the runner's
# whole chain on Saxon-HE Java only; fixtures/ros/p4rlib (ports typed by Papyrus for Robotics' ROS 2
# library) keeps ROS goldens only, written by the text stylesheets every ROS-only fixture runs here
DIALECTS = ("robotml", "p4r", "umlrt", "sysml", "designer", "p4rlib")
STAGE_RUNS = [(case, step) for case in CASES for step in STAGES
              if case.name not in DIALECTS or step in ("import", "bind")] + [
    (case, step) for case in ONE_TARGET for step in STAGES if step in ("import", "bind") or step.startswith("orocos-")] + [
    (case, step) for case in ROS_ONLY if case.name not in DIALECTS for step in STAGES if step in ("ros1-text", "ros2-text")]


class Cli:
    """One engine's command line: -s: -xsl: -o: name=value, as Saxon's."""

    def __init__(self, name: str, argv: list[str], compile_first: bool) -> None:
        self.name = name
        self.argv = argv
        self.compile_first = compile_first
        self._compiled: dict[Path, Path] = {}

    def stylesheet(self, xsl: Path, workdir: Path) -> Path:
        """SaxonJS compiles XSLT to SEF on each call (seconds): compile each stylesheet once."""
        if not self.compile_first:
            return xsl
        if xsl not in self._compiled:
            sef = workdir / (xsl.relative_to(ROOT).as_posix().replace("/", "_") + ".sef.json")
            subprocess.run(self.argv + [f"-xsl:{xsl}", f"-export:{sef}", "-nogo"], check=True,
                           capture_output=True, text=True, timeout=300)
            self._compiled[xsl] = sef
        return self._compiled[xsl]

    def run(self, xsl: Path, source: Path, out: Path, params: dict[str, str], workdir: Path) -> None:
        cmd = self.argv + [f"-s:{source}", f"-xsl:{self.stylesheet(xsl, workdir)}", f"-o:{out}"]
        cmd += [f"{k}={v}" for k, v in params.items()]
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, f"{self.name} failed: {' '.join(cmd)}\n{done.stderr[-3000:]}"


def _engines() -> list[object]:
    params = []
    java = shutil.which("java")
    params.append(pytest.param(
        Cli("saxon-he-java", [java or "java", "-cp", str(SAXON_JAR), "net.sf.saxon.Transform"], False),
        id="saxon-he-java",
        marks=pytest.mark.skipif(not (java and SAXON_JAR.is_file()),
                                 reason=f"Saxon-HE Java not installed (java, {SAXON_JAR}): "
                                        "tests/run.sh installs libsaxonhe-java as root on Debian")))
    node = shutil.which("node")
    params.append(pytest.param(
        Cli("saxonjs", [node or "node", str(XSLT3)], True),
        id="saxonjs",
        marks=pytest.mark.skipif(not (node and XSLT3.is_file()),
                                 reason=f"SaxonJS not installed (node, {XSLT3}): tests/run.sh runs npm ci "
                                        "in tests/engines")))
    return params


ENGINES = _engines()


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("engines")


# SaxonJS takes 15 s a stage of a dialect fixture: it reads the import and bind of the one whose dialect
# takes the most paths of dialects.xsl and bind/classes.xsl (UML-RT: message sets, conjugation, runtime
# ports, the top capsule); Papyrus for Robotics' import (patterns, parameter blocks, activities, and the
# stand-ins of its ROS 2 library) it reads in fixtures/ros/p4rlib, one of the export shapes below;
# Saxon-HE Java reads all five. (So CI stays under 20 minutes: this session's rehearsals took 18.9 and 19.9.)
SAXONJS_DIALECTS = ("umlrt",)
STAGE_PARAMS = [pytest.param(engine.values[0], case, step, id=f"{step}-{case.name}-{engine.id}", marks=engine.marks)
                for engine in ENGINES for case, step in STAGE_RUNS
                if not (engine.id == "saxonjs" and case.name in DIALECTS and case.name not in SAXONJS_DIALECTS)]


@pytest.mark.parametrize(("engine", "case", "step"), STAGE_PARAMS)
def test_each_stage_writes_the_same_bytes(engine: Cli, case: Path, step: str, workdir: Path) -> None:
    xsl, source, golden, params, target = STAGES[step]
    out = workdir / f"{engine.name}-{case.name}-{step}.xml"
    engine.run(xsl, case / source, out, params, workdir)
    if golden is not None:
        expected = (case / golden).read_bytes()
    elif target in targets():  # the file set is not a golden itself: compare with SaxonC-HE's, through the driver
        expected = generate(case / "model.xmi", case / "out", target, write=False).stages["text"].encode("utf-8")
    else:  # the diagrams
        expected = diagram(case / "model.xmi", case / "out", write=False).stages["text"].encode("utf-8")
    assert out.read_bytes() == expected


# The whole chain through the pure-XSLT runner: on Saxon-HE Java for every case; on SaxonJS
# (a minute a case) for the cases that take the runner's every path (several processes and
# hosts, composites and operation calls, data types), since test_each_stage_writes_the_same_bytes
# already compares every stage of every case on SaxonJS.
RUNNER_ON_SAXONJS = ("distributed", "learning", "structured")
RUNNER_RUNS = [pytest.param(engine.values[0], case, id=f"{case.name}-{engine.id}", marks=engine.marks)
               for engine in ENGINES for case in CASES + ONE_TARGET
               if engine.id != "saxonjs" or case.name in RUNNER_ON_SAXONJS]


@pytest.mark.parametrize("engine, case", RUNNER_RUNS)
def test_pure_xslt_runner_writes_the_golden_package(engine: Cli, case: Path, workdir: Path) -> None:
    model = (case / "model.xmi").resolve().as_uri()
    bound = workdir / f"{engine.name}-{case.name}-runner-bind.xml"
    engine.run(ROOT / "xslt/util/run-pipeline.xsl", ROOT / "pipelines/import.xml", bound, {"model": model}, workdir)
    assert bound.read_bytes() == (case / "expected/bind.xml").read_bytes()

    package = workdir / f"{engine.name}-{case.name}-package"
    engine.run(ROOT / "xslt/util/run-pipeline.xsl", ROOT / "pipelines/orocos.xml", package / "written.xml",
               {"model": model, "model-dir-from-output": ".."}, workdir)
    _assert_same_package(package, case)


def test_pure_xslt_runner_under_saxonc(tmp_path: Path) -> None:
    """The runner also works in SaxonC-HE (fn:transform), the driver's engine."""
    case = CASES[0]
    with PySaxonProcessor(license=False) as proc:
        runner = proc.new_xslt30_processor().compile_stylesheet(
            stylesheet_file=str(ROOT / "xslt/util/run-pipeline.xsl"))
        runner.set_parameter("model", proc.make_string_value((case / "model.xmi").resolve().as_uri()))
        runner.set_parameter("model-dir-from-output", proc.make_string_value(".."))
        runner.set_base_output_uri((tmp_path / "written.xml").as_uri())
        manifest = proc.parse_xml(xml_file_name=str(ROOT / "pipelines/orocos.xml"))
        runner.set_global_context_item(xdm_item=manifest)
        runner.apply_templates_returning_file(xdm_value=manifest, output_file=str(tmp_path / "written.xml"))
    _assert_same_package(tmp_path, case)


def _assert_same_package(package: Path, case: Path) -> None:
    listing = (case / "expected/orocos/files.tsv").read_text().splitlines()
    expected = {}
    for line in listing:
        mode, path = line.split("\t")
        written = path + ".robomda-new" if mode == "user" else path
        expected[written] = (case / "expected/orocos/files" / path).read_bytes()
    got = {p.relative_to(package).as_posix(): p.read_bytes()
           for p in package.rglob("*") if p.is_file() and p.name != "written.xml"}
    assert sorted(got) == sorted(expected)
    for path, data in expected.items():
        assert got[path] == data, path


# ------------------------------------------------------------------------------------------------
# The shapes of real exports that no fixture case holds (issue 30: xsi:type, template
# placeholders, several clients, nested connector ends, EA exposed interfaces), built by the
# builders of tests/test_import_content.py, and a model whose ports a tool's library types
# (fixtures/ros/p4rlib): the import reads them alike on every engine.
def _export_shapes() -> dict[str, str]:
    import test_import_content as shapes

    return {
        "templates-xsi.uml": shapes._template_model(shapes.Xmi("xsi")),
        "several-clients.uml": shapes._multi_model(shapes.Xmi("eclipse"), "impl prt cmp pkg"),
        "nested-end.xmi": shapes._nested_model(shapes.Xmi("magicdraw"), nested="sysml", second=True)[0],
        # Papyrus for Robotics' ROS 2 library services and primitives, stood in from their hrefs
        "p4rlib.uml": (ROOT / "fixtures" / "ros" / "p4rlib" / "model.xmi").read_text(encoding="utf-8"),
    }


@pytest.mark.parametrize("engine", ENGINES)
def test_the_import_reads_real_export_shapes_alike(engine: Cli, workdir: Path) -> None:
    from robomda.api import import_model

    for name, text in _export_shapes().items():
        model = workdir / f"{engine.name}-shapes" / name
        model.parent.mkdir(exist_ok=True)
        model.write_text(text, encoding="utf-8")
        out = workdir / f"{engine.name}-shapes-{name}.pim.xml"
        engine.run(ROOT / "xslt/util/run-pipeline.xsl", ROOT / "pipelines/import.xml", out,
                   {"model": model.resolve().as_uri()}, workdir)
        assert out.read_text(encoding="utf-8") == import_model(model), name


# the product lines (fixtures/variability/<line>) and their valid configurations
CONFIGURATIONS = [("researchcamp", c) for c in ("map-lab-offboard", "map-vfh-hall", "marker-dwa-pick")] + [
    ("calligraphy", c) for c in ("direct-buffered", "joint-compliant-soft", "joint-firm")]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize(("line", "config"), CONFIGURATIONS)
def test_configure_stage_writes_the_same_bytes(engine: Cli, line: str, config: str, workdir: Path) -> None:
    """The configure step (xslt/m2m/configure.xsl) on the template's golden PIM writes the golden configured
    PIM of each configuration (tests/test_variability.py)."""
    step = next(s for s in pipeline.load(ROOT / "pipelines" / "import.xml").steps if s.name == "configure")
    camp = ROOT / "fixtures" / "variability" / line
    variability = camp / "variability"
    params = {"features": (variability / "configs" / f"{config}.xml").as_uri(),
              "feature-model": (variability / "model.xml").as_uri(),
              "resolution": (variability / "resolution.xml").as_uri()}
    out = workdir / f"{engine.name}-{line}-{config}-configure.xml"
    engine.run(step.stylesheet, camp / "expected" / "import.xml", out, params, workdir)
    assert out.read_bytes() == (camp / "expected" / config / "configure.xml").read_bytes()


@pytest.mark.parametrize("engine", ENGINES)
def test_pure_xslt_runner_configures_a_product_line(engine: Cli, workdir: Path) -> None:
    """run-pipeline.xsl with a configuration runs the configure step (step/@if) and writes the golden
    bound PIM of the variant."""
    camp = ROOT / "fixtures" / "variability" / "researchcamp"
    variability = camp / "variability"
    params = {"model": (camp / "model.xmi").as_uri(),
              "features": (variability / "configs" / "map-vfh-hall.xml").as_uri(),
              "feature-model": (variability / "model.xml").as_uri(),
              "resolution": (variability / "resolution.xml").as_uri()}
    bound = workdir / f"{engine.name}-researchcamp-runner-bind.xml"
    engine.run(ROOT / "xslt/util/run-pipeline.xsl", ROOT / "pipelines/import.xml", bound, params, workdir)
    assert bound.read_bytes() == (camp / "expected" / "map-vfh-hall" / "bind.xml").read_bytes()


@pytest.mark.parametrize("engine", ENGINES)
def test_configure_stage_resolves_jobs_given_as_configurations(engine: Cli, workdir: Path) -> None:
    """The configure step in job mode (no features; the jobs name configurations, docs/jobs.md) on the
    template's golden PIM writes the golden configured PIM of fixtures/variability/teleop."""
    step = next(s for s in pipeline.load(ROOT / "pipelines" / "import.xml").steps if s.name == "configure")
    line = ROOT / "fixtures" / "variability" / "teleop"
    out = workdir / f"{engine.name}-teleop-jobs-configure.xml"
    engine.run(step.stylesheet, line / "expected" / "import.xml", out, {"model-uri": (line / "model.xmi").as_uri()},
               workdir)
    assert out.read_bytes() == (line / "expected" / "configure.xml").read_bytes()


@pytest.mark.parametrize("engine", ENGINES)
def test_pure_xslt_runner_configures_jobs_given_as_configurations(engine: Cli, workdir: Path) -> None:
    """run-pipeline.xsl runs the configure step when the model's jobs ask for it (step/@if
    job-configurations) and writes the golden bound PIM."""
    line = ROOT / "fixtures" / "variability" / "teleop"
    bound = workdir / f"{engine.name}-teleop-jobs-runner-bind.xml"
    engine.run(ROOT / "xslt/util/run-pipeline.xsl", ROOT / "pipelines/import.xml", bound,
               {"model": (line / "model.xmi").as_uri()}, workdir)
    assert bound.read_bytes() == (line / "expected" / "bind.xml").read_bytes()
