"""robomda: UML XMI to robot middleware code, by a chain of XSLT 3.0 stylesheets.

The public API is small: :func:`generate` (XMI to files for a target),
:func:`import_model` (XMI to the bound PIM) and :class:`RobomdaError`, raised
with diagnostics that point at the user's XMI file and line.
"""

from robomda.api import generate, import_model, targets
from robomda.diagnostics import Diagnostic, RobomdaError

__all__ = ["generate", "import_model", "targets", "Diagnostic", "RobomdaError"]
__version__ = "0.1.0"
