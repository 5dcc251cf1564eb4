"""Stage 8: the ``ocio-thinfilm`` command.

:mod:`.main` (parser, one-line errors, signals) and one module per command group
(:mod:`.export` for ``bake`` and ``export``, :mod:`.render`, :mod:`.report`,
:mod:`.demo`).
"""
