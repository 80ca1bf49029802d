"""The section markers of scripts/docs.py, for the measurement scripts of its GENERATORS.

A measurement script prints each of its tables as

    <!-- generated: NAME -->                or  <!-- generated: NAME; machine-dependent: COL, ... -->
    | ... |
    <!-- end -->

and prints the names alone with `--list` (without running anything); docs.py puts the tables into
the docs where the same markers stand.
"""
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
