#!/usr/bin/env python3
"""`zsim run` alternating with the plainest OpenGL harness, llvmpipe on one thread.

Each alternation runs `zsim run SCENE --format none --threads 1` five times
(their median) and then `benches/plain_llvmpipe.py SCENE 15` with
LP_NUM_THREADS=0 (llvmpipe rasterizing on the thread that draws), and prints
two ratios to llvmpipe's clear + draw + glFinish: zsim's rasterized time
(clearing and drawing, in buffers made beforehand, as the harness draws in a
framebuffer it made and drew into once before timing), and zsim's buffers
made + rasterized (its fresh buffers' pages included). Then the medians of
both over the alternations, with their least and greatest.

    pip install moderngl
    python3 benches/against_llvmpipe.py target/release/zsim r20k.json 15
"""

import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def zsim_run(zsim, scene):
    shown = subprocess.run([zsim, "run", scene, "--format", "none", "--threads", "1"], capture_output=True,
                           text=True, check=True).stdout
    made = float(re.search(r"buffers made ([\d.]+) ms", shown).group(1))
    rasterized = float(re.search(r"rasterized ([\d.]+) ms", shown).group(1))
    return rasterized, made + rasterized


def llvmpipe(scene):
    environment = dict(os.environ, LP_NUM_THREADS="0")
    shown = subprocess.run([sys.executable, os.path.join(HERE, "plain_llvmpipe.py"), scene, "15"],
                           capture_output=True, text=True, env=environment, check=True).stdout
    return float(re.search(r"finish ([\d.]+) ms", shown).group(1))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    zsim, scene, times = sys.argv[1], sys.argv[2], int(sys.argv[3])
    drawn, whole = [], []
    for _ in range(times):
        runs = [zsim_run(zsim, scene) for _ in range(5)]
        rasterized = statistics.median(r for r, _ in runs)
        with_buffers = statistics.median(w for _, w in runs)
        gpu = llvmpipe(scene)
        drawn.append(rasterized / gpu)
        whole.append(with_buffers / gpu)
        print(f"zsim rasterized {rasterized:.2f} ms, buffers made + rasterized {with_buffers:.2f} ms; "
              f"llvmpipe {gpu:.2f} ms: {drawn[-1]:.3f}, {whole[-1]:.3f}", flush=True)
    print(f"rasterized / llvmpipe: median {statistics.median(drawn):.3f} ({min(drawn):.3f} … {max(drawn):.3f}); "
          f"buffers made + rasterized / llvmpipe: median {statistics.median(whole):.3f} "
          f"({min(whole):.3f} … {max(whole):.3f}); {times} alternations")


if __name__ == "__main__":
    main()
