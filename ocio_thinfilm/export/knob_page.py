"""A static HTML page to choose the compression's knobs: the exported GLSL in WebGL2.

``docs/knobs.html`` is written by :func:`write_knob_page` and committed. Opened from disk
(``file://``, no server), it draws test colours (:func:`sample_rows`: the spectrum,
Smits & Meyer's Figure 4; a soap film's colours, Eq. 7; saturated ramps at constant
luminance) through the ``Constant-Lightness Clip`` and ``Constant-Lightness Compress``
views of an SDR display, each the GLSL of
:func:`ocio_thinfilm.export.shader.shader_source` in a WebGL2 program. Sliders set the
compression's uniforms, a select the display, and the page prints the knobs ready to
paste (the ``ocio-thinfilm bake`` and ``export shader`` options, the DCTL sliders'
values; the DCTL's input space from :data:`SOURCES`).

The page takes settings from its URL query (``?display=sRGB&threshold=0.6&limit=1.5``,
``&source=ACEScg``); ``&readback=1`` writes what it drew as JSON into
``<pre id="readback">`` (``tests/test_knob_page.py`` reads it from headless Chromium).
The style sheet and the script are :mod:`.knob_page_script`'s. More: docs/compress.md,
*Design notes*.
"""

from __future__ import annotations

import html
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ocio_thinfilm import __version__, registry
from ocio_thinfilm.colour import colorimetry, compress
from ocio_thinfilm.export import shader
from ocio_thinfilm.export.knob_page_script import SCRIPT, STYLE
from ocio_thinfilm.io import StrPath, check_output_file, write_text

__all__ = [
    "DISPLAYS",
    "SOURCES",
    "DEFAULT_SOURCE",
    "WIDTH",
    "BAND_HEIGHT",
    "INNER_GAP",
    "GROUP_GAP",
    "DATA_ID",
    "Row",
    "Band",
    "sample_rows",
    "bands",
    "canvas_height",
    "knob_page_html",
    "write_knob_page",
]

#: The displays the page offers (the SDR ones: a browser canvas holds 8-bit SDR codes).
DISPLAYS = registry.DISPLAYS
#: The input spaces the page's DCTL command offers: the encoded and scene-linear spaces
#: ``export shader --from`` takes, encoded first (what a grading timeline holds).
SOURCES = tuple(
    s for s in registry.ENCODED_SPACES + registry.SCENE_LINEAR_SPACES if s in shader.SHADER_SOURCES
)
#: The one selected when the page opens (Resolve's ACES timelines grade in ACEScct).
DEFAULT_SOURCE = "ACEScct"
#: Samples per test row, and the canvas's width in pixels (one column per sample).
WIDTH = 640
#: Height of one strip (one test row through one view), pixels.
BAND_HEIGHT = 56
#: Background pixels between a test row's two strips, and between two test rows (room
#: for the ramps' marks' letters).
INNER_GAP = 2
GROUP_GAP = 20
#: The ``id`` of the page's ``<script type="application/json">`` with its data.
DATA_ID = "ocio-thinfilm-data"
#: Significant digits of the embedded XYZ values (the texture is float32).
DIGITS = 6
#: Luminances of the spectrum's rows.
SPECTRUM_Y = (0.1, 0.4)
#: The soap film's optical thickness range, nm.
FILM_RANGE_NM = (0.0, 1500.0)
#: The ramps' luminance, and for each its wavelength (nm) and how far it goes: up to the
#: monochromatic colour itself or ``RAMP_REACH`` sRGB boundary distances from the grey,
#: whichever is nearer.
RAMP_Y = 0.25
RAMP_WAVELENGTHS = (470.0, 510.0, 650.0)
RAMP_REACH = 2.5
#: The views, as the page and its readback name them.
VIEW_KEYS = {"clip": shader.SHADER_VIEWS[0], "compress": shader.SHADER_VIEWS[1]}


@dataclass(frozen=True)
class Row:
    """One row of test colours: a label and ``WIDTH`` CIE-XYZ-D65 values.

    Attributes
    ----------
    label : str
        What the row holds, as the page shows it.
    axis : dict
        What varies from left to right, by display name (:data:`DISPLAYS`).
    XYZ : numpy.ndarray
        float64 (WIDTH, 3), rounded to :data:`DIGITS` significant digits (the values the
        page embeds).
    reach : dict or None
        A ramp's boundary distance at its last column, by display name (it grows
        linearly from 0 at the grey); None for the other rows.
    """

    label: str
    axis: dict[str, str]
    XYZ: np.ndarray
    reach: dict[str, float] | None = None


