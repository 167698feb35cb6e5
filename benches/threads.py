#!/usr/bin/env python3
"""`zsim run` on two threads against one, in alternating pairs.

Each pair runs `zsim run SCENE --format none --threads 1`, then the same with
`--threads 2`, and reads the rasterized time each prints (as
`benches/alternate.py` reads it); prints each side's median and the median of
the pairs' ratios two/one, with their least and greatest.

    python3 benches/threads.py target/release/zsim r20k.json 21
"""

import statistics
import sys

from alternate import timed


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    zsim, scene, pairs = sys.argv[1], sys.argv[2], int(sys.argv[3])
    one, two, ratios = [], [], []
    for _ in range(pairs):
        one.append(timed(zsim, [scene, "--threads", "1"]))
        two.append(timed(zsim, [scene, "--threads", "2"]))
        ratios.append(two[-1] / one[-1])
    print(f"one thread: median {statistics.median(one):.2f} ms; two: median {statistics.median(two):.2f} ms; "
          f"two/one: median {statistics.median(ratios):.3f} ({min(ratios):.3f} … {max(ratios):.3f}), {pairs} pairs")


if __name__ == "__main__":
    main()
