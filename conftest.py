"""pytest at the repository root: ``python -m ocio_thinfilm`` runs the command when
imported, so ``--doctest-modules`` does not collect it; ``evaluation/blender_scene.py`` is
the script Blender's own Python runs (it imports ``bpy``, which lives in its own venv:
:mod:`evaluation.blender`). Without Mitsuba 3 (the optional extra ``mitsuba``) its host
module raises ImportError on import, so its doctests are not collected then
(tests/test_mitsuba.py skips, saying so)."""

import importlib.util

collect_ignore = ["ocio_thinfilm/__main__.py", "evaluation/blender_scene.py"]
if importlib.util.find_spec("mitsuba") is None:
    collect_ignore.append("ocio_thinfilm/export/hosts/mitsuba.py")
