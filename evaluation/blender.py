"""Blender as a Python module (PyPI ``bpy``) in its own venv, for the renderer tests.

``bpy`` wants its own Python (3.11 for :data:`BPY_VERSION`) and NumPy < 2, so it lives in a
venv of its own under the user's cache directory, never in the project's environment;
the tests run Blender in a subprocess with that venv's Python and the scene script
:data:`SCENE` (``evaluation/blender_scene.py``, which imports only ``bpy`` and the
standard library). This module imports only the standard library at its top, so
``.ci/run`` can run it before the project's requirements are installed.

- :func:`bpy_python` -- the venv's Python where ``bpy`` is installed, or None.
- :func:`install_bpy` -- make the venv and ``pip install bpy==BPY_VERSION`` (once);
  ``.ci/run`` calls it (``python -m evaluation.blender``) ahead of the tests.
- :func:`render` -- run :data:`SCENE` with a JSON job; returns its JSON answer.
- :func:`sphere_pixels` -- what each pixel of :data:`SCENE`'s render sees: the pixel
  centres, the disc away from the silhouette, cos(theta) there.
- :func:`render_film` -- the sphere with a generated film material, and the exact
  colours at its pixels (:mod:`evaluation.materials`).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

__all__ = [
    "BPY_VERSION",
    "SCENE",
    "FRAME",
    "bpy_directory",
    "bpy_python",
    "install_bpy",
    "render",
    "read_exr",
    "sphere_pixels",
    "render_film",
]

#: The PyPI ``bpy`` release the tests render with (Blender 5.0.1, Python 3.11).
BPY_VERSION = "5.0.1"
#: The scene script the venv's Python runs.
SCENE = Path(__file__).resolve().with_name("blender_scene.py")
#: The width of :data:`SCENE`'s orthographic frame (the unit sphere and a margin).
FRAME = 2.2


def bpy_directory() -> Path:
    """The venv: ``$XDG_CACHE_HOME/ocio-thinfilm/bpy-<version>`` (default ``~/.cache``)."""
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "ocio-thinfilm" / f"bpy-{BPY_VERSION}"


def _python_of(venv: Path) -> Path:
    return venv / "bin" / "python"


def bpy_python() -> Path | None:
    """The venv's Python if ``bpy`` is installed there (its marker file), else None."""
    venv = bpy_directory()
    if (venv / "bpy-installed").exists() and _python_of(venv).exists():
        return _python_of(venv)
    return None


def _python311() -> str | None:
    if sys.version_info[:2] == (3, 11):
        return sys.executable
    return shutil.which("python3.11")


def install_bpy() -> Path:
    """Make the venv and install ``bpy`` :data:`BPY_VERSION` into it (once).

    Returns the venv's Python. Raises RuntimeError with the reason in one line where
    there is no Python 3.11 or the install fails (no network).
    """
    found = bpy_python()
    if found is not None:
        return found
    base = _python311()
    if base is None:
        raise RuntimeError(f"bpy {BPY_VERSION} needs Python 3.11; there is no python3.11")
    venv = bpy_directory()
    shutil.rmtree(venv, ignore_errors=True)
    venv.parent.mkdir(parents=True, exist_ok=True)
    steps = (
        [base, "-m", "venv", str(venv)],
        [str(_python_of(venv)), "-m", "pip", "install", "-q", f"bpy=={BPY_VERSION}"],
    )
    for step in steps:
        done = subprocess.run(step, capture_output=True, text=True, timeout=1800)
        if done.returncode != 0:
            shutil.rmtree(venv, ignore_errors=True)
            last = (done.stderr.strip().splitlines() or ["no output"])[-1]
            raise RuntimeError(f"{' '.join(step[-3:])} failed: {last}")
    (venv / "bpy-installed").write_text(BPY_VERSION + "\n")
    return _python_of(venv)


