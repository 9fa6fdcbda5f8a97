"""sbsim's host tools: what runs around the ``sbsim`` program, in a plain Python.

Story scripts import :mod:`storyboard` (the story API, which exists only inside a run). Everything
else is here, one job a module:

* :mod:`sbsim.runner`: run the program (and find it, and its C++ SDK);
* :mod:`sbsim.events`, :mod:`sbsim.summary`, :mod:`sbsim.fcd`: read what a run writes (the event log,
  the ``--summary`` JSON, SUMO's FCD output);
* :mod:`sbsim.report`: one run's stories as figures and an HTML page (``python -m sbsim.report``);
* :mod:`sbsim.study`: one story over parameter values x seeds on Dask (``python -m sbsim.study``);
* :mod:`sbsim.scenarios`: generated SUMO scenarios for tests and benchmarks (``tools/make_grid.py``);
* :mod:`sbsim.sumo`: the SUMO installation these use.
"""

from __future__ import annotations

__version__ = "0.1.0"
