#!/usr/bin/env python3
"""Two zsim builds (or two ways of running one) timed in alternating pairs.

Each pair runs A then B as whole processes, `run SCENE --format none` with the
options given, and reads the time each prints after "rasterized" (clearing the
buffers and drawing, as `zsim run` times it, in buffers made beforehand); prints each side's median and
the median of the pairs' ratios B/A, with their least and greatest. Run it
with A and B swapped too: on a shared machine the second of a pair is not
always as fast as the first.

    python3 benches/alternate.py A B PAIRS SCENE.json [OPTIONS…]
    python3 benches/alternate.py target/release/zsim /tmp/zsim-before 31 r20k.json --threads 1

A side may be `ENV=VALUE:PATH`, to run PATH with ENV set.
"""

import os
import re
import statistics
import subprocess
import sys


def timed(side, arguments):
    environment = dict(os.environ)
    if ":" in side and "=" in side.split(":", 1)[0]:
        setting, side = side.split(":", 1)
        name, value = setting.split("=", 1)
        environment[name] = value
    shown = subprocess.run([side, "run", *arguments, "--format", "none"], capture_output=True, text=True,
                           env=environment, check=True).stdout
    return float(re.search(r"rasterized ([\d.]+) ms", shown).group(1))


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    a, b, pairs, arguments = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    first, second, ratios = [], [], []
    for _ in range(pairs):
        first.append(timed(a, arguments))
        second.append(timed(b, arguments))
        ratios.append(second[-1] / first[-1])
    print(f"A: median {statistics.median(first):.2f} ms; B: median {statistics.median(second):.2f} ms; "
          f"B/A: median {statistics.median(ratios):.3f} ({min(ratios):.3f} … {max(ratios):.3f}), {pairs} pairs")


if __name__ == "__main__":
    main()
