#!/usr/bin/env python3
"""Print the blend config of bench/bench_data.h blend_config(k) as FORMATS.md JSON (for timing
`bpde blend` from the command line, docs/performance_measurements.md, "Blend"):

    scripts/blend_config.py 128 > cfg.json && /usr/bin/time -v build/bpde blend cfg.json --out d

Smooth edges y = 0 and y = 1 on a k x k partition, a = epsilon = 1, no data points, 50 samples.
"""
import json
import math
import sys


def blend_config(k):
    xs = [i / k for i in range(k + 1)]
    return {
        "kind": "blend", "partition": [k, k], "a": 1.0, "epsilon": 1.0,
        "edges": {
            "y0": {"value": [[x, 0.0, 0.2 * math.sin(math.pi * x)] for x in xs], "dy": [[0.0, 1.0, 0.5] for _ in xs]},
            "y1": {"value": [[x, 1.0, 0.3 * math.cos(math.pi * x)] for x in xs], "dy": [[0.0, 1.0, -0.5] for _ in xs]},
        },
        "points": [], "data": [], "samples": 50,
    }


if __name__ == "__main__":
    if len(sys.argv) != 2 or not sys.argv[1].isdigit():
        sys.exit("usage: blend_config.py K")
    json.dump(blend_config(int(sys.argv[1])), sys.stdout)
    sys.stdout.write("\n")
