"""Build hook: the wheel carries the baked OCIO config as package data.

``configs/thinfilm`` (``config.ocio`` and ``luts/*.clf``, the files ``ocio-thinfilm bake``
writes; 37 MB of text with the compression view, 8.6 MB compressed in the wheel) is
copied to
``ocio_thinfilm/data/thinfilm`` in the build, where
:data:`ocio_thinfilm.render.processors.PACKAGE_CONFIG` reads it through
``importlib.resources``: an installed package renders without baking and never writes
beside its code. Shipped rather than baked on first use into a cache: 9 MB of download
against a bake of 15-25 s (plus the clip-node fits) on every new machine, container or
farm node, and a config that is byte for byte the one the tests checked (about 2.8 MB
more per display). Everything else is declared in pyproject.toml.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

CONFIG = Path(__file__).resolve().parent / "configs" / "thinfilm"


class BuildWithConfig(build_py):
    """``build_py`` plus the config folder (an editable install reads the checkout's)."""

    def run(self) -> None:
        super().run()
        if getattr(self, "editable_mode", False):
            return
        files = [CONFIG / "config.ocio", *sorted((CONFIG / "luts").glob("*.clf"))]
        if not files[0].is_file() or len(files) < 2:
            raise SystemExit(f"{CONFIG} has no baked config: run 'ocio-thinfilm bake' first")
        target = Path(self.build_lib) / "ocio_thinfilm" / "data" / "thinfilm"
        shutil.rmtree(target, ignore_errors=True)
        (target / "luts").mkdir(parents=True)
        for path in files:
            shutil.copyfile(path, target / path.relative_to(CONFIG))


setup(cmdclass={"build_py": BuildWithConfig})
