"""Benchmark: the fitted display LUT's inside-gamut weight against both errors.

Run:  python benchmarks/bench_view_fit.py [--weights 1 3 10 30] [--display sRGB]
                                          [--out reports]

The plain 65^3 ``ACEScct -> <display> / Constant-Lightness Clip`` ``.cube`` is baked
with its 3D table fitted by lattice regression (:mod:`ocio_thinfilm.export.view_fit`)
at each weight of the colours inside the display's gamut (the node samples of the
view, the table before the fit, are the first row, ``weight = sampled``), and applied
as hosts apply it by default: ffmpeg's ``lut3d`` (tetrahedral; skipped when ffmpeg is
absent), OpenColorIO's ``FileTransform`` and colour-science's ``LUT3D.apply``
(trilinear). Errors are ΔE2000 against the analytic clip on the evaluation sets
(``evaluation.colours``: object colours inside AP1, 20,000 colours inside AP0 and the
spectral-line mixtures), split into colours inside the display's gamut and outside it.

Writes ``<out>/bench_view_fit.json``, ``.md`` and ``.png`` (the curve: p99 and max
against the weight, inside and outside, per host), and (for sRGB) the object-colour
table in docs/gamut_map.md between its markers (:func:`docs_markdown` of the JSON).
Prints its own measurements.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from benchmarks import _reports  # noqa: E402  (after the path above)
from evaluation.colours import gamut_map_sets, object_colours  # noqa: E402
from ocio_thinfilm.colour import clip, colorimetry  # noqa: E402
from ocio_thinfilm.export import view as export_view  # noqa: E402
from ocio_thinfilm.export import view_fit  # noqa: E402

VIEW = "Constant-Lightness Clip"
FFMPEG = shutil.which("ffmpeg")
DOC = Path(__file__).resolve().parents[1] / "docs" / "gamut_map.md"
BEGIN, END = "<!-- bench_view_fit:begin -->", "<!-- bench_view_fit:end -->"


def acescct(XYZ):
    """XYZ (D65) -> ACEScct by colour-science (Bradford), with the ACEScg values."""
    import colour

    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    acescg = colour.XYZ_to_RGB(
        XYZ, colour.RGB_COLOURSPACES["ACEScg"], d65, chromatic_adaptation_transform="Bradford"
    )
    return acescg, colour.models.log_encoding_ACEScct(np.maximum(acescg, 1e-10))


def test_sets():
    """name -> (XYZ, ACEScct) of the evaluation colours inside AP1."""
    out = {}
    sets = {"object": object_colours()} | {
        k: v for k, v in gamut_map_sets().items() if k in ("ap0", "mixtures")
    }
    for name, XYZ in sets.items():
        acescg, cct = acescct(XYZ)
        keep = (acescg >= 0).all(axis=1)
        out[name] = XYZ[keep], cct[keep]
    return out


def apply_ocio(path, values):
    import PyOpenColorIO as ocio

    px = np.ascontiguousarray(values, dtype=np.float32).copy()
    t = ocio.FileTransform(str(path))  # default interpolation: trilinear for a 3D LUT
    ocio.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(px)
    return px.astype(np.float64)


def apply_colour(path, values):
    import colour

    return colour.read_LUT(str(path)).apply(np.asarray(values, dtype=np.float64))


def apply_ffmpeg(path, values):
    rgb = np.asarray(values, dtype=np.float32).reshape(-1, 3)
    n, w = len(rgb), 256
    h = -(-n // w)
    img = np.zeros((w * h, 3), np.float32)
    img[:n] = rgb
    img = img.reshape(h, w, 3)
    planes = np.stack([img[..., 1], img[..., 2], img[..., 0]])  # gbrp
    args = [FFMPEG, "-v", "error", "-f", "rawvideo", "-pix_fmt", "gbrpf32le"]
    args += ["-s", f"{w}x{h}", "-i", "-", "-vf", f"lut3d=file={path}"]
    args += ["-f", "rawvideo", "-pix_fmt", "gbrpf32le", "-"]
    result = subprocess.run(args, input=planes.astype("<f4").tobytes(), capture_output=True)
    if result.returncode:
        raise RuntimeError(result.stderr.decode())
    out = np.frombuffer(result.stdout, "<f4").reshape(3, h, w)
    return np.stack([out[2], out[0], out[1]], axis=-1).reshape(-1, 3)[:n].astype(np.float64)


def decode(code, display):
    import colour

    code = np.clip(code, 0.0, 1.0)
    return code**2.4 if display == "Rec.2020" else colour.cctf_decoding(code, "sRGB")


def errors(code, XYZ, display):
    got = colorimetry.RGB_to_XYZ(decode(code, display), display)
    want = colorimetry.RGB_to_XYZ(
        clip.clip_RGB(colorimetry.XYZ_to_RGB(XYZ, display), display), display
    )
    return colorimetry.delta_E2000(got, want)


def measure(path, sets, display, hosts):
    row = {}
    for name, (XYZ, cct) in sets.items():
        inside = clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ, display))
        for host, apply in hosts.items():
            dE = errors(apply(path, cct), XYZ, display)
            for part, mask in (("inside", inside), ("outside", ~inside)):
                if mask.any():
                    row[f"{name}/{host}/{part}"] = (
                        float(np.percentile(dE[mask], 99)),
                        float(dE[mask].max()),
                    )
    return row


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--weights", type=float, nargs="+", default=[1.0, 3.0, 10.0, 30.0])
    parser.add_argument("--display", default="sRGB")
    parser.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "reports"))
    _reports.add_update_docs(parser)
    args = parser.parse_args(argv)
    display = args.display
    hosts = {"ocio": apply_ocio, "colour": apply_colour}
    if FFMPEG:
        hosts = {"ffmpeg": apply_ffmpeg} | hosts
    else:
        print("ffmpeg not installed: its column is left out")
    sets = test_sets()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp) / "sampled.cube"
        cfg, _ = export_view.view_config("ACEScct", 65, display)
        # the node samples: OCIO's Baker without the fit
        import PyOpenColorIO as ocio

        baker = ocio.Baker()
        baker.setConfig(cfg)
        baker.setFormat("resolve_cube")
        baker.setInputSpace("ACEScct")
        baker.setDisplayView(display, VIEW)
        baker.setCubeSize(65)
        text = baker.bake()
        base.write_text(text)
        rows.append(dict(weight="sampled", fit_s=0.0) | measure(base, sets, display, hosts))
        print(json.dumps(rows[-1]))
        for weight in args.weights:
            t0 = time.perf_counter()
            # the computation itself, not its memo (on disk), with a fresh config
            cfg, _ = export_view.view_config("ACEScct", 65, display)
            nodes = view_fit.fit_view_table(cfg, "ACEScct", display, VIEW, 65, weight)
            fit_s = time.perf_counter() - t0
            path = Path(tmp) / f"w{weight:g}.cube"
            path.write_text(export_view._with_table(text, nodes))
            rows.append(dict(weight=weight, fit_s=fit_s) | measure(path, sets, display, hosts))
            print(json.dumps(rows[-1]))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    _reports.write_json(
        "view_fit", dict(display=display, rows=rows), path=out / "bench_view_fit.json"
    )
    write_markdown(out / "bench_view_fit.md", display, rows, list(hosts))
    plot(out / "bench_view_fit.png", display, rows, list(hosts))
    print(f"wrote {out}/bench_view_fit.{{json,md,png}}")
    if display == "sRGB" and out == DOC.parents[1] / "reports":
        update_doc(dict(display=display, rows=rows), update=args.update_docs)


def _hosts(rows):
    return [h for h in ("ffmpeg", "ocio", "colour") if f"object/{h}/inside" in rows[0]]


def table(rows, hosts, name="object"):
    """The markdown table of one colour set: a row per weight, p99 / max per host,
    inside and outside the gamut."""
    head = ["weight", "fit s"] + [f"{h} {p}" for h in hosts for p in ("inside", "outside")]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row in rows:
        weight = row["weight"]
        label = str(weight)
        if weight == view_fit.INSIDE_WEIGHT:
            label += " (shipped)"
        cells = [label, f"{row['fit_s']:.1f}"]
        for h in hosts:
            for p in ("inside", "outside"):
                v = row.get(f"{name}/{h}/{p}")
                cells.append("-" if v is None else f"{v[0]:.2f} / {v[1]:.2f}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def docs_markdown(result):
    """docs/gamut_map.md's block: the object-colour table of ``result`` (the JSON)."""
    return table(result["rows"], _hosts(result["rows"]))