@dataclass(frozen=True)
class Band:
    """One strip of the canvas: a test row drawn through one view.

    Attributes
    ----------
    row : int
        Index into :func:`sample_rows`.
    view : str
        ``"clip"`` or ``"compress"`` (:data:`VIEW_KEYS`).
    top : int
        First canvas row (pixels from the top).
    height : int
        Its height in pixels.
    """

    row: int
    view: str
    top: int
    height: int


def _rounded(XYZ: np.ndarray) -> np.ndarray:
    """Return values rounded to :data:`DIGITS` significant digits, as the page holds them."""
    return np.array([float(f"{v:.{DIGITS}g}") for v in np.ravel(XYZ)]).reshape(XYZ.shape)


def sample_rows() -> list[Row]:
    """Return the page's test colours, computed by the package.

    Returns
    -------
    list of Row
        Two spectrum rows, the soap-film row and the ramps, each ``WIDTH`` XYZ values.

    Examples
    --------
    >>> rows = sample_rows()
    >>> len(rows), rows[0].XYZ.shape
    (6, (640, 3))
    >>> bool(np.allclose(rows[0].XYZ[:, 1], 0.1))
    True
    """
    rows = []
    wl = np.linspace(380.0, 700.0, WIDTH)
    for Y in SPECTRUM_Y:
        rows.append(
            Row(
                f"Spectrum, Y = {Y:g}",
                dict.fromkeys(DISPLAYS, "380 nm to 700 nm"),
                _rounded(colorimetry.spectral_locus_XYZ(Y, wl)),
            )
        )
    lo, hi = FILM_RANGE_NM
    t = np.linspace(lo, hi, WIDTH)
    rows.append(
        Row(
            "Soap film (phase change)",
            dict.fromkeys(DISPLAYS, f"optical thickness {lo:g} nm to {hi:g} nm"),
            _rounded(colorimetry.film_XYZ(t, "phase-change")),
        )
    )
    grey = RAMP_Y * colorimetry.white_XYZ("sRGB")
    s = np.linspace(0.0, 1.0, WIDTH)[:, None]
    for w in RAMP_WAVELENGTHS:
        spectral = colorimetry.spectral_locus_XYZ(RAMP_Y, [w])[0]
        d = float(compress.boundary_distance(colorimetry.XYZ_to_RGB(spectral, "sRGB"), "sRGB"))
        reach = min(1.0, RAMP_REACH / d)
        end = " (spectral)" if reach == 1.0 else ""
        XYZ = _rounded(grey + s * reach * (spectral - grey))
        last = {
            g: float(compress.boundary_distance(colorimetry.XYZ_to_RGB(XYZ[-1], g), g))
            for g in DISPLAYS
        }
        axis = {g: f"grey to {last[g]:.2g}x the {g} boundary{end}" for g in DISPLAYS}
        rows.append(Row(f"Ramp to {w:g} nm, Y = {RAMP_Y:g}", axis, XYZ, last))
    return rows


def bands(n_rows: int | None = None) -> list[Band]:
    """Return the canvas layout: each test row through the clip, then the compression.

    Parameters
    ----------
    n_rows : int, optional
        The number of test rows (default: :func:`sample_rows`'s).

    Returns
    -------
    list of Band
        Top to bottom, :data:`BAND_HEIGHT` pixels each, :data:`INNER_GAP` between a
        row's two strips and :data:`GROUP_GAP` between rows.

    Examples
    --------
    >>> [(b.row, b.view, b.top) for b in bands(2)]
    [(0, 'clip', 0), (0, 'compress', 58), (1, 'clip', 134), (1, 'compress', 192)]
    """
    n = len(sample_rows()) if n_rows is None else n_rows
    out, top = [], 0
    for row in range(n):
        for view in VIEW_KEYS:
            out.append(Band(row, view, top, BAND_HEIGHT))
            top += BAND_HEIGHT + INNER_GAP
        top += GROUP_GAP - INNER_GAP
    return out


def canvas_height(n_rows: int | None = None) -> int:
    """Return the canvas's height in pixels for ``n_rows`` test rows.

    Parameters
    ----------
    n_rows : int, optional
        The number of test rows (default: :func:`sample_rows`'s).

    Returns
    -------
    int
        The last band's bottom.

    Examples
    --------
    >>> canvas_height(2)
    248
    """
    last = bands(n_rows)[-1]
    return last.top + last.height


def _json_script(data: object) -> str:
    """Return JSON safe inside ``<script>``: no ``</`` can end the element."""
    return json.dumps(data, separators=(",", ":"), ensure_ascii=True).replace("</", "<\\/")


#: The canvas colour spaces browsers have (WebGL's ``drawingBufferColorSpace``), by the
#: display whose codes they show as they are meant.
_CANVAS_SPACES = {"sRGB": "srgb", "Display P3": "display-p3"}


