"""Headless Chromium for the tests of the browser pages, and three.js from npm.

- :func:`chromium` -- the Chromium to run (Debian's ``chromium`` package), or None.
- :func:`dump_dom` -- open a URL headless (WebGL2 on SwiftShader, a fresh profile, no
  background traffic), let it run, and return the DOM it ends with (``--dump-dom``).
- :func:`page_readback` -- the JSON a page wrote into its ``<pre id="readback">``.
- :func:`serve` -- a directory on ``http://127.0.0.1:<port>/`` for as long as a ``with``
  block runs (ES modules and ``fetch`` do not work from ``file://``).
- :func:`install_three` -- three.js (:data:`THREE_VERSION`) from npm into the user's
  cache directory, once; ``.ci/run`` calls it ahead of the tests.
"""

from __future__ import annotations

import contextlib
import functools
import html
import http.server
import json
import os
import re
import shutil
import subprocess
import threading
import time
from collections.abc import Iterator
from pathlib import Path

__all__ = [
    "CHROMIUM",
    "FLAGS",
    "THREE_VERSION",
    "chromium",
    "dump_dom",
    "page_readback",
    "serve",
    "three_directory",
    "install_three",
]

#: Debian's Chromium.
CHROMIUM = "/usr/bin/chromium"
#: Headless, WebGL2 without a GPU (ANGLE on SwiftShader; Chromium 120+ wants the unsafe
#: flag for it), no sandbox (CI containers run as root), nothing fetched in the
#: background, and ten seconds of the page's virtual time before the DOM is dumped.
FLAGS = (
    "--headless",
    "--disable-gpu",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--no-sandbox",
    "--no-first-run",
    "--disable-extensions",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--virtual-time-budget=10000",
)
#: The three.js release the documentation's three.js example is run with.
THREE_VERSION = "0.187.0"


def chromium() -> str | None:
    """Return the Chromium executable (``chromium`` on the PATH, else :data:`CHROMIUM`),
    or None where there is none."""
    path = shutil.which("chromium")
    if path is None and Path(CHROMIUM).exists():
        path = CHROMIUM
    return path


def dump_dom(
    browser: str, url: str, profile: Path, *flags: str, timeout: float = 120.0
) -> tuple[str, str, float]:
    """Open ``url`` in headless ``browser`` and return the final DOM.

    Parameters
    ----------
    browser : str
        The Chromium executable (:func:`chromium`).
    url : str
        The page, with its query.
    profile : pathlib.Path
        A directory for a fresh ``--user-data-dir``.
    *flags : str
        More command-line flags (e.g. ``--force-device-scale-factor=2``).
    timeout : float, optional
        Seconds before the run is abandoned.

    Returns
    -------
    tuple
        The DOM as text (stdout), Chromium's stderr and the seconds the run took.
    """
    start = time.perf_counter()
    done = subprocess.run(
        [browser, *FLAGS, *flags, f"--user-data-dir={profile}", "--dump-dom", url],
        capture_output=True,
        text=True,
        timeout=timeout,
    )
    return done.stdout, done.stderr, time.perf_counter() - start


def page_readback(dom: str, stderr: str = "") -> dict:
    """Return the JSON of the DOM's ``<pre id="readback">`` (AssertionError with
    Chromium's stderr where the page wrote none)."""
    match = re.search(r'<pre id="readback">(.*?)</pre>', dom, re.S)
    assert match and match.group(1), f"no readback from the page: {stderr[-2000:]}"
    return json.loads(html.unescape(match.group(1)))


def run_page(
    browser: str, url: str, profile: Path, *flags: str, timeout: float = 120.0, attempts: int = 2
) -> dict:
    """Open ``url`` (:func:`dump_dom`) and return its readback (:func:`page_readback`).

    A page whose GPU work outlasts Chromium's virtual time budget under load (SwiftShader
    compiling several programs while other processes take the cores) is dumped before it
    wrote its readback: the page is deterministic, so it is run again, up to
    ``attempts`` times, each with a fresh profile.
    """
    for attempt in range(attempts):
        dom, stderr, _ = dump_dom(
            browser, url, profile.with_name(f"{profile.name}-{attempt}"), *flags, timeout=timeout
        )
        if re.search(r'<pre id="readback">.+?</pre>', dom, re.S) or attempt == attempts - 1:
            return page_readback(dom, stderr)
    raise AssertionError("unreachable")


class _Quiet(http.server.SimpleHTTPRequestHandler):
    """Serves files with JavaScript's MIME type (module scripts require it), silently."""

    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".js": "text/javascript",
        ".mjs": "text/javascript",
        ".glsl": "text/plain",
        ".json": "application/json",
    }

    def log_message(self, format, *args):  # noqa: A002 (the base class's name)
        pass


@contextlib.contextmanager
def serve(directory: Path) -> Iterator[str]:
    """Serve ``directory`` on 127.0.0.1 (a free port) while the block runs; yields the
    base URL, ending in ``/``."""
    handler = functools.partial(_Quiet, directory=str(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


def three_directory() -> Path:
    """Return where :func:`install_three` puts three.js: ``node_modules/three`` under
    ``$XDG_CACHE_HOME/ocio-thinfilm/npm-three-<version>`` (default ``~/.cache``)."""
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "ocio-thinfilm" / f"npm-three-{THREE_VERSION}" / "node_modules" / "three"


def install_three() -> Path:
    """Install three.js :data:`THREE_VERSION` with npm (once) and return its directory.

    Returns
    -------
    pathlib.Path
        :func:`three_directory`, holding ``build/three.module.js``.

    Raises
    ------
    RuntimeError
        Without npm, or when the install fails (no network): the reason, in one line.
    """
    target = three_directory()
    if (target / "build" / "three.module.js").exists():
        return target
    npm = shutil.which("npm")
    if npm is None:
        raise RuntimeError("no npm to install three.js with")
    prefix = target.parents[1]
    prefix.mkdir(parents=True, exist_ok=True)
    done = subprocess.run(
        [
            npm,
            "install",
            "--prefix",
            str(prefix),
            "--no-audit",
            "--no-fund",
            f"three@{THREE_VERSION}",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    if done.returncode != 0 or not (target / "build" / "three.module.js").exists():
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"npm install three@{THREE_VERSION} failed: {last}")
    return target


if __name__ == "__main__":  # .ci/run: python -m evaluation.browser
    print(f"three.js {THREE_VERSION} in {install_three()}")
