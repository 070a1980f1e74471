"""Shared fixtures of the module's tests: run from the build tree with PYTHONPATH=build/python
(scripts/python_test.sh, or ctest's Python.pytest)."""
import json
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "python"
sys.path.insert(0, str(EXAMPLES))


def tecido_bin():
    return os.environ.get("TECIDO_BIN", str(ROOT / "build" / "bin" / "tecido"))


@pytest.fixture(scope="session")
def cli():
    """Runs the command line: cli(args...) -> CompletedProcess (text)."""
    path = tecido_bin()
    if not os.access(path, os.X_OK):
        pytest.fail(f"the tecido executable is missing at {path} (build it, or set TECIDO_BIN)")

    def run(*args, check=True):
        p = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"tecido {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
        return p

    return run


@pytest.fixture(scope="session")
def engine_cmd():
    """The --engine-cmd of the example engine through the JSON-lines door."""
    return f"py={sys.executable} {EXAMPLES / 'tecido_engine.py'}"


def write_json(path, doc):
    path.write_text(json.dumps(doc))
    return path
