"""Values written with units (issue 30 item 10): xslt/common/units.xsl, and bind reading every
value with a dimension through it (periods, host memory, bus bandwidth).

Property tests (hypothesis) run f:quantity itself under SaxonC: a non-negative number with any
accepted unit gives the number times the unit's factor in the canonical unit (seconds, MiB,
Mbit/s; a frequency gives its period); the canonical value written back, bare or with the
canonical unit, reads as itself; a value in the canonical unit gives the double its decimal
literal gives; anything else is refused. Then, through the whole import on models built by
tests/nodeploy_models.py in the Eclipse and EA dialects: '8GB', '512 MiB', '1 Gbit/s', '100 Mbps',
'3 ms', '100 Hz' land in the PIM converted, and a bad form is a located BND010 that shows the
accepted form.
"""

from __future__ import annotations

import os
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest
from lxml import etree

hypothesis = pytest.importorskip("hypothesis", reason="hypothesis not installed (pip install -e '.[test]')")
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from saxonche import PySaxonProcessor  # noqa: E402

from nodeploy_models import write  # noqa: E402
from robomda.api import import_model  # noqa: E402
from robomda.diagnostics import RobomdaError  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
UNITS = ROOT / "xslt" / "common" / "units.xsl"
EXAMPLES = int(os.environ.get("ROBOMDA_HYPOTHESIS_EXAMPLES", "100"))
NS = {"p": "urn:robomda:pim:1"}

# the accepted units, as docs/profile.md lists them: factor to the canonical unit (exact)
MiB = 2 ** 20
TIME = {"s": 1, "sec": 1, "ms": Fraction(1, 1000), "us": Fraction(1, 10 ** 6), "\u00b5s": Fraction(1, 10 ** 6),
        "\u03bcs": Fraction(1, 10 ** 6), "ns": Fraction(1, 10 ** 9), "min": 60}
FREQUENCY = {"Hz": 1, "kHz": 1000, "KHz": 1000}
MEMORY = {"B": Fraction(1, MiB), "kB": Fraction(1000, MiB), "KB": Fraction(1000, MiB), "MB": Fraction(10 ** 6, MiB),
          "GB": Fraction(10 ** 9, MiB), "TB": Fraction(10 ** 12, MiB),
          "KiB": Fraction(1, 1024), "MiB": 1, "GiB": 1024, "TiB": 1024 ** 2}
_BITS = {"": Fraction(1, 10 ** 6), "k": Fraction(1, 1000), "K": Fraction(1, 1000), "M": 1, "G": 1000, "T": 10 ** 6}
BANDWIDTH = {**{p + u: f for p, f in _BITS.items() for u in ("bit/s", "bps", "b/s")},
             **{p + "B/s": 8 * f for p, f in _BITS.items()},
             "KiB/s": Fraction(8 * 1024, 10 ** 6), "MiB/s": Fraction(8 * MiB, 10 ** 6), "GiB/s": Fraction(8 * 1024 * MiB, 10 ** 6)}
DIMENSIONS = {"period": {**TIME, **FREQUENCY}, "time": TIME, "memory": MEMORY, "bandwidth": BANDWIDTH}
CANONICAL = {"period": "s", "time": "s", "memory": "MiB", "bandwidth": "Mbit/s"}

PROBE = f"""<xsl:stylesheet version="3.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:f="urn:robomda:xslt:function" exclude-result-prefixes="#all">
  <xsl:include href="{UNITS.as_uri()}"/>
  <xsl:output method="text"/>
  <xsl:template match="/q"><xsl:value-of select="(f:quantity(string(.), string(@d)) ! string(.), 'refused')[1]"/></xsl:template>
</xsl:stylesheet>"""


@pytest.fixture(scope="module")
def quantity():
    proc = PySaxonProcessor(license=False)
    executable = proc.new_xslt30_processor().compile_stylesheet(stylesheet_text=PROBE)

    def run(text: str, dimension: str) -> str:
        q = etree.Element("q", d=dimension)
        q.text = text
        return executable.transform_to_string(xdm_node=proc.parse_xml(xml_text=etree.tostring(q, encoding="unicode")))

    return run


numbers = st.decimals(min_value=0, max_value=10 ** 6, places=4, allow_nan=False, allow_infinity=False)
spaces = st.sampled_from(["", " ", "  "])


def _unit_cases():
    return st.sampled_from(sorted(DIMENSIONS)).flatmap(
        lambda d: st.tuples(st.just(d), st.sampled_from(sorted(DIMENSIONS[d]))))


def _expected(number: Decimal, dimension: str, unit: str) -> Fraction | None:
    value = Fraction(number) * Fraction(DIMENSIONS[dimension][unit])
    if unit in FREQUENCY:
        return None if value == 0 else 1 / value
    return value


@settings(max_examples=EXAMPLES, derandomize=True, deadline=None)
@given(number=numbers, case=_unit_cases(), space=spaces)
def test_a_value_with_a_unit_is_the_number_times_the_unit(quantity, number: Decimal, case, space: str) -> None:
    dimension, unit = case
    got = quantity(f"{number}{space}{unit}", dimension)
    want = _expected(number, dimension, unit)
    if want is None:  # 0 Hz: no period
        assert got == "refused"
        return
    assert float(got) == pytest.approx(float(want), rel=1e-12, abs=0)
    # the canonical value reads back as itself, bare and with the canonical unit
    assert quantity(got, dimension) == got
    assert quantity(f"{got} {CANONICAL[dimension]}", dimension) == got


