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
    assert printed[-1].replace(str(tmp_path / "strip.png"), "soap_strip.png") == block[-1]


def _command_lines(text: str) -> list[str]:
    """The ``ocio-thinfilm`` command lines of the shell blocks of ``text``, joined where
    they continue with a backslash, without comments."""
    lines = []
    for block in re.findall(r"```(?:sh|bash|shell)\n(.*?)```", text, flags=re.S):
        for line in block.replace("\\\n", " ").splitlines():
            line = re.sub(r"\s+#\s.*$", "", line).strip()
            # a synopsis ({a,b}, [--x]) or a farm template's placeholders is not a command
            if line.startswith("ocio-thinfilm ") and not re.search(r"[{<\[]|#\w+#", line):
                lines.append(line)
    return lines


def test_the_documented_command_lines_parse():
    """Every ``ocio-thinfilm`` command line in the README's and the docs' shell blocks is
    one the parser takes: a known command and sub-command, only their options (running
    them is the other tests' work)."""
    import shlex

    from ocio_thinfilm.cli import main as cli

    parser = cli.build_parser()
    pages = [README, *sorted((README.parent / "docs").glob("*.md"))]
    commands = [c for page in pages for c in _command_lines(page.read_text())]
    assert len(commands) > 20 and any(c.startswith("ocio-thinfilm export film") for c in commands)
    refused = {}
    for command in commands:
        try:
            _, extra = parser.parse_known_args(shlex.split(command)[1:])
        except Exception as error:  # noqa: BLE001 -- the parser's one-line error
            refused[command] = str(error)
            continue
        if extra:
            refused[command] = f"unrecognized {extra}"
    assert refused == {}
