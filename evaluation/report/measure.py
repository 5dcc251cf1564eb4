"""Measurement helpers of the report: timing, error statistics, ΔE, OCIO speed, the
machine, and the number format of every table (:func:`fmt`, defined in
:mod:`evaluation.formatting` so that :mod:`evaluation.stability`
can use it without importing the report).

Everything here is small and independent of the sections; the sections combine it.
"""

from __future__ import annotations

import contextlib
import datetime as _dt
import inspect
import os
import platform
import subprocess
import time
from pathlib import Path

import numpy as np

from evaluation.formatting import fmt
from ocio_thinfilm.colour import colorimetry

__all__ = [
    "fmt",
    "best_time",
    "stats",
    "dE_white",
    "table",
    "default",
    "machine_description",
    "ocio_cpu",
    "ocio_apply_speed",
    "film_XYZ_chunked",
    "json_default",
]


def best_time(fn, *, repeat=3, min_time=0.02, max_calls=50):
    """Best wall time per call of ``fn()``, in seconds.

    After one warm-up call (imports, caches), ``repeat`` rounds each call ``fn`` until
    ``min_time`` has passed or ``max_calls`` calls were made; the minimum over the
    rounds is the figure least disturbed by other processes.

    Parameters
    ----------
    fn : callable
        Called without arguments.
    repeat, min_time, max_calls : optional
        Rounds, seconds per round, and the cap on calls per round.

    Returns
    -------
    float
        Seconds per call.
    """
    fn()
    best = float("inf")
    for _ in range(repeat):
        calls, start = 0, time.perf_counter()
        while True:
            fn()
            calls += 1
            elapsed = time.perf_counter() - start
            if elapsed >= min_time or calls >= max_calls:
                break
        best = min(best, elapsed / calls)
    return best


def stats(de) -> dict:
    """Mean, 99th percentile, maximum and count of the finite values of ``de``."""
    de = np.asarray(de, dtype=np.float64).ravel()
    de = de[np.isfinite(de)]
    if de.size == 0:
        return {"mean": float("nan"), "p99": float("nan"), "max": float("nan"), "n": 0}
    return {
        "mean": float(de.mean()),
        "p99": float(np.percentile(de, 99)),
        "max": float(de.max()),
        "n": int(de.size),
    }


def dE_white(a, b, white_xy):
    """ΔE2000 between XYZ ``a`` and ``b`` through CIELAB relative to ``white_xy``."""
    import colour

    la = colour.XYZ_to_Lab(np.asarray(a, float), white_xy)
    lb = colour.XYZ_to_Lab(np.asarray(b, float), white_xy)
    return colour.delta_E(la, lb, method="CIE 2000")


def table(header, rows) -> str:
    """A markdown table; non-string cells go through :func:`fmt`."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for row in rows:
        lines.append("| " + " | ".join(fmt(c) if not isinstance(c, str) else c for c in row) + " |")
    return "\n".join(lines)


def default(fn, name):
    """A keyword default read from a function's signature (the shipped default)."""
    try:
        p = inspect.signature(fn).parameters[name]
    except (KeyError, TypeError, ValueError):
        return None
    return None if p.default is inspect.Parameter.empty else p.default


def film_XYZ_chunked(t, step, band_limited, chunk=128, illuminant="D65"):
    """:func:`colorimetry.film_XYZ` of many thicknesses ``t`` (nm), ``chunk`` at a time."""
    out = []
    for s in range(0, t.size, chunk):
        out.append(
            colorimetry.film_XYZ(
                t[s : s + chunk], step=step, band_limited=band_limited, illuminant=illuminant
            )
        )
    return np.concatenate(out)


def ocio_cpu(transform):
    """The default CPU processor of an OCIO transform (in a raw config)."""
    import PyOpenColorIO as ocio

    return ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()


def ocio_apply_speed(cpu, img, repeat=2) -> float:
    """Mpixel/s of ``cpu.applyRGB`` on a copy of ``img`` ((N, 3) float32), with the
    copy that restores the input measured and subtracted."""
    work = img.copy()

    def run():
        np.copyto(work, img)
        cpu.applyRGB(work)

    copy_sec = best_time(lambda: np.copyto(work, img), repeat=repeat, min_time=0.05, max_calls=10)
    sec = best_time(run, repeat=repeat, min_time=0.05, max_calls=10)
    return img.shape[0] / max(sec - copy_sec, 1e-9) / 1e6


def machine_description() -> dict:
    """The machine the report runs on.

    Returns
    -------
    dict
        CPU model, logical and usable core counts, memory (GiB), OS, versions of
        Python, numpy, colour-science, matplotlib, OpenColorIO, OpenImageIO and
        ocio-thinfilm, the git revision, the load average and the date (UTC).
    """
    import colour
    import matplotlib

    info = {"cpu": platform.processor() or platform.machine()}
    with contextlib.suppress(OSError):
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.lower().startswith("model name"):
                info["cpu"] = line.split(":", 1)[1].strip()
                break
    info["logical_cpus"] = os.cpu_count()
    with contextlib.suppress(AttributeError):
        info["usable_cpus"] = len(os.sched_getaffinity(0))
    with contextlib.suppress(OSError, ValueError, IndexError):
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal"):
                info["memory_GiB"] = round(int(line.split()[1]) / 2**20, 1)
    info["os"] = platform.platform()
    info["python"] = platform.python_version()
    info["numpy"] = np.__version__
    info["colour-science"] = colour.__version__
    info["matplotlib"] = matplotlib.__version__
    try:
        import PyOpenColorIO as ocio

        info["OpenColorIO"] = ocio.__version__
    except ImportError:  # pragma: no cover
        info["OpenColorIO"] = "missing"
    try:
        import OpenImageIO as oiio

        info["OpenImageIO"] = oiio.__version__
    except ImportError:  # pragma: no cover
        info["OpenImageIO"] = "missing"
    from ocio_thinfilm import __version__

    info["ocio-thinfilm"] = __version__
    with contextlib.suppress(OSError, subprocess.SubprocessError):
        rev = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"],
            capture_output=True,
            text=True,
            cwd=Path(__file__).parent,
            timeout=5,
        )
        if rev.returncode == 0:
            info["git"] = rev.stdout.strip()
    with contextlib.suppress(OSError, AttributeError):
        info["load_average_1_5_15min"] = " / ".join(f"{v:.2f}" for v in os.getloadavg())
    info["date_utc"] = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    return info


def json_default(o):
    """``json.dumps`` fallback: numpy scalars and arrays as Python values, else ``str``."""
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, np.bool_):
        return bool(o)
    return str(o)
