"""The older name of :mod:`sbsim.report` (``python -m storyboard.report`` works as ``python -m sbsim.report``):
kept so that commands and code written against it still work. New code imports :mod:`sbsim.report`."""

from sbsim.report import *  # noqa: F403 -- the whole public API, under the older name
from sbsim.report import main

if __name__ == "__main__":
    raise SystemExit(main())
