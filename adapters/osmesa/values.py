#!/usr/bin/python3
"""Mesa values adapter: renders the interpolated values of one varying of a rasterproof
scene with Mesa's llvmpipe or softpipe through OSMesa into a float32 TIFF, so that
`rasterproof compare SCENE.json OUT.tiff --as values` can judge the driver's interpolator.

    /usr/bin/python3 adapters/osmesa/values.py SCENE.json OUT.tiff [--varying NAME]
        [--driver llvmpipe|softpipe] [--fault affine|provoking]

`--fault` draws with a deliberate bug, so that `compare` and `hunt --as values` can be
seen naming it on a real renderer: `affine` declares a `smooth` varying `noperspective`
in the shaders (no perspective correction); `provoking` sets the other provoking vertex.

Needs Debian's libosmesa6, python3-opengl, python3-numpy and python3-tifffile for
/usr/bin/python3.

What it draws: the scene's window-space `triangles`, in id order, each vertex with the
varying's channels as a vec4 vertex attribute (the exact values rounded once to f32,
missing channels 0) and the fragment shader writing it unchanged. Other primitives (lines,
polygons, clip-space triangles) are refused (exit 2).

GL state: an OSMesa context with an RGBA float32 colour buffer the size of the canvas
(OSMesaMakeCurrent with GL_FLOAT), no depth, stencil or multisampling; fragment, vertex
and read colour clamping off (glClampColor ... GL_FALSE), so values outside [0, 1] are
written and read as they are; blending, dithering and culling disabled; the last triangle
drawn wins a pixel, as the oracle's highest id does. glProvokingVertex is the scene's
`provoking_vertex` (GL's default is the last; a scene's is the first).

The shaders (GLSL 1.30; `sample` needs GLSL 4.00, which llvmpipe and softpipe have):

    in vec4 pos; in vec4 v; QUALIFIERS out vec4 val;
    void main() { gl_Position = pos; val = v; }
    QUALIFIERS in vec4 val; void main() { gl_FragColor = val; }

with QUALIFIERS the varying's interpolation (`smooth`, `noperspective`, `flat`) and
sampling (nothing for `centre`, `centroid`, `sample`).

How positions are mapped: as adapters/osmesa/render.py's canvas viewport. S is the
smallest power of two at least the canvas's width and height, glViewport(0, H - S, S, S),
and a vertex at window point (x, y) with clip-space w is sent as the clip-space position
(w (2x/S - 1), w (1 - 2y/S), 0, w), so that GL's divide and viewport give back
x_gl = x, y_gl = H - y: the scene is y down, GL's window y up. Every step is exact in f32
when x and y are f32-exact and w is a power of two; otherwise the clip-space position is
rounded once (the adapter says on stderr how many numbers were not exact). A w <= 0 is
refused. glReadPixels returns the bottom row first; the rows are flipped before writing.

The TIFF: uncompressed, 32-bit IEEE float samples; one channel grey, two or three RGB (a
two-channel varying's blue is 0), four RGBA.

Exit status: 0 when the TIFF was written; 2 with a message on stderr otherwise.
"""

import argparse
import json
import os
import sys
from fractions import Fraction

NAME = "osmesa/values.py"
DRIVERS = ("llvmpipe", "softpipe")

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from rasterproof_scene import JsonNumber, Refused, exact, fields, integer, point  # noqa: E402

INTERPOLATIONS = ("smooth", "noperspective", "flat")
SAMPLINGS = ("centre", "centroid", "sample")


