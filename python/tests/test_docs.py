"""The Python examples of docs/python.md run as written (each ```python block, in order, in one
namespace, from the repository's root)."""
import os
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def python_blocks(path):
    return re.findall(r"^```python\n(.*?)^```", path.read_text(), flags=re.S | re.M)


def promised_outputs(code):
    """The outputs a block promises: `print(...)  # [ True]` promises that "[ True]" is printed."""
    return re.findall(r"^print\(.*\)\s+#\s+(\[.*?\])\s*$", code, flags=re.M)


@pytest.mark.parametrize("doc", ["docs/python.md", "README.md"])
def test_python_examples_run(doc, monkeypatch, capsys):
    blocks = python_blocks(ROOT / doc)
    assert blocks, f"{doc} has no ```python block"
    monkeypatch.chdir(ROOT)
    namespace = {"__name__": "__doc_example__"}
    for code in blocks:
        exec(compile(code, doc, "exec"), namespace)
        printed = capsys.readouterr().out
        for promised in promised_outputs(code):
            assert promised in printed, f"{doc}: the example promises {promised!r}, printed {printed!r}"
