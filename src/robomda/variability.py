"""Product lines: find and check the files of a feature configuration (issue 32; docs/variability.md).

A configuration (FeatureIDE's ``configs/NAME.xml``) configures the feature
model ``model.xml`` of its FeatureIDE project: the configuration's folder, or
the folder above it. The resolution model ``resolution.xml`` lies beside the
feature model. This module finds the three, validates each against robomda's
schema (schemas/variability/1/) with located diagnostics, and gives the
pipeline their URIs; the configure stage (xslt/m2m/configure.xsl) does the
rest.
"""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from robomda.diagnostics import EXIT_FINDINGS, EXIT_INPUT, Diagnostic, RobomdaError
from robomda.resources import resource_root
from robomda.validate import schema_of

__all__ = ["feature_context", "product_line_files", "configurations", "schema_findings"]

_SCHEMAS = {"configuration": "featureide-configuration.xsd", "feature model": "featureide-model.xsd",
            "resolution": "resolution.xsd"}
_CODES = {"configuration": "VAR001", "feature model": "VAR002", "resolution": "VAR003"}


def product_line_files(config: Path) -> dict[str, Path]:
    """The configuration, its feature model and resolution model; VAR004 when one is missing."""
    if not config.is_file():
        raise RobomdaError([Diagnostic("error", "VAR004", f"no such configuration file: {config}",
                                       file=str(config))], EXIT_INPUT)
    for folder in (config.parent, config.parent.parent):
        if (folder / "model.xml").is_file():
            model = folder / "model.xml"
            break
    else:
        raise RobomdaError([Diagnostic("error", "VAR004", "no feature model (model.xml) in the configuration's "
                                       "folder or the folder above it", file=str(config))], EXIT_INPUT)
    resolution = model.parent / "resolution.xml"
    if not resolution.is_file():
        raise RobomdaError([Diagnostic("error", "VAR004", f"no resolution model {resolution} beside the "
                                       "feature model", file=str(model))], EXIT_INPUT)
    return {"configuration": config, "feature model": model, "resolution": resolution}


def schema_findings(kind: str, path: Path) -> list[Diagnostic]:
    """The located schema violations of ``path`` (empty when it is valid)."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    try:
        tree = etree.parse(str(path), parser)
    except etree.XMLSyntaxError as exc:
        line, column = exc.position if exc.position else (None, None)
        return [Diagnostic("error", "XML001", f"not well-formed XML: {exc.msg}", file=str(path), line=line,
                           column=column)]
    schema = schema_of(resource_root() / "schemas" / "variability" / "1" / _SCHEMAS[kind])
    if schema.validate(tree):
        return []
    return [Diagnostic("error", _CODES[kind], f"the {kind} breaks robomda's schema {_SCHEMAS[kind]}: {e.message}",
                       file=str(path), line=e.line, column=e.column or None) for e in schema.error_log]


def feature_context(config: Path | str | None) -> dict[str, str]:
    """The pipeline values for configuration ``config`` (all empty without one): refused with located
    diagnostics before anything runs when a file is missing or breaks its schema."""
    if config is None:
        return {"features": "", "feature-model": "", "resolution": ""}
    files = product_line_files(Path(config))
    found = [d for kind, path in files.items() for d in schema_findings(kind, path)]
    if found:
        raise RobomdaError(found, EXIT_INPUT if any(d.code == "XML001" for d in found) else EXIT_FINDINGS)
    uri = {kind: path.resolve().as_uri() for kind, path in files.items()}
    return {"features": uri["configuration"], "feature-model": uri["feature model"],
            "resolution": uri["resolution"]}


def configurations(folder: Path | str) -> list[Path]:
    """The configurations of a folder (``--all-configurations``): its ``*.xml`` files but the feature
    and resolution models, by name."""
    return sorted(p for p in Path(folder).glob("*.xml") if p.name not in ("model.xml", "resolution.xml"))