def read_scene(path, wanted):
    """The canvas, the varying `wanted` (or the first) and the triangles with its values."""
    try:
        with open(path, encoding="utf-8") as f:
            raw = json.load(f, parse_float=JsonNumber, parse_int=JsonNumber)
    except (OSError, ValueError) as e:
        raise Refused(f"{path}: cannot read the scene: {e}") from e
    if not isinstance(raw, dict):
        raise Refused(f"{path}: not a JSON object")
    for kind in ("lines", "polygons", "clip_space_triangles"):
        if raw.get(kind):
            raise Refused(f"{path}: {kind}: this adapter draws window-space triangles only")
    width = integer(raw.get("width"), f"{path}: width", 1, 16384)
    height = integer(raw.get("height"), f"{path}: height", 1, 16384)
    varyings = raw.get("varyings") or []
    if not varyings:
        raise Refused(f"{path}: varyings: the scene declares none")
    offset, chosen = 0, None
    for k, v in enumerate(varyings):
        what = f"{path}: varyings[{k}]"
        fields(v, what, ("name", "channels", "interpolation", "sampling"))
        channels = integer(v.get("channels"), f"{what}.channels", 1, 128)
        if chosen is None and (wanted is None or v.get("name") == wanted):
            chosen = {
                "name": v.get("name"),
                "channels": channels,
                "interpolation": v.get("interpolation", "smooth"),
                "sampling": v.get("sampling", "centre"),
            }
            if chosen["channels"] > 4:
                raise Refused(f"{what}.channels: {channels}; a vec4 holds at most 4")
            if chosen["interpolation"] not in INTERPOLATIONS or chosen["sampling"] not in SAMPLINGS:
                raise Refused(f"{what}: interpolation or sampling not one of {INTERPOLATIONS} / {SAMPLINGS}")
        offset += channels
    if chosen is None:
        raise Refused(f"{path}: varyings: no varying named {wanted!r}")
    provoking = raw.get("provoking_vertex", "first")
    if provoking not in ("first", "last"):
        raise Refused(f"{path}: provoking_vertex: {provoking!r} is not first or last")
    triangles = []
    for k, t in enumerate(raw.get("triangles") or []):
        what = f"{path}: triangles[{k}]"
        vs = t.get("v") if isinstance(t, dict) else t
        if not isinstance(vs, list) or len(vs) != 3:
            raise Refused(f"{what}: not three vertices")
        pts = [point(p, f"{what}.v[{i}]") for i, p in enumerate(vs)]
        ws = [Fraction(1)] * 3
        values = [[Fraction(0)] * chosen["channels"] for _ in range(3)]
        if isinstance(t, dict):
            if "w" in t:
                ws = [exact(w, f"{what}.w[{i}]") for i, w in enumerate(t["w"])]
                if any(w <= 0 for w in ws):
                    raise Refused(f"{what}.w: a w <= 0")
            given = (t.get("varyings") or {}).get(chosen["name"])
            if given is not None:
                values = [[exact(c, f"{what}.varyings.{chosen['name']}[{i}]") for c in vertex]
                          for i, vertex in enumerate(given)]
        triangles.append((pts, ws, values))
    return width, height, chosen, provoking, triangles


class F32:
    """Rounds Fractions to the nearest f32 (ties to even) and counts the inexact ones."""

    def __init__(self, np):
        self.np, self.inexact = np, 0

    def __call__(self, q):
        np = self.np
        f = np.float32(float(q))
        best = min((c for c in (np.nextafter(f, np.float32(-np.inf)), f, np.nextafter(f, np.float32(np.inf)))
                    if np.isfinite(c)),
                   key=lambda c: (abs(Fraction(float(c)) - q), int(np.array(c).view(np.uint32)) % 2))
        if Fraction(float(best)) != q:
            self.inexact += 1
        return best


def qualifiers(varying):
    q = varying["interpolation"]
    if varying["sampling"] != "centre":
        q += " " + varying["sampling"]
    return q


