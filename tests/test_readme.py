"""The README's Python examples run as written (its import paths follow the layout)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_python_examples_run():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)
    assert blocks
    for block in blocks:
        namespace = {}
        exec(compile(block, str(README), "exec"), namespace)  # noqa: S102
    # the first-look example clips a soap film's green into sRGB, keeping its Y
    rgb = namespace["rgb"]
    assert rgb.min() >= 0.0 and rgb.max() <= 1.0
    Y = namespace["XYZ"][1]
    assert abs(float(np.dot(rgb, [0.2126, 0.7152, 0.0722])) - Y) < 1e-3


def test_readme_first_look_is_what_the_demo_prints(tmp_path, capsys):
    """The console block under *A first look* is the demo's output (a PNG to a temporary
    path instead of docs/)."""
    from ocio_thinfilm.cli import main as cli

    block = (
        re.search(r"```console\n\$ ocio-thinfilm demo\n(.*?)```", README.read_text(), flags=re.S)
        .group(1)
        .splitlines()
    )
    assert cli.main(["demo", "--out", str(tmp_path / "strip.png")]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert printed[:-1] == block[:-1]
    assert printed[-1].replace(str(tmp_path / "strip.png"), "docs/soap_strip.png") == block[-1]
