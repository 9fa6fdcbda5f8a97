"""The older name of :mod:`sbsim.runner` (run the program, read its outputs): kept so that code written
against ``storyboard.runner`` still works. New code imports :mod:`sbsim.runner`."""

from sbsim.runner import *  # noqa: F403 -- the whole public API, under the older name
from sbsim.runner import main

if __name__ == "__main__":
    raise SystemExit(main())
