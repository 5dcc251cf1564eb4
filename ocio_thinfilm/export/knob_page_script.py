"""The knob page's style sheet and script, as :mod:`.knob_page` embeds them.

The script (plain JavaScript, no library) reads the page's JSON data (the element of id
``__DATA_ID__``, replaced by :data:`.knob_page.DATA_ID`): it compiles the exported GLSL
of each display's views into WebGL2 programs, uploads the test colours as an RGBA32F
texture, draws each strip of the canvas, keeps the ramps' marks (threshold, boundary,
limit) and axis labels in step with the display and the knobs, and prints the commands
to paste. With ``?readback=1`` it writes what it drew as JSON into ``<pre id="readback">``
(see :mod:`.knob_page`).
"""

from __future__ import annotations

__all__ = ["STYLE", "SCRIPT"]

STYLE = """
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
#plot { position: relative; flex: none; }
#view { image-rendering: pixelated; display: block; }
#marks div { position: absolute; width: 0; border-left: 1px solid #fff;
             box-shadow: 1px 0 0 #000; pointer-events: none; }
#marks span { position: absolute; top: 0; left: 3px; font-size: 11px; line-height: 1;
              color: #fff; }
/* the notes' space is kept, so that the strips stay where they are */
#note { color: #fc6; min-height: 4.4em; margin: 0; }
#status:empty { display: none; }
#readback { display: none; }
"""

SCRIPT = r"""
"use strict";
(function () {
  const DATA = JSON.parse(document.getElementById("__DATA_ID__").textContent);
  const $ = (id) => document.getElementById(id);
  const canvas = $("view"), select = $("display"), source = $("source");
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
    placeMarks();
    $("threshold-value").textContent = t.toFixed(2);
    $("limit-value").textContent = l.toFixed(2);
    const knobs = "--compress-threshold " + t + " --compress-limit " + l;
    $("commands").textContent = [
      "# the config's Constant-Lightness Compress views, baked with these knobs",
      "ocio-thinfilm bake " + knobs,
      "# DaVinci Resolve DCTL with these knobs as its sliders' defaults",
      "ocio-thinfilm export shader --lang dctl --from " + q(source.value) +
        " --display " + q(display) + " --view " + q(DATA.views.compress) + " " + knobs +
        " --out compress.dctl",
      "# ... or the sliders of any exported Compress DCTL (ResolveFX DCTL)",
      "Threshold " + t.toFixed(2) + "    Limit " + l.toFixed(2),
      "# GLSL (three.js, a game engine, Matchbox): the uniforms",
      "ocio_thinfilm_threshold = " + t.toFixed(2) + ";  ocio_thinfilm_limit = " +
        l.toFixed(2) + ";",
    ].join("\n");
    draw();
  }

  // the ramps' marks: the threshold, the display's boundary (d = 1) and the limit, at the
  // column of that boundary distance (d grows linearly from the grey at column 0 to
  // the row's reach at the last column); hidden beyond the row's end
  function markAt(row, name, d) {
    const mark = $("mark-" + row + "-" + name);
    const column = d / DATA.rows[row].reach[select.value] * (DATA.width - 1);
    mark.style.display = column <= DATA.width - 1 ? "" : "none";
    mark.style.left = (column + 0.5).toFixed(2) + "px";
  }

  function placeMarks() {
    DATA.rows.forEach((row, r) => {
      if (!row.reach) return;
      markAt(r, "threshold", knob("threshold"));
      markAt(r, "boundary", 1.0);
      markAt(r, "limit", knob("limit"));
    });
  }

  function changeDisplay() {
    const display = select.value;
    DATA.rows.forEach((row, r) => { $("axis-" + r).textContent = row.axis[display]; });
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
  source.addEventListener("change", update);
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
  if (query.has("source")) {
    source.value = query.get("source");
    source.dispatchEvent(new Event("change"));
  }
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
    const marks = {};
    DATA.rows.forEach((row, r) => {
      if (!row.reach) return;
      marks[r] = {};
      for (const name of ["threshold", "boundary", "limit"]) {
        const mark = $("mark-" + r + "-" + name);
        marks[r][name] = mark.style.display === "none" ? null : parseFloat(mark.style.left);
      }
    });
    const out = {
      display: select.value,
      source: source.value,
      commands: $("commands").textContent,
      axes: DATA.rows.map((row, r) => $("axis-" + r).textContent),
      marks: marks,
      canvasTop: canvas.getBoundingClientRect().top + window.scrollY,
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
