"""Shared output of the side-by-side bench scripts (bench_arb_bessel.py,
bench_arb_hyp1f2.py): the provenance footer, and writing a markdown table
below a marker line so that the prose above it survives a rerun."""

import os


def footer(script):
    """The line naming the script and the load average at the end of the run."""
    load = "load average %.2f / %.2f / %.2f (1/5/15 min) on %d cores at the end of the run" % (
        os.getloadavg() + (os.cpu_count(),))
    return ("Measured by `reference/%s` (wall time per call in one process, both libraries "
            "in the same session); %s." % (script, load))


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
