"""The drop-in OpenColorIO config: data -> factories -> config -> validate -> files.

In the style of OpenColorIO-Config-ACES:

- :mod:`.data` -- the config described as plain data (:func:`config_data`), from the
  registry, the thin-film tables and the clip LUTs;
- :mod:`.spaces` -- the colour spaces that need no LUT file (the encoded spaces by their
  log curves);
- :mod:`.luts` -- the config's LUT files and references to them;
- :mod:`.named` -- the named transforms;
- :mod:`.factories` -- one OCIO object from one dict;
- :mod:`.generate` -- :func:`generate_config` (validated);
- :mod:`.merge` -- the same additions merged into an existing config (``bake --into``).

This stage turns data into OCIO ``Config`` objects and writes nothing: the files are
``ocio_thinfilm.export``'s (:mod:`ocio_thinfilm.export.bake`,
:mod:`ocio_thinfilm.export.merged`).

The public names of :mod:`.data`, :mod:`.luts`, :mod:`.named`, :mod:`.factories` and
:mod:`.generate` are importable from this package.
"""

from ocio_thinfilm.config.data import *  # noqa: F401,F403
from ocio_thinfilm.config.data import __all__ as _data_all
from ocio_thinfilm.config.factories import *  # noqa: F401,F403
from ocio_thinfilm.config.factories import __all__ as _factories_all
from ocio_thinfilm.config.generate import *  # noqa: F401,F403
from ocio_thinfilm.config.generate import __all__ as _generate_all
from ocio_thinfilm.config.luts import *  # noqa: F401,F403
from ocio_thinfilm.config.luts import __all__ as _luts_all
from ocio_thinfilm.config.named import *  # noqa: F401,F403
from ocio_thinfilm.config.named import __all__ as _named_all

__all__ = [*_data_all, *_luts_all, *_named_all, *_factories_all, *_generate_all]
