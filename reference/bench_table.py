"""Shared output of the side-by-side bench scripts (bench_arb_bessel.py,
bench_arb_hyp1f2.py, bench_arb_hyp1f2_grid.py, bench_f64_targets.py): the provenance footer, and writing a markdown table
below a marker line so that the prose above it survives a rerun."""

import os


def footer(script, timing="wall time per call in one process"):
    """The line naming the script, how it timed, and the load average at the end of the run."""
    load = "load average %.2f / %.2f / %.2f (1/5/15 min) on %d cores at the end of the run" % (
        os.getloadavg() + (os.cpu_count(),))
    return ("Measured by `reference/%s` (%s, both libraries "
            "in the same session); %s." % (script, timing, load))


def write_below_marker(path, marker, text):
    """Writes `text` to `path`, keeping everything of an existing file up to and
    including the `marker` line."""
    prefix = ""
    if os.path.exists(path):
        with open(path) as fh:
            old = fh.read()
        if marker in old:
            prefix = old[: old.index(marker) + len(marker)] + "\n\n"
    with open(path, "w") as fh:
        fh.write(prefix + text)


def write_between_markers(path, begin, end, text):
    """Replaces what lies between the `begin` and `end` marker lines of the
    existing file `path` by `text` (both markers must be there)."""
    with open(path) as fh:
        old = fh.read()
    if begin not in old or end not in old:
        raise SystemExit("%s: markers %r ... %r not found" % (path, begin, end))
    head = old[: old.index(begin) + len(begin)]
    tail = old[old.index(end):]
    with open(path, "w") as fh:
        fh.write(head + "\n\n" + text + "\n" + tail)
