"""``python -m symimpact.cli``: the ``symimpact`` command."""

import sys

from . import main

sys.exit(main())
