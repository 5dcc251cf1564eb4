"""The knob page (docs/knobs.html): committed as generated, and drawing the views right.

The page is opened from disk in headless Chromium (SwiftShader's WebGL2), its URL query
sets the display, the knobs and the DCTL's input space through the page's own controls,
and the canvas it reads back (``<pre id="readback">``) is held, pixel by pixel, to the
double-precision analytic view (:func:`evaluation.shaders.analytic_view`) of the XYZ
values the page embeds. The readback's commands are run, the ramps' marks are held to
where colour-science's RGB of the display leaves [0, 1], and the strips' position is
the same whatever the display's note.
"""

from __future__ import annotations

import base64
import html
import json
import os
import re
import shlex
import warnings
from pathlib import Path

import numpy as np
import pytest

from evaluation import browser
from evaluation.shaders import analytic_view
from ocio_thinfilm import registry
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.export import knob_page, shader

#: The committed page; ``OCIO_THINFILM_TEST_KNOB_PAGE`` points the tests at another
#: generation of it (one written to /tmp before the committed page is regenerated).
PAGE = Path(
    os.environ.get("OCIO_THINFILM_TEST_KNOB_PAGE")
    or Path(__file__).resolve().parents[1] / "docs" / "knobs.html"
)
#: 8-bit canvas codes against the analytic view's code values.
TOLERANCE = 2.0 / 255.0


def test_the_committed_page_is_what_the_generator_writes(tmp_path):
    written = knob_page.write_knob_page(tmp_path / "knobs.html")
    assert PAGE.read_text(encoding="utf-8") == written.read_text(encoding="utf-8"), (
        "docs/knobs.html is stale: regenerate it with "
        "python -c 'from ocio_thinfilm.export.knob_page import write_knob_page; "
        'write_knob_page("docs/knobs.html")\''
    )


def test_the_page_embeds_the_exported_glsl_and_is_self_contained():
    text = PAGE.read_text(encoding="utf-8")
    data = _data(text)
    assert set(data["shaders"]) == set(registry.DISPLAYS)
    for display, views in data["shaders"].items():
        for key, view in knob_page.VIEW_KEYS.items():
            assert views[key] == shader.shader_source("glsl", display, view)
    assert not re.search(r"""(src|href)=["']?(https?:)?//""", text)  # nothing from the net
    assert "drawingBufferColorSpace" in text and "readPixels" in text


def _data(text):
    block = re.search(
        rf'<script type="application/json" id="{knob_page.DATA_ID}">(.*?)</script>', text, re.S
    )
    return json.loads(block.group(1))


def _readback(chromium, tmp_path, query):
    """Open the page with ``query`` and return its readback JSON and the seconds it took."""
    dom, stderr, seconds = browser.dump_dom(
        chromium, f"{PAGE.as_uri()}?{query}&readback=1", tmp_path / "profile"
    )
    return browser.page_readback(dom, stderr), seconds


@pytest.mark.parametrize(
    "display, threshold, limit",
    # every display of the page at the default knobs; other knobs on two of them
    [(d, 0.8, 1.3) for d in knob_page.DISPLAYS] + [("sRGB", 0.6, 1.5), ("Display P3", 0.9, 1.1)],
)
def test_the_page_draws_the_analytic_view(chromium, tmp_path, display, threshold, limit):
    """Every canvas pixel of every strip within 2/255 of the analytic view; the gaps
    between the strips are the background."""
    out, seconds = _readback(
        chromium, tmp_path, f"display={display}&threshold={threshold}&limit={limit}"
    )
    if out["error"] == "this browser gives no WebGL2 context":
        pytest.skip("this Chromium gives no WebGL2 context headless (no SwiftShader)")
    assert out["error"] is None, out["error"]
    assert (out["display"], out["threshold"], out["limit"]) == (display, threshold, limit)
    if display == "Display P3":
        assert out["drawingBufferColorSpace"] == "display-p3"
    width, height = out["width"], out["height"]
    assert (width, height) == (knob_page.WIDTH, knob_page.canvas_height())
    rgba = np.frombuffer(base64.b64decode(out["rgba"]), dtype=np.uint8)
    canvas = rgba.reshape(height, width, 4)[::-1] / 255.0  # top row first
    data = _data(PAGE.read_text(encoding="utf-8"))
    drawn = np.zeros(height, bool)
    worst, exact, total, moved = {}, 0, 0, 0.0
    for band in knob_page.bands():
        XYZ = np.asarray(data["rows"][band.row]["xyz"], np.float32).reshape(-1, 3)
        view = knob_page.VIEW_KEYS[band.view]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            truth = analytic_view(XYZ, registry.REFERENCE, display, view, threshold, limit)
        strip = canvas[band.top : band.top + band.height, :, :3]
        err = np.abs(strip - truth[None]).max()
        if band.view == "compress" and (threshold, limit) != (0.8, 1.3):
            default = analytic_view(XYZ, registry.REFERENCE, display, view)
            moved = max(moved, float(np.abs(truth - default).max()))
        key = (data["rows"][band.row]["label"], band.view)
        worst[key] = round(float(err) * 255, 3)
        exact += int((np.round(strip * 255) == np.round(truth * 255)[None]).sum())
        total += strip.size
        drawn[band.top : band.top + band.height] = True
    print(
        f"\n{display} {threshold}/{limit}: max |page - analytic| = "
        f"{max(worst.values()):.3f}/255; {exact / total:.2%} of the 8-bit codes equal to "
        f"the analytic view's rounded (Chromium {seconds:.1f} s); per strip (1/255): {worst}"
    )
    assert max(worst.values()) <= TOLERANCE * 255
    if (threshold, limit) != (0.8, 1.3):  # the knobs set by the query do show
        assert moved > 10 * TOLERANCE
    assert np.all(canvas[~drawn, :, 3] == 1.0)
    assert np.ptp(canvas[~drawn, :, :3]) == 0.0  # the gaps: one background colour