def _note(display: registry.Display) -> str:
    """Return what the page says under the canvas when ``display`` is chosen."""
    if display.name == "sRGB":
        return ""
    if display.name in _CANVAS_SPACES:
        return (
            f"{display.name} codes, drawn into a canvas tagged "
            f"{_CANVAS_SPACES[display.name]} (drawingBufferColorSpace): a colour-managed "
            f"browser shows them as {display.name} on a wide-gamut screen."
        )
    same = display.primaries == registry.DISPLAY_LIST[0].primaries
    looks = "the same hues, other tones" if same else "duller, other hues"
    return (
        f"{display.name} codes are shown as they are: browsers show a canvas only as "
        f"{' or '.join(_CANVAS_SPACES)}, so these codes appear as if they were sRGB "
        f"({looks}). Compare the knobs with them; judge the colours on a {display.name} "
        "display."
    )


_NOTES = {d.name: _note(d) for d in registry.DISPLAY_LIST}
_NO_P3 = (
    "This browser cannot tag a WebGL canvas as Display P3: the P3 codes are shown as if "
    "they were sRGB (duller, other hues)."
)


#: The ramps' marks: id suffix, letter, tooltip; and the letters' room above a ramp, px.
_MARKS = (
    ("threshold", "T", "threshold"),
    ("boundary", "1", "the display's gamut boundary, d = 1"),
    ("limit", "L", "limit"),
)
_MARK_LABEL = 13


def _body(rows: list[Row], layout: list[Band], height: int) -> str:
    """Return the page's visible HTML: controls, the labelled canvas, commands, notes."""
    return _intro() + _controls() + _figure(rows, layout, height) + _commands() + _notes()


def _intro() -> str:
    """Return the page's title and what the compression does."""
    return """<h1>Constant-Lightness Compress: choose the knobs</h1>
<p>Smits &amp; Meyer's constant-lightness gamut clip (<i>Newton's Colors</i>, 1990,
Section 3.2) moves colours outside the display's gamut towards the grey of the same
luminance until they reach the gamut's boundary. The compression keeps that ray and the
luminance and softens the cut: colours up to <b>threshold</b> of the way to the boundary stay
as they are, and the rest is compressed with the ACES 1.3 power curve so that a colour
<b>limit</b> boundary distances out lands on the boundary (further out: the clip). Each
test row below is drawn through the clip (top strip) and through the compression (bottom
strip); both are the GLSL that <code>ocio-thinfilm export shader</code> writes, run by your
browser's WebGL2.</p>
"""


def _controls() -> str:
    """Return the knobs: the display, the threshold and limit sliders, the defaults."""
    e = html.escape
    t_lo, t_hi, t_step = shader.THRESHOLD_SLIDER
    l_lo, l_hi, l_step = shader.LIMIT_SLIDER
    options = "".join(f'<option value="{e(d)}">{e(d)}</option>' for d in DISPLAYS)
    return f"""<div id="controls">
<label>Display <select id="display">{options}</select></label>
<label>Threshold <input type="range" id="threshold" min="{t_lo:g}" max="{t_hi:g}"
 step="{t_step:g}" value="{compress.THRESHOLD:g}"> <output id="threshold-value"></output></label>
<label>Limit <input type="range" id="limit" min="{l_lo:g}" max="{l_hi:g}" step="{l_step:g}"
 value="{compress.LIMIT:g}"> <output id="limit-value"></output></label>
<button id="defaults" type="button">Defaults ({compress.THRESHOLD:g} / {compress.LIMIT:g})</button>
</div>
<p id="note"></p>
<p id="status"></p>
"""


def _figure(rows: list[Row], layout: list[Band], height: int) -> str:
    """Return the canvas with its strips' labels and the ramps' marks, and their key."""
    e = html.escape
    labels, marks = [], []
    for band in layout:
        row = rows[band.row]
        mid = band.top + band.height / 2
        labels.append(f'<div style="top:{mid - 7:g}px">{e(VIEW_KEYS[band.view].split()[-1])}</div>')
        if band.view != "clip":
            continue
        labels.append(
            f'<div class="group" style="top:{band.top + band.height + INNER_GAP / 2 - 15:g}px">'
            f'{e(row.label)}<br><span class="axis" id="axis-{band.row}">'
            f"{e(row.axis[DISPLAYS[0]])}</span></div>"
        )
        if row.reach is not None:  # the script places them
            span = 2 * band.height + INNER_GAP + _MARK_LABEL
            marks += [
                f'<div id="mark-{band.row}-{name}" title="{title}" '
                f'style="top:{band.top - _MARK_LABEL}px;height:{span}px">'
                f"<span>{letter}</span></div>"
                for name, letter, title in _MARKS
            ]
    return f"""<div id="figure">
<div id="labels" style="height:{height}px">
{chr(10).join(labels)}
</div>
<div id="plot">
<canvas id="view" width="{WIDTH}" height="{height}"
 style="width:{WIDTH}px;height:{height}px"></canvas>
<div id="marks">
{chr(10).join(marks)}
</div>
</div>
</div>
<p>On the ramps, <b>T</b> marks the threshold, <b>1</b> the selected display's gamut
boundary (boundary distance d = 1: where the clip starts) and <b>L</b> the limit (a mark
beyond a ramp's end is not shown).</p>
"""


