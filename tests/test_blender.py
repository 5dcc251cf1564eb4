"""The film as a Blender material (:mod:`ocio_thinfilm.export.blender`), rendered.

The tables come from :mod:`evaluation.materials` (colour-science's transfer-matrix method,
CMFs, D65 and BT.709: nothing of the package), the renders from PyPI ``bpy``
(:data:`evaluation.blender.BPY_VERSION`, its own venv: ``python -m evaluation.blender``)
and, for Blender 3.x, Debian's ``blender``. The scene (:mod:`evaluation.blender_scene`):
a mirror sphere in a uniform white world, an orthographic camera down -z, so the pixel at
(x, y) sees the reflectance at cos(theta) = sqrt(1 - x^2 - y^2), and the film thickness
is a ramp in x.
"""

from __future__ import annotations

import json
import shutil
import subprocess

import numpy as np
import pytest

from evaluation import blender, materials
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export.blender import blender_name, blender_script

#: The table's range and resolution (256 x 128: the bilinear lookup of it is within
#: DeltaE2000 0.52 of the exact film at the test's pixels, measured in NumPy).
RANGE = (0.0, 1.0)
WIDTH, HEIGHT = 256, 128
#: The thickness ramp over the sphere (object x = -1 -> +1), micrometres.
RAMP = (0.05, 0.95)
#: Pixels, and the disc compared: away from the silhouette (cos(theta) >= 0.31).
SIZE = 96
RADIUS = 0.95


def _bpy():
    if blender.bpy_python() is None:
        try:
            blender.install_bpy()
        except RuntimeError as error:
            pytest.skip(f"no PyPI bpy {blender.BPY_VERSION} venv: {error}")


def _film_folder(tmp_path, stack, key, *, transmittance=False):
    """The tables and the script, as ``export material`` lays them out."""
    folder = tmp_path / key
    folder.mkdir()
    r_name = f"ThinFilm_User_{key}_R.exr"
    rgb = materials.table(stack, RANGE, WIDTH, HEIGHT)
    materials.write_table(folder / r_name, rgb, key=key, quantity="reflectance", range_um=RANGE)
    t_name = None
    if transmittance:
        t_name = f"ThinFilm_User_{key}_T.exr"
        rgb = materials.table(stack, RANGE, WIDTH, HEIGHT, quantity="transmittance")
        materials.write_table(
            folder / t_name, rgb, key=key, quantity="transmittance", range_um=RANGE
        )
    script = folder / f"ThinFilm_User_{key}.py"
    script.write_text(blender_script(key, r_name, t_name, RANGE))
    return script


def _read(path):
    import OpenImageIO as oiio

    return oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)[..., :3].astype(float)


def _pixels():
    """Pixel centres (x, y), the disc mask and cos(theta) = n_z there."""
    c = -1.1 + 2.2 * (np.arange(SIZE) + 0.5) / SIZE
    x, y = np.meshgrid(c, -c)
    r2 = x**2 + y**2
    return x, y, r2 < RADIUS**2, np.sqrt(np.clip(1 - r2, 0, 1))


def delta_e(colour, a, b):
    """CIE 2000 of two linear BT.709 colour sets, colour-science throughout."""
    white = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]

    def lab(rgb):
        return colour.XYZ_to_Lab(colour.RGB_to_XYZ(rgb, "ITU-R BT.709"), white)

    return colour.delta_E(lab(a), lab(b), method="CIE 2000")


def render_film(tmp_path, stack, key, engine="CYCLES", **job):
    """The sphere with the film's generated material: (render, exact R, disc mask)."""
    script = _film_folder(tmp_path, stack, key, transmittance=job.pop("transmittance", False))
    out = tmp_path / f"{key}_{engine}.exr"
    answer = blender.render(
        {
            "engine": engine,
            "size": SIZE,
            "out": str(out),
            "material": {"kind": "script", "script": str(script), "name": blender_name(key)},
            "thickness_um": RAMP,
            **job,
        }
    )
    x, _, disc, cos_theta = _pixels()
    thickness = RAMP[0] + (x + 1) / 2 * (RAMP[1] - RAMP[0])
    exact = materials.film_rgb(stack, thickness[disc], cos_theta[disc])
    return _read(out)[disc], exact, answer


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
        (("Soap", "a_R.exr", None, "ab"), "range_um"),
    ],
)
def test_blender_script_names_the_bad_parameter(arguments, parameter):
    with pytest.raises(ParameterError) as error:
        blender_script(*arguments)
    assert error.value.parameter == parameter
    assert "\n" not in str(error.value)


