"""The film as a Blender material (:mod:`ocio_thinfilm.export.hosts.blender`), rendered.

The tables come from :mod:`evaluation.materials` (colour-science's transfer-matrix method,
CMFs, D65 and BT.709: nothing of the package), the renders from PyPI ``bpy``
(:data:`evaluation.blender.BPY_VERSION`, its own venv: ``python -m evaluation.blender``)
and, for Blender 3.x, Debian's ``blender``. The scene (:mod:`evaluation.blender_scene`):
a mirror sphere in a uniform white world, an orthographic camera down -z, so the pixel at
(x, y) sees the reflectance at cos(theta) = sqrt(1 - x^2 - y^2), and the film thickness
is a ramp in x.
"""

from __future__ import annotations

import functools
import json
import shutil
import subprocess

import numpy as np
import pytest

from evaluation import blender, materials
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export.hosts.blender import BlenderTables, blender_name, blender_script

#: The renders' tables (evaluation.blender.render_film) are 256 x 128 over 0-1 um: their
#: bilinear lookup is within DeltaE2000 0.52 of the exact film at the test's pixels,
#: measured in NumPy (64 rows give 1.2, from the rows near normal incidence). The tests
#: that only build the material use small ones.
RANGE = (0.0, 1.0)
WIDTH, HEIGHT = 16, 8


@functools.cache
def _install_error() -> str | None:
    """Install the bpy venv once per run (``.ci/run`` does it ahead of the tests); the
    reason it cannot be made, or None."""
    try:
        blender.install_bpy()
    except RuntimeError as error:
        return str(error)
    return None


def _bpy():
    error = _install_error()
    if error is not None:
        pytest.skip(f"no PyPI bpy {blender.BPY_VERSION} venv: {error}")


def _film_folder(tmp_path, stack, key, *, transmittance=False):
    """The tables and the script, as ``export material`` lays them out."""
    return materials.write_film_folder(
        tmp_path / key, stack, key, RANGE, WIDTH, HEIGHT, transmittance=transmittance
    )


# --------------------------------------------------------------------------- #
# The script's text
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize(
    ("arguments", "parameter"),
    [
        (("", "a_R.exr", None, (0, 1)), "key"),
        (("Soap", "/abs/a_R.exr", None, (0, 1)), "reflectance_exr"),
        (("Soap", "../a_R.exr", None, (0, 1)), "reflectance_exr"),
        (("Soap", "a_R.png", None, (0, 1)), "reflectance_exr"),
        (("Soap", "a_R.exr", "C:/a_T.exr", (0, 1)), "transmittance_exr"),
        (("Soap", "a_R.exr", None, (1, 1)), "range_um"),
        (("Soap", "a_R.exr", None, (-0.1, 1)), "range_um"),
        (("Soap", "a_R.exr", None, (0, float("inf"))), "range_um"),
    ],
)
def test_blender_script_names_the_bad_parameter(arguments, parameter):
    with pytest.raises(ParameterError) as error:
        blender_script(*arguments)
    assert error.value.parameter == parameter
    assert "\n" not in str(error.value)


def test_blender_script_refuses_a_range_that_is_no_pair_of_numbers():
    with pytest.raises(TypeError, match="range_um"):
        blender_script("Soap", "a_R.exr", None, "ab")


def test_blender_script_is_python_with_the_constants():
    text = blender_script('Odd "key"', "sub/a_R.exr", "sub/a_T.exr", (0.25, 2))
    compile(text, "film.py", "exec")
    # quoted as ruff format quotes it (single quotes around a name holding double ones)
    assert """NAME = 'Thin Film Odd "key"'""" in text
    names = {}
    exec(text.split("\n\ndef ")[0].replace("import bpy", ""), names)
    assert names["NAME"] == 'Thin Film Odd "key"'
    assert '"reflectance": "sub/a_R.exr"' in text and '"transmittance": "sub/a_T.exr"' in text
    assert '"space": "Linear Rec.709 (sRGB)"' in text and '"outside": (0.0, 0.0)' in text
    assert "RANGE_UM = (0.25, 2.0)" in text
    assert blender_name("Soap") == "Thin Film Soap"


