"""Shared paths: the repository root (studies, recordings) and the command-line binary."""

import os
import pathlib
import shutil
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def cli_command():
    """The `cellstudio` binary `cargo test --release` built (CELLSTUDIO_BIN, then the target
    folders), else `cargo run --release`, which builds it."""
    candidates = [os.environ.get("CELLSTUDIO_BIN")]
    for target in (os.environ.get("CARGO_TARGET_DIR"), REPO / "target"):
        if target:
            candidates.append(pathlib.Path(target) / "release" / "cellstudio")
    for c in candidates:
        if c and pathlib.Path(c).is_file():
            return [str(c)]
    if shutil.which("cargo") is None:
        pytest.skip("no cellstudio binary and no cargo to build one")
    return ["cargo", "run", "--release", "--quiet", "--manifest-path", str(REPO / "Cargo.toml"), "--"]


def run_cli(args, cwd):
    """Runs the command line in `cwd`; its stdout."""
    done = subprocess.run(cli_command() + list(args), cwd=cwd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.fixture
def at_repo(monkeypatch):
    """Runs the test in the repository root, where study files name their recordings."""
    monkeypatch.chdir(REPO)
    return REPO