def _commands() -> str:
    """Return the paste section: the DCTL's input space and the commands."""
    e = html.escape
    sources = "".join(
        f'<option value="{e(s)}"{" selected" if s == DEFAULT_SOURCE else ""}>{e(s)}</option>'
        for s in SOURCES
    )
    return f"""<h2>Paste</h2>
<p><label>The DCTL's input space (the timeline's colour space)
<select id="source">{sources}</select></label></p>
<pre id="commands"></pre>
"""


def _notes() -> str:
    """Return the notes on reading the strips and where the page comes from."""
    e = html.escape
    return f"""<h2>Reading the strips</h2>
<ul>
<li>A lower <b>threshold</b> starts the compression earlier: more of the in-gamut colours
move (they lose saturation), and the shading of the colours outside is kept more
evenly.</li>
<li>A higher <b>limit</b> reaches further out: more of the out-of-gamut colours keep
their shading (the ramps keep rising instead of ending in a flat band), at the cost of
pulling the colours near the boundary further in.</li>
<li>Threshold close to 1 with a limit close to 1 is the clip. The defaults,
{compress.THRESHOLD:g} and {compress.LIMIT:g}, sit inside the range of ACES 1.3's gamut
compression (thresholds 0.80&ndash;0.88, limits 1.15&ndash;1.31), but this compression
works along the paper's ray and keeps the luminance; ACES works per channel.</li>
<li>Luminance is kept exactly: a colour never gets brighter or darker, only less
saturated.</li>
</ul>
<p>The page needs WebGL2 and runs from disk; nothing is loaded from the network. It was
written by ocio-thinfilm {e(__version__)} (<code>ocio_thinfilm.export.knob_page</code>); the
shaders and the test colours are embedded. Docs: <a href="shaders.md">shaders.md</a>.</p>
<pre id="readback"></pre>
"""


def knob_page_html() -> str:
    """Return the knob page: HTML with its style, data (shaders, test colours) and script.

    Returns
    -------
    str
        A complete HTML5 document, UTF-8, self-contained (no network, no server).

    Examples
    --------
    >>> text = knob_page_html()
    >>> text.startswith("<!DOCTYPE html>"), 'id="readback"' in text
    (True, True)
    """
    rows = sample_rows()
    layout = bands(len(rows))
    height = canvas_height(len(rows))
    data = {
        "width": WIDTH,
        "height": height,
        "views": VIEW_KEYS,
        "defaults": {"threshold": compress.THRESHOLD, "limit": compress.LIMIT},
        "rows": [
            {
                "label": r.label,
                "axis": r.axis,
                "reach": r.reach,
                "xyz": [float(v) for v in r.XYZ.ravel()],
            }
            for r in rows
        ],
        "bands": [{"row": b.row, "view": b.view, "top": b.top, "height": b.height} for b in layout],
        "shaders": {
            d: {key: shader.shader_source("glsl", d, view) for key, view in VIEW_KEYS.items()}
            for d in DISPLAYS
        },
        "notes": _NOTES,
        "noP3": _NO_P3,
    }
    script = SCRIPT.replace("__DATA_ID__", DATA_ID).strip("\n")
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<title>Constant-Lightness Compress: choose the knobs (ocio-thinfilm)</title>\n"
        f"<style>{STYLE}</style>\n</head>\n<body>\n"
        + _body(rows, layout, height)
        + f'<script type="application/json" id="{DATA_ID}">{_json_script(data)}</script>\n'
        + f"<script>\n{script}\n</script>\n</body>\n</html>\n"
    )


def write_knob_page(path: StrPath) -> Path:
    """Write :func:`knob_page_html` to ``path`` (written aside, checked, then renamed).

    Parameters
    ----------
    path : str or os.PathLike
        The HTML file (the repository's is ``docs/knobs.html``).

    Returns
    -------
    pathlib.Path
        The file written.

    Raises
    ------
    ValueError
        For a path that cannot be written (naming ``path``).
    OSError
        If the write fails.
    """
    return write_text(check_output_file(path, "path"), knob_page_html())
