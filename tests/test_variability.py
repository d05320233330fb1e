"""Product lines (issue 32; docs/variability.md): FeatureIDE feature models and configurations, the
resolution model, the configure stage and its commands, on the Research Camp fixture
(fixtures/variability/researchcamp, written by its make.py).

Goldens per configuration in fixtures/variability/researchcamp/expected/<configuration>/: the
configured PIM (configure.xml), the bound PIM, each target's package, and what ``robomda check``
prints; the broken product lines' diagnostics in .../broken/<case>.txt. Regenerate on purpose only
(``--force-regen``) and read the diff.
"""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

import pytest
from lxml import etree

from robomda.api import generate, import_model, targets
from robomda.cli import main
from test_golden import _check_all  # every golden of a run compared, all differences reported

ROOT = Path(__file__).resolve().parent.parent
CAMP = ROOT / "fixtures" / "variability" / "researchcamp"
CONFIGS = CAMP / "variability" / "configs"
VALID = ["map-lab-offboard", "map-vfh-hall", "marker-dwa-pick"]
FS = "{urn:robomda:fileset:1}"
# every product line and its configurations, valid and invalid
LINES = {"researchcamp": (VALID, ["invalid-pick-blind"]),
         "calligraphy": (["direct-buffered", "joint-compliant-soft", "joint-firm"], ["invalid-compliant-firm"])}
VARIANTS = [(line, config) for line, (valid, _) in LINES.items() for config in valid]
CHECKED = [(line, config) for line, (valid, invalid) in LINES.items() for config in valid + invalid]


