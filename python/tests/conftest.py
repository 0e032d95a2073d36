"""Shared fixtures: the `maugis` command line for the model comparisons."""

import os
import pathlib
import shutil

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def maugis_cli():
    """Path of the `maugis` binary: $MAUGIS_CLI (set by `./dev test`, must exist),
    else target/release/maugis or `maugis` on PATH; skipped when none is built."""
    env = os.environ.get("MAUGIS_CLI")
    if env:
        if not os.access(env, os.X_OK):
            pytest.fail(f"MAUGIS_CLI={env} is not an executable")
        return env
    for candidate in (REPO / "target" / "release" / "maugis", REPO / "target" / "debug" / "maugis"):
        if os.access(candidate, os.X_OK):
            return str(candidate)
    found = shutil.which("maugis")
    if found:
        return found
    pytest.skip("the maugis CLI is not built (cargo build --release -p maugis-cli, or set MAUGIS_CLI)")