@pytest.mark.parametrize(
    ("options", "parameter"),
    [
        ({"name": ""}, "name"),
        ({"name": "two\nlines"}, "name"),
        ({"space": "sRGB"}, "space"),
        ({"outside": (1.5, -0.1)}, "outside"),
        ({"outside": (0.1, 0.2)}, "outside"),
        ({"alternates": [BlenderTables("Linear Rec.709 (sRGB)", "b_R.exr")]}, "alternates"),
        ({"alternates": [BlenderTables("Linear Rec.2020", "b_R.exr", "b_T.exr")]}, "alternates"),
        ({"alternates": [BlenderTables("Linear Rec.2020", "../b_R.exr")]}, "alternates"),
    ],
)
def test_blender_script_names_the_bad_option(options, parameter):
    with pytest.raises(ParameterError) as error:
        blender_script("Soap", "a_R.exr", None, (0, 1), **options)
    assert error.value.parameter == parameter
    assert "\n" not in str(error.value)


def test_the_script_is_named_by_the_film_name_like_the_exr_header(tmp_path):
    """``export material``'s script names the node group and material by the film's
    ``name`` (the film file's, e.g. "Thin Film Oil on Water" for key OilOnWater), the
    name the EXR header starts with; without a name, ``Thin Film <key>``."""
    import OpenImageIO as oiio

    from ocio_thinfilm.cli.main import main as cli_main

    films = tmp_path / "films.toml"
    films.write_text(
        "[materials.Soapy]\nn = 1.33\n\n"
        '[films.Wall]\nstack = ["air", "Soapy", "air"]\nrange_um = [0, 1]\n'
        'name = "Bubble wall"\n\n'
        '[films.Plain]\nstack = ["air", "Soapy", "air"]\nrange_um = [0, 1]\n'
    )
    for key, name in (("Wall", "Bubble wall"), ("Plain", "Thin Film Plain")):
        out = tmp_path / key
        argv = ["export", "material", "--films", str(films), "--film", key, "--out", str(out)]
        assert cli_main([*argv, "--size", "8x4"]) == 0
        text = (out / f"ThinFilm_User_{key}.py").read_text()
        header = oiio.ImageInput.open(str(out / f"ThinFilm_User_{key}_R.exr"))
        description = header.spec().getattribute("ImageDescription")
        header.close()
        assert description.startswith(f"{name}: ")
        assert f'NAME = "{name}"' in text


def test_the_written_script_passes_the_repository_ruff(tmp_path):
    """The script ``export material`` writes passes ``ruff check`` and ``ruff format
    --check`` with the repository's configuration (no per-file ignores: as if saved in a
    checked folder), with several spaces' tables and odd names."""
    ruff = shutil.which("ruff")
    if ruff is None:
        pytest.skip("ruff not installed")
    from pathlib import Path

    config = Path(__file__).resolve().parents[1] / "pyproject.toml"
    text = blender_script(
        "Soap",
        "ThinFilm_User_Soap_R.exr",
        "ThinFilm_User_Soap_T.exr",
        (0.0, 1.0),
        name='A "quoted" film',
        outside=(0.1234, -0.05),
        alternates=[
            BlenderTables(
                "Linear Rec.2020",
                "ThinFilm_User_Soap_LinearRec2020_R.exr",
                "ThinFilm_User_Soap_LinearRec2020_T.exr",
            )
        ],
    )
    script = tmp_path / "ThinFilm_User_Soap.py"
    script.write_text(text)
    for command in (["check"], ["format", "--check"]):
        done = subprocess.run(
            [ruff, *command, "--config", str(config), str(script)], capture_output=True, text=True
        )
        assert done.returncode == 0, done.stdout + done.stderr


