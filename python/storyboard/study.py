"""The older name of :mod:`sbsim.study` (``python -m storyboard.study`` works as ``python -m sbsim.study``):
kept so that commands and code written against it still work. New code imports :mod:`sbsim.study`."""

from sbsim.study import *  # noqa: F403 -- the whole public API, under the older name
from sbsim.study import main

if __name__ == "__main__":
    raise SystemExit(main())
