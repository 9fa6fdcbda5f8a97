"""``python -m sbsim.report``: see :mod:`sbsim.report.cli`."""

import sys

from sbsim.report.cli import main

sys.exit(main())
