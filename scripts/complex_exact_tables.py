#!/usr/bin/env python3
"""The tables of docs/complex.md, "The exact cases": runs the example program
example_005_complex_exact --tables over the job files of examples/005-complex-exact and prints its
sections (complex-exact-CASE), for scripts/docs.py --run complex-exact (about 10 minutes).

Usage: complex_exact_tables.py PROGRAM [--list] [EXAMPLE ARGUMENTS ...]
  --list  only the names of the sections it prints
  EXAMPLE ARGUMENTS (passed on): --all, --grid CASE=P:R,... (see examples/005-complex-exact/main.cpp)
"""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CASES = ["cap-circle", "cap-arcs-5", "cap-arcs-6", "cap-arcs-8", "enneper", "catenoid", "rectangle", "rectangle-area", "dirichlet-disc"]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    program, rest = sys.argv[1], sys.argv[2:]
    if "--list" in rest:
        print("\n".join("complex-exact-" + c for c in CASES))
        return 0
    with tempfile.TemporaryDirectory(prefix="bpde_complex_exact_") as tmp:
        r = subprocess.run([program, "--tables"] + rest + [str(ROOT / "examples" / "005-complex-exact"), tmp],
                           stdout=subprocess.PIPE, text=True)
    sys.stdout.write(r.stdout)
    return r.returncode


if __name__ == "__main__":
    sys.exit(main())
