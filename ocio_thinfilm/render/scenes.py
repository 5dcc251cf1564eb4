"""The paper's example scenes (Smits & Meyer 1990, Section 4, Figures 4-7).

Stage 7 of the pipeline. A scene is geometry and shading only: it computes, per pixel,
the *encoded* value a precomputed table is indexed with (optical thickness t' in um for a
film, cos(theta) for the Morpho multilayer) and composites the table's colour, from a
``lookup(spec, encoded)`` callable (:func:`ocio_thinfilm.render.processors.make_lookup`:
the config's thin-film colour spaces), in scene-linear CIE XYZ. Each scene declares the
tables it needs (:class:`TableSpec`); what every scene is made of is
:mod:`ocio_thinfilm.render.scene_base`. This module holds the scenes:

- ``spectrum`` (Fig. 4): the visible spectrum and Newton's colours through four views;
- ``oil`` (Fig. 5): an oil slick on wet asphalt, Eq. 12-13;
- ``soap`` (Fig. 6): a soap bubble, black at the thin top;
- ``morpho`` (Fig. 7): a wavy surface coloured by the Morpho angle table (Eq. 9 + 14).

Each scene in pictures: docs/render.md, *Gallery*; the conventions (images, units,
frames): its *Design notes*.
"""

from __future__ import annotations

import numpy as np

from ocio_thinfilm import registry, reproducible
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.physics import spectra
from ocio_thinfilm.render import noise
from ocio_thinfilm.render.scene_base import (
    D65_WHITE,
    FILM_TABLE,
    MORPHO_TABLE,
    Lookup,
    Picture,
    Scene,
    TableSpec,
)
from ocio_thinfilm.render.scene_base import grey as _grey
from ocio_thinfilm.render.scene_base import optical_thickness_um as _optical_thickness_um
from ocio_thinfilm.render.scene_base import pixel_grid as _pixel_grid
from ocio_thinfilm.render.scene_base import smoothstep as _smoothstep
from ocio_thinfilm.render.scene_base import unit as _unit

__all__ = [
    "TableSpec",
    "Picture",
    "Scene",
    "SCENES",
    "FILM_TABLE",
    "MORPHO_TABLE",
    "get_scene",
    "D65_WHITE",
]


