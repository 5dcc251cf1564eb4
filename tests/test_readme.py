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
