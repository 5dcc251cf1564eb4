"""ocio-thinfilm: Smits & Meyer's "Newton's Colors" (1990) as a colour-managed tool.

The sub-packages are the pipeline's stages, in order; each imports only from the
ones before it and from the shared leaves (:mod:`.checks`, :mod:`.registry`,
:mod:`.cache`, :mod:`.io`):

- :mod:`.physics`     thin-film reflectance spectra (paper Section 2, Eq. 5-14)
- :mod:`.colour`      spectra -> CIE XYZ -> linear RGB (Section 2.1) and the
  constant-lightness parallelepiped clip (Section 3.2)
- :mod:`.lut`         the 1D tables, the clip's 3D LUTs and every view as OCIO transforms
- :mod:`.config`      the drop-in OpenColorIO config (data -> factories -> validated
  config), and its merge into existing configs
- :mod:`.export`      the files users load: ``bake`` (config folder, ``luts/`` set) and
  standalone LUTs
- :mod:`.render`      the paper's example scenes through a config's processors (Section 4)
- :mod:`.cli`         the ``ocio-thinfilm`` command (options, errors, signals)

What the tests, benchmarks and report measure against is not in this package: it is
the repository's top-level ``evaluation`` package, beside ``benchmarks/``.
"""

from importlib import metadata as _metadata

try:
    #: The installed distribution's version (one place: ``pyproject.toml``).
    __version__ = _metadata.version("ocio-thinfilm")
except _metadata.PackageNotFoundError:  # imported from a checkout that is not installed
    __version__ = "0+unknown"

__all__ = ["__version__"]
