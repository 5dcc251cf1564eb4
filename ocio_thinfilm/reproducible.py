"""Arithmetic that gives the same bits on every CPU, so every written file does too.

What the package writes (the config's LUTs, ``luts/``, the shaders, the knob page) must be
the same bytes whatever machine computes it. Correctly rounded elementwise operations
give the same bits everywhere; BLAS, LAPACK and SIMD transcendental functions do not,
and a last-bit difference decides a stored value that lies on a rounding boundary. So
the package uses, instead:

- :func:`matmul` -- ``a @ b`` in a fixed order, no BLAS;
- :func:`pairwise_sum` -- a sum over the last axis by halves, a fixed binary tree that
  numpy's SIMD loops evaluate (the material tables' integrations);
- :func:`inv3` -- the inverse of 3x3 matrices by the adjugate, no LAPACK;
- :func:`canonical` -- a table rounded to 32 significant bits, tiny values to 0;
- :func:`snap` -- values rounded to 36 significant bits before they are quantised;
- :func:`float32_of` -- a ufunc evaluated in float64 and rounded to float32.

``tests/test_reproducible.py`` regenerates the files under other BLAS kernels and SIMD
levels and compares their bytes. What differs between CPUs and why these roundings
suffice: docs/internals.md.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

__all__ = [
    "TABLE_BITS",
    "SNAP_BITS",
    "matmul",
    "pairwise_sum",
    "inv3",
    "canonical",
    "snap",
    "float32_of",
]

#: Tables are rounded to this many significant bits (:func:`canonical`).
TABLE_BITS = 32
#: Values are rounded to this many significant bits before quantisation (:func:`snap`).
SNAP_BITS = 36
#: Largest product array (elements) :func:`matmul` forms at once.
_ACCUMULATE_SIZE = 1 << 22


def matmul(a: npt.ArrayLike, b: npt.ArrayLike) -> np.ndarray:
    """Return ``a @ b`` summed in a fixed order, float64, without BLAS.

    ``sum_k a[..., k] * b[k, ...]`` accumulated from k = 0 upwards with elementwise
    numpy operations, which are correctly rounded: the same bits on every CPU. Shapes
    as numpy's ``@`` for a stack of row vectors or one matrix ``a`` (..., K) and a
    matrix (K, M) or vector (K,) ``b``.

    Parameters
    ----------
    a : array_like
        (..., K).
    b : array_like
        (K, M) or (K,).

    Returns
    -------
    numpy.ndarray
        float64, (..., M) or (...).

    Examples
    --------
    >>> matmul([[1.0, 2.0], [3.0, 4.0]], [[1.0, 0.0], [1.0, 1.0]]).tolist()
    [[3.0, 2.0], [7.0, 4.0]]
    >>> float(matmul([0.2126, 0.7152, 0.0722], [1.0, 1.0, 1.0]))
    1.0
    """
    A = np.asarray(a, dtype=np.float64)
    B = np.asarray(b, dtype=np.float64)
    if A.ndim == 0 or B.ndim not in (1, 2) or A.shape[-1] != B.shape[0]:
        raise ValueError(f"matmul: shapes {A.shape} and {B.shape} do not chain")
    column = B.ndim == 1
    if column:
        B = B[:, None]
    if A.size * B.shape[1] <= _ACCUMULATE_SIZE:
        # the same products summed in the same order by one ufunc call (add.accumulate
        # is sequential, never pairwise): the loop's bits, without its per-k overhead
        products = A[..., :, None] * B
        out = np.add.accumulate(products, axis=-2)[..., -1, :]
    else:
        out = A[..., 0, None] * B[0]
        for k in range(1, B.shape[0]):
            out = out + A[..., k, None] * B[k]
    return out[..., 0] if column else out


def pairwise_sum(values: npt.ArrayLike, *, overwrite: bool = False) -> np.ndarray:
    """Return the sum over the last axis by halves: a fixed binary tree, float64.

    With ``k`` terms left: if ``k`` is odd the last is added to the first, then the
    second half is added to the first half elementwise (``x[:k/2] += x[k/2:k]``), until
    one is left. Every step is an elementwise, correctly rounded numpy addition, so the
    result has the same bits on every CPU and SIMD level, and for a row it does not
    depend on the other rows; unlike :func:`matmul`'s sequential sum numpy evaluates it
    with vector instructions, and its rounding error grows like ``log2(k)`` instead of
    ``k`` (pairwise summation: Higham, N. J. (1993). The accuracy of floating point
    summation. SIAM J. Sci. Comput. 14(4), 783-799).

    Parameters
    ----------
    values : array_like
        (..., K), K >= 1.
    overwrite : bool, optional
        Work in ``values`` itself (a float64 array; its contents are destroyed)
        instead of a copy.

    Returns
    -------
    numpy.ndarray
        float64, (...).

    Examples
    --------
    The tree is ``(1 + -1e16) + (1e16 + 1)`` here, 0 in float64 (the exact sum is 2; a
    sequential sum gives 1):

    >>> pairwise_sum([1.0, 1e16, -1e16, 1.0]).tolist()
    0.0
    >>> pairwise_sum([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).tolist()
    [6.0, 15.0]
    """
    if overwrite and isinstance(values, np.ndarray) and values.dtype == np.float64:
        x = values
    else:
        x = np.array(values, dtype=np.float64)
    if x.ndim == 0 or x.shape[-1] == 0:
        raise ValueError(f"pairwise_sum: needs at least one term on the last axis, got {x.shape}")
    k = x.shape[-1]
    while k > 1:
        if k % 2:
            x[..., 0] += x[..., k - 1]
            k -= 1
        half = k // 2
        x[..., :half] += x[..., half:k]
        k = half
    return x[..., 0] + 0.0


def inv3(M: npt.ArrayLike) -> np.ndarray:
    """Return the inverse of a 3x3 matrix (or a stack of them) by the adjugate.

    Elementwise operations only (no LAPACK), so the same bits on every CPU.

    Parameters
    ----------
    M : array_like
        (..., 3, 3), invertible.

    Returns
    -------
    numpy.ndarray
        float64, (..., 3, 3).

    Examples
    --------
    >>> inv3([[2.0, 0.0, 0.0], [0.0, 4.0, 0.0], [1.0, 0.0, 1.0]]).tolist()
    [[0.5, 0.0, 0.0], [0.0, 0.25, 0.0], [-0.5, 0.0, 1.0]]
    """
    m = np.asarray(M, dtype=np.float64)
    if m.shape[-2:] != (3, 3):
        raise ValueError(f"inv3: M must be (..., 3, 3), got shape {m.shape}")
    cof = np.empty_like(m)
    for i in range(3):
        i1, i2 = (i + 1) % 3, (i + 2) % 3
        for j in range(3):
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            # cofactor C[i, j]; the cyclic indices carry the sign
            cof[..., i, j] = m[..., i1, j1] * m[..., i2, j2] - m[..., i1, j2] * m[..., i2, j1]
    det = m[..., 0, 0] * cof[..., 0, 0] + m[..., 0, 1] * cof[..., 0, 1]
    det = det + m[..., 0, 2] * cof[..., 0, 2]
    return np.swapaxes(cof, -1, -2) / det[..., None, None]


def canonical(values: npt.ArrayLike) -> np.ndarray:
    """Round a table computed with BLAS to 32 significant bits, and tiny values to 0.

    For colour-science's interpolated colour matching functions and illuminants: the
    last-bit differences between CPUs (2e-15 there) vanish, values below 2^-40 (1e-12:
    interpolation noise around exact zeros, 1e-22 and either sign) become exactly 0,
    and what is left (a relative 2.3e-10) lies far below what colorimetry resolves.

    Parameters
    ----------
    values : array_like

    Returns
    -------
    numpy.ndarray
        float64, same shape; never a negative zero.

    Examples
    --------
    >>> canonical([1.0524667000000003, 1.0524666999999983, -8.5e-22]).tolist()
    [1.0524666998535395, 1.0524666998535395, 0.0]
    """
    a = snap(values, TABLE_BITS)
    return np.where(np.abs(a) < 2.0**-40, 0.0, a) + 0.0


def snap(values: npt.ArrayLike, bits: int = SNAP_BITS) -> np.ndarray:
    """Round values to ``bits`` significant bits (default 36), float64 out.

    Before a value is quantised (16-bit codes, half floats, printed digits): a value
    that lies on a rounding boundary in exact arithmetic (0.5 of a 16-bit code is
    32767.5) but carries a CPU's last-bit error lands on that boundary exactly, and then
    rounds the same way on every CPU. Zero, infinities and NaN pass unchanged.

    Parameters
    ----------
    values : array_like
    bits : int, optional
        Significant bits kept, 1 to 52.

    Returns
    -------
    numpy.ndarray
        float64, same shape.

    Examples
    --------
    >>> v = snap([0.5 - 2.0**-50, 0.5 + 2.0**-50, 1.0 / 3.0])
    >>> v[:2].tolist(), bool(abs(v[2] - 1.0 / 3.0) < 2.0**-36)
    ([0.5, 0.5], True)
    """
    a = np.asarray(values, dtype=np.float64)
    if not 1 <= bits <= 52:
        raise ValueError(f"snap: bits must be in 1..52, got {bits!r}")
    mantissa, exponent = np.frexp(a)
    with np.errstate(invalid="ignore"):
        rounded = np.ldexp(np.round(np.ldexp(mantissa, bits)), exponent - bits)
    return np.where(np.isfinite(a), rounded, a) + 0.0


def float32_of(func: Callable[..., npt.ArrayLike], *args: npt.ArrayLike) -> np.ndarray:
    """Return ``func(*args)`` evaluated in float64 and rounded to float32.

    For a transcendental ufunc (``np.sin``, ``np.exp``, ``np.arccos`` ...) of float32
    data: numpy's float32 loops of these differ in the last bit between its AVX-512,
    AVX2 and baseline implementations (``NPY_DISABLE_CPU_FEATURES`` shows it), and a
    last float32 bit decides an 8-bit code or a half float often enough to change a
    picture. The float64 loops differ by a few float64 ulps at most, which rounding to
    float32 removes except with probability about 2^-27 per value.

    Parameters
    ----------
    func : callable
        A numpy ufunc (or any function of float64 arrays).
    *args : array_like
        Its arguments, taken as float64.

    Returns
    -------
    numpy.ndarray
        float32, the shape of ``func``'s result.

    Examples
    --------
    >>> float32_of(np.exp, np.float32(1.0)).dtype, float(float32_of(np.cos, 0.0))
    (dtype('float32'), 1.0)
    """
    result = func(*(np.asarray(a, dtype=np.float64) for a in args))
    return np.asarray(result, dtype=np.float64).astype(np.float32)
