"""What a film's material table costs: memory and time, estimated before computing.

``export material`` refuses a size the machine cannot hold or finish
(:func:`check_size`) in milliseconds, from the table's samples
(:func:`ocio_thinfilm.lut.material_tables.sample_count`), :data:`NS_PER_SAMPLE` and the
memory available.

- :func:`available_memory` -- bytes a new allocation can take without swapping;
- :func:`table_cost` -- memory, seconds and samples of a table;
- :func:`check_size` -- the refusal, with both estimates and the most texels allowed.
"""

from __future__ import annotations

import math
import os

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics.films import Film

__all__ = ["MAX_SECONDS", "NS_PER_SAMPLE", "available_memory", "table_cost", "check_size"]

#: The longest an export may be estimated to take (s): a larger ``size`` is refused
#: before anything is computed (:func:`check_size`).
MAX_SECONDS = 600.0
#: Time per sample (a texel at one wavelength, ns) of one worker of
#: :func:`~ocio_thinfilm.lut.material_tables.film_angle_XYZ`, an upper estimate from
#: benchmarks/bench_material.py (docs/materials.md): the time estimate of
#: :func:`check_size`.
NS_PER_SAMPLE = 45.0
#: Bytes per texel of one table while it is made and written: its XYZ, RGB and clipped
#: RGB (float64) and the EXR's float32 pixels.
_BYTES_PER_TEXEL = 3 * (8 + 8 + 8 + 4)
#: Bytes a worker's block of work holds (coefficients, powers and spectra of a group of
#: rows, :mod:`ocio_thinfilm.lut.material_tables`).
_WORKER_BYTES = 96 << 20
#: Fraction of the available memory an export may plan to use.
_MEMORY_SHARE = 0.8


def available_memory() -> int:
    """Return the memory (bytes) available to a new allocation without swapping.

    ``MemAvailable`` of /proc/meminfo (Linux), else the free physical pages
    (``os.sysconf``), else 0 (unknown: no memory bound).

    Returns
    -------
    int
        Bytes.
    """
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (OSError, ValueError, AttributeError):
        return 0


def table_cost(film: Film, width: int, height: int, workers: int) -> tuple[float, float, float]:
    """Estimate what a film's table of ``width`` x ``height`` texels costs to make.

    Parameters
    ----------
    film : Film
        The film.
    width, height : int
        The table's size.
    workers : int
        Threads that evaluate it.

    Returns
    -------
    memory : float
        Bytes: the tables (R, and T for a free-standing film) while made and written, and
        each worker's block of work.
    seconds : float
        Wall time on the development machine: the samples
        (:func:`~ocio_thinfilm.lut.material_tables.sample_count`) times
        :data:`NS_PER_SAMPLE`, over the workers.
    samples : float
        The samples.
    """
    quantities = 2 if material_tables.free_standing(film) else 1
    samples = material_tables.sample_count(film, width, height)
    memory = float(width) * height * quantities * _BYTES_PER_TEXEL + workers * _WORKER_BYTES
    return memory, samples * NS_PER_SAMPLE * 1e-9 / workers, samples


def _amount(value: float, unit: str) -> str:
    return f"{value:.2g} {unit}" if value < 10 else f"{value:.0f} {unit}"


def _bytes(n: float) -> str:
    for unit, scale in (("GB", 1e9), ("MB", 1e6)):
        if n >= scale:
            return _amount(n / scale, unit)
    return _amount(n / 1e3, "kB")


def _duration(seconds: float) -> str:
    for unit, scale in (("h", 3600.0), ("min", 60.0)):
        if seconds >= scale:
            return _amount(seconds / scale, unit)
    return _amount(seconds, "s")


def check_size(
    film: Film, width: int, height: int, workers: int, parameter: str = "size"
) -> tuple[int, int]:
    """Refuse a table the machine cannot hold or finish in :data:`MAX_SECONDS`.

    The estimates of :func:`table_cost` against :func:`available_memory` (at most 80 %
    of it) and :data:`MAX_SECONDS`; milliseconds, before anything is computed.

    Parameters
    ----------
    film : Film
        The film.
    width, height : int
        The table's size.
    workers : int
        Threads that would evaluate it.
    parameter : str, optional
        The parameter named in the message (default ``"size"``).

    Returns
    -------
    tuple of int
        (width, height).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) with the estimates and about the most texels allowed.
    """
    memory, seconds, samples = table_cost(film, width, height, workers)
    available = available_memory() * _MEMORY_SHARE
    texels = float(width) * height
    fits = available <= 0 or memory <= available
    if fits and seconds <= MAX_SECONDS:
        return width, height
    per_texel_memory = (memory - workers * _WORKER_BYTES) / texels
    limits = [MAX_SECONDS / (seconds / texels)]
    if available > 0:
        limits.append(max(0.0, available - workers * _WORKER_BYTES) / per_texel_memory)
    most = min(limits)
    side = max(2, int(math.sqrt(most)))
    where = f"{_bytes(available / _MEMORY_SHARE)} available" if available > 0 else ""
    raise ParameterError(
        parameter,
        f" {width}x{height}: needs about {_bytes(memory)} of memory"
        f"{f' ({where})' if where else ''} and {_duration(seconds)} here with {workers} "
        f"worker{'s' if workers != 1 else ''} (at most {_duration(MAX_SECONDS)}); at most "
        f"about {most / 1e6:.3g} million texels (e.g. {side}x{side})",
    )