def _make(line: str = "researchcamp"):
    spec = importlib.util.spec_from_file_location(f"{line}_make", ROOT / "fixtures" / "variability" / line / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _cli(capsys: pytest.CaptureFixture[str], argv: list[str]) -> tuple[int, str, str]:
    capsys.readouterr()
    code = main(argv)
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize("line", sorted(LINES))
def test_the_fixture_is_what_make_py_writes(line: str) -> None:
    for path, text in _make(line).texts().items():
        assert path.read_text(encoding="utf-8") == text, path


@pytest.mark.parametrize("line", sorted(LINES))
def test_the_template_imports_to_its_golden(line: str, file_regression) -> None:
    """The template's PIM before configuration: the input of the configure step's engine test."""
    folder = ROOT / "fixtures" / "variability" / line
    file_regression.check(import_model(folder / "model.xmi", bind=False), fullpath=folder / "expected" / "import.xml",
                          binary=False)


def test_a_configured_model_is_the_variant_drawn_by_hand(tmp_path: Path) -> None:
    """map-vfh-hall removes six parts (and their connectors) and sets the Hall map: the configured PIM
    is byte for byte the import of the model drawn without them, with that map."""
    by_hand = tmp_path / "model.xmi"  # the same file name: the PIM names its source
    by_hand.write_text(_make().model_text(frozenset({"camera", "markerDetector", "markerPlanner", "objectDetector",
                                                     "kinematics", "arm"}), map_file="maps/hall.yaml"),
                       encoding="utf-8")
    configured = import_model(CAMP / "model.xmi", bind=False, features=CONFIGS / "map-vfh-hall.xml")
    assert "markerDetector" not in configured and "maps/hall.yaml" in configured
    assert configured == import_model(by_hand, bind=False)


@pytest.mark.parametrize("target", targets())
@pytest.mark.parametrize(("line", "config"), VARIANTS)
def test_each_variant_matches_its_goldens(line: str, config: str, target: str, file_regression) -> None:
    folder = ROOT / "fixtures" / "variability" / line
    done = generate(folder / "model.xmi", folder / "out", target, write=False,
                    features=folder / "variability" / "configs" / f"{config}.xml")
    assert list(done.stages)[:3] == ["import", "configure", "bind"]
    expected = folder / "expected" / config
    files = etree.fromstring(done.stages["text"].encode("utf-8"))
    nodes = list(files.iter(f"{FS}file"))
    listing = "".join(f"{node.get('mode', 'generated')}\t{node.get('path')}\n" for node in nodes)
    _check_all(file_regression, [(done.stages["configure"], expected / "configure.xml"),
                                 (done.stages["bind"], expected / "bind.xml"),
                                 (listing, expected / target / "files.tsv")]
               + [(node.text or "", expected / target / "files" / node.get("path")) for node in nodes])


def test_the_variants_differ_as_their_features_say() -> None:
    pims = {c: import_model(CAMP / "model.xmi", features=CONFIGS / f"{c}.xml") for c in VALID}
    # DWA swaps the avoider's realizing class; VFH keeps the template's
    assert 'realizing-class="DwaAvoider"' in pims["marker-dwa-pick"] or "DwaAvoider" in pims["marker-dwa-pick"]
    avoider = 'name="ObstacleAvoider"'
    assert avoider in pims["map-vfh-hall"]
    # the marker variant has the camera and the marker parts, not the map parts
    assert 'name="markerDetector"' in pims["marker-dwa-pick"] and 'name="mapPlanner"' not in pims["marker-dwa-pick"]
    # MarkerBased sets a buffer of 4 on the camera-to-marker connection
    assert 'name="size" value="4"' in import_model(CAMP / "model.xmi", bind=False,
                                                   features=CONFIGS / "marker-dwa-pick.xml")
    # Offboard moves the deployment to the off-board PC
    assert "offboardPC" in pims["map-lab-offboard"]


@pytest.mark.parametrize(("line", "config"), CHECKED)
def test_check_prints_the_golden_diagnostics(line: str, config: str, capsys: pytest.CaptureFixture[str],
                                              monkeypatch: pytest.MonkeyPatch, file_regression) -> None:
    monkeypatch.chdir(ROOT)
    code, out, err = _cli(capsys, ["check", f"fixtures/variability/{line}/model.xmi", "--features",
                                   f"fixtures/variability/{line}/variability/configs/{config}.xml"])
    assert "Traceback" not in err
    assert code == (1 if config.startswith("invalid") else 0)
    file_regression.check(f"exit {code}\n{err}", fullpath=ROOT / "fixtures" / "variability" / line / "expected" / config
                          / "check.txt", binary=False)


def test_the_calligraphy_variants_differ_as_their_features_say(capsys: pytest.CaptureFixture[str]) -> None:
    """Seed 003's follower driven three ways: the application's gain for the follower (a part's value),
    the joint-space approach, the compliance connection and its rule, a buffered strokes connection."""
    folder = ROOT / "fixtures" / "variability" / "calligraphy"
    configs = folder / "variability" / "configs"
    soft = import_model(folder / "model.xmi", bind=False, features=configs / "joint-compliant-soft.xml")
    assert 'attribute="_atfAtfV1" value="8.0"' in soft and 'name="jsGen"' in soft
    direct = import_model(folder / "model.xmi", bind=False, features=configs / "direct-buffered.xml")
    assert 'name="jsGen"' not in direct and 'name="approach"' not in direct and 'name="size" value="16"' in direct
    # without the compliance connection the planner's compliance input is unconnected: the Orocos rule
    # says so, and the configure step said which feature removed the connection
    code, _, err = _cli(capsys, ["check", str(folder / "model.xmi"), "--features", str(configs / "joint-firm.xml")])
    assert code == 0 and "[ORO010]" in err
    assert "[VAR032] connector 'compliance' is removed in configuration 'joint-firm.xml' (feature Compliance not " \
           "selected)" in err


def test_an_invalid_configuration_is_refused_before_anything_is_written(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    config = "fixtures/variability/researchcamp/variability/configs/invalid-pick-blind.xml"
    code, _, err = _cli(capsys, ["generate", "fixtures/variability/researchcamp/model.xmi", "-o",
                                 str(tmp_path / "out"), "--features", config])
    assert code == 1
    assert f"{config}:2:1: error: [VAR017] the selection breaks the constraint " \
           "'ObjectManipulation implies ObjectPerception'" in err
    assert not (tmp_path / "out").exists()


def test_the_template_alone_is_no_valid_system(capsys: pytest.CaptureFixture[str]) -> None:
    """Both planners feed the avoider in the template: only a configuration makes it one system."""
    code, _, err = _cli(capsys, ["check", str(CAMP / "model.xmi")])
    assert code == 1 and "[BND008]" in err


def test_all_configurations_generates_each_variant_and_says_which_fail(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "out"
    code, stdout, _ = _cli(capsys, ["generate", str(CAMP / "model.xmi"), "-o", str(out), "--all-configurations",
                                    str(CONFIGS), "-j", "2"])
    assert code == 1  # one variant is invalid
    rows = {line.split()[0]: line.split()[1:] for line in stdout.splitlines()[1:-1]}
    assert rows["invalid-pick-blind"] == ["failed", "0", "VAR017"]
    for config in VALID:
        assert rows[config][0] == "ok" and rows[config][2] == "-"
        assert (out / config / "CMakeLists.txt").is_file()
    assert not (out / "invalid-pick-blind").exists()
    # the inputs' hash: nothing changed, nothing regenerated; a configuration changed, that variant again
    code, stdout, _ = _cli(capsys, ["generate", str(CAMP / "model.xmi"), "-o", str(out), "--all-configurations",
                                    str(CONFIGS), "-j", "1"])
    assert "3 unchanged" in stdout.splitlines()[-1]
    configs = tmp_path / "camp"
    shutil.copytree(CAMP / "variability", configs)
    (configs / "configs" / "map-vfh-hall.xml").write_text(
        (CONFIGS / "map-vfh-hall.xml").read_text(encoding="utf-8").replace(
            'manual="selected" name="Hall"', 'manual="unselected" name="Hall"').replace(
            'manual="unselected" name="Lab"', 'manual="selected" name="Lab"'), encoding="utf-8")
    code, stdout, _ = _cli(capsys, ["generate", str(CAMP / "model.xmi"), "-o", str(out), "--all-configurations",
                                    str(configs / "configs"), "-j", "1"])
    rows = {line.split()[0]: line.split()[1] for line in stdout.splitlines()[1:-1]}
    assert rows["map-vfh-hall"] == "ok" and rows["map-lab-offboard"] == "skipped", stdout


# Broken product lines: (file under variability/, text, its replacement), the configuration to check.
# Each is the fixture with that one edit; the diagnostics are goldens in fixtures/variability/researchcamp/broken/.
_P = "researchcamp::components::ResearchCamp::"
BROKEN = {
    "config-unknown-feature": ("configs/map-vfh-hall.xml", 'name="Offboard"/>', 'name="Offboard"/>\n'
                               '  <feature automatic="undefined" manual="selected" name="Teleoperation"/>', "map-vfh-hall"),
    "config-two-alternatives": ("configs/map-vfh-hall.xml", 'manual="unselected" name="DWA"', 'manual="selected" name="DWA"',
                                "map-vfh-hall"),
    "config-no-alternative": ("configs/map-vfh-hall.xml", 'manual="selected" name="VFH"', 'manual="unselected" name="VFH"',
                              "map-vfh-hall"),
    "config-child-without-parent": ("configs/marker-dwa-pick.xml", 'manual="unselected" name="Lab"',
                                    'manual="selected" name="Lab"', "marker-dwa-pick"),
    "config-breaks-schema": ("configs/map-vfh-hall.xml", 'manual="selected" name="VFH"', 'manual="yes" name="VFH"',
                             "map-vfh-hall"),
    "model-rule-unknown-feature": ("model.xml", "<var>ObjectPerception</var>", "<var>Perception</var>", "map-vfh-hall"),
    "model-empty-group": ("model.xml", '<alt abstract="true" name="Environment">\n          <feature name="Hall"/>\n'
                          '          <feature name="Lab"/>\n        </alt>',
                          '<alt abstract="true" name="Environment"/>\n        <feature name="Hall"/>\n'
                          '        <feature name="Lab"/>', "map-vfh-hall"),
    "presence-unknown-feature": ("resolution.xml", 'when="ObjectPerception"', 'when="Perception"', "map-vfh-hall"),
    "presence-unknown-element": ("resolution.xml", f'element="{_P}arm"', f'element="{_P}gripper"', "map-vfh-hall"),
    "action-wrong-kind": ("resolution.xml", 'component="researchcamp::components::ObstacleAvoider"',
                          f'component="{_P}avoider"', "marker-dwa-pick"),
    "actions-conflict": ("resolution.xml", '<feature name="Offboard">',
                         '<feature name="ObjectPerception">\n    <set attribute="researchcamp::atomic::AmclLocalizer::mapFile" '
                         'value="maps/objects.yaml"/>\n  </feature>\n  <feature name="Offboard">', "map-lab-offboard"),
    "no-feature-model": ("model.xml", None, None, "map-vfh-hall"),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_a_broken_product_line_gets_the_golden_diagnostics(case: str, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                            monkeypatch: pytest.MonkeyPatch, file_regression) -> None:
    name, old, new, config = BROKEN[case]
    shutil.copy(CAMP / "model.xmi", tmp_path / "model.xmi")
    shutil.copytree(CAMP / "variability", tmp_path / "variability")
    edited = tmp_path / "variability" / name
    if old is None:
        edited.unlink()
    else:
        text = edited.read_text(encoding="utf-8")
        assert text.count(old) == 1, old
        edited.write_text(text.replace(old, new), encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    code, out, err = _cli(capsys, ["check", "model.xmi", "--features", f"variability/configs/{config}.xml"])
    assert code in (1, 2) and "Traceback" not in err + out and "INTERNAL" not in err
    file_regression.check(f"exit {code}\n{err}", fullpath=CAMP / "broken" / f"{case}.txt", binary=False)
    # generate refuses it too, and writes nothing
    code, _, _ = _cli(capsys, ["generate", "model.xmi", "-o", "out", "--features", f"variability/configs/{config}.xml"])
    assert code in (1, 2) and not (tmp_path / "out").exists()


ORO_INSTALL = Path(__import__("os").environ.get("OROCOS_INSTALL", Path.home() / "orocos" / "install"))


@pytest.mark.orocos_toolchain
@pytest.mark.skipif(not (ORO_INSTALL / "bin" / "deployer").exists(),
                    reason=f"no Orocos toolchain in {ORO_INSTALL}: build it with toolchains/orocos/build.sh")
@pytest.mark.parametrize("config", ["map-vfh-hall", "marker-dwa-pick"])
def test_a_configured_orocos_package_builds_and_deploys(config: str, tmp_path: Path) -> None:
    """The variant's package builds against the fixture's atomic code and deploys (every component
    Running, oro_deploy_verify of toolchains/orocos/env.sh)."""
    import subprocess

    out = tmp_path / "researchcamp"  # named like the package (see tests/test_orocos_deploy.py)
    generate(CAMP / "model.xmi", out, "orocos", features=CONFIGS / f"{config}.xml")
    env_sh = ROOT / "toolchains" / "orocos" / "env.sh"
    script = (f"source {env_sh} >/dev/null && oro_build_pkg {out} && oro_add_prefix {out}/install && "
              f"oro_verdict oro_deploy_verify {out}/deploy/researchcamp.xml 2")
    run = subprocess.run(["bash", "-c", script], cwd=tmp_path, capture_output=True, text=True, timeout=1800,
                         env=dict(__import__("os").environ, OROCOS_INSTALL=str(ORO_INSTALL)))
    assert run.returncode == 0 and "oro_verdict: OK" in run.stdout, run.stdout[-4000:] + run.stderr[-2000:]


def test_import_shows_the_configured_pim(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = _cli(capsys, ["import", str(CAMP / "model.xmi"), "--no-bind", "-o", str(tmp_path / "pim.xml"),
                                 "--features", str(CONFIGS / "map-vfh-hall.xml")])
    assert code == 0 and "PIM written" in out
    assert (tmp_path / "pim.xml").read_text(encoding="utf-8") == \
        (CAMP / "expected" / "map-vfh-hall" / "configure.xml").read_text(encoding="utf-8")
