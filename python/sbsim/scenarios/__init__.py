"""Generated SUMO scenarios: small, seeded and byte-for-byte reproducible, for tests and benchmarks.

:mod:`sbsim.scenarios.grid` builds grid networks with random trips or constant-load loops
(``tools/make_grid.py`` is its command line)."""
