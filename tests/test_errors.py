"""Bad models through the whole command line: one located message, an exit code, nothing written.

Each case mutates a real fixture (or uses a tiny hand-made file) and checks
the exact FILE:LINE:COL, the code, the element named and that the output
folder was not created.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from robomda.cli import main

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "fixtures" / "cases"
DATA = ROOT / "tests" / "data" / "import"


def _mutated(tmp_path: Path, case: str, old: str, new: str, name: str = "model.xmi") -> Path:
    text = (CASES / case / name).read_text(encoding="utf-8")
    assert text.count(old) >= 1, old
    model = tmp_path / name
    model.write_text(text.replace(old, new, 1), encoding="utf-8")
    return model


def _line_of(model: Path, needle: str) -> tuple[int, int]:
    for number, line in enumerate(model.read_text(encoding="utf-8").splitlines(), 1):
        if needle in line:
            return number, line.index("<") + 1
    raise AssertionError(needle)


def _generate(capsys: pytest.CaptureFixture[str], model: Path, out: Path, *target: str) -> tuple[int, list[str]]:
    code = main(["generate", str(model), "-o", str(out), *target])
    err = capsys.readouterr().err.strip().splitlines()
    return code, err


def test_port_typed_by_a_missing_interface(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    port = 'xmi:id="_QZjQLKDPm9lYATkGnxV7dw" name="visionValue" visibility="public" type="_OvrYHkhPodbwEviCI8ZQU9"'
    model = _mutated(tmp_path, "headlamp", port, port.replace("_OvrYHkhPodbwEviCI8ZQU9", "_gone"))
    code, err = _generate(capsys, model, tmp_path / "out")
    line, column = _line_of(model, 'xmi:id="_QZjQLKDPm9lYATkGnxV7dw"')
    assert code == 1 and len(err) == 1
    assert err[0].startswith(f"{model}:{line}:{column}: error: [IMP011] ")
    assert "_gone" in err[0] and err[0].endswith("(uml:Port 'visionValue', _QZjQLKDPm9lYATkGnxV7dw)")
    assert not (tmp_path / "out").exists()


def test_unknown_middleware_names_the_execution_environment(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    model = _mutated(tmp_path, "meka", 'name="OROCOS"', 'name="Gazebo"')
    code, err = _generate(capsys, model, tmp_path / "out")
    line, column = _line_of(model, 'name="Gazebo"')
    assert code == 1 and len(err) == 1
    assert err[0].startswith(f"{model}:{line}:{column}: error: [BND003] ")
    assert "Gazebo" in err[0] and "(uml:ExecutionEnvironment 'Gazebo', " in err[0]
    assert not (tmp_path / "out").exists()


def test_dangling_realizing_classifier_in_the_ea_dialect(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    text = (CASES / "headlamp" / "model.ea.xmi").read_text(encoding="cp1252")
    found = re.search(r'<packagedElement xmi:type="uml:Realization" xmi:id="([^"]+)"[^>]*client="([^"]+)"', text)
    assert found, "the EA fixture has a class-to-component Realization"
    realization, client = found.groups()
    start = found.start()
    end = text.index(">", start)
    model = tmp_path / "model.ea.xmi"
    model.write_text(text[:start] + text[start:end].replace(client, "EAID_MISSING") + text[end:], encoding="cp1252")
    code, err = _generate(capsys, model, tmp_path / "out")
    line, column = _line_of(model, f'xmi:id="{realization}"')
    assert code == 1 and len(err) == 1
    assert err[0].startswith(f"{model}:{line}:{column}: error: [IMP013] ") and "EAID_MISSING" in err[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("name", "code", "exit_code"), [
    ("xmi1x.xmi", "IMP001", 2),
    ("not-uml.xml", "IMP002", 2),
    ("duplicate-id.uml", "IMP004", 1),
])
def test_unsupported_or_broken_files(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                     name: str, code: str, exit_code: int) -> None:
    out = tmp_path / "out"
    status, err = _generate(capsys, DATA / name, out)
    assert status == exit_code and len(err) == 1
    assert err[0].startswith(f"{DATA / name}:") and f"error: [{code}]" in err[0]
    assert not out.exists()


def test_a_failed_run_leaves_an_existing_output_untouched(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "out"
    assert main(["generate", str(CASES / "meka" / "model.xmi"), "-o", str(out)]) == 0
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}
    model = _mutated(tmp_path, "meka", 'name="OROCOS"', 'name="Gazebo"')
    capsys.readouterr()
    code, _ = _generate(capsys, model, out)
    assert code == 1
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before


def test_a_model_deployed_elsewhere_is_generated_with_a_located_warning(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = _mutated(tmp_path, "meka", 'name="OROCOS"', 'name="ROS"')
    # named on purpose: without --target, generate picks the model's own middleware (ROS)
    code, err = _generate(capsys, model, tmp_path / "out", "--target", "orocos",
                          "--maintainer", "A B <a@b.org>", "--license", "MIT")
    line, column = _line_of(model, 'name="ROS"')
    assert code == 0
    assert err[0].startswith(f"{model}:{line}:{column}: warning: [ORO006] ") and "all 6 are generated for Orocos" in err[0]
    # then the Orocos rules' warnings on the Meka activities and lifecycle: ORO102 on the six instances
    # as one finding (the other five as notes, each located)
    assert [e.split(": ")[1] + " " + e.split("[")[1][:6] for e in err[1:]] == [
        "warning ORO102"] + ["note ORO102"] * 5 + ["warning ORO103"]
    assert err[1].endswith("[6 alike: 'GX1050Camera', 'ATIForceSensor', 'ScrewDetection', 'TrajectoryPlanner', "
                           "'ImpedanceController', 'MekaArm']")
    assert len(list((tmp_path / "out" / "src").glob("*.cpp"))) == 7


@pytest.mark.parametrize(("target", "code"), [("orocos", "ORO005"), ("ros1", "ROS008"), ("ros2", "ROS008")])
def test_a_model_without_components_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                               target: str, code: str) -> None:
    text = (CASES / "meka" / "model.xmi").read_text(encoding="utf-8")
    model = tmp_path / "empty.xmi"
    # keep the classes and the platform, turn every component into a plain class without ports
    model.write_text(text.replace('xmi:type="uml:Component"', 'xmi:type="uml:Class"')
                     .replace('xmi:type="uml:Port"', 'xmi:type="uml:Property"'), encoding="utf-8")
    status = main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", target])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 1 and f"[{code}] nothing to generate" in err[-1]
    # the component realizations that lost their component are named, not dropped in silence
    assert err[:-1] and all(": warning: [IMP112] ComponentRealization" in e for e in err[:-1])
    assert not (tmp_path / "out").exists()


def test_every_bad_value_of_every_instance_is_reported_at_once(tmp_path: Path,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    """Bind stopped at the first bad value (BND010): a user fixed one, ran again, found the next."""
    text = (CASES / "pid" / "model.xmi").read_text(encoding="utf-8")
    for old, new in (('xmi:id="_pid009v" value="0.01"', 'xmi:id="_pid009v" value="-0.01"'),
                     ('xmi:id="_pid033v" value="0.01"', 'xmi:id="_pid033v" value="fast"')):
        assert text.count(old) == 1
        text = text.replace(old, new)
    (tmp_path / "model.xmi").write_text(text, encoding="utf-8")
    code, err = _generate(capsys, tmp_path / "model.xmi", tmp_path / "out")
    assert code == 1
    found = [line for line in err if "[BND010]" in line]
    assert len(found) == 2, err
    assert any("'-0.01'" in line for line in found) and any("'fast'" in line for line in found)
    assert not (tmp_path / "out").exists()


def test_every_connector_that_joins_nothing_is_reported_at_once(tmp_path: Path,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    text = (CASES / "headlamp" / "model.xmi").read_text(encoding="utf-8")
    # two connectors whose ends are swapped to the same side: each joins two inputs or two outputs
    ends = re.findall(r'<end xmi:type="uml:ConnectorEnd" xmi:id="[^"]+" partWithPort="([^"]+)" role="([^"]+)"/>', text)
    assert len(ends) >= 4
    broken = text
    for first, second in ((ends[0], ends[1]), (ends[2], ends[3])):
        # the second end becomes a copy of the first: an output joined to itself, no input
        old = f'partWithPort="{second[0]}" role="{second[1]}"/>'
        new = f'partWithPort="{first[0]}" role="{first[1]}"/>'
        broken = broken.replace(old, new, 1)
    (tmp_path / "model.xmi").write_text(broken, encoding="utf-8")
    code, err = _generate(capsys, tmp_path / "model.xmi", tmp_path / "out")
    assert code == 1
    assert len([line for line in err if "[BND007]" in line]) == 2, err


def test_text_groups_only_what_is_said_alike_of_several_elements() -> None:
    from robomda.diagnostics import Diagnostic, format_all

    def warn(message: str, line: int, code: str = "APP021") -> Diagnostic:
        return Diagnostic("warning", code, message, file="m.xmi", line=line, column=3, element_kind="uml:Component",
                          element_name="x", xmi_id=f"_{line}")

    lines = format_all([warn("component 'a' is bad on 'h1'", 10), warn("other", 11, "APP022"),
                        warn("component 'b' is bad on 'h1'", 12), warn("component 'c' is bad on 'h2'", 13),
                        warn("component 'd' is bad on 'h1'", 14, "APP023"), warn("component 'e' is bad on 'h1'", 15)])
    assert lines == [
        "m.xmi:10:3: warning: [APP021] component 'a' is bad on 'h1' (uml:Component 'x', _10) [3 alike: 'a', 'b', 'e']",
        "m.xmi:12:3: note: [APP021] the same for 'b' (uml:Component 'x', _12)",
        "m.xmi:15:3: note: [APP021] the same for 'e' (uml:Component 'x', _15)",
        "m.xmi:11:3: warning: [APP022] other (uml:Component 'x', _11)",
        # differs in the other name: its own finding; another code: its own finding
        "m.xmi:13:3: warning: [APP021] component 'c' is bad on 'h2' (uml:Component 'x', _13)",
        "m.xmi:14:3: warning: [APP023] component 'd' is bad on 'h1' (uml:Component 'x', _14)"]