# --------------------------------------------------------------------------- #
# Figure 4: the spectrum and Newton's colours through four views.
# --------------------------------------------------------------------------- #
class SpectrumScene(Scene):
    """Figure 4: the visible spectrum and two rows of interference colours.

    The visible spectrum, Newton's colours of a soap film against thickness and the
    Morpho colours against angle, each strip through four views side by side (the clip
    and the compression keep luminance, the clamp and ACES do not).
    """

    name = "spectrum"
    figure = "Figure 4"
    title = (
        "The visible spectrum (380 nm at the top to 700 nm) and two rows of "
        "interference colours -- Newton's colours of a soap film (t' = 0 to 1 um) and "
        "the near-spectral Morpho multilayer (0 to 60 degrees) -- through the "
        "Constant-Lightness Clip, Constant-Lightness Compress, Channel Clamp and ACES "
        "Gamut Compression views side by side"
    )
    animation = "none (every frame is the same)"
    tables = (FILM_TABLE, MORPHO_TABLE)

    #: The views compared, left to right (the registry's of these kinds).
    VIEWS = tuple(registry.view_of_kind(k).name for k in ("clip", "compress", "clamp", "aces"))
    #: Peak luminance of the spectrum strip (Y of the equal-energy spectrum at 555 nm).
    SPECTRUM_PEAK_Y = 0.6
    WAVELENGTHS = (380.0, 700.0)
    THICKNESS = (0.0, 1.0)
    ANGLES = (0.0, 60.0)
    STRIPS = ("spectrum", "film", "morpho")

    def render(
        self, width: int, height: int, *, lookup: Lookup, seed: int = 0, frame: int = 1
    ) -> Picture:
        """Render one frame: see :meth:`Scene.render`."""
        header = max(2, int(round(height * 0.11)))
        gap = max(1, width // 64)
        panel = (width - (len(self.VIEWS) + 1) * gap) // len(self.VIEWS)
        strip = (panel - 2 * gap) // 3
        rows = np.arange(header, height - gap)
        frac = (rows - header + 0.5) / max(1, len(rows))

        xyz = np.zeros((height, width, 3), np.float32)
        aovs = {
            k: np.zeros((height, width), np.float32) for k in ("wavelength", "thickness", "angle")
        }

        # Spectrum: the CIE 1931 matching functions (equal-energy light), every 1 nm
        # interpolated to the rows.
        lo, hi = self.WAVELENGTHS
        wl = lo + (hi - lo) * frac
        grid = np.arange(360.0, 831.0)
        cmfs = colorimetry.cmfs_at(grid)
        spec = np.stack([np.interp(wl, grid, cmfs[:, k]) for k in range(3)], axis=-1)
        spec *= self.SPECTRUM_PEAK_Y / cmfs[:, 1].max()

        # Newton's colours through the film table, the Morpho's through its angle
        # table (one column each, then broadcast).
        t0, t1 = self.THICKNESS
        t_opt = (t0 + (t1 - t0) * frac).astype(np.float32)
        film = lookup(FILM_TABLE, t_opt[:, None])[:, 0, :]
        a0, a1 = self.ANGLES
        theta = (a0 + (a1 - a0) * frac).astype(np.float32)
        cos_t = reproducible.float32_of(np.cos, np.radians(theta.astype(np.float64)))
        morpho = MorphoScene.EXPOSURE * lookup(MORPHO_TABLE, cos_t[:, None])[:, 0, :]

        columns: list[tuple[np.ndarray, str, np.ndarray]] = [
            (spec, "wavelength", wl),
            (film, "thickness", t_opt),
            (morpho, "angle", theta),
        ]
        regions, labels = [], []
        font = int(min(header * 0.42, panel / (0.5 * max(map(len, self.VIEWS)))))
        small = int(font * 0.75)
        body = slice(header, height - gap)
        for i, view in enumerate(self.VIEWS):
            x0 = gap + i * (panel + gap)
            for j, (values, aov, coordinate) in enumerate(columns):
                xs = slice(x0 + j * (strip + gap), x0 + j * (strip + gap) + strip)
                xyz[body, xs] = values[:, None, :]
                aovs[aov][body, xs] = coordinate[:, None]
                labels.append(
                    (x0 + j * (strip + gap) + strip // 2, int(header * 0.9), self.STRIPS[j], small)
                )
            left = 0 if i == 0 else x0 - gap // 2
            right = width if i == len(self.VIEWS) - 1 else x0 + panel + gap // 2
            regions.append((left, right, view))
            labels.append((x0 + panel // 2, int(header * 0.45), view, font))
        if small < 6:  # too small to read: no captions on thumbnails
            labels = []
        return Picture(
            xyz=xyz,
            aovs=aovs,
            aov_docs={
                "wavelength": "wavelength of the spectrum strips in nm (0 elsewhere)",
                "thickness": "optical thickness t' = n t cos(theta_t) of the film "
                "strips in micrometres (0 elsewhere)",
                "angle": "view angle of the Morpho strips in degrees (0 elsewhere)",
            },
            regions=regions,
            labels=labels,
            attributes={
                "spectrum_peak_Y": self.SPECTRUM_PEAK_Y,
                "morpho_exposure": MorphoScene.EXPOSURE,
            },
        )


# --------------------------------------------------------------------------- #
# Figure 5: an oil slick on wet asphalt.
# --------------------------------------------------------------------------- #
class OilScene(Scene):
    """Figure 5: an oil slick on wet asphalt, seen by a camera looking down at the road.

    An oil slick (n = 1.5; air|oil inverts, oil|water does not: a phase change) on wet
    asphalt, thickness t = T exp(-k1 r^2) made irregular by turbulence (Eq. 12-13):
    each pixel's view angle gives its optical thickness (Eq. 10 form).
    """

    name = "oil"
    figure = "Figure 5"
    title = "An oil slick on wet asphalt (Eq. 12-13), seen from above at an angle"
    animation = (
        "the slick spreads: k1 and the centre thickness fall as "
        "1/(1 + 0.04 (frame - 1)), keeping its volume"
    )
    tables = (FILM_TABLE,)
    takes_films = True

    N_OIL = 1.5  # oil on water: air|oil inverts, oil|water does not -> phase change
    T_CENTRE = 0.75  # physical thickness at the centre of the slick, um
    K1 = 1.6  # Eq. 12: t = T exp(-k1 r^2), r in slick units (SLICK_SCALE)
    K2 = 0.9  # Eq. 13: irregularity of the spreading
    SLICK_SCALE = 0.38  # metres per slick unit
    SPREAD = 0.04  # per frame
    CAMERA_HEIGHT = 1.5  # metres above the road
    PITCH = 52.0  # degrees below the horizon, looking at the slick centre
    FOV = 44.0  # vertical field of view, degrees
    FILM_GAIN = 0.4  # strength of the film's reflection of the sky
    WATER_SHEEN = 0.012  # Fresnel reflection of the sky by the bare water film

    def camera_rays(self, width: int, height: int) -> tuple[np.ndarray, np.ndarray, np.float32]:
        """Return the rays of a pinhole camera (z up, looking along +y and down by PITCH).

        Parameters
        ----------
        width, height : int
            Image size in pixels.

        Returns
        -------
        directions : numpy.ndarray
            float32 (H, W, 3) unit ray directions.
        eye : numpy.ndarray
            float32 (3,) camera position in metres (CAMERA_HEIGHT above the road).
        pixel_angle : numpy.float32
            Size of one pixel on the image plane at unit distance (radians, nearly).
        """
        x, y = _pixel_grid(width, height)
        tan_half = np.float32(np.tan(np.radians(self.FOV) / 2))
        u = (x / width * 2 - 1) * tan_half * (width / height)
        v = (1 - y / height * 2) * tan_half
        p = np.radians(self.PITCH)
        forward = np.array([0.0, np.cos(p), -np.sin(p)], np.float32)
        up = np.array([0.0, np.sin(p), np.cos(p)], np.float32)
        right = np.array([1.0, 0.0, 0.0], np.float32)
        d = forward + u[..., None] * right + v[..., None] * up
        d = _unit(d)
        eye = np.array([0.0, -self.CAMERA_HEIGHT / np.tan(p), self.CAMERA_HEIGHT], np.float32)
        pixel_angle = 2 * tan_half / height
        return d, eye, pixel_angle

    def render(
        self, width: int, height: int, *, lookup: Lookup, seed: int = 0, frame: int = 1
    ) -> Picture:
        """Render one frame: see :meth:`Scene.render`."""
        d, eye, pixel_angle = self.camera_rays(width, height)
        dz = np.minimum(d[..., 2], np.float32(-1e-3))
        s = -eye[2] / dz  # distance to the road
        gx = eye[0] + s * d[..., 0]
        gy = eye[1] + s * d[..., 1]
        cos_view = -dz  # cos of the view angle
        theta = np.degrees(reproducible.float32_of(np.arccos, np.clip(cos_view, 0.0, 1.0)))
        # Pixel footprint on the road (metres), stretched along the view direction.
        footprint = (s * pixel_angle / np.sqrt(cos_view)).astype(np.float32)

        # Eq. 13 with the slick spreading over the frames (volume ~ T / k1 kept).
        spread = 1.0 + self.SPREAD * (frame - 1)
        k1, t_centre = self.K1 / spread, self.T_CENTRE / spread
        sx, sy = gx / self.SLICK_SCALE, gy / self.SLICK_SCALE
        turb = noise.turbulence(
            sx * 0.9,
            sy * 0.9,
            octaves=4,
            seed=seed,
            filter_width=footprint * (0.9 / self.SLICK_SCALE),
        )
        t_phys = t_centre * reproducible.float32_of(
            np.exp, -k1 * (sx * sx + sy * sy + self.K2 * (turb - 0.45))
        )
        t_phys = np.minimum(t_phys, np.float32(t_centre)).astype(np.float32)
        # Optical thickness through the refraction angle (paper Eq. 10 form).
        t_opt = _optical_thickness_um(t_phys, self.N_OIL, theta)
        asphalt = self.asphalt(gx, gy, footprint, seed)
        # Overcast sky seen in the mirror direction: CIE overcast gradation (1 + 2 cos z)/3,
        # the reflected ray's zenith angle equals the view angle.
        sky = (1.0 + 2.0 * cos_view) / 3.0
        if self.film is not None:
            # a user's film: its physical reflectance (the water's own Fresnel sheen
            # included) at its own angle, against the physical thickness
            film = lookup(self.film, t_phys)
            xyz = (asphalt + sky[..., None] * film).astype(np.float32)
            thickness = (t_phys, "physical thickness of the film's varying layer in um")
        else:
            film = lookup(FILM_TABLE, t_opt)
            xyz = (
                asphalt
                + _grey(self.WATER_SHEEN * sky)
                + np.float32(self.FILM_GAIN) * sky[..., None] * film
            ).astype(np.float32)
            thickness = (
                t_opt,
                "optical thickness t' = n t cos(theta_t) of the oil in micrometres "
                "(the table index)",
            )
        return Picture(
            xyz=xyz,
            aovs={"thickness": thickness[0], "angle": theta},
            aov_docs={
                "thickness": thickness[1],
                "angle": "view angle from the road's normal in degrees",
            },
            regions=[(0, width, None)],
            attributes={
                "k1": k1,
                "k2": self.K2,
                "centre_thickness_um": t_centre,
                "n_oil": self.N_OIL,
                "film_gain": self.FILM_GAIN,
            },
        )

    @staticmethod
    def asphalt(
        gx: np.ndarray, gy: np.ndarray, footprint: np.ndarray | float, seed: int
    ) -> np.ndarray:
        """Return wet asphalt as XYZ (H, W, 3).

        Two noise calls set the local bump scale (a blend between coarse and fine
        aggregate) and the roughness (the bumps' amplitude); very fine bumps go on top.
        Shaded by the bump slope under the overcast sky; the water film darkens it.

        Parameters
        ----------
        gx, gy : numpy.ndarray
            (H, W) road coordinates in metres.
        footprint : numpy.ndarray or float
            Size of a pixel on the road in metres (band-limits the turbulence).
        seed : int
            Noise seed, an integer >= 0.

        Returns
        -------
        numpy.ndarray
            float32 (H, W, 3) CIE XYZ.
        """
        scale = _smoothstep(-0.35, 0.35, noise.noise(gx * 0.8, gy * 0.8, seed=seed + 11))
        rough = np.clip(
            0.6 + 0.8 * noise.noise(gx * 1.5 + 5.3, gy * 1.5, seed=seed + 12), 0.15, 1.2
        )
        coarse = noise.turbulence(
            gx * 14.0, gy * 14.0, octaves=3, seed=seed + 13, filter_width=footprint * 14.0
        )
        small = noise.turbulence(
            gx * 40.0, gy * 40.0, octaves=2, seed=seed + 14, filter_width=footprint * 40.0
        )
        fine = noise.turbulence(
            gx * 220.0, gy * 220.0, octaves=2, seed=seed + 15, filter_width=footprint * 220.0
        )
        height = rough * (coarse + scale * (small - coarse)) + 0.3 * fine
        # Shading from the height's slope in the image (light from the upper left).
        dy, dx = np.gradient(height)
        shade = np.clip(1.0 + 1.5 * (dx * -0.6 + dy * -0.8), 0.4, 1.7)
        albedo = 0.018 + 0.03 * np.clip(height, 0.0, 1.5)  # aggregate lighter than binder
        return _grey((albedo * shade).astype(np.float32))


# --------------------------------------------------------------------------- #
# Figure 6: a soap bubble.
# --------------------------------------------------------------------------- #
class SoapScene(Scene):
    """Figure 6: a soap bubble (n = 1.33, phase change), black at the thin, drained top.

    Its thickness is proportional to the normalised height plus turbulence.
    """

    name = "soap"
    figure = "Figure 6"
    title = "A soap bubble: thickness proportional to height plus turbulence, black at the top"
    animation = "the film drains: the black film at the top grows and the bands sink"
    tables = (FILM_TABLE,)
    takes_films = True

    N_SOAP = 1.33
    T_BOTTOM = 1.0  # physical thickness at the bottom of the bubble, um
    TURB = 0.2  # weight of the turbulence added to the normalised height
    BLACK = 0.06  # the still's black film: heights above this are drained
    DRAIN = 0.01  # per frame: the black film grows by this much height
    RADIUS = 0.44  # of the image's smaller side
    FILM_GAIN = 0.85

    def _thickness(
        self, nx: np.ndarray, ny: np.ndarray, r: np.float32, seed: int, frame: int
    ) -> tuple[np.ndarray, float]:
        """Return the film's physical thickness (um) and the drained height."""
        # Height normalised to 0 at the top and 1 at the bottom, plus turbulence (air
        # currents) swirling around the bubble; draining raises the black line.
        h = (1.0 - ny) / 2.0
        drain = min(0.6, self.BLACK + self.DRAIN * (frame - 1))
        # Air currents: turbulence stretched sideways (bands swirl more than they
        # rise), its lattice warped by one more noise call.
        swirl = noise.noise(nx * 1.2, ny * 1.2 + 7.1, seed=seed + 21)
        turb = noise.turbulence(
            nx * 1.4 + 0.9 * swirl,
            ny * 3.2 + 0.6 * swirl - 0.02 * (frame - 1),
            octaves=5,
            seed=seed,
            filter_width=np.float32(3.2 / r),
        )
        level = h + self.TURB * (turb - 0.45)
        level = np.clip((level - drain) / (1.0 - drain), 0.0, None)
        return (self.T_BOTTOM * level).astype(np.float32), drain

    @staticmethod
    def _studio(nx: np.ndarray, ny: np.ndarray, nz: np.ndarray) -> np.ndarray:
        """Return the studio environment's light seen in the mirror direction."""
        # Studio environment seen in the mirror direction: a soft bright window at the
        # upper left over a dim room, brighter above than below.
        rx, ry, rz = 2 * nz * nx, 2 * nz * ny, 2 * nz * nz - 1
        window = np.array([-0.45, 0.6, 0.66], np.float32)
        window /= np.sqrt(reproducible.matmul(window, window))
        key = _smoothstep(0.86, 0.97, rx * window[0] + ry * window[1] + rz * window[2])
        return 0.55 + 0.3 * ry + 0.45 * key

    def render(
        self, width: int, height: int, *, lookup: Lookup, seed: int = 0, frame: int = 1
    ) -> Picture:
        """Render one frame: see :meth:`Scene.render`."""
        x, y = _pixel_grid(width, height)
        r = np.float32(self.RADIUS * min(width, height))
        nx = (x - width / 2) / r
        ny = (height / 2 - y) / r  # up
        rho2 = nx * nx + ny * ny
        inside = rho2 < 1.0
        nz = np.sqrt(np.clip(1.0 - rho2, 0.0, 1.0))  # towards the (orthographic) viewer
        cos_view = nz
        theta = np.degrees(reproducible.float32_of(np.arccos, np.clip(cos_view, 0.0, 1.0)))

        t_phys, drain = self._thickness(nx, ny, r, seed, frame)
        t_opt = _optical_thickness_um(
            np.where(inside, t_phys, 0.0), self.N_SOAP, np.where(inside, theta, 0.0)
        )
        if self.film is not None:  # a user's film: physical reflectance, own angle
            film = lookup(self.film, np.where(inside, t_phys, 0.0).astype(np.float32))
        else:
            film = lookup(FILM_TABLE, t_opt)

        env = self._studio(nx, ny, nz)
        # Background: a dark gradient, seen through the bubble too (transmission ~ 1).
        backdrop = _grey(0.012 + 0.03 * (y / height))
        edge = _smoothstep(1.0, 0.985, np.sqrt(rho2))  # anti-aliased silhouette
        # The normalised two-beam model has no Fresnel growth towards grazing angles;
        # a faint Schlick rim (F0 = 0.02) of the environment keeps the silhouette of
        # the black film visible.
        grazing = 1.0 - cos_view
        grazing2 = grazing * grazing  # (1 - cos)^5 by products: np.power's loops differ
        rim = 0.02 + 0.98 * (grazing2 * grazing2 * grazing)
        if self.film is not None:
            xyz = backdrop + (edge * env)[..., None] * film
            aov = (t_phys, "physical thickness of the film's varying layer in um")
        else:
            xyz = backdrop + (
                (edge * env)[..., None] * (np.float32(self.FILM_GAIN) * film + _grey(0.12 * rim))
            )
            aov = (t_opt, "optical thickness t' of the soap film in micrometres (the table index")
        return Picture(
            xyz=xyz.astype(np.float32),
            aovs={
                "thickness": np.where(inside, aov[0], 0.0).astype(np.float32),
                "angle": np.where(inside, theta, 0.0).astype(np.float32),
            },
            aov_docs={
                "thickness": f"{aov[1]}; 0 off the bubble)"
                if self.film is None
                else f"{aov[1]} (0 off the bubble)",
                "angle": "view angle from the bubble's normal in degrees (0 off it)",
            },
            regions=[(0, width, None)],
            attributes={
                "n_soap": self.N_SOAP,
                "bottom_thickness_um": self.T_BOTTOM,
                "drain": drain,
                "film_gain": self.FILM_GAIN,
            },
        )


# --------------------------------------------------------------------------- #
# Figure 7: the Morpho butterfly's iridescent blue.
# --------------------------------------------------------------------------- #
class MorphoScene(Scene):
    """Figure 7: a wavy surface coloured by the Morpho multilayer (Eq. 9 + 14).

    Through the angle table: blue-violet face on and darker towards grazing.
    """

    name = "morpho"
    figure = "Figure 7"
    title = (
        "A wavy iridescent surface coloured by the Morpho multilayer table "
        "(Eq. 9 + 14, d1 = 150 nm, d2 = 50 nm, n = 1.53, 12 layers)"
    )
    animation = (
        "the wing tilts back and forth: view tilt 6 + 18 sin(2 pi (frame - 1) / 48) "
        "degrees, a 48-frame loop"
    )
    tables = (MORPHO_TABLE,)

    #: Eq. 9 is peak-normalised and narrow: Y ~ 0.03 at normal incidence. The scene is
    #: lit 5x brighter than the reference white so the blue reads on a display.
    EXPOSURE = 5.0
    PIGMENT_Y = 0.006  # the dark melanin under the scales
    TILT = 6.0  # degrees, the still's view tilt
    TILT_SWING = 18.0  # degrees either side, over a loop of
    TILT_PERIOD = 48  # frames
    WAVES = 3.2  # waves across the image

    def render(
        self, width: int, height: int, *, lookup: Lookup, seed: int = 0, frame: int = 1
    ) -> Picture:
        """Render one frame: see :meth:`Scene.render`."""
        x, y = _pixel_grid(width, height)
        side = np.float32(min(width, height))
        u, v = x / side, y / side
        # Height field: ridges across the wing, bent and varied by noise.
        bend = noise.noise(u * 1.6, v * 1.6, seed=seed + 31)
        across = 2 * np.pi * v * 0.8
        wave = reproducible.float32_of(np.sin, across)
        phase = 2 * np.pi * (self.WAVES * (u + 0.18 * wave) + 0.5 * bend)
        amp = 0.032 * (1.0 + 0.35 * noise.noise(u * 2.3 + 3.7, v * 2.3, seed=seed + 32))
        # Slopes of h = amp sin(phase) (amp's own slope is small and ignored).
        k = 2 * np.pi * self.WAVES
        dphase_du = k
        dphase_dv = k * 0.18 * 2 * np.pi * 0.8 * reproducible.float32_of(np.cos, across)
        grad_bend_v, grad_bend_u = np.gradient(bend * np.float32(np.pi), 1 / side)
        cos_phase = reproducible.float32_of(np.cos, phase)
        hu = amp * cos_phase * (dphase_du + grad_bend_u)
        hv = amp * cos_phase * (dphase_dv + grad_bend_v)
        # Fine scale texture: the rows of scales.
        fine = noise.noise(u * 90.0, v * 14.0, seed=seed + 33)
        hu = hu + 0.05 * fine
        n = np.stack([-hu, hv, np.ones_like(hu)], axis=-1)  # image v runs down
        n = _unit(n)
        tilt = np.radians(
            self.TILT + self.TILT_SWING * np.sin(2 * np.pi * (frame - 1) / self.TILT_PERIOD)
        )
        view = np.array([np.sin(tilt) * 0.6, np.sin(tilt) * 0.8, np.cos(tilt)], np.float32)
        view /= np.sqrt(reproducible.matmul(view, view))
        cos_view = np.clip(reproducible.matmul(n, view), 0.0, 1.0).astype(np.float32)
        colour = lookup(MORPHO_TABLE, cos_view)
        # Soft diffuse term for the shape, light from the upper left.
        light = np.array([-0.4, 0.5, 0.77], np.float32)
        light /= np.sqrt(reproducible.matmul(light, light))
        diffuse = np.clip(reproducible.matmul(n, light), 0.0, 1.0)
        xyz = np.float32(self.EXPOSURE) * colour + _grey(self.PIGMENT_Y * (0.4 + 0.6 * diffuse))
        theta = np.degrees(reproducible.float32_of(np.arccos, cos_view))
        return Picture(
            xyz=xyz.astype(np.float32),
            aovs={"cos_theta": cos_view, "angle": theta},
            aov_docs={
                "cos_theta": "facing ratio cos(theta) = N.V (the table index)",
                "angle": "view angle from the surface normal in degrees",
            },
            regions=[(0, width, None)],
            attributes={
                "exposure": self.EXPOSURE,
                "tilt_deg": float(np.degrees(tilt)),
                "d1_nm": spectra.MORPHO["d1"],
                "d2_nm": spectra.MORPHO["d2"],
                "n": spectra.MORPHO["n"],
                "layers": spectra.MORPHO["layers"],
            },
        )


SCENES = {s.name: s for s in (SpectrumScene(), OilScene(), SoapScene(), MorphoScene())}


def get_scene(name: str) -> Scene:
    """Return the scene called ``name``.

    Parameters
    ----------
    name : str
        A key of :data:`SCENES`.

    Returns
    -------
    Scene

    Raises
    ------
    ValueError
        For any other name; the message lists the choices.

    Examples
    --------
    >>> get_scene("oil").figure
    'Figure 5'
    """
    try:
        return SCENES[name]
    except KeyError:
        raise ValueError(
            f"unknown scene {name!r}; choose from {', '.join(SCENES)} or all"
        ) from None
