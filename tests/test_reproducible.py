"""The same bytes on every CPU: the arithmetic of ocio_thinfilm.reproducible, and a sample
of the package's files regenerated under other BLAS kernels and SIMD levels.
"""

from __future__ import annotations

import filecmp
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from evaluation import reproduce
from ocio_thinfilm import reproducible
from ocio_thinfilm.lut import storage

ROOT = Path(__file__).resolve().parents[1]

#: Settings that change numpy's arithmetic below the last bit: OpenBLAS kernels of
#: other CPUs (every x86-64 CPU runs Prescott's and Sandybridge's) and numpy's SIMD
#: dispatch without AVX-512 and without AVX2/FMA (names of numpy's CPU features).
_NO_AVX512 = "X86_V4 AVX512F AVX512CD AVX512VL AVX512BW AVX512DQ AVX512_SKX AVX512_CLX"
_NO_AVX512 += " AVX512_CNL AVX512_ICL AVX512_SPR"
VARIANTS = {
    "openblas-prescott+numpy-no-avx512": {
        "OPENBLAS_CORETYPE": "Prescott",
        "NPY_DISABLE_CPU_FEATURES": _NO_AVX512,
    },
    "openblas-sandybridge+numpy-no-avx2": {
        "OPENBLAS_CORETYPE": "Sandybridge",
        "NPY_DISABLE_CPU_FEATURES": _NO_AVX512 + " X86_V3 AVX2 FMA3 AVX F16C",
    },
}


# --------------------------------------------------------------------------- #
# The arithmetic
# --------------------------------------------------------------------------- #
def test_matmul_and_inv3_agree_with_numpy():
    rng = np.random.default_rng(1)
    a, b = rng.normal(size=(200, 421)), rng.normal(size=(421, 3))
    np.testing.assert_allclose(reproducible.matmul(a, b), a @ b, rtol=0, atol=1e-12)
    M = rng.normal(size=(50, 3, 3)) + 3 * np.eye(3)
    np.testing.assert_allclose(reproducible.inv3(M), np.linalg.inv(M), rtol=0, atol=1e-12)
    v = rng.normal(size=3)
    np.testing.assert_allclose(reproducible.matmul(M[0], v), M[0] @ v, atol=1e-14)
    assert reproducible.matmul(v, v) == pytest.approx(v @ v, abs=1e-14)


def test_matmul_sums_alike_in_one_call_and_in_a_loop(monkeypatch):
    # small products are summed by one add.accumulate, large ones by a loop over k: the
    # same products in the same order, so the same bits
    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(300, 421)), rng.normal(size=(421, 3))
    one_call = reproducible.matmul(a, b)
    monkeypatch.setattr(reproducible, "_ACCUMULATE_SIZE", 0)
    assert np.array_equal(reproducible.matmul(a, b), one_call)


def test_matmul_is_one_fixed_order():
    # the order is k = 0, 1, 2, ...: (1 + 1e16) - 1e16 = 0 in float64, (-1e16 + 1e16) + 1
    # = 1; a pairwise or BLAS order may differ, this one may not
    a = np.array([[1.0, 1e16, -1e16]])
    assert reproducible.matmul(a, np.ones(3)).tolist() == [0.0]
    assert reproducible.matmul(a[:, ::-1], np.ones(3)).tolist() == [1.0]


def test_pairwise_sum_is_one_fixed_tree():
    # halves: (1e16 + -1e16) + (1 + 1) = 2, where the sequential order (matmul's) gives 1
    assert reproducible.pairwise_sum([1e16, 1.0, -1e16, 1.0]).tolist() == 2.0
    assert reproducible.matmul([[1e16, 1.0, -1e16, 1.0]], np.ones(4)).tolist() == [1.0]
    # an odd count folds the last term into the first: (1e16 + -1e16) + 1
    assert reproducible.pairwise_sum([1e16, 1.0, -1e16]).tolist() == 1.0


def test_pairwise_sum_agrees_with_numpy_and_rows_are_independent():
    rng = np.random.default_rng(5)
    a = rng.normal(size=(40, 421))
    total = reproducible.pairwise_sum(a)
    np.testing.assert_allclose(total, a.sum(axis=-1), rtol=0, atol=1e-12)
    # a row's sum does not depend on the rows beside it (a table split among workers)
    assert np.array_equal(reproducible.pairwise_sum(a[7:11]), total[7:11])
    kept = a.copy()
    reproducible.pairwise_sum(a)
    assert np.array_equal(a, kept)  # a copy unless overwrite=True


def test_canonical_removes_last_bit_noise_and_false_zeros():
    # colour-science's CMF at one wavelength under two OpenBLAS kernels, and the
    # interpolation noise around an exact zero
    table = np.array([1.0524667000000003, 3.9e-5, -8.47e-22])
    noisy = np.array([1.0524666999999983, 3.9e-5 * (1 + 2e-15), 2.12e-22])
    assert np.array_equal(reproducible.canonical(table), reproducible.canonical(noisy))
    zero = reproducible.canonical(table)[2]
    assert zero == 0.0 and not np.signbit(zero)
    rel = np.abs(reproducible.canonical(table[:2]) / table[:2] - 1.0)
    assert rel.max() <= 2.0**-32


