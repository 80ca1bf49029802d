"""The section markers of scripts/docs.py, for the measurement scripts of its GENERATORS, and the
CPU time of a child process (what those scripts time, so that other load on the machine does not
count).

A measurement script prints each of its tables as

    <!-- generated: NAME -->                or  <!-- generated: NAME; machine-dependent: COL, ... -->
    | ... |
    <!-- end -->

and prints the names alone with `--list` (without running anything); docs.py puts the tables into
the docs where the same markers stand.
"""
import resource
import subprocess
import sys


def section(name, lines, machine_dependent=()):
    """The lines of one marked section (the table's lines in between)."""
    cols = f"; machine-dependent: {', '.join(machine_dependent)}" if machine_dependent else ""
    return [f"<!-- generated: {name}{cols} -->"] + list(lines) + ["<!-- end -->"]


def print_section(name, lines, machine_dependent=()):
    print("\n".join(section(name, lines, machine_dependent)) + "\n", flush=True)


def list_sections(names):
    """With --list on the command line: print the names and exit."""
    if "--list" in sys.argv[1:]:
        print("\n".join(names))
        sys.exit(0)


def cpu_run(cmd, timeout=None):
    """Runs cmd (output captured): (CompletedProcess, or None on a timeout; the user + system CPU
    seconds of the child, resource.getrusage(RUSAGE_CHILDREN) before and after)."""
    def cpu():
        r = resource.getrusage(resource.RUSAGE_CHILDREN)
        return r.ru_utime + r.ru_stime
    before = cpu()
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        done = None
    return done, cpu() - before
