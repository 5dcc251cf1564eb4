"""A static HTML page to choose the compression's knobs: the exported GLSL in WebGL2.

``docs/knobs.html`` is written by :func:`write_knob_page` and committed. Opened from disk
(``file://``, no server), it draws test colours through the ``Constant-Lightness Clip``
and ``Constant-Lightness Compress`` views of an SDR display, each view being the GLSL of
:func:`ocio_thinfilm.export.shader.shader_source` (one WebGL2 program per shader; the
CIE-XYZ-D65 test colours uploaded as an RGBA32F texture and read with ``texelFetch``;
the view's code values written to the canvas). Sliders set the compression's uniforms
``ocio_thinfilm_threshold`` and ``ocio_thinfilm_limit``, a select the display, and the
page prints the knobs ready to paste: the ``ocio-thinfilm bake`` and ``export shader``
options and the DCTL sliders' values.

The test colours (:func:`sample_rows`) are computed here, by the package:

- the spectrum, 380-700 nm, at two luminances (:func:`.colorimetry.spectral_locus_XYZ`;
  Smits & Meyer's Figure 4);
- a soap film's colours over optical thickness 0-1500 nm (:func:`.colorimetry.film_XYZ`,
  phase change: Eq. 7);
- three saturated ramps of light at constant luminance from the display white's grey
  towards monochromatic colours, out to well beyond every display's gamut.

The page takes settings from its URL query, ``?display=sRGB&threshold=0.6&limit=1.5``:
its script sets the select and the sliders and dispatches their ``change`` and ``input``
events, as a user's hand would. ``&readback=1`` then writes the canvas read back with
``gl.readPixels`` (and the knobs and display it drew with) as JSON into the
``<pre id="readback">`` element (``tests/test_knob_page.py`` reads it from headless
Chromium's ``--dump-dom``).

Display P3 draws into a canvas whose ``drawingBufferColorSpace`` is ``"display-p3"``
where the browser has it; Rec.2020 codes are shown as they are (no browser shows a
canvas as BT.2020 / BT.1886).
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
from ocio_thinfilm.io import StrPath, check_output_file, write_text

__all__ = [
    "DISPLAYS",
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
#: Samples per test row, and the canvas's width in pixels (one column per sample).
WIDTH = 640
#: Height of one strip (one test row through one view), pixels.
BAND_HEIGHT = 20
#: Background pixels between a test row's two strips, and between two test rows.
INNER_GAP = 2
GROUP_GAP = 10
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
    axis : str
        What varies from left to right.
    XYZ : numpy.ndarray
        float64 (WIDTH, 3), rounded to :data:`DIGITS` significant digits (the values the
        page embeds).
    """

    label: str
    axis: str
    XYZ: np.ndarray


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
                "380 nm to 700 nm",
                _rounded(colorimetry.spectral_locus_XYZ(Y, wl)),
            )
        )
    lo, hi = FILM_RANGE_NM
    t = np.linspace(lo, hi, WIDTH)
    rows.append(
        Row(
            "Soap film (phase change)",
            f"optical thickness {lo:g} nm to {hi:g} nm",
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
        rows.append(
            Row(
                f"Ramp to {w:g} nm, Y = {RAMP_Y:g}",
                f"grey to {reach * d:.2g}x the sRGB boundary{end}",
                _rounded(grey + s * reach * (spectral - grey)),
            )
        )
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
    [(0, 'clip', 0), (0, 'compress', 22), (1, 'clip', 52), (1, 'compress', 74)]
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
    94
    """
    last = bands(n_rows)[-1]
    return last.top + last.height


def _json_script(data: object) -> str:
    """Return JSON safe inside ``<script>``: no ``</`` can end the element."""
    return json.dumps(data, separators=(",", ":"), ensure_ascii=True).replace("</", "<\\/")


_STYLE = """
body { font: 15px/1.45 system-ui, sans-serif; margin: 1.5em auto; max-width: 70em;
       padding: 0 1em; color: #ddd; background: #222; }
a { color: #9cf; }
code, pre { font: 13px/1.4 ui-monospace, monospace; }
pre { background: #111; padding: 0.7em; overflow-x: auto; white-space: pre-wrap; }
#controls { display: flex; flex-wrap: wrap; gap: 0.6em 2em; align-items: center;
            margin: 1em 0; }
#controls input[type=range] { width: 14em; vertical-align: middle; }
#controls output { display: inline-block; min-width: 2.6em; font-weight: bold; }
#figure { display: flex; gap: 0.8em; align-items: flex-start; }
#labels { position: relative; width: 22em; flex: none; }
#labels div { position: absolute; right: 0; font-size: 12px; line-height: 1.2;
              text-align: right; white-space: nowrap; }
#labels .group { right: 5.5em; }
#labels .axis { color: #999; }
#view { image-rendering: pixelated; flex: none; }
#note { color: #fc6; }
#status:empty, #note:empty { display: none; }
#readback { display: none; }
"""

_SCRIPT = r"""
"use strict";
(function () {
  const DATA = JSON.parse(document.getElementById("__DATA_ID__").textContent);
  const $ = (id) => document.getElementById(id);
  const canvas = $("view"), select = $("display");
  const sliders = { threshold: $("threshold"), limit: $("limit") };
  const status = $("status"), note = $("note");
  const gl = canvas.getContext("webgl2", {
    alpha: false, antialias: false, depth: false, stencil: false,
    premultipliedAlpha: false, preserveDrawingBuffer: true,
  });
  let error = gl ? null : "this browser gives no WebGL2 context";

  const VERTEX = "#version 300 es\n" +
    "void main()\n{\n" +
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n" +
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n";
  const HEAD = "#version 300 es\nprecision highp float;\nprecision highp int;\n" +
    "precision highp sampler2D;\nuniform sampler2D ocio_thinfilm_xyz;\n" +
    "uniform int ocio_thinfilm_row;\nout vec4 ocio_thinfilm_colour;\n";
  const MAIN = "\nvoid main()\n{\n" +
    "    ivec2 at = ivec2(int(gl_FragCoord.x), ocio_thinfilm_row);\n" +
    "    vec3 xyz = texelFetch(ocio_thinfilm_xyz, at, 0).rgb;\n" +
    "    ocio_thinfilm_colour = vec4(ocio_thinfilm_view(xyz), 1.0);\n}\n";

  function compile(type, source) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
      throw new Error("shader does not compile: " + gl.getShaderInfoLog(s));
    }
    return s;
  }

  function link(fragment) {
    const p = gl.createProgram();
    gl.attachShader(p, compile(gl.VERTEX_SHADER, VERTEX));
    gl.attachShader(p, compile(gl.FRAGMENT_SHADER, HEAD + fragment + MAIN));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) {
      throw new Error("program does not link: " + gl.getProgramInfoLog(p));
    }
    return p;
  }

  const programs = {};
  function programsOf(display) {
    if (!programs[display]) {
      const code = DATA.shaders[display];
      programs[display] = { clip: link(code.clip), compress: link(code.compress) };
    }
    return programs[display];
  }

  if (gl) {
    try {
      const rows = DATA.rows.length, width = DATA.width;
      const texels = new Float32Array(width * rows * 4);
      DATA.rows.forEach((row, r) => {
        for (let i = 0; i < width; i++) {
          for (let c = 0; c < 3; c++) texels[4 * (r * width + i) + c] = row.xyz[3 * i + c];
          texels[4 * (r * width + i) + 3] = 1.0;
        }
      });
      const texture = gl.createTexture();
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, rows, 0, gl.RGBA, gl.FLOAT, texels);
      gl.bindVertexArray(gl.createVertexArray());
    } catch (e) {
      error = String(e.message || e);
    }
  }

  // the knobs as the sliders hold them, to their step (0.01)
  function knob(name) {
    return Number(Number(sliders[name].value).toFixed(2));
  }

  function draw() {
    if (!gl || error) return;
    const display = select.value;
    let p;
    try {
      p = programsOf(display);
    } catch (e) {
      error = String(e.message || e);
      status.textContent = "Cannot draw: " + error;
      return;
    }
    const h = canvas.height;
    gl.viewport(0, 0, canvas.width, h);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(0.13, 0.13, 0.13, 1.0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.enable(gl.SCISSOR_TEST);
    for (const band of DATA.bands) {
      const program = p[band.view];
      gl.useProgram(program);
      gl.uniform1i(gl.getUniformLocation(program, "ocio_thinfilm_xyz"), 0);
      gl.uniform1i(gl.getUniformLocation(program, "ocio_thinfilm_row"), band.row);
      const t = gl.getUniformLocation(program, "ocio_thinfilm_threshold");
      const l = gl.getUniformLocation(program, "ocio_thinfilm_limit");
      if (t !== null) gl.uniform1f(t, knob("threshold"));
      if (l !== null) gl.uniform1f(l, knob("limit"));
      gl.scissor(0, h - band.top - band.height, canvas.width, band.height);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    gl.disable(gl.SCISSOR_TEST);
  }

  function q(text) {
    return /^[\w.+-]+$/.test(text) ? text : '"' + text + '"';
  }

  function update() {
    const t = knob("threshold"), l = knob("limit"), display = select.value;
    $("threshold-value").textContent = t.toFixed(2);
    $("limit-value").textContent = l.toFixed(2);
    const knobs = "--compress-threshold " + t + " --compress-limit " + l;
    $("commands").textContent = [
      "# the config's Constant-Lightness Compress views, baked with these knobs",
      "ocio-thinfilm bake " + knobs,
      "# DaVinci Resolve DCTL with these knobs as its sliders' defaults",
      "ocio-thinfilm export shader --lang dctl --display " + q(display) +
        " --view " + q(DATA.views.compress) + " " + knobs + " --out compress.dctl",
      "# ... or the sliders of any exported Compress DCTL (ResolveFX DCTL)",
      "Threshold " + t.toFixed(2) + "    Limit " + l.toFixed(2),
      "# GLSL (three.js, a game engine, Matchbox): the uniforms",
      "ocio_thinfilm_threshold = " + t.toFixed(2) + ";  ocio_thinfilm_limit = " +
        l.toFixed(2) + ";",
    ].join("\n");
    draw();
  }

  function changeDisplay() {
    const display = select.value;
    let text = DATA.notes[display] || "";
    if (gl && display === "Display P3" && !("drawingBufferColorSpace" in gl)) {
      text = DATA.noP3;
    }
    note.textContent = text;
    if (gl && "drawingBufferColorSpace" in gl) {
      gl.drawingBufferColorSpace = display === "Display P3" ? "display-p3" : "srgb";
    }
    update();
  }

  select.addEventListener("change", changeDisplay);
  sliders.threshold.addEventListener("input", update);
  sliders.limit.addEventListener("input", update);
  $("defaults").addEventListener("click", () => {
    sliders.threshold.value = DATA.defaults.threshold;
    sliders.limit.value = DATA.defaults.limit;
    sliders.threshold.dispatchEvent(new Event("input"));
    sliders.limit.dispatchEvent(new Event("input"));
  });
  changeDisplay();
  if (error) status.textContent = "Cannot draw: " + error;

  // settings from the URL query, through the same events as a user's
  const query = new URLSearchParams(window.location.search);
  if (query.has("display")) {
    select.value = query.get("display");
    select.dispatchEvent(new Event("change"));
  }
  for (const name of ["threshold", "limit"]) {
    if (query.has(name)) {
      sliders[name].value = query.get(name);
      sliders[name].dispatchEvent(new Event("input"));
    }
  }
  if (query.get("readback") === "1") {
    const out = {
      display: select.value,
      threshold: knob("threshold"),
      limit: knob("limit"),
      width: canvas.width,
      height: canvas.height,
      origin: "bottom-left",
      drawingBufferColorSpace: gl && gl.drawingBufferColorSpace ? gl.drawingBufferColorSpace : null,
      error: error,
      rgba: null,
    };
    if (gl && !error) {
      const px = new Uint8Array(canvas.width * canvas.height * 4);
      gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
      let bytes = "";
      for (let i = 0; i < px.length; i += 0x8000) {
        bytes += String.fromCharCode.apply(null, px.subarray(i, i + 0x8000));
      }
      out.rgba = btoa(bytes);
    }
    $("readback").textContent = JSON.stringify(out);
  }
})();
"""

_NOTES = {
    "sRGB": "",
    "Display P3": (
        "Display P3 codes, drawn into a canvas tagged display-p3 (drawingBufferColorSpace): "
        "a colour-managed browser shows them as Display P3 on a wide-gamut screen."
    ),
    "Rec.2020": (
        "Rec.2020 codes are shown as they are: no browser shows a canvas as BT.2020 with "
        "BT.1886, so these codes appear as if they were sRGB (duller, other hues). Compare "
        "the knobs with them; judge the colours on a Rec.2020 monitor."
    ),
}
_NO_P3 = (
    "This browser cannot tag a WebGL canvas as Display P3: the P3 codes are shown as if "
    "they were sRGB (duller, other hues)."
)


def _body(rows: list[Row], layout: list[Band], height: int) -> str:
    """Return the page's visible HTML: controls, the labelled canvas, commands, notes."""
    e = html.escape
    t_lo, t_hi, t_step = shader.THRESHOLD_SLIDER
    l_lo, l_hi, l_step = shader.LIMIT_SLIDER
    options = "".join(f'<option value="{e(d)}">{e(d)}</option>' for d in DISPLAYS)
    labels = []
    for band in layout:
        row = rows[band.row]
        mid = band.top + band.height / 2
        labels.append(f'<div style="top:{mid - 7:g}px">{e(VIEW_KEYS[band.view].split()[-1])}</div>')
        if band.view == "clip":
            labels.append(
                f'<div class="group" style="top:{band.top + band.height + INNER_GAP / 2 - 15:g}px">'
                f'{e(row.label)}<br><span class="axis">{e(row.axis)}</span></div>'
            )
    return f"""<h1>Constant-Lightness Compress: choose the knobs</h1>
<p>Smits &amp; Meyer's constant-lightness gamut clip (<i>Newton's Colors</i>, 1990,
Section 3.2) moves colours outside the display's gamut towards the grey of the same
luminance until they reach the gamut's boundary. The compression keeps that ray and the
luminance and softens the cut: colours up to <b>threshold</b> of the way to the boundary stay
as they are, and the rest is compressed with the ACES 1.3 power curve so that a colour
<b>limit</b> boundary distances out lands on the boundary (further out: the clip). Each
test row below is drawn through the clip (top strip) and through the compression (bottom
strip); both are the GLSL that <code>ocio-thinfilm export shader</code> writes, run by your
browser's WebGL2.</p>
<div id="controls">
<label>Display <select id="display">{options}</select></label>
<label>Threshold <input type="range" id="threshold" min="{t_lo:g}" max="{t_hi:g}"
 step="{t_step:g}" value="{compress.THRESHOLD:g}"> <output id="threshold-value"></output></label>
<label>Limit <input type="range" id="limit" min="{l_lo:g}" max="{l_hi:g}" step="{l_step:g}"
 value="{compress.LIMIT:g}"> <output id="limit-value"></output></label>
<button id="defaults" type="button">Defaults ({compress.THRESHOLD:g} / {compress.LIMIT:g})</button>
</div>
<p id="note"></p>
<p id="status"></p>
<div id="figure">
<div id="labels" style="height:{height}px">
{chr(10).join(labels)}
</div>
<canvas id="view" width="{WIDTH}" height="{height}"
 style="width:{WIDTH}px;height:{height}px"></canvas>
</div>
<h2>Paste</h2>
<pre id="commands"></pre>
<h2>Reading the strips</h2>
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
            {"label": r.label, "axis": r.axis, "xyz": [float(v) for v in r.XYZ.ravel()]}
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
    script = _SCRIPT.replace("__DATA_ID__", DATA_ID).strip("\n")
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<title>Constant-Lightness Compress: choose the knobs (ocio-thinfilm)</title>\n"
        f"<style>{_STYLE}</style>\n</head>\n<body>\n"
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
