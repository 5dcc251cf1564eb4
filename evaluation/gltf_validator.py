"""Khronos glTF-Validator (npm ``gltf-validator``) run with node, for the ``.glb`` tests.

- :func:`install_validator` -- the validator from npm into the user's cache, once;
- :func:`validate` -- its report (JSON) on a ``.glb``.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

__all__ = ["VALIDATOR_VERSION", "validator_directory", "install_validator", "validate"]

#: The gltf-validator release the tests run.
VALIDATOR_VERSION = "2.0.0-dev.3.10"

_SCRIPT = """const fs = require("fs");
const validator = require(process.argv[1]);
const data = new Uint8Array(fs.readFileSync(process.argv[2]));
validator.validateBytes(data, { maxIssues: 1000 }).then(
  (report) => { console.log(JSON.stringify(report)); },
  (error) => { console.error(String(error)); process.exit(1); });
"""


def validator_directory() -> Path:
    """Return ``node_modules/gltf-validator`` under the cache (``$XDG_CACHE_HOME`` or
    ``~/.cache``)/ocio-thinfilm/npm-gltf-validator-<version>."""
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    folder = Path(base) / "ocio-thinfilm" / f"npm-gltf-validator-{VALIDATOR_VERSION}"
    return folder / "node_modules" / "gltf-validator"


def install_validator() -> Path:
    """Install gltf-validator with npm (once) and return its directory.

    Raises
    ------
    RuntimeError
        Without node or npm, or when the install fails: the reason, in one line.
    """
    target = validator_directory()
    if shutil.which("node") is None:
        raise RuntimeError("no node to run gltf-validator with")
    if (target / "package.json").exists():
        return target
    npm = shutil.which("npm")
    if npm is None:
        raise RuntimeError("no npm to install gltf-validator with")
    prefix = target.parents[1]
    prefix.mkdir(parents=True, exist_ok=True)
    done = subprocess.run(
        [
            npm,
            "install",
            "--prefix",
            str(prefix),
            "--no-audit",
            "--no-fund",
            f"gltf-validator@{VALIDATOR_VERSION}",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    if done.returncode != 0 or not (target / "package.json").exists():
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"npm install gltf-validator@{VALIDATOR_VERSION} failed: {last}")
    return target


def validate(path: Path) -> dict:
    """Return gltf-validator's report on the file ``path`` (its ``issues`` hold
    ``numErrors``, ``numWarnings``, ``numInfos``, ``numHints`` and ``messages``)."""
    target = install_validator()
    done = subprocess.run(
        ["node", "-e", _SCRIPT, str(target), str(path)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    if done.returncode != 0:
        raise RuntimeError(f"gltf-validator failed: {done.stderr.strip()[-500:]}")
    return json.loads(done.stdout)


if __name__ == "__main__":  # .ci/run: python -m evaluation.gltf_validator
    print(f"gltf-validator {VALIDATOR_VERSION} in {install_validator()}")
