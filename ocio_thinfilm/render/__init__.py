"""Stage 7: the paper's example scenes through a config.

- :mod:`.noise` -- Perlin noise and turbulence;
- :mod:`.scene_base` -- what a scene declares and returns, and its base class;
- :mod:`.scenes` -- the four scenes (Figures 4-7), each declaring its tables;
- :mod:`.processors` -- the config's processors a render uses;
- :mod:`.frames` -- one frame rendered and written (EXR + PNG).
"""