# --------------------------------------------------------------------------- #
# In Blender: the data it builds
# --------------------------------------------------------------------------- #
#: Runs the script twice beside a material of the user's, and prints what exists.
_INSPECT = """
import json, runpy, sys, bpy
keep = bpy.data.materials.new("Keep")
def names():
    kinds = ("node_groups", "materials", "images")
    return {k: {d.name for d in getattr(bpy.data, k)} for k in kinds}
before = names()
runpy.run_path(sys.argv[-1], run_name="__main__")
mine = bpy.data.materials.new("Mine")  # a user's material around the group
if mine.node_tree is None:
    mine.use_nodes = True
mine_node = mine.node_tree.nodes.new("ShaderNodeGroup")
mine_node.node_tree = bpy.data.node_groups["Thin Film Soap"]
runpy.run_path(sys.argv[-1], run_name="__main__")
before["materials"].add("Mine")
name = "Thin Film Soap"
group = bpy.data.node_groups[name]
sockets = (
    [(s.in_out, s.name) for s in group.interface.items_tree]
    if hasattr(group, "interface")
    else [("INPUT", s.name) for s in group.inputs] + [("OUTPUT", s.name) for s in group.outputs]
)
textures = [n for n in group.nodes if n.bl_idname == "ShaderNodeTexImage"]
material = bpy.data.materials[name]
node = next(n for n in material.node_tree.nodes if n.bl_idname == "ShaderNodeGroup")
print("JSON" + json.dumps({
    "added": {k: sorted(v - before[k]) for k, v in names().items()},
    "removed": {k: sorted(before[k] - v) for k, v in names().items()},
    "sockets": sockets,
    "thickness": node.inputs["Thickness"].default_value,
    "textures": [
        (t.interpolation, t.extension, t.image.colorspace_settings.name) for t in textures
    ],
    "mine": mine_node.node_tree.name if mine_node.node_tree else None,
}))
"""


