"""Study throughput: a 24-run study (grid-rain: 3 rain speeds x 8 seeds, 600 s each) on a local Dask
cluster with 1 and with 2 worker processes. Prints runs per minute for each and the ratio.

    .venv/bin/python bench/study.py [--end 600] [--seeds 8]
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

from sbsim import study

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end", type=float, default=600.0, help="simulated seconds per run (default 600)")
    parser.add_argument("--seeds", type=int, default=8, help="seeds per rain speed (default 8: 24 runs)")
    args = parser.parse_args()

    rates = {}
    for workers in (1, 2):
        out = Path(tempfile.mkdtemp(prefix=f"sbsim-study-{workers}w-"))
        spec = study.StudySpec.from_dict(
            {
                "sumocfg": "stories/grid-rain/grid-rain.sumocfg",
                "story": "stories/grid-rain/story.py",
                "seeds": {"first": 1, "count": args.seeds},
                "end": args.end,
                "args": ["--threads", "1"],  # one core per run: the workers are the parallelism
                "parameters": {"rain_speed": [5, 10, 15]},
                "outputs": {"directory": str(out)},
            },
            base=ROOT,
        )
        started = time.monotonic()
        result = study.run(spec, workers=workers, progress=False)
        wall = time.monotonic() - started
        assert not result.failed, result.failed
        rates[workers] = 60.0 * len(result.rows) / wall
        print(f"{workers} worker(s): {len(result.rows)} runs in {wall:.1f} s = {rates[workers]:.1f} runs/min")
        shutil.rmtree(out)
    print(f"2 workers / 1 worker: {rates[2] / rates[1]:.2f}x")


if __name__ == "__main__":
    main()