def test_the_page_offers_the_input_spaces_export_shader_takes():
    """Every encoded space of the registry (the grading timelines' log spaces) and every
    scene-linear one, ACEScct selected; each one a source ``export shader`` writes."""
    text = PAGE.read_text(encoding="utf-8")
    select = re.search(r'<select id="source">(.*?)</select>', text, re.S).group(1)
    options = re.findall(r'<option value="([^"]*)"( selected)?>', select)
    names = [html_name for html_name, _ in options]
    assert set(registry.ENCODED_SPACES) <= set(names) and "ACEScg" in names
    assert [n for n, selected in options if selected] == ["ACEScct"]
    for name in names:
        shader.shader_source("dctl", "sRGB", registry.COMPRESS_VIEW, html.unescape(name))


def test_the_strips_are_large_enough_to_compare():
    assert knob_page.BAND_HEIGHT >= 48


def _ramp_columns(XYZ, display):
    """The fractional column where a ramp leaves the display's gamut: colour-science's
    RGB of the display's primaries and white (evaluation/truth.py) leaving [0, 1]
    (linear between two columns)."""
    from evaluation.truth import colour_science_RGB_to_XYZ

    rgb = XYZ @ np.linalg.inv(colour_science_RGB_to_XYZ(display)).T  # Bradford for DCI
    inside = np.minimum(rgb.min(axis=1), 1.0 - rgb.max(axis=1))
    c = int(np.argmax(inside < 0))
    assert c > 0
    return c - 1 + inside[c - 1] / (inside[c - 1] - inside[c])


#: The controls set together: three examples of knobs and input space, and every other
#: display of the page at the defaults.
COMMAND_CASES = [
    ("sRGB", 0.8, 1.3, None),
    ("Display P3", 0.6, 1.5, "ACEScg"),
    ("Rec.2020", 0.9, 2.5, "Linear Rec.709 (sRGB)"),
]
COMMAND_CASES += [
    (d, 0.8, 1.3, None) for d in knob_page.DISPLAYS if d not in {c[0] for c in COMMAND_CASES}
]


@pytest.mark.parametrize("display, threshold, limit, source", COMMAND_CASES)
def test_the_commands_marks_and_axes_follow_the_controls(
    chromium, tmp_path, display, threshold, limit, source
):
    query = f"display={display}&threshold={threshold}&limit={limit}"
    if source is not None:
        query += f"&source={source}"
    out, _ = _readback(chromium, tmp_path, query)
    # the DCTL command: --from the selected space (ACEScct unless chosen), and it runs
    expected = "ACEScct" if source is None else source
    assert out["source"] == expected
    line = next(x for x in out["commands"].splitlines() if "--lang dctl" in x)
    args = shlex.split(line)
    assert args[args.index("--from") + 1] == expected
    assert args[args.index("--display") + 1] == display
    dctl = tmp_path / "compress.dctl"
    args[args.index("--out") + 1] = str(dctl)
    assert cli.main(args[1:]) == 0
    assert dctl.read_text().startswith("// ") and expected in dctl.read_text()
    # the ramps: the axis names the display's boundary; the marks where d = t, 1, limit
    data = _data(PAGE.read_text(encoding="utf-8"))
    ramps = [r for r, row in enumerate(data["rows"]) if row["reach"] is not None]
    assert len(ramps) == len(knob_page.RAMP_WAVELENGTHS)
    worst = 0.0
    for r in ramps:
        assert f"the {display} boundary" in out["axes"][r]
        XYZ = np.asarray(data["rows"][r]["xyz"]).reshape(-1, 3)
        boundary = _ramp_columns(XYZ, display)
        for name, d in (("threshold", threshold), ("boundary", 1.0), ("limit", limit)):
            column = d * boundary
            got = out["marks"][str(r)][name]
            if column > knob_page.WIDTH - 1:
                assert got is None, (r, name)
                continue
            assert got is not None, (r, name)
            worst = max(worst, abs(got - (column + 0.5)))
    print(f"\n{display}: the ramps' marks within {worst:.3f} px of colour-science's columns")
    assert worst <= 0.25


def test_the_strips_stay_put_when_the_display_changes(chromium, tmp_path):
    """The display's note has its space kept: the canvas's top is the same for each."""
    tops = {}
    for i, display in enumerate(knob_page.DISPLAYS):
        out, _ = _readback(chromium, tmp_path / str(i), f"display={display}")
        tops[display] = out["canvasTop"]
    print(f"\nthe canvas's top by display (CSS px): {tops}")
    assert len(set(tops.values())) == 1