def _inspect(command, tmp_path):
    script = _film_folder(tmp_path, materials.SOAP_BUBBLE, "Soap", transmittance=True)
    moved = tmp_path / "moved"
    shutil.move(script.parent, moved)
    probe = tmp_path / "film_probe.py"
    probe.write_text(_INSPECT)
    done = subprocess.run(
        [*command, str(probe), "--", str(moved / script.name)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = [line for line in done.stdout.splitlines() if line.startswith("JSON")]
    assert done.returncode == 0 and lines, done.stdout[-2000:] + done.stderr[-2000:]
    return json.loads(lines[-1][4:])


def _check_inspected(found):
    assert found["added"] == {
        "node_groups": ["Thin Film Soap"],
        "materials": ["Thin Film Soap"],
        "images": ["ThinFilm_User_Soap_R.exr", "ThinFilm_User_Soap_T.exr"],
    }
    assert found["removed"] == {"node_groups": [], "materials": [], "images": []}
    for socket in ("Thickness", "Roughness"):
        assert ["INPUT", socket] in found["sockets"]
    for socket in ("BSDF", "Reflectance", "Transmittance"):
        assert ["OUTPUT", socket] in found["sockets"]
    assert found["thickness"] == pytest.approx(0.5)
    assert found["mine"] == "Thin Film Soap"  # rebuilt in place, still used
    assert found["textures"] == [["Closest", "EXTEND", "Non-Color"]] * 8


def test_the_script_builds_once_from_a_moved_folder_in_bpy(tmp_path):
    """Run twice from a folder moved after writing: one group, one material, one image per
    table, the user's material kept; the group's sockets and texture settings."""
    _bpy()
    _check_inspected(_inspect([str(blender.bpy_python())], tmp_path))


@pytest.mark.skipif(shutil.which("blender") is None, reason="Debian blender (3.x) not installed")
def test_the_script_builds_in_blender_3(tmp_path):
    """Blender 3.x (Debian's): the node group's sockets through ``inputs``/``outputs``."""
    command = [shutil.which("blender"), "-b", "--factory-startup", "--python-exit-code", "1"]
    _check_inspected(_inspect([*command, "--python"], tmp_path))


# --------------------------------------------------------------------------- #
# In Blender: the renders
# --------------------------------------------------------------------------- #
def test_cycles_mirror_sphere_is_the_exact_reflectance(tmp_path):
    """Soap film in air (n = 1.33), reflection only: every pixel of the disc within
    DeltaE2000 1.0 of colour-science's exact R at its thickness and angle. Exact colours
    outside BT.709 (a channel < 0) are compared clamped at 0: Cycles clamps a closure's
    negative colour to 0, so the table's gamut mapping is what it can show of them."""
    _bpy()
    got, exact, _ = blender.render_film(tmp_path, materials.SOAP_BUBBLE, "Soap", samples=1)
    inside = exact.min(axis=1) >= 0
    de = materials.delta_e(got, np.where(inside[:, None], exact, np.clip(exact, 0, None)))
    assert inside.sum() > 2000 and (~inside).sum() > 0
    assert np.percentile(de[inside], 99) <= 0.6, np.percentile(de[inside], [50, 99, 100])
    assert de.max() <= 1.0, (de[inside].max(), de[~inside].max())
    assert got.min() >= 0


def test_cycles_mirror_sphere_centre_pixel_is_exact(tmp_path):
    """An odd frame (97 px) puts a pixel centre on the sphere's centre: normal
    incidence, cos theta = 1, the tables' top row (node-centred, exact there). That
    pixel and every other of the disc within DeltaE2000 1.0 of colour-science's R."""
    _bpy()
    size = 97
    got, exact, _ = blender.render_film(
        tmp_path, materials.SOAP_BUBBLE, "Soap", samples=1, size=size
    )
    _, _, disc, cos_theta = blender.sphere_pixels(size)
    centre = int(np.argmax(cos_theta[disc]))
    assert cos_theta[disc][centre] == 1.0
    de = materials.delta_e(got, np.clip(exact, 0, None))
    assert de[centre] <= 1.0, (de[centre], got[centre], exact[centre])
    assert de.max() <= 1.0, np.percentile(de, [50, 99, 100])


def test_cycles_film_on_glass_is_the_exact_reflectance(tmp_path):
    """A soap-like film on glass (1.33 on 1.5, semi-infinite): the same bound."""
    _bpy()
    got, exact, _ = blender.render_film(tmp_path, materials.SOAP_ON_GLASS, "Glass", samples=1)
    de = materials.delta_e(got, np.clip(exact, 0, None))
    assert de.max() <= 1.0, np.percentile(de, [50, 99, 100])


def test_export_material_renders_the_exact_film_in_cycles(tmp_path):
    """The user's path: a film file, ``ocio-thinfilm export material``, and the Blender
    script it writes beside the package's own tables (the exact engine), run in Blender:
    a soap-like film on glass within DeltaE2000 1.0 of colour-science's exact R."""
    from ocio_thinfilm.cli.main import main as cli_main

    _bpy()
    films = tmp_path / "films.toml"
    films.write_text(
        "[materials.Soapy]\nn = 1.33\n\n[materials.Glass]\nn = 1.5\n\n"
        '[films.OnGlass]\nstack = ["air", "Soapy", "Glass"]\nrange_um = [0, 1]\n'
    )
    out = tmp_path / "materials"
    argv = ["export", "material", "--films", str(films), "--film", "OnGlass", "--out", str(out)]
    assert cli_main(argv) == 0
    scripts = sorted(out.glob("*.py"))
    assert [p.name for p in scripts] == ["ThinFilm_User_OnGlass.py"]
    size, ramp = 96, (0.05, 0.95)
    render = tmp_path / "render.exr"
    material = {"kind": "script", "script": str(scripts[0]), "name": blender_name("OnGlass")}
    job = {"engine": "CYCLES", "size": size, "out": str(render), "material": material}
    blender.render({**job, "thickness_um": list(ramp), "samples": 1})
    x, _, disc, cos_theta = blender.sphere_pixels(size)
    thickness = ramp[0] + (x + 1) / 2 * (ramp[1] - ramp[0])
    exact = materials.film_rgb(materials.SOAP_ON_GLASS, thickness[disc], cos_theta[disc])
    de = materials.delta_e(blender.read_exr(render)[disc], np.clip(exact, 0, None))
    assert de.max() <= 1.0, np.percentile(de, [50, 99, 100])


def test_cycles_free_standing_bubble_conserves_energy(tmp_path):
    """The bubble (R and T tables, 16 bounces) in a white world: R + T = 1 for a film
    that absorbs nothing, so light reaches the camera undimmed: white on average over
    the disc (Cycles picks the glossy or the transparent closure by weight per sample,
    so one pixel is noisy, their mean is not). A material that dropped T (mean ~0.1) or
    counted R twice is far off."""
    _bpy()
    got, _, _ = blender.render_film(
        tmp_path, materials.SOAP_BUBBLE, "Bubble", samples=16, transmittance=True
    )
    mean = got.mean(axis=0)
    assert np.abs(mean - 1).max() <= 0.01, mean
    assert np.abs(np.median(got, axis=0) - 1).max() <= 0.1, np.median(got, axis=0)


def test_principled_thin_film_side_by_side(tmp_path):
    """Principled BSDF's thin film (Blender 4.2+) on the same scene and film (1.33 on
    glass 1.5, thickness in nm from the same ramp): near the exact film (its model is an
    approximation: measured p50 0.8, max 1.8 at 128 px, docs/blender.md) and farther
    from it than the node group. A wrong unit or index in the side-by-side scene puts it
    tens of DeltaE away."""
    _bpy()
    ours, exact, _ = blender.render_film(tmp_path, materials.SOAP_ON_GLASS, "Glass", samples=1)
    out = tmp_path / "principled.exr"
    blender.render(
        {
            "engine": "CYCLES",
            "size": 96,
            "samples": 1,
            "out": str(out),
            "material": {"kind": "principled", "ior": 1.5, "film_ior": 1.33},
            "thickness_um": [0.05, 0.95],
        }
    )
    principled = blender.read_exr(out)[blender.sphere_pixels(96)[2]]
    clipped = np.clip(exact, 0, None)
    theirs = materials.delta_e(principled, clipped)
    mine = materials.delta_e(ours, clipped)
    assert np.median(theirs) <= 2.0 and theirs.max() <= 4.0, np.percentile(theirs, [50, 100])
    assert np.median(mine) < np.median(theirs) and mine.max() < theirs.max()


def test_eevee_mirror_sphere_is_the_exact_reflectance(tmp_path):
    """EEVEE (headless: EGL on Mesa's llvmpipe in CI), the same scene and bound as
    Cycles. The node group's bilinear lookup is its own (four Closest reads): EEVEE's
    filtered texture read picks a mipmap level from the screen-space derivatives of the
    lookup, which on llvmpipe returned wrong colours (DeltaE2000 p50 16 with the
    thickness ramp, scattered pixels at 68 with a uniform thickness)."""
    _bpy()
    got, exact, _ = blender.render_film(
        tmp_path, materials.SOAP_BUBBLE, "Soap", engine="BLENDER_EEVEE", samples=1
    )
    de = materials.delta_e(got, np.clip(exact, 0, None))
    assert de.max() <= 1.0, np.percentile(de, [50, 99, 100])


def test_docs_quote_the_benchmark(load_benchmark, marked):
    """docs/blender.md's numbers are benchmarks/bench_blender.py's last run
    (reports/bench_blender.json) as its markdown renders them."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    result = json.loads((root / "reports" / "bench_blender.json").read_text())
    text = (root / "docs" / "blender.md").read_text()
    block = marked(text, "<!-- bench_blender:begin -->", "<!-- bench_blender:end -->")
    assert block == load_benchmark("bench_blender").markdown(result).strip()
    assert result["ratio"] <= 1.3


@pytest.mark.parametrize("name", ["bench_bubbles", "bench_blender_spaces"])
def test_docs_quote_the_bubble_and_space_benchmarks(load_benchmark, marked, name):
    """docs/blender.md's bubble noise and working-space tables are the benchmarks' last
    runs (reports/<name>.json) as their markdown renders them."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    result = json.loads((root / "reports" / f"{name}.json").read_text())
    text = (root / "docs" / "blender.md").read_text()
    block = marked(text, f"<!-- {name}:begin -->", f"<!-- {name}:end -->")
    assert block == load_benchmark(name).markdown(result).strip()


def test_a_missing_table_changes_nothing(tmp_path):
    """The script checks every table before it touches Blender's data: with the
    transmittance table gone it fails naming the path, and the group and material of an
    earlier run are left as they were."""
    _bpy()
    script = _film_folder(tmp_path, materials.SOAP_BUBBLE, "Soap", transmittance=True)
    probe = tmp_path / "film_probe.py"
    probe.write_text(
        "import json, runpy, sys, bpy\n"
        "runpy.run_path(sys.argv[-2], run_name='__main__')\n"
        "group = bpy.data.node_groups['Thin Film Soap']\n"
        "count = len(group.nodes)\n"
        "import os; os.remove(sys.argv[-1])\n"
        "try:\n"
        "    runpy.run_path(sys.argv[-2], run_name='__main__')\n"
        "    error = None\n"
        "except FileNotFoundError as e:\n"
        "    error = str(e)\n"
        "print('JSON' + json.dumps([error, count, len(group.nodes)]))\n"
    )
    t_table = script.parent / "ThinFilm_User_Soap_T.exr"
    done = subprocess.run(
        [str(blender.bpy_python()), str(probe), str(script), str(t_table)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = [line for line in done.stdout.splitlines() if line.startswith("JSON")]
    assert lines, done.stdout[-2000:] + done.stderr[-2000:]
    error, before, after = json.loads(lines[-1][4:])
    assert error is not None and str(t_table) in error and "\n" not in error
    assert before == after > 10


# --------------------------------------------------------------------------- #
# The working space (Blender 5) and the tables' spaces
# --------------------------------------------------------------------------- #
#: Runs the script in a fresh file per working space and prints what it chose and said.
_SPACES = """
import contextlib, io, json, runpy, sys, bpy
found = {}
for space in sys.argv[-1].split(","):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.set_working_color_space(working_space=space, convert_colors=False)
    with contextlib.redirect_stdout(io.StringIO()) as said:
        runpy.run_path(sys.argv[-2], run_name="__main__")
    found[space] = {
        "images": sorted(i.name for i in bpy.data.images),
        "said": said.getvalue().splitlines(),
    }
print("JSON" + json.dumps(found))
"""

ALL_SPACES = ("Linear Rec.709 (sRGB)", "Linear Rec.2020", "ACEScg")


def _run_spaces(tmp_path, spaces, working_spaces):
    script = materials.write_film_folder(
        tmp_path / "Soap", materials.SOAP_BUBBLE, "Soap", RANGE, WIDTH, HEIGHT, spaces=spaces
    )
    probe = tmp_path / "spaces_probe.py"
    probe.write_text(_SPACES)
    done = subprocess.run(
        [str(blender.bpy_python()), str(probe), str(script), ",".join(working_spaces)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = [line for line in done.stdout.splitlines() if line.startswith("JSON")]
    assert lines, done.stdout[-2000:] + done.stderr[-2000:]
    return json.loads(lines[-1][4:])


def test_the_script_loads_the_working_space_tables_in_bpy(tmp_path):
    """Tables in three spaces in one folder: a Linear Rec.2020 or ACEScg scene loads
    that space's tables and says nothing of the others; a Linear Rec.709 scene loads the
    plain ones and says once, in one line, how much of the film is outside its gamut
    (the soap film's blues: a negative red) and what to do."""
    _bpy()
    found = _run_spaces(tmp_path, ALL_SPACES, ("Linear Rec.2020", "ACEScg", "Linear Rec.709"))
    assert found["Linear Rec.2020"]["images"] == ["ThinFilm_User_Soap_LinearRec2020_R.exr"]
    assert found["ACEScg"]["images"] == ["ThinFilm_User_Soap_ACEScg_R.exr"]
    assert found["Linear Rec.709"]["images"] == ["ThinFilm_User_Soap_R.exr"]
    for space in ("Linear Rec.2020", "ACEScg"):
        assert not any(
            "gamut" in line or "working space is" in line for line in found[space]["said"]
        )
    gamut = [line for line in found["Linear Rec.709"]["said"] if "gamut" in line]
    assert len(gamut) == 1 and "--gamut clip" in gamut[0] and "Rec.2020" in gamut[0]
    # the share written into the script is colour-science's table's
    rgb = materials.table(materials.SOAP_BUBBLE, RANGE, WIDTH, HEIGHT)
    share = 100 * np.mean((rgb < 0).any(axis=-1))
    assert f"{share:.1f} %" in gamut[0] and f"{rgb.min():.3f}" in gamut[0]


def test_the_script_says_when_the_spaces_differ_in_bpy(tmp_path):
    """Only Linear Rec.709 tables, an ACEScg scene: the script loads them and says so
    once, in one line, naming both spaces."""
    _bpy()
    found = _run_spaces(tmp_path, ALL_SPACES[:1], ("ACEScg",))
    assert found["ACEScg"]["images"] == ["ThinFilm_User_Soap_R.exr"]
    differ = [line for line in found["ACEScg"]["said"] if "working space is" in line]
    assert len(differ) == 1, found
    assert "Linear Rec.709 (sRGB)" in differ[0] and "ACEScg" in differ[0]


@pytest.mark.parametrize("space", ["Linear Rec.2020", "ACEScg"])
def test_a_wide_working_space_renders_the_soap_film_blues(tmp_path, space):
    """The soap film at 0.25 um, whose blues lie outside Rec.709 (a negative red near
    normal incidence), on the mirror sphere in a Blender 5 scene whose working space is
    ``space``: the script loads that space's tables and Cycles renders every pixel
    within DeltaE2000 1.0 of colour-science's exact, unclamped colour. The same film in
    a Linear Rec.709 scene is farther (Cycles clamps the negative red): the test can
    tell them apart."""
    import colour

    _bpy()
    renders = {}
    for working in (space, "Linear Rec.709"):
        got, exact, answer = blender.render_film(
            tmp_path / working.replace(" ", "_"),
            materials.SOAP_BUBBLE,
            "Soap",
            samples=1,
            size=64,
            ramp_um=(0.25, 0.25),
            spaces=ALL_SPACES,
            working_space=working,
        )
        if working != "Linear Rec.709":
            got = colour.RGB_to_RGB(
                got,
                materials.COLOUR_SPACES[space],
                "ITU-R BT.709",
                chromatic_adaptation_transform="CAT02",
            )
        renders[working] = materials.delta_e(got, exact)
    assert (exact.min(axis=1) < -0.002).mean() > 0.1  # the blues are outside Rec.709
    assert renders[space].max() <= 1.0, np.percentile(renders[space], [50, 99, 100])
    assert renders["Linear Rec.709"].max() > 1.5, renders["Linear Rec.709"].max()


# --------------------------------------------------------------------------- #
# export material with several spaces
# --------------------------------------------------------------------------- #
_FILMS = (
    "[materials.Soapy]\nn = 1.33\n\n"
    '[films.Wall]\nstack = ["air", "Soapy", "air"]\nrange_um = [0, 1]\n'
)


def test_export_material_writes_tables_for_several_spaces(tmp_path):
    """``--space`` twice: the first space's tables keep the plain names, the second's
    carry the space; each EXR says its space; the script lists both (first first)."""
    import OpenImageIO as oiio

    from ocio_thinfilm.cli.main import main as cli_main

    films = tmp_path / "films.toml"
    films.write_text(_FILMS)
    out = tmp_path / "out"
    argv = ["export", "material", "--films", str(films), "--out", str(out), "--size", "8x4"]
    spaces = ["--space", "Linear Rec.709 (sRGB)", "--space", "Linear Rec.2020"]
    assert cli_main([*argv, *spaces]) == 0
    stem = "ThinFilm_User_Wall"
    expected = {
        f"{stem}_R.exr": "Linear Rec.709 (sRGB)",
        f"{stem}_T.exr": "Linear Rec.709 (sRGB)",
        f"{stem}_LinearRec2020_R.exr": "Linear Rec.2020",
        f"{stem}_LinearRec2020_T.exr": "Linear Rec.2020",
    }
    for name, space in expected.items():
        image = oiio.ImageInput.open(str(out / name))
        assert image.spec().getattribute("ocio_thinfilm:space") == space
        image.close()
    text = (out / f"{stem}.py").read_text()
    first, second = text.index('"space": "Linear Rec.709'), text.index('"space": "Linear Rec.2020')
    assert first < second
    assert f'"reflectance": "{stem}_LinearRec2020_R.exr"' in text
    # one space: the file names of a single-space export are unchanged
    single = tmp_path / "single"
    argv[5] = str(single)
    assert cli_main([*argv, "--space", "Linear Rec.2020"]) == 0
    assert (single / f"{stem}_R.exr").exists() and not list(single.glob("*LinearRec2020*"))


@pytest.mark.parametrize(
    ("spaces", "says"),
    [
        (["Linear Rec.2020", "sRGB"], "--space must be a scene-linear space"),
        (["ACEScg", "ACEScg"], "--space names 'ACEScg' twice"),
    ],
)
def test_export_material_refuses_bad_spaces(tmp_path, capsys, spaces, says):
    from ocio_thinfilm.cli.main import main as cli_main

    films = tmp_path / "films.toml"
    films.write_text(_FILMS)
    out = tmp_path / "out"
    argv = ["export", "material", "--films", str(films), "--out", str(out)]
    code = cli_main([*argv, *[a for space in spaces for a in ("--space", space)]])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and says in err, err
    assert not out.exists()


# --------------------------------------------------------------------------- #
# Noise: a bubble against Blender's own nearest bubble
# --------------------------------------------------------------------------- #
#: How much noisier than Principled's bubble ours may measure and still pass. Measured
#: (benchmarks/bench_bubbles.py, docs/blender.md; 64 px, 3 seeds): one material's RMSE
#: moves by about +-2 % between seeds, ours / Principled's is 0.99 at 32 samples and
#: 1.03 at 128. On the test's 48 px frame (half the pixels) the ratio of two renders
#: moves by about 5 % (one sigma): 1.15 is three sigma, so a material as noisy as
#: Principled's passes and one 1.3 times as noisy (or the twice-as-noisy pixels of a
#: wrong closure choice) fails.
MARGIN = 1.15


def _bubble_noise(tmp_path, material, engine, samples, reference, size=48, **job):
    """RMSE over the disc of a ``samples`` render against a ``reference`` one."""
    tmp_path.mkdir(parents=True, exist_ok=True)
    ref, test = tmp_path / f"{engine}_ref.exr", tmp_path / f"{engine}_{samples}.exr"
    blender.render(
        {
            "engine": engine,
            "size": size,
            "samples": reference,
            "seed": 1000,
            "out": str(ref),
            "material": material,
            "thickness_um": [0.1, 0.9],
            "scene": "bubble",
            "series": [[samples, 0, str(test)]],
            **job,
        },
        timeout=900,
    )
    disc = blender.sphere_pixels(size)[2]
    difference = blender.read_exr(test)[disc] - blender.read_exr(ref)[disc]
    return float(np.sqrt(np.mean(difference**2)))


def _bubble_materials(tmp_path):
    script = materials.write_film_folder(
        tmp_path / "Bubble", materials.SOAP_BUBBLE, "Bubble", RANGE, 64, 32, transmittance=True
    )
    ours = {"kind": "script", "script": str(script), "name": blender_name("Bubble")}
    return ours, {"kind": "principled_bubble", "film_ior": 1.33}


def test_a_cycles_bubble_is_no_noisier_than_principled(tmp_path):
    """The free-standing soap film's material as the script builds it (Glossy R +
    Transparent T), in the bubble scene (a sphere of film before a checker, under a
    varying world): its RMSE against its own converged render (32 samples against 512)
    is at most MARGIN times Principled's bubble's (transmission 1, IOR 1.0, thin film)
    at equal samples."""
    _bpy()
    ours, principled = _bubble_materials(tmp_path)
    mine = _bubble_noise(tmp_path / "ours", ours, "CYCLES", 32, 512)
    theirs = _bubble_noise(tmp_path / "principled", principled, "CYCLES", 32, 512)
    assert theirs > 0.005, theirs  # the measure sees a bubble's noise
    assert mine <= MARGIN * theirs, (mine, theirs)


def test_an_eevee_bubble_is_noise_free(tmp_path):
    """EEVEE, 16 samples against 32: the script's render method (Blended) draws the
    bubble without noise, no noisier than Principled's bubble (whose refraction EEVEE
    does not sample at random either); the script's former method, Dithered, is
    speckled (the measure can tell: measured 0.04 on the benchmark's frame)."""
    _bpy()
    ours, principled = _bubble_materials(tmp_path)
    mine = _bubble_noise(tmp_path / "ours", ours, "BLENDER_EEVEE", 16, 32)
    theirs = _bubble_noise(tmp_path / "principled", principled, "BLENDER_EEVEE", 16, 32)
    dithered = _bubble_noise(
        tmp_path / "dithered", ours, "BLENDER_EEVEE", 16, 32, render_method="DITHERED"
    )
    assert dithered > 0.01, dithered
    assert mine <= max(MARGIN * theirs, 0.1 * dithered), (mine, theirs, dithered)
