"""Suite-wide rules.

Under CI (environment variable CI set, as the CI runner does) a skipped test
is a failure: tests/run.sh installs every tool the real-tool tests need, so a
skip there means an install step is missing, which must not pass unnoticed.
On a developer's machine the same tests skip and say what is missing.

Two exceptions, for toolchains built from public sources that CI cannot
fetch: tests marked ``orocos_toolchain`` build and deploy generated packages
on a real Orocos RTT / OCL 2.10 toolchain
(toolchains/orocos/), and tests marked ``ros2_toolchain``
build and launch generated packages on a minimal ROS 2 Jazzy
(toolchains/ros2/), tests marked ``rtt_ros_toolchain`` run a mixed Orocos
<-> ROS 1 system on that Orocos toolchain with the rtt_ros_integration packages
of toolchains/orocos/build-ros.sh, and tests marked ``openrtm_toolchain`` build and run
generated packages on OpenRTM-aist 2.0 (toolchains/openrtm/). CI deselects them, and says so in the summary; developers
run them where the toolchain is installed.
"""

from __future__ import annotations

import os

import pytest

_CI = os.environ.get("CI", "").lower() not in ("", "0", "false", "no")


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "orocos_toolchain: needs a real Orocos RTT / OCL 2.10 toolchain "
                            "built by toolchains/orocos/build.sh (not in CI: it is built from fetched sources)")
    config.addinivalue_line("markers", "ros2_toolchain: needs a minimal ROS 2 Jazzy built by toolchains/ros2/build.sh "
                            "(not in CI: it is built from fetched sources)")
    config.addinivalue_line("markers", "rtt_ros_toolchain: needs the Orocos toolchain and the rtt_ros_integration "
                            "packages of toolchains/orocos/build-ros.sh with Debian's ROS 1 (not in CI: built from "
                            "fetched sources)")
    config.addinivalue_line("markers", "openrtm_toolchain: needs OpenRTM-aist 2.0 built by toolchains/openrtm/build.sh "
                            "(not in CI: it is built from fetched sources)")


_TOOLCHAIN_MARKERS = ("orocos_toolchain", "ros2_toolchain", "rtt_ros_toolchain", "openrtm_toolchain")


def _needs_toolchain(item: pytest.Item) -> bool:
    return any(item.get_closest_marker(m) is not None for m in _TOOLCHAIN_MARKERS)


# Module fixtures that build something costly once for all of a file's tests (every
# fixture's generated package, every diagram rendered; test_ros's catkin workspace is
# shared by the workers through a lock of its own): under
# pytest-xdist (tests/run.sh --dist loadgroup) their tests share one worker, so the
# fixture is built once, not once per worker.
_SHARED_FIXTURES = ("runs", "drawn", "built", "built_slow", "workspace", "mixed", "tmp_root")


@pytest.hookimpl(tryfirst=True)  # before xdist reads the groups
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        shared = [name for name in _SHARED_FIXTURES if name in getattr(item, "fixturenames", ())]
        if shared:
            item.add_marker(pytest.mark.xdist_group(f"{item.nodeid.split('::')[0]}:{shared[0]}"))
    if not _CI:
        return
    kept = [item for item in items if not _needs_toolchain(item)]
    dropped = [item for item in items if _needs_toolchain(item)]
    if dropped:
        config.hook.pytest_deselected(items=dropped)
        items[:] = kept


def pytest_report_header(config: pytest.Config) -> str | None:
    if _CI:
        return ("CI: skips fail; tests marked orocos_toolchain, ros2_toolchain, rtt_ros_toolchain or openrtm_toolchain are deselected "
                "(those toolchains cannot be fetched here)")
    return None


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]):
    outcome = yield
    report = outcome.get_result()
    if _CI and report.skipped:
        reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
        report.outcome = "failed"
        report.longrepr = f"skipped under CI, where every test must run: {reason}"