def test_blender_script_is_python_with_the_constants():
    text = blender_script('Odd "key"', "sub/a_R.exr", "sub/a_T.exr", (0.25, 2))
    compile(text, "film.py", "exec")
    assert 'NAME = "Thin Film Odd \\"key\\""' in text
    assert 'REFLECTANCE = "sub/a_R.exr"' in text and 'TRANSMITTANCE = "sub/a_T.exr"' in text
    assert "RANGE_UM = (0.25, 2.0)" in text


# --------------------------------------------------------------------------- #
# In Blender: the data it builds
# --------------------------------------------------------------------------- #
#: Runs the script twice beside a material of the user's, and prints what exists.
_INSPECT = """
import json, runpy, sys, bpy
keep = bpy.data.materials.new("Keep")
def names():
    return {k: {d.name for d in getattr(bpy.data, k)} for k in ("node_groups", "materials", "images")}
before = names()
for _ in range(2):
    runpy.run_path(sys.argv[-1], run_name="__main__")
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
    "textures": [(t.interpolation, t.extension, t.image.colorspace_settings.name) for t in textures],
    "users": node.node_tree.name,
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
    assert ["INPUT", "Thickness"] in found["sockets"] and ["INPUT", "Roughness"] in found["sockets"]
    assert ["OUTPUT", "BSDF"] in found["sockets"] and ["OUTPUT", "Transmittance"] in found["sockets"]
    assert found["thickness"] == pytest.approx(0.5)
    assert found["textures"] == [["Linear", "EXTEND", "Non-Color"]] * 2


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
def test_cycles_mirror_sphere_is_the_exact_reflectance(tmp_path, colour):
    """Soap film in air (n = 1.33), reflection only: every pixel of the disc within
    DeltaE2000 1.0 of colour-science's exact R at its thickness and angle. Exact colours
    outside BT.709 (a channel < 0) are compared clamped at 0: Cycles clamps a closure's
    negative colour to 0, so the table's gamut mapping is what it can show of them."""
    _bpy()
    got, exact, _ = render_film(tmp_path, materials.SOAP_BUBBLE, "Soap", samples=1)
    inside = exact.min(axis=1) >= 0
    de = delta_e(colour, got, np.where(inside[:, None], exact, np.clip(exact, 0, None)))
    assert inside.sum() > 2000 and (~inside).sum() > 0
    assert np.percentile(de[inside], 99) <= 0.6, np.percentile(de[inside], [50, 99, 100])
    assert de.max() <= 1.0, (de[inside].max(), de[~inside].max())
    assert got.min() >= 0


def test_cycles_film_on_glass_is_the_exact_reflectance(tmp_path, colour):
    """A soap-like film on glass (1.33 on 1.5, semi-infinite): the same bound."""
    _bpy()
    got, exact, _ = render_film(tmp_path, materials.SOAP_ON_GLASS, "Glass", samples=1)
    de = delta_e(colour, got, np.clip(exact, 0, None))
    assert de.max() <= 1.0, np.percentile(de, [50, 99, 100])


def test_cycles_free_standing_bubble_conserves_energy(tmp_path):
    """The bubble (R and T tables, 16 bounces) in a white world: R + T = 1 for a film
    that absorbs nothing, so light reaches the camera undimmed: white on average over
    the disc (Cycles picks the glossy or the transparent closure by weight per sample,
    so one pixel is noisy, their mean is not). A material that dropped T (mean ~0.1) or
    counted R twice is far off."""
    _bpy()
    got, _, _ = render_film(
        tmp_path, materials.SOAP_BUBBLE, "Bubble", samples=16, transmittance=True
    )
    mean = got.mean(axis=0)
    assert np.abs(mean - 1).max() <= 0.01, mean
    assert np.abs(np.median(got, axis=0) - 1).max() <= 0.1, np.median(got, axis=0)
