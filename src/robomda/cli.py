"""The ``robomda`` command line: a thin layer over :mod:`robomda.api`."""

from __future__ import annotations

import argparse
import itertools
import os
import re
import signal
import sys
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import TYPE_CHECKING

from robomda import __version__
from robomda.diagnostics import EXIT_FINDINGS, EXIT_INPUT, EXIT_OK, Diagnostic, RobomdaError, as_error, format_all
from robomda.formats import FORMATS, render
from robomda.resources import available_targets as targets

if TYPE_CHECKING:
    from robomda.batch import BatchReport
    from robomda.output import Drift

# robomda.api (the engine, schemas and rules), robomda.batch and
# robomda.output are imported by the commands that use them: `--version`
# and `--help` stay a blink.

__all__ = ["main"]

EXIT_SIGINT = 130  # 128 + SIGINT, as shells report it
EXIT_SIGTERM = 143  # 128 + SIGTERM

_EXIT_CODES = """exit codes:
  0  success (warnings may have been reported)
  1  the model has errors (each reported as FILE:LINE:COL: error: [CODE] ...); generate --check / --diff:
     OUT is not what would be generated
  2  usage error, or input that cannot be read (missing, not XML, not UML XMI)
  3  internal error in robomda (please report it with the model)
  130 / 143  interrupted by SIGINT (Ctrl-C) / SIGTERM: no output folder is half-written"""


def _year(text: str) -> str:
    """--copyright-year: four digits."""
    if not re.fullmatch(r"[0-9]{4}", text):
        raise argparse.ArgumentTypeError(f"not a year: {text!r} (four digits, e.g. 2026)")
    return text


def _package(args: argparse.Namespace) -> tuple[str, str, str, str]:
    """What the package options say: version, maintainer, license, copyright year (PackageInfo's fields)."""
    year = args.copyright_year
    if year is None:
        epoch = os.environ.get("SOURCE_DATE_EPOCH", "")
        stamp = datetime.fromtimestamp(int(epoch), timezone.utc) if epoch.isdigit() else datetime.now(timezone.utc)
        year = f"{stamp.year:04d}"
    return (args.package_version, args.maintainer, args.license, year)


def _package_options(parser: argparse.ArgumentParser) -> None:
    """The options of what a package is made from and named: generate and watch share them."""
    parser.add_argument("--maintainer", default="", metavar="'NAME <E-MAIL>'",
                        help="the package maintainer written in package.xml")
    parser.add_argument("--license", default="", metavar="LICENSE", help="the package license (e.g. Apache-2.0)")
    parser.add_argument("--package-version", default="", metavar="X.Y.Z", help="the package version (default 0.0.0)")
    parser.add_argument("--copyright-year", default=None, metavar="YYYY", type=_year,
                        help="the year of the copyright notices written with --maintainer (default: the year of "
                             "SOURCE_DATE_EPOCH when set, else this year)")
    parser.add_argument("-t", "--target", default=None, choices=targets(),
                        help="middleware target (default: the one the model deploys on; Orocos if it deploys on none, "
                             "ROS 2 if it deploys on none and runs managed nodes)")
    parser.add_argument("--package-name", default="", metavar="NAME",
                        help="package / CMake project name (default: derived from the model name)")
    parser.add_argument("--type-map", type=Path, metavar="FILE",
                        help="ROS targets: your message type map (format of xslt/m2m/ros/types.xml); its entries win")
    parser.add_argument("--model-path", type=Path, action="append", default=[], metavar="DIR",
                        help="a folder of model files your model references (libraries kept elsewhere); "
                             "repeat for several. Without it only files in the model's project (the nearest "
                             "folder above it with a .project, .git, .hg or .svn; else the model's own folder) "
                             "and the other projects of its workspace are read")


def _check_options(parser: argparse.ArgumentParser) -> None:
    """generate --check / --diff: compare OUT with what would be written, write nothing (as black does)."""
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if OUT is not exactly what would be generated, listing the "
                             "files that would be added, changed or removed (on stderr)")
    parser.add_argument("--diff", action="store_true",
                        help="write nothing; print a unified diff of each file that would change on stdout "
                             "(implies --check's exit code)")


