#!/usr/bin/env python3
"""Process start-up CPU of `bpde` against /bin/true (docs/performance.md, "Start-up").

Runs each command in turn (A B C A B C ...), `--runs` times after one warm-up round, and takes
the CPU time (user + system, from the kernel's accounting of each finished child: os.wait4) of
each run. Prints, per command, the minimum and median CPU in milliseconds and the ratio of the
minima to /bin/true's, and the dynamic loader's relocation count (LD_DEBUG=statistics).

The commands: `bpde --version` (the process floor), `bpde --help`, and `bpde export` of a small
tensor net to a STEP file (the one command that loads the STEP plugin, OpenCASCADE).

Usage: scripts/startup.py [path/to/bpde] [--runs N] [--json]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

NET = {"type": "tensor", "degree": [2, 2],
       "points": [[i / 2, j / 2, (i * j) / 4] for i in range(3) for j in range(3)]}


def cpu_of(argv):
    """CPU seconds (user + system) of one run of argv, its output discarded."""
    with open(os.devnull, "wb") as null:
        pid = os.posix_spawn(argv[0], argv, os.environ, file_actions=[
            (os.POSIX_SPAWN_DUP2, null.fileno(), 1), (os.POSIX_SPAWN_DUP2, null.fileno(), 2)])
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(" ".join(argv) + ": exit status " + str(os.waitstatus_to_exitcode(status)))
    return usage.ru_utime + usage.ru_stime


def relocations(argv):
    env = dict(os.environ, LD_DEBUG="statistics")
    err = subprocess.run(argv, env=env, capture_output=True, text=True).stderr
    found = re.findall(r"final number of relocations: (\d+)", err)
    return int(found[-1]) if found else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bpde", nargs="?", default="build/bpde")
    ap.add_argument("--runs", type=int, default=30)
    ap.add_argument("--json", action="store_true", help="print the figures as JSON")
    a = ap.parse_args()
    bpde = os.path.abspath(a.bpde)
    with tempfile.TemporaryDirectory() as tmp:
        net = os.path.join(tmp, "net.json")
        with open(net, "w") as f:
            json.dump(NET, f)
        commands = {
            "/bin/true": ["/bin/true"],
            "bpde --version": [bpde, "--version"],
            "bpde --help": [bpde, "--help"],
            "bpde export (STEP)": [bpde, "export", net, "--quiet", "--step", os.path.join(tmp, "s.step")],
        }
        times = {k: [] for k in commands}
        for r in range(a.runs + 1):
            for k, argv in commands.items():
                t = cpu_of(argv)
                if r > 0:
                    times[k].append(t)
        base = min(times["/bin/true"])
        rows = []
        for k, argv in commands.items():
            m = min(times[k])
            rows.append({"command": k, "min_ms": 1e3 * m, "median_ms": 1e3 * statistics.median(times[k]),
                         "ratio_to_true": m / base if base > 0 else None, "relocations": relocations(argv)})
    if a.json:
        json.dump(rows, sys.stdout, indent=1)
        print()
        return
    print(f"{'command':<22} {'min CPU ms':>10} {'median ms':>10} {'min / true':>10} {'relocations':>12}")
    for r in rows:
        ratio = f"{r['ratio_to_true']:.1f}" if r["ratio_to_true"] else "-"
        print(f"{r['command']:<22} {r['min_ms']:>10.2f} {r['median_ms']:>10.2f} {ratio:>10} {str(r['relocations']):>12}")


if __name__ == "__main__":
    main()
