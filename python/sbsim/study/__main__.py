"""``python -m sbsim.study``: see :mod:`sbsim.study.cli`."""

import sys

from sbsim.study.cli import main

sys.exit(main())