def render(job: dict, *, timeout: float = 300.0) -> dict:
    """Run :data:`SCENE` in the venv's Blender with ``job`` (JSON) and return its answer.

    The environment loses ``OCIO`` (Blender's own colour config, whose scene linear is
    Linear Rec.709) and ``PYTHONPATH``. Raises RuntimeError with Blender's last lines
    where the run fails.
    """
    python = bpy_python()
    if python is None:
        raise RuntimeError(f"bpy {BPY_VERSION} not installed (python -m evaluation.blender)")
    env = {k: v for k, v in os.environ.items() if k not in ("OCIO", "PYTHONPATH")}
    with tempfile.TemporaryDirectory(prefix="ocio-thinfilm-bpy-") as work:
        answer = Path(work) / "answer.json"
        spec = Path(work) / "job.json"
        spec.write_text(json.dumps({**job, "answer": str(answer)}))
        done = subprocess.run(
            [str(python), str(SCENE), str(spec)],
            capture_output=True,
            text=True,
            timeout=timeout,
            env=env,
        )
        if done.returncode != 0 or not answer.exists():
            tail = "\n".join((done.stdout + done.stderr).strip().splitlines()[-15:])
            raise RuntimeError(f"Blender run failed ({done.returncode}):\n{tail}")
        return json.loads(answer.read_text())


def read_exr(path: Path):
    """The RGB of an EXR as float64 (H, W, 3), first scanline first (OpenImageIO)."""
    import OpenImageIO as oiio

    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3].astype(float)


def sphere_pixels(size: int, radius: float = 0.95):
    """(x, y, disc, cos_theta) of :data:`SCENE`'s ``size`` x ``size`` render, rows from
    the top: the pixel centres on the unit sphere's plane, the pixels with
    ``x^2 + y^2 < radius^2`` (away from the silhouette) and ``n_z = sqrt(1 - x^2 -
    y^2)``, the cosine of the angle between the normal and the view (+z)."""
    import numpy as np

    c = -FRAME / 2 + FRAME * (np.arange(size) + 0.5) / size
    x, y = np.meshgrid(c, -c)
    r2 = x**2 + y**2
    return x, y, r2 < radius**2, np.sqrt(np.clip(1 - r2, 0, 1))


def render_film(
    folder: Path,
    stack,
    key: str,
    *,
    range_um=(0.0, 1.0),
    table_size=(256, 128),
    ramp_um=(0.05, 0.95),
    size: int = 96,
    engine: str = "CYCLES",
    transmittance: bool = False,
    name: str | None = None,
    spaces=("Linear Rec.709 (sRGB)",),
    **job,
):
    """Render the sphere with film ``stack`` as the generated material and return
    (rendered RGB on the disc, exact R on the disc, Blender's answer).

    The tables (``table_size`` = width, height over ``range_um``) and the script go to
    ``folder / key`` (:func:`evaluation.materials.write_film_folder`); the film's
    thickness ramps over ``ramp_um`` from object x = -1 to +1. ``name``: the node group's
    and material's (default ``Thin Film <key>``); ``spaces``: the tables' spaces (the
    script loads the scene's working space's); ``job``'s further keys go to :func:`render`
    (e.g. ``working_space``). The exact R is linear BT.709.
    """
    from evaluation import materials
    from ocio_thinfilm.export.hosts.blender import blender_name

    script = materials.write_film_folder(
        Path(folder) / key,
        stack,
        key,
        range_um,
        *table_size,
        transmittance=transmittance,
        name=name,
        spaces=spaces,
    )
    out = Path(folder) / f"{key}_{engine}.exr"
    material = {"kind": "script", "script": str(script), "name": name or blender_name(key)}
    answer = render(
        {
            "engine": engine,
            "size": size,
            "out": str(out),
            "material": material,
            "thickness_um": list(ramp_um),
            **job,
        }
    )
    x, _, disc, cos_theta = sphere_pixels(size)
    thickness = ramp_um[0] + (x + 1) / 2 * (ramp_um[1] - ramp_um[0])
    exact = materials.film_rgb(stack, thickness[disc], cos_theta[disc])
    return read_exr(out)[disc], exact, answer


if __name__ == "__main__":
    print(f"bpy {BPY_VERSION}: {install_bpy()}")