@settings(max_examples=EXAMPLES, derandomize=True, deadline=None)
@given(number=numbers, dimension=st.sampled_from(sorted(DIMENSIONS)), space=spaces)
def test_a_value_in_the_canonical_unit_is_its_decimal_literal(quantity, number: Decimal, dimension: str,
                                                              space: str) -> None:
    literal = float(str(number))
    assert float(quantity(str(number), dimension)) == literal
    assert float(quantity(f"{number}{space}{CANONICAL[dimension]}", dimension)) == literal


_ACCEPTED = {u for units in DIMENSIONS.values() for u in units}


@settings(max_examples=EXAMPLES, derandomize=True, deadline=None)
@given(number=numbers, dimension=st.sampled_from(sorted(DIMENSIONS)),
       unit=st.text(alphabet="bBgGkKmMiIsSzZhHpP/ u\u00b5", min_size=1, max_size=6))
def test_an_unknown_unit_is_refused(quantity, number: Decimal, dimension: str, unit: str) -> None:
    if unit.strip() in DIMENSIONS[dimension] or unit.strip() in ("", "f", "F", "d", "D"):
        return
    assert quantity(f"{number} {unit}", dimension) == "refused"


@pytest.mark.parametrize("text", ["-1", "-3 ms", "INF", "NaN", "8gb", "8 G", "8 M", "1 Gbit", "three ms", "", "ms",
                                  "1e400x", "0 Hz", "1,5 s"])
@pytest.mark.parametrize("dimension", ["period", "memory", "bandwidth"])
def test_bad_forms_are_refused(quantity, text: str, dimension: str) -> None:
    assert quantity(text, dimension) == "refused"


@pytest.mark.parametrize(("text", "dimension", "want"), [
    ("8GB", "memory", "7629.39453125"), ("512 MiB", "memory", "512"), ("8 GiB", "memory", "8192"),
    ("1 Gbit/s", "bandwidth", "1000"), ("100 Mbps", "bandwidth", "100"), ("125 MB/s", "bandwidth", "1000"),
    ("3 ms", "period", "0.003"), ("0.01 s", "period", "0.01"), ("100 Hz", "period", "0.01"), ("0.01f", "period", "0.01")])
def test_the_values_people_write(quantity, text: str, dimension: str, want: str) -> None:
    assert quantity(text, dimension) == want


# ------------------------------------------------------------------ through the import (bind)
@pytest.mark.parametrize("dialect", ["eclipse", "ea"])
@pytest.mark.parametrize(("memory", "bandwidth", "period", "mib", "mbits", "seconds"), [
    ("8GB", "1 Gbit/s", "3 ms", "7629", "1000", "0.003"),
    ("8 GiB", "100 Mbps", "100 Hz", "8192", "100", "0.01"),
    ("512 MiB", "1000", "0.01 s", "512", "1000", "0.01")])
def test_bind_reads_units_in_every_dimension(dialect: str, memory: str, bandwidth: str, period: str, mib: str,
                                             mbits: str, seconds: str, tmp_path: Path) -> None:
    model = write(tmp_path / f"units.{dialect}.xmi", dialect, node=True, environment="OROCOS", host_memory=memory,
                  bandwidth=bandwidth, period=period)
    pim = etree.fromstring(import_model(model).encode("utf-8"))
    assert pim.xpath("//p:binding/p:host[@name='robotPC']/@memory", namespaces=NS) == [mib]
    assert pim.xpath("//p:binding/p:link/@bandwidth", namespaces=NS) == [mbits]
    assert pim.xpath("//p:binding/p:instance[@name='wheels']/p:activity/@period", namespaces=NS) == [seconds]


@pytest.mark.parametrize("dialect", ["eclipse", "ea"])
@pytest.mark.parametrize(("option", "value", "app", "shown"), [
    ("host_memory", "8 G", "HostApp", "8GB = 8,000,000,000 bytes"),
    ("host_memory", "100 kB", "HostApp", "less than 1 MiB"),
    ("bandwidth", "1 Gbit", "BusApp", "Gbit/s"),
    ("period", "3 fortnights", "ActApp", "100 Hz = 0.01 s")])
def test_a_bad_value_is_refused_on_its_stereotype_with_the_accepted_form(dialect: str, option: str, value: str,
                                                                         app: str, shown: str, tmp_path: Path) -> None:
    model = write(tmp_path / f"bad.{dialect}.xmi", dialect, node=True, environment="OROCOS", **{option: value})
    with pytest.raises(RobomdaError) as info:
        import_model(model)
    [error] = info.value.diagnostics
    prefix = "EAID_" if dialect == "ea" else "_nd"
    assert (error.code, error.xmi_id) == ("BND010", prefix + app)
    assert f"'{value}'" in error.message and shown in error.message and error.line