def update_doc(result, path=DOC, update=False):
    """docs/gamut_map.md's object-colour table from ``result``.

    Written only if ``update``; else says whether it would change.
    """
    _reports.update_section(path, BEGIN, END, docs_markdown(result), update=update)


def write_markdown(path, display, rows, hosts):
    lines = [
        f"# Fitted display LUT: inside-gamut weight against both errors ({display})",
        "",
        f"`benchmarks/bench_view_fit.py`: the plain 65^3 ACEScct -> {display} / {VIEW} "
        "`.cube`, its table sampled (first row) or fitted by lattice regression with the "
        "colours inside the gamut weighted `weight` times, applied by each host at its "
        "default interpolation. ΔE2000 p99 / max against the analytic clip; object "
        "colours inside AP1 (the tests' set), AP0 colours and spectral-line mixtures "
        "inside AP1, split inside / outside the display's gamut. `fit s`: the config in "
        "memory, the training colours and the fit (no disk memo), on the machine that ran "
        "the benchmark. The shipped weight is `view_fit.INSIDE_WEIGHT`.",
        "",
    ]
    for name in ("object", "ap0", "mixtures"):
        lines += [f"## {name}", "", table(rows, hosts, name), ""]
    path.write_text("\n".join(lines))


def plot(path, display, rows, hosts):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fitted = [r for r in rows if r["weight"] != "sampled"]
    w = [r["weight"] for r in fitted]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharex=True)
    for ax, stat, label in ((axes[0], 0, "p99"), (axes[1], 1, "max")):
        # OCIO and colour-science coincide: drawn wider and below
        styles = {"ffmpeg": ("C0", "o", 1.5), "ocio": ("C1", "s", 4.0), "colour": ("C2", "^", 1.2)}
        for h in hosts:
            colour, marker, lw = styles[h]
            for part, style in (("inside", "-"), ("outside", "--")):
                key = f"object/{h}/{part}"
                ax.plot(
                    w,
                    [r[key][stat] for r in fitted],
                    style,
                    color=colour,
                    marker=marker,
                    lw=lw,
                    label=f"{h} {part}",
                )
                ax.axhline(rows[0][key][stat], color=colour, ls=style, lw=0.6, alpha=0.5)
        ax.axhline(1.0 if stat == 0 else 3.0, color="k", lw=1.0, ls=":")
        ax.set_xscale("log")
        ax.set_xlabel("weight of the colours inside the gamut")
        ax.set_ylabel(f"ΔE2000 {label}")
        ax.set_title(f"object colours, {label} (thin lines: sampled nodes)")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"ACEScct -> {display} / {VIEW}, plain 65^3 .cube, lattice regression")
    fig.tight_layout()
    fig.savefig(path, dpi=100)


if __name__ == "__main__":
    main()
