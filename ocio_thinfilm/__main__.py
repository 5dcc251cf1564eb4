"""``python -m ocio_thinfilm`` is the ``ocio-thinfilm`` command."""

from .cli import main

raise SystemExit(main())
