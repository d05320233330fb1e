"""robomda: UML XMI to robot middleware code, by a chain of XSLT 3.0 stylesheets.

The public API is small: :func:`generate` (XMI to files for a target),
:func:`import_model` (XMI to the bound PIM), :func:`check`, :func:`diagram`
(the model's component and deployment diagrams), and
:class:`RobomdaError`, raised with diagnostics that point at the user's XMI
file and line. A process that calls them keeps every stylesheet, schema and
rule set compiled from one call to the next; :class:`Watcher` and
:func:`watch` regenerate packages on each save of their models
(``docs/api.md``).
"""

from __future__ import annotations

__all__ = ["generate", "diagram", "import_model", "check", "targets", "Watcher", "watch", "Diagnostic", "RobomdaError"]
__version__ = "0.1.0"

# The public names are imported on first use (PEP 562): `robomda --version`
# and `--help` need none of the engine, schema and rule machinery, and a
# user's `import robomda` pays for it only when it generates.
_LAZY = {"generate": "robomda.api", "diagram": "robomda.api", "import_model": "robomda.api", "check": "robomda.api", "targets": "robomda.api",
         "Watcher": "robomda.watcher", "watch": "robomda.watcher",
         "Diagnostic": "robomda.diagnostics", "RobomdaError": "robomda.diagnostics"}


def __getattr__(name: str) -> object:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'robomda' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value