def _files(count: int) -> str:
    return f"{count} file" + ("" if count == 1 else "s")


def _show_drift(out: Path, drift: Drift, label: str, diff: bool) -> int:
    """Report a check-mode comparison: the listing on stderr, the diff on stdout; the exit code."""
    if diff:
        sys.stdout.write(drift.diff())
    if not drift:
        print(f"robomda: {label} in {out} is up to date", file=sys.stderr)
        return EXIT_OK
    print(f"robomda: {label} in {out} would change ({_files(len(drift.lines()))}):", file=sys.stderr)
    for line in drift.lines():
        print(f"  {line}", file=sys.stderr)
    return EXIT_FINDINGS


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="robomda",
        description="Generate robot middleware code and deployment files from UML XMI models.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"robomda {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    gen = sub.add_parser(
        "generate", help="generate a middleware package from an XMI model",
        description="Run the target's chain (import, bind, PSM, text) on MODEL and write the package into OUT. "
                    "Nothing is written if any step fails; files you edit are never overwritten. "
                    "With a folder, every model under it is generated (in parallel, skipping unchanged ones) "
                    "and a summary is printed.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    gen.add_argument("model", type=Path, metavar="MODEL",
                     help="the UML XMI file (.xmi, .uml, .xml), or a folder: every UML model under it "
                          "(found by content) goes into its own folder under OUT")
    gen.add_argument("-o", "--output", type=Path, required=True, metavar="OUT", help="output folder (the package root)")
    gen.add_argument("-j", "--jobs", type=int, default=None, metavar="N",
                     help="folder mode: models generated in parallel (default: number of CPUs)")
    gen.add_argument("--force", action="store_true",
                     help="folder mode: regenerate models whose input and stylesheets did not change")
    _package_options(gen)
    gen.add_argument("--diagrams", action="store_true",
                     help="also write the model's component and deployment diagrams into OUT/diagrams/ "
                          "(PlantUML .puml, and .svg where PlantUML is installed; docs/diagrams.md)")
    gen.add_argument("--features", type=Path, metavar="CONFIG",
                     help="a FeatureIDE configuration of the product line MODEL is the template of: generate "
                          "that variant (docs/variability.md)")
    gen.add_argument("--all-configurations", type=Path, metavar="DIR",
                     help="generate one variant per configuration in DIR, each into OUT/<configuration name>, "
                          "in parallel, with a summary of the variants and the rules they fail")
    gen.add_argument("--save-stages", type=Path, metavar="DIR",
                     help="also write every intermediate model (PIM, PSM, file set) into DIR")
    gen.add_argument("--format", default="text", choices=FORMATS,
                     help="how to report diagnostics: text on stderr (default), or a json / sarif document "
                          "on stdout (one model only)")
    _check_options(gen)

    chk = sub.add_parser(
        "check", help="check an XMI model without generating anything",
        description="Run the model checks on MODEL: import and bind errors, the Schematron rules on the PIM "
                    "(schemas/pim/1/pim.sch) and on the target's PSM. Without --target, the model is checked "
                    "for every middleware its components are deployed on. Writes nothing.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    chk.add_argument("model", type=Path, metavar="MODEL", help="the UML XMI file")
    chk.add_argument("-t", "--target", default=None, choices=targets(),
                     help="check what generating for this target needs (default: the middlewares the model "
                          "deploys on)")
    chk.add_argument("--format", default="text", choices=FORMATS,
                     help="text on stderr (default), or a json / sarif document on stdout")
    chk.add_argument("--package-name", default="", metavar="NAME", help="as for generate")
    chk.add_argument("--features", type=Path, metavar="CONFIG", help="as for generate")
    chk.add_argument("--type-map", type=Path, metavar="FILE", help="as for generate")
    chk.add_argument("--model-path", type=Path, action="append", default=[], metavar="DIR", help="as for generate")
    chk.add_argument("--replace", action="append", default=[], metavar="OLD=NEW",
                     help="also check that component NEW may take the place of component OLD (seed 004: same "
                          "outputs, no extra inputs, OLD's properties, a compatible period; docs/substitution.md); "
                          "repeatable. Every «Alternative» of the model is checked anyway")

    wat = sub.add_parser(
        "watch", help="regenerate packages on each save of their models",
        description="Generate each MODEL into OUT (one model) or into OUT/<its path below the folder that holds "
                    "them all>, then again on each save of the model or of a file it reads (the model files it "
                    "references, the URDF files it names, the type map), with one line of result per run. "
                    "Stylesheets stay compiled between runs. A failed run writes nothing; the next save "
                    "retries. Ctrl-C stops.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    wat.add_argument("models", type=Path, nargs="+", metavar="MODEL", help="the UML XMI files to watch")
    wat.add_argument("-o", "--output", type=Path, required=True, metavar="OUT", help="output folder")
    _package_options(wat)
    wat.add_argument("--interval", type=float, default=0.25, metavar="SECONDS",
                     help="how often the files are checked (default 0.25)")
    wat.add_argument("--polls", type=int, default=None, metavar="N",
                     help="stop after N checks (scripts and tests; default: until Ctrl-C), exit code that of "
                          "each model's latest run, the worst")

    _diagram_parser(sub)
    _features_parser(sub)

    imp = sub.add_parser(
        "import", help="write the platform-independent model (PIM) of an XMI model",
        description="Import MODEL into robomda's PIM (validated against schemas/pim/1/pim.xsd) and write it, "
                    "so you can see what robomda understood of your model.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    imp.add_argument("model", type=Path, metavar="MODEL", help="the UML XMI file")
    imp.add_argument("-o", "--output", type=Path, required=True, metavar="OUT",
                     help="a file ending in .xml, or a folder that receives MODEL-NAME.pim.xml")
    imp.add_argument("--model-path", type=Path, action="append", default=[], metavar="DIR", help="as for generate")
    imp.add_argument("--features", type=Path, metavar="CONFIG",
                     help="show the template model configured for this FeatureIDE configuration")
    imp.add_argument("--no-bind", action="store_true",
                     help="stop after the import proper (skip the platform binding)")
    return parser


def _diagram_parser(sub: argparse._SubParsersAction) -> None:
    dia = sub.add_parser(
        "diagram", help="draw an XMI model: its component and deployment diagrams (PlantUML, SVG)",
        description="Write MODEL's component view (components, ports, connectors, composites with their "
                    "parts and delegations) and deployment view (hosts, buses, processes and their middleware, "
                    "threads, component sets, instances) into OUT/diagrams/ as PlantUML (.puml), and as SVG "
                    "where PlantUML is installed (plantuml on PATH, or ROBOMDA_PLANTUML). Nothing else is "
                    "written; nothing at all if the model has errors.",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    dia.add_argument("model", type=Path, metavar="MODEL", help="the UML XMI file")
    dia.add_argument("-o", "--output", type=Path, required=True, metavar="OUT", help="output folder")
    dia.add_argument("--model-path", type=Path, action="append", default=[], metavar="DIR", help="as for generate")
    dia.add_argument("--format", default="text", choices=FORMATS,
                     help="text on stderr (default), or a json / sarif document on stdout")


def _features_parser(sub: argparse._SubParsersAction) -> None:
    fea = sub.add_parser(
        "features", help="analyse a FeatureIDE feature model: void, dead features, products (needs robomda[analysis])",
        description="Analyse the FeatureIDE feature model MODEL with flamapy (the optional extra: "
                    "pip install 'robomda[analysis]'): a void model (error), dead and false-optional features, "
                    "the number of products and, with --resolution, each presence condition that no valid "
                    "configuration satisfies or that every one does. Writes nothing (docs/variability.md).",
        epilog=_EXIT_CODES, formatter_class=argparse.RawDescriptionHelpFormatter)
    fea.add_argument("model", type=Path, metavar="MODEL", help="the feature model (FeatureIDE model.xml)")
    fea.add_argument("--resolution", type=Path, metavar="FILE",
                     help="a resolution model whose presence conditions are checked against MODEL")
    fea.add_argument("--format", default="text", choices=FORMATS,
                     help="text on stderr (default), or a json / sarif document on stdout")


def _features(args: argparse.Namespace) -> int:
    from robomda.analysis import analyse

    done = analyse(args.model, args.resolution)
    code = EXIT_FINDINGS if any(d.severity == "error" for d in done.diagnostics) else EXIT_OK
    _report(args.format, done.diagnostics, code)
    if args.format == "text":
        print(f"robomda: {args.model}: {done.products} products, "
              + ", ".join(f"{sum(d.code == c for d in done.diagnostics)} {what}" for c, what in (
                  ("VAR042", "dead"), ("VAR043", "false-optional"), ("VAR045", "never-present"))))
    return code


def _diagram(args: argparse.Namespace, fmt: str) -> int:
    from robomda.api import diagram

    done = diagram(args.model, args.output, model_path=args.model_path)
    _report(fmt, done.warnings, EXIT_OK)
    report = done.report
    if report is not None:
        drawn = sorted(p for p in report.written + report.unchanged if p.startswith("diagrams/"))
        print(f"robomda: diagrams in {args.output}: {', '.join(drawn)} ({len(report.written)} written, "
              f"{len(report.unchanged)} unchanged)", file=sys.stdout if fmt == "text" else sys.stderr)
    return EXIT_OK


def _write_model_file(dest: Path, text: str) -> None:
    """Write a stage model, replacing only a file that is itself a robomda model."""
    from lxml import etree

    from robomda.output import atomic_write

    if dest.exists():
        try:
            namespace = etree.QName(etree.parse(str(dest)).getroot()).namespace or ""
        except (etree.XMLSyntaxError, OSError):
            namespace = ""
        if not namespace.startswith("urn:robomda:"):
            raise RobomdaError([Diagnostic("error", "OUT001", f"refusing to overwrite {dest}: it is not a model "
                                           "robomda wrote; choose another output", file=str(dest))], EXIT_INPUT)
    atomic_write(dest, text.encode("utf-8"))


def _pim_destination(model: Path, out: Path) -> Path:
    if out.suffix.lower() == ".xml" and not out.is_dir():
        return out
    return out / f"{model.stem.split('.')[0]}.pim.xml"


def _batch(args: argparse.Namespace) -> int:
    from robomda.batch import ProgressBar, run_batch

    if args.save_stages or args.diagrams:
        print(f"robomda: {'--save-stages' if args.save_stages else '--diagrams'} applies to one model, not to a "
              "folder", file=sys.stderr)
        return EXIT_INPUT
    if args.jobs is not None and args.jobs < 1:
        print("robomda: -j needs a positive number", file=sys.stderr)
        return EXIT_INPUT
    check = "diff" if args.diff else "check" if args.check else ""
    report = run_batch(args.model, args.output, args.target, package_name=args.package_name, jobs=args.jobs,
                       package=_package(args),
                       force=args.force, type_map=args.type_map, model_path=args.model_path,
                       progress=ProgressBar(), check=check)
    for result in report.results:
        for line in result.diagnostics:
            print(line, file=sys.stderr)
        if result.drift:
            print(f"robomda: {result.model}: its output would change ({_files(len(result.drift))}):", file=sys.stderr)
            for line in result.drift:
                print(f"  {line}", file=sys.stderr)
        sys.stdout.write(result.diff)
    _batch_table(report, bool(check))
    if not report.results:
        print(f"robomda: no UML model found under {args.model}", file=sys.stderr)
        return EXIT_INPUT
    return report.exit_code


def _variants(args: argparse.Namespace) -> int:
    """generate --all-configurations: every variant, then which fail which rule."""
    import re

    from robomda.batch import ProgressBar, run_variants

    report = run_variants(args.model, args.all_configurations, args.output, args.target, jobs=args.jobs,
                          force=args.force, package=_package(args),
                          progress=ProgressBar())
    for result in report.results:
        for line in result.diagnostics:
            print(line, file=sys.stderr)
    print(f"{'configuration':<24} {'status':<8} {'files':>5}  rules failed", file=sys.stdout)
    for r in report.results:
        codes = sorted({m for line in r.diagnostics for m in re.findall(r" error: \[(\w+)\]", line)})
        print(f"{r.model:<24} {r.status:<8} {r.files_written:>5}  {', '.join(codes) or '-'}", file=sys.stdout)
    print(f"robomda: {len(report.results)} configurations: {report.count('ok')} ok, {report.count('skipped')} "
          f"unchanged, {report.count('failed')} failed", file=sys.stdout)
    if not report.results:
        print(f"robomda: no configuration in {args.all_configurations}", file=sys.stderr)
        return EXIT_INPUT
    return report.exit_code


def _batch_table(report: BatchReport, check: bool) -> None:
    """The summary of a batch: one row per model, then the counts; in check mode (on stderr, stdout holds
    the diffs) the files column counts the files that would change."""
    stream = sys.stderr if check else sys.stdout
    files = sum(r.files_written for r in report.results)
    width = max([len(r.model) for r in report.results] + [5])
    print(f"{'model':<{width}}  {'status':<8} {'files':>5} {'seconds':>8}", file=stream)
    for r in report.results:
        print(f"{r.model:<{width}}  {r.status:<8} {r.files_written:>5} {r.seconds:>8.2f}", file=stream)
    libraries = f", {report.count('library')} libraries" if report.count("library") else ""
    if check:
        print(f"robomda: {len(report.results)} models: {report.count('ok')} up to date, {report.count('drifted')} "
              f"drifted, {report.count('failed')} failed{libraries}; {_files(files)} would change "
              f"(checked in {report.seconds:.1f} s)", file=stream)
        return
    print(f"robomda: {len(report.results)} models: {report.count('ok')} ok, {report.count('skipped')} unchanged, "
          f"{report.count('failed')} failed{libraries}; {files} files written in {report.seconds:.1f} s", file=stream)


def _report(fmt: str, diagnostics: list[Diagnostic], exit_code: int) -> None:
    """Diagnostics as text on stderr, or as one json / sarif document on stdout."""
    if fmt == "text":
        for line in format_all(diagnostics):
            print(line, file=sys.stderr)
    else:
        sys.stdout.write(render(fmt, diagnostics, exit_code))


def _check(args: argparse.Namespace) -> int:
    from robomda.api import check

    done = check(args.model, args.target, package_name=args.package_name, type_map=args.type_map,
                 model_path=args.model_path, features=args.features, replace=args.replace)
    _report(args.format, done.diagnostics, done.exit_code)
    summary = (f"robomda: {args.model}: {done.count('error')} errors, {done.count('warning')} warnings, "
               f"{done.count('info')} notes (checked for {', '.join(done.targets)}; rules: "
               f"{', '.join(done.rule_sets) or 'none, the import or bind stopped first'})")
    print(summary, file=sys.stdout if args.format == "text" else sys.stderr)
    return done.exit_code


def _watch(args: argparse.Namespace) -> int:
    from robomda.api import PackageInfo
    from robomda.watcher import Regeneration, watch

    if args.polls is not None and args.polls < 1 or args.interval < 0:
        print("robomda: --polls needs a positive number and --interval a non-negative one", file=sys.stderr)
        return EXIT_INPUT
    polls = itertools.count(1)
    shown: dict[Path, list[str]] = {}

    def show(result: Regeneration) -> None:
        # the diagnostics when they differ from the model's last ones; always the one line of result
        lines = format_all(result.diagnostics)
        if lines != shown.get(result.model):
            for line in lines:
                print(line, file=sys.stderr)
            shown[result.model] = lines
        print(f"{time.strftime('%H:%M:%S')} {result.line()}", flush=True)

    print(f"robomda: watching {len(args.models)} model(s) every {args.interval:g} s; Ctrl-C stops",
          file=sys.stderr, flush=True)
    return watch(args.models, args.output, interval=args.interval, on_result=show,
                 stop=(lambda: next(polls) >= args.polls) if args.polls else None,
                 target=args.target, package_name=args.package_name, type_map=args.type_map,
                 model_path=args.model_path,
                 package=PackageInfo(*_package(args)))


class Terminated(BaseException):
    """SIGTERM, raised where Python next runs, as KeyboardInterrupt is for SIGINT."""


def _on_sigterm(signum: int, frame: object) -> None:
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    fmt = getattr(args, "format", "text")
    previous = signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        return _main(args, fmt)
    except (KeyboardInterrupt, Terminated) as exc:
        # the output folder is the old package or the new one (output.py); say so in one line
        name, code = ("SIGINT", EXIT_SIGINT) if isinstance(exc, KeyboardInterrupt) else ("SIGTERM", EXIT_SIGTERM)
        print(f"robomda: interrupted ({name}); every output folder is as it was before or completely "
              "written, never half of each", file=sys.stderr)
        return code
    finally:
        signal.signal(signal.SIGTERM, previous)


def _main(args: argparse.Namespace, fmt: str) -> int:
    try:
        from robomda.api import PackageInfo, generate, import_model

        if args.command == "generate" and args.all_configurations is not None:
            return _variants(args)
        if args.command == "generate" and args.model.is_dir():
            if fmt != "text":
                print("robomda: --format json / sarif applies to one model, not to a folder", file=sys.stderr)
                return EXIT_INPUT
            return _batch(args)
        if args.command == "check":
            return _check(args)
        if args.command == "watch":
            return _watch(args)
        if args.command == "diagram":
            return _diagram(args, fmt)
        if args.command == "features":
            return _features(args)
        if args.command == "generate":
            checking = args.check or args.diff
            if checking and args.save_stages or args.diff and fmt != "text":
                print("robomda: --check and --diff write nothing (leave out --save-stages), and --diff prints on "
                      "stdout, as json / sarif do: use one of them", file=sys.stderr)
                return EXIT_INPUT
            done = generate(args.model, args.output, args.target, package_name=args.package_name,
                            type_map=args.type_map, model_path=args.model_path, diagrams=args.diagrams, check=checking,
                            features=args.features,
                            package=PackageInfo(*_package(args)))
            _report(fmt, done.warnings, EXIT_OK)
            if checking:
                from robomda.output import Drift

                return _show_drift(args.output, done.drift or Drift(), f"{done.target} package", args.diff)
            if args.save_stages:
                for name, text in done.stages.items():
                    _write_model_file(args.save_stages / f"{name}.xml", text)
            report = done.report
            if report is not None:
                print(f"robomda: {done.target} package in {args.output}: {len(report.written)} written, "
                      f"{len(report.unchanged)} unchanged, {len(report.kept_user)} user files kept"
                      + (f", fresh copies beside them: {', '.join(report.fresh_copies)}" if report.fresh_copies else "")
                      + (f", removed stale: {', '.join(report.removed)}" if report.removed else "")
                      + (f"; kept edited stale files: {', '.join(report.kept_stale)}" if report.kept_stale else ""),
                      file=sys.stdout if fmt == "text" else sys.stderr)
        else:
            found: list[Diagnostic] = []
            text = import_model(args.model, bind=not args.no_bind, warnings=found, model_path=args.model_path,
                                features=args.features)
            _report("text", found, EXIT_OK)
            dest = _pim_destination(args.model, args.output)
            _write_model_file(dest, text)
            print(f"robomda: PIM written to {dest}")
    except Exception as exc:  # noqa: BLE001 - the last guard: a bug is reported without a traceback
        failed = as_error(exc, str(getattr(args, "model", "")))
        _report(fmt, failed.diagnostics, failed.exit_code)
        return failed.exit_code
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