def render(scene, driver, fault=None):
    width, height, varying, provoking, triangles = scene
    if fault == "affine" and varying["interpolation"] == "smooth":
        varying = dict(varying, interpolation="noperspective")
    if fault == "provoking":
        provoking = "last" if provoking == "first" else "first"
    os.environ["PYOPENGL_PLATFORM"] = "osmesa"
    os.environ["GALLIUM_DRIVER"] = driver
    try:
        import numpy as np
        from OpenGL import GL, osmesa
        from OpenGL.GL import shaders
    except Exception as e:
        raise Refused(f"cannot load the OSMesa Python stack ({e}); install libosmesa6 python3-opengl "
                      f"python3-numpy and run /usr/bin/python3") from e
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 0, 0, 0, None)
    if not ctx:
        raise Refused("OSMesaCreateContextExt failed")
    try:
        buf = np.zeros((height, width, 4), dtype=np.float32)
        if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_FLOAT, width, height):
            raise Refused(f"OSMesaMakeCurrent failed for a {width}x{height} float buffer")
        name = GL.glGetString(GL.GL_RENDERER).decode()
        print(f"{NAME}: renderer: {name}; {GL.glGetString(GL.GL_VERSION).decode()}", file=sys.stderr)
        if not name.startswith(driver):
            raise Refused(f"asked for {driver}, but GL_RENDERER is {name!r}")
        for clamp in (GL.GL_CLAMP_FRAGMENT_COLOR, GL.GL_CLAMP_READ_COLOR, GL.GL_CLAMP_VERTEX_COLOR):
            GL.glClampColor(clamp, GL.GL_FALSE)
        for cap in (GL.GL_BLEND, GL.GL_DEPTH_TEST, GL.GL_DITHER, GL.GL_CULL_FACE, GL.GL_MULTISAMPLE,
                    GL.GL_SCISSOR_TEST, GL.GL_STENCIL_TEST):
            GL.glDisable(cap)
        GL.glProvokingVertex(GL.GL_FIRST_VERTEX_CONVENTION if provoking == "first"
                             else GL.GL_LAST_VERTEX_CONVENTION)
        version = "400" if varying["sampling"] == "sample" else "130"
        q = qualifiers(varying)
        vs = shaders.compileShader(
            f"#version {version}\nin vec4 pos; in vec4 v; {q} out vec4 val;\n"
            "void main() { gl_Position = pos; val = v; }\n", GL.GL_VERTEX_SHADER)
        fs = shaders.compileShader(
            f"#version {version}\n{q} in vec4 val;\n"
            "void main() { gl_FragColor = val; }\n", GL.GL_FRAGMENT_SHADER)
        prog = GL.glCreateProgram()
        GL.glAttachShader(prog, vs)
        GL.glAttachShader(prog, fs)
        GL.glBindAttribLocation(prog, 0, "pos")
        GL.glBindAttribLocation(prog, 1, "v")
        GL.glLinkProgram(prog)
        if GL.glGetProgramiv(prog, GL.GL_LINK_STATUS) != GL.GL_TRUE:
            raise Refused(f"the shaders do not link: {GL.glGetProgramInfoLog(prog)}")
        GL.glUseProgram(prog)
        span = 1
        while span < max(width, height):
            span *= 2
        GL.glViewport(0, height - span, span, span)
        GL.glClearColor(0, 0, 0, 0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        f32 = F32(np)
        pos, val = [], []
        for pts, ws, values in triangles:
            for (x, y), w, vertex in zip(pts, ws, values):
                ndc = (2 * x / span - 1, 1 - 2 * y / span)
                pos.append([f32(ndc[0] * w), f32(ndc[1] * w), 0.0, f32(w)])
                val.append([f32(c) for c in vertex] + [0.0] * (4 - len(vertex)))
        if pos:
            pos_a = np.array(pos, dtype=np.float32)
            val_a = np.array(val, dtype=np.float32)
            GL.glEnableVertexAttribArray(0)
            GL.glVertexAttribPointer(0, 4, GL.GL_FLOAT, False, 0, pos_a)
            GL.glEnableVertexAttribArray(1)
            GL.glVertexAttribPointer(1, 4, GL.GL_FLOAT, False, 0, val_a)
            GL.glDrawArrays(GL.GL_TRIANGLES, 0, len(pos))
        GL.glFinish()
        data = np.asarray(GL.glReadPixels(0, 0, width, height, GL.GL_RGBA, GL.GL_FLOAT), dtype=np.float32)
        rows = data.reshape(height, width, 4)[::-1].copy()
        if f32.inexact:
            print(f"{NAME}: note: {f32.inexact} number(s) were not f32-exact; rounded to the nearest f32",
                  file=sys.stderr)
        return rows
    finally:
        osmesa.OSMesaDestroyContext(ctx)


def write_tiff(rows, channels, out):
    try:
        import tifffile
    except ImportError as e:
        raise Refused(f"cannot import tifffile ({e}); install python3-tifffile") from e
    if channels == 1:
        data, photometric = rows[:, :, 0].copy(), "minisblack"
    elif channels <= 3:
        data, photometric = rows[:, :, :3].copy(), "rgb"
        if channels == 2:
            data[:, :, 2] = 0
    else:
        data, photometric = rows, "rgb"
    try:
        tifffile.imwrite(out, data, photometric=photometric,
                         extrasamples=["unassalpha"] if channels == 4 else None)
    except (OSError, ValueError) as e:
        raise Refused(f"{out}: cannot write the TIFF: {e}") from e


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        print(f"{NAME}: {message}", file=sys.stderr)
        sys.exit(2)


def main(argv):
    p = Parser(prog=NAME, description="Render one varying of a rasterproof scene with Mesa into a float32 TIFF.")
    p.add_argument("scene", help="the scene file (JSON)")
    p.add_argument("out", help="the TIFF to write")
    p.add_argument("--varying", help="the varying drawn (default the scene's first)")
    p.add_argument("--driver", choices=DRIVERS, default="llvmpipe", help="the Gallium driver (default llvmpipe)")
    p.add_argument("--fault", choices=("affine", "provoking"), help="draw with this deliberate bug")
    args = p.parse_args(argv)
    try:
        scene = read_scene(args.scene, args.varying)
        rows = render(scene, args.driver, args.fault)
        write_tiff(rows, scene[2]["channels"], args.out)
    except Refused as e:
        print(f"{NAME}: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