def test_codes_on_a_rounding_boundary_round_alike():
    # 0.5 is code 32767.5: one ulp either side must not decide the code
    values = np.array([0.5, np.nextafter(0.5, 0.0), np.nextafter(0.5, 1.0)])
    codes = storage.q16(values) * storage.LUT_CODE_MAX
    assert codes.tolist() == [32768.0] * 3
    # a half-float midpoint (1 + 2^-11) likewise
    mid = 1.0 + 2.0**-11
    halves = storage.half16(np.array([mid, np.nextafter(mid, 0.0), np.nextafter(mid, 2.0)]))
    assert len(set(halves.tolist())) == 1


# --------------------------------------------------------------------------- #
# The files, regenerated under other CPUs' arithmetic
# --------------------------------------------------------------------------- #
def _committed(relative: Path) -> Path:
    """The committed file a regenerated one must equal (None: compared across runs)."""
    top = relative.parts[0]
    if top == "cfg":
        return ROOT / "configs" / "thinfilm" / "luts" / relative.name
    if top == "luts":
        return ROOT / "luts" / relative.name
    if relative.name == "knobs.html":
        return ROOT / "docs" / "knobs.html"
    return None


def _regenerate(out: Path, extra_env: dict) -> subprocess.Popen:
    env = dict(os.environ, OCIO_THINFILM_CACHE="0", **extra_env)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    return subprocess.Popen(
        [sys.executable, "-m", "evaluation.reproduce", str(out)],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


@pytest.fixture(scope="module")
def regenerated(tmp_path_factory):
    """{variant: directory} of the sample regenerated under each setting, in parallel."""
    base = tmp_path_factory.mktemp("reproduce")
    runs = {name: (base / name, _regenerate(base / name, env)) for name, env in VARIANTS.items()}
    out = {}
    for name, (directory, proc) in runs.items():
        stdout, stderr = proc.communicate(timeout=900)
        assert proc.returncode == 0, f"{name}: {stderr[-2000:]}"
        out[name] = directory
    return out


def _files(directory: Path) -> list[Path]:
    return sorted(p.relative_to(directory) for p in directory.rglob("*") if p.is_file())


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_files_are_the_committed_bytes_under_other_cpus(regenerated, variant):
    directory = regenerated[variant]
    files = _files(directory)
    assert len(files) == 7 + 1 + len(reproduce.SHADERS) + 1 + 2 * 4
    differ = [
        str(relative)
        for relative in files
        if (committed := _committed(relative)) is not None
        and not filecmp.cmp(directory / relative, committed, shallow=False)
    ]
    assert differ == [], f"{variant}: regenerated files differ from the committed ones"


def test_shaders_are_the_same_bytes_under_other_cpus(regenerated, tmp_path):
    # no shader is committed: this process's own output (default settings) is the
    # reference
    from ocio_thinfilm.cli.main import main as cli_main

    for display, view, language in reproduce.SHADERS:
        name = reproduce.shader_name(display, view, language)
        argv = ["export", "shader", "--lang", language, "--from", "ACEScct"]
        argv += ["--display", display, "--view", view, "--out", str(tmp_path / name)]
        assert cli_main(argv) == 0
        reference = (tmp_path / name).read_bytes()
        for variant, directory in regenerated.items():
            assert (directory / "shaders" / name).read_bytes() == reference, (variant, name)


def test_renders_are_the_same_bytes_under_other_cpus(regenerated, tmp_path):
    # the gallery's path (noise, scenes, the config's processors, EXR and PNG) at a small
    # size; this process's own render (default settings) is the reference. numpy's
    # float32 sin/cos/exp/arccos differ between SIMD levels: before the scenes took them
    # in float64 (reproducible.float32_of), oil.exr and morpho.exr differed here
    from ocio_thinfilm.cli.main import main as cli_main

    assert cli_main([*reproduce.RENDER_ARGV, "--out", str(tmp_path)]) == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == sorted(
        f"{s}.{e}" for s in ("spectrum", "oil", "soap", "morpho") for e in ("exr", "png")
    )
    for variant, directory in regenerated.items():
        differ = [
            name
            for name in names
            if (directory / "render" / name).read_bytes() != (tmp_path / name).read_bytes()
        ]
        assert differ == [], f"{variant}: rendered files differ from this process's"


#: A material table (the exact engine's fast path: coefficients, phasor powers, sums by
#: halves) as bytes, for the regenerations below.
_MATERIAL_SCRIPT = """
import hashlib, sys
import numpy as np
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics import films
fs = films.read_films("docs/films.toml")
digest = hashlib.sha256()
for key in ("SoapFilm", "CoatedGold", "Temper"):
    film = fs[key]
    t = material_tables.axis_nodes(*film.range_um, 96)
    c = np.linspace(0.0, 1.0, 13)
    R, T = material_tables.film_angle_XYZ(film, t, c, transmittance=key == "SoapFilm", workers=2)
    digest.update(R.tobytes())
    if T is not None:
        digest.update(T.tobytes())
print(digest.hexdigest())
"""


def test_material_tables_are_the_same_bits_under_other_cpus():
    # the float64 tables themselves (not only their float32 EXRs): every operation of the
    # engine is correctly rounded or libm's
    def run(extra_env):
        env = dict(os.environ, **extra_env)
        env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
        return subprocess.Popen(
            [sys.executable, "-c", _MATERIAL_SCRIPT],
            cwd=ROOT,
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )

    procs = {name: run(env) for name, env in {"default": {}, **VARIANTS}.items()}
    digests = {}
    for name, proc in procs.items():
        stdout, stderr = proc.communicate(timeout=600)
        assert proc.returncode == 0, f"{name}: {stderr[-2000:]}"
        digests[name] = stdout.strip()
    assert len(set(digests.values())) == 1, digests
