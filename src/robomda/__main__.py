"""``python -m robomda``."""

import sys

from robomda.cli import main

sys.exit(main())
