"""The command line: usage, bad input, exit codes, and nothing written on failure."""

from __future__ import annotations

from pathlib import Path

import pytest

from robomda.cli import main


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize("command", ["generate", "import"])
def test_help_names_the_options_and_exit_codes(capsys: pytest.CaptureFixture[str], command: str) -> None:
    with pytest.raises(SystemExit) as done:
        main([command, "--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    assert "-o OUT" in out and "exit codes" in out and "MODEL" in out


def test_missing_model_is_an_input_error(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, err = run(capsys, "generate", str(tmp_path / "nope.xmi"), "-o", str(tmp_path / "out"))
    assert code == 2
    assert "[IO001]" in err and "nope.xmi" in err
    assert not (tmp_path / "out").exists()


def test_malformed_xml_names_file_line_and_column(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    model = tmp_path / "broken.xmi"
    model.write_text('<?xml version="1.0"?>\n<xmi:XMI xmlns:xmi="http://www.omg.org/spec/XMI/20131001">\n'
                     "  <uml:Model>\n</xmi:XMI>\n")
    code, _, err = run(capsys, "generate", str(model), "-o", str(tmp_path / "out"))
    assert code == 2
    first = err.splitlines()[0]
    assert first.startswith(f"{model}:3:") and "[XML001]" in first
    assert not (tmp_path / "out").exists()


def test_unknown_target_is_refused_by_the_parser(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    with pytest.raises(SystemExit) as done:
        main(["generate", "m.xmi", "-o", str(tmp_path), "--target", "player"])
    assert done.value.code == 2
    assert "invalid choice" in capsys.readouterr().err


def test_import_writes_the_pim_and_never_replaces_a_user_file(capsys: pytest.CaptureFixture[str],
                                                               tmp_path: Path) -> None:
    model = Path(__file__).resolve().parent.parent / "fixtures" / "cases" / "meka" / "model.xmi"
    assert main(["import", str(model), "-o", str(tmp_path)]) == 0
    pim = tmp_path / "model.pim.xml"
    assert "urn:robomda:pim:1" in pim.read_text() and "<pim:binding" in pim.read_text()
    assert main(["import", str(model), "-o", str(pim), "--no-bind"]) == 0  # a robomda model: replaced
    assert "<pim:binding" not in pim.read_text()
    mine = tmp_path / "notes.xml"
    mine.write_text("<notes>mine</notes>")
    capsys.readouterr()
    assert main(["import", str(model), "-o", str(mine)]) == 2
    assert "[OUT001]" in capsys.readouterr().err and mine.read_text() == "<notes>mine</notes>"


def test_a_user_type_map_overrides_the_message_types(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    model = Path(__file__).resolve().parent.parent / "fixtures" / "cases" / "pid" / "model.xmi"
    type_map = tmp_path / "my-types.xml"
    type_map.write_text('<types xmlns="urn:robomda:ros-types:1"><type primitive="float64" cpp="double" '
                        'msg="my_msgs/Angle" field="radians" msg-field="float64" param1="double" '
                        'param2="double" sample="0.0"/></types>')
    assert main(["generate", str(model), "-o", str(tmp_path / "out"), "--target", "ros1",
                 "--type-map", str(type_map)]) == 0
    header = (tmp_path / "out" / "include" / "pid" / "PIDController.hpp").read_text()
    assert "my_msgs/Angle.h" in header and "std_msgs/Float64" not in header
    capsys.readouterr()
    assert main(["generate", str(model), "-o", str(tmp_path / "o2"), "--target", "ros1",
                 "--type-map", str(tmp_path / "missing.xml")]) == 2
    assert "[IO001]" in capsys.readouterr().err
