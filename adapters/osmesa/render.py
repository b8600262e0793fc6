#!/usr/bin/python3
"""Mesa adapter: renders a rasterproof scene with Mesa's llvmpipe or softpipe through
OSMesa (off-screen GL, no window system) and writes the ids PNG (`render --ids-out`'s
layout), so that `rasterproof compare SCENE.json OUT.png --as ids` can judge the driver.

    /usr/bin/python3 adapters/osmesa/render.py SCENE.json OUT.png [--driver llvmpipe|softpipe]
        [--viewport canvas|wide]
    /usr/bin/python3 adapters/osmesa/render.py --serve [--driver ...] [--viewport ...]

With --serve it stays alive: one OSMesa context, made current on a buffer of each scene's
size, answering one JSON request per line on stdin (rasterproof hunt --serve; the protocol
is in docs/oracle.md and adapters/python/rasterproof_adapter.py).

Needs Debian's libosmesa6, python3-opengl, python3-numpy and python3-pil, which are
installed for /usr/bin/python3 (not for a pyenv or venv `python3` on PATH).

GL state: an OSMesa context (8-bit RGBA colour, 8-bit stencil, no depth buffer, no
multisampling) the size of the canvas; blending, depth test, dithering, culling, smoothing
and multisampling disabled; flat shading; the colour of primitive `id` is id + 1 as
glColor4ub(low byte, middle byte, high byte, 255), drawn in id order (the last writer wins
a pixel). A second pass draws every primitive again with additive blending of
glColor4ub(1, 0, 0, 0) to count the primitives that cover each pixel; where two or more do,
the ids PNG gets alpha 254 (its "several owners" mark).

How y is mapped: the scene is y down with the origin at the top left; GL's window origin is
the lower left. With S the smallest power of two at least the canvas's width and height,
the projection is glOrtho(0, S, S, 0, -1, 1) and the viewport glViewport(0, H - S, S, S):
the scene's square [0, S)^2 is the viewport, so a scene point (x, y) reaches GL window
coordinates

    x_gl = x,   y_gl = H - y

through NDC (2x/S - 1, 1 - 2y/S) and the viewport transform (scale S/2, offsets S/2 and
H - S/2). S is a power of two, so every step is exact in f32 for coordinates on a 2^-10
grid inside the viewport; the one that can round is the sum H - y. This is
glOrtho(0, W, H, 0, -1, 1) with glViewport(0, 0, W, H), the usual 2D setup, except that
2 / W is exact in f32 only when W is a power of two, so the viewport is widened to one
(the extra rows and columns lie off the framebuffer). GL clips what leaves the viewport, in
f32, so a triangle crossing the canvas's border gets new, rounded vertices there.

`--viewport wide` uses the largest viewport GL allows instead (S = 16384, the square
[-S/2, S/2)^2 when the canvas fits in S/2, else [0, S)^2: glOrtho(L, L + S, L + S, L, -1,
1), glViewport(L, H - L - S, S, S)), so nothing within S/2 px is clipped; llvmpipe then
draws vertices far outside the canvas differently (adapters/README.md).

GL pixel row r (counted from the bottom) samples y_gl = r + 1/2, the scene's row
H - 1 - r: glReadPixels returns the bottom row first, so the rows are flipped before the
PNG is written. GL's own tie rule therefore
meets the scene mirrored; rasterproof's `gl` preset ("bottom-left in a y-down image") is
top-left in GL's y-up window.

Coordinates are read exactly (fractions.Fraction: JSON numbers, "1/3", "0.1") and rounded
once to the nearest f32 (ties to even), GL's vertex type; scenes should use f32-exact
coordinates (the adapter says on stderr how many were not).

What it draws:
  triangles             glDrawArrays(GL_TRIANGLES)
  lines                 GL_LINES, width 1, not smoothed: a diamond-exit line from `from` to
                        `to` as written; a Bresenham line (pixel addresses) from the centre
                        of its first pixel to the centre of its last
  polygons              stencil then cover, contour by contour, as the scene judges a
                        polygon ("inside the outline and in none of the holes", each under
                        the fill rule): each contour as a triangle fan into the stencil's
                        winding bits (nonzero: +1 front faces, -1 back faces, mod 64;
                        even-odd: bit 0 inverted), then a cover pass of the bounding box
                        sets (outline) or clears (hole) an "inside" bit where they are not
                        zero; finally the colour where the inside bit is set
  clip window           its outline as a fan into stencil bit 7 first (GL's own raster of
                        the window); every later draw is tested against it
  clip-space triangles  glVertex4f(x, -y if the viewport's ndc_y is down, 2z - w for depth
                        zero-to-one, w) with identity matrices and glViewport(vx, H - vy -
                        vh, vw, vh): GL clips, divides and maps them. Refused (exit 2) unless
                        the viewport is integer; without one, the whole canvas

The driver: GALLIUM_DRIVER is set before OpenGL is imported; the adapter prints
GL_RENDERER on stderr and fails (exit 2) when it does not name the requested driver.

Exit status: 0 when the PNG was written; 2 with a message on stderr otherwise (bad
arguments, an unreadable scene, what the adapter refuses, a missing library, the wrong
driver). It does not validate the scene as rasterproof does: run `rasterproof render` on a
hand-written scene first.
"""

import argparse
import json
import os
import sys
from fractions import Fraction

NAME = "osmesa/render.py"
DRIVERS = ("llvmpipe", "softpipe")
MAX_ENCODED = (1 << 24) - 1
# The stencil bit of the clip window, the bit of "inside the polygon being drawn" and the
# bits of one contour's winding number (mod 64).
CLIP_BIT = 0x80
INSIDE_BIT = 0x40
WINDING_BITS = 0x3F


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from rasterproof_scene import JsonNumber, Refused, load_scene, scene_from_raw  # noqa: E402


# ---- exact to f32 -----------------------------------------------------------------------

class F32:
    """Rounds Fractions to the nearest f32 (ties to even) and counts the inexact ones."""

    def __init__(self, numpy):
        self.np = numpy
        self.inexact = 0

    def __call__(self, q, what):
        np = self.np
        try:
            d = float(q)  # correctly rounded to f64
        except OverflowError:
            d = float("inf")
        with np.errstate(over="ignore"):
            f = np.float32(d)
        if not np.isfinite(f):
            raise Refused(f"{what}: {q} does not fit f32 (GL's vertex type)")
        # f64 then f32 can round twice: pick the nearest of f and its neighbours exactly.
        best = None
        for c in (np.nextafter(f, np.float32(-np.inf)), f, np.nextafter(f, np.float32(np.inf))):
            if not np.isfinite(c):
                continue
            err = abs(Fraction(float(c)) - q)
            even = int(np.array(c, dtype=np.float32).view(np.uint32)) % 2 == 0
            key = (err, not even)
            if best is None or key < best[0]:
                best = (key, c)
        c = best[1]
        if Fraction(float(c)) != q:
            self.inexact += 1
        return float(c)


# ---- GL ---------------------------------------------------------------------------------

def colour(id_):
    """id + 1 as (R, G, B, 255), R the low byte."""
    encoded = id_ + 1
    if encoded > MAX_ENCODED:
        raise Refused(f"primitive id {id_} does not fit the 24 bits of an ids PNG")
    return (encoded & 0xFF, (encoded >> 8) & 0xFF, (encoded >> 16) & 0xFF, 255)


class Renderer:
    """Draws a scene into the current OSMesa context."""

    def __init__(self, GL, np, scene, to_f32, low, span):
        # The scene square [low, low + span)^2 is the viewport.
        self.GL, self.np, self.scene, self.f32 = GL, np, scene, to_f32
        self.low, self.span = low, span
        self.W, self.H = scene["width"], scene["height"]
        self.prepare()

    def prepare(self):
        """Every vertex as f32 up front, so that both passes draw the same numbers."""
        s, f = self.scene, self.f32
        half = Fraction(1, 2)
        self.tris = [[(f(x, "triangle"), f(y, "triangle")) for x, y in t] for t in s["triangles"]]
        self.lines = []
        for a, b, rule in s["lines"]:
            o = half if rule == "bresenham" else 0
            self.lines.append([(f(p[0] + o, "line"), f(p[1] + o, "line")) for p in (a, b)])
        self.polys = []
        for outline, holes, rule in s["polygons"]:
            contours = [[(f(x, "polygon"), f(y, "polygon")) for x, y in c] for c in [outline] + holes]
            self.polys.append((contours, rule))
        self.clip = None
        if s["clip"] is not None:
            self.clip = [(f(x, "clip"), f(y, "clip")) for x, y in s["clip"]]
        self.clip_space = []
        if s["clip_space_triangles"]:
            vp = s["viewport"] or {}
            box = [vp.get("x", Fraction(0)), vp.get("y", Fraction(0)),
                   vp.get("width", Fraction(self.W)), vp.get("height", Fraction(self.H))]
            if any(v.denominator != 1 for v in box):
                raise Refused("viewport: not integer; this adapter maps clip space with glViewport, "
                              "which takes integers")
            self.viewport = [int(v) for v in box]
            ndc_y = vp.get("ndc_y") or ("down" if s["preset"] == "vulkan" else "up")
            depth = vp.get("depth") or ("minus-one-to-one" if s["preset"] == "gl" else "zero-to-one")
            if ndc_y not in ("up", "down"):
                raise Refused(f"viewport.ndc_y: {json.dumps(ndc_y)} is not up or down")
            for t in s["clip_space_triangles"]:
                vs = []
                for x, y, z, w in t:
                    y = -y if ndc_y == "down" else y
                    z = 2 * z - w if depth == "zero-to-one" else z
                    vs.append(tuple(f(c, "clip-space vertex") for c in (x, y, z, w)))
                self.clip_space.append(vs)

    def setup(self):
        GL = self.GL
        for cap in (GL.GL_BLEND, GL.GL_DEPTH_TEST, GL.GL_DITHER, GL.GL_CULL_FACE, GL.GL_POLYGON_SMOOTH,
                    GL.GL_LINE_SMOOTH, GL.GL_MULTISAMPLE, GL.GL_SCISSOR_TEST, GL.GL_STENCIL_TEST,
                    GL.GL_ALPHA_TEST, GL.GL_LIGHTING, GL.GL_TEXTURE_2D, GL.GL_DEPTH_CLAMP):
            GL.glDisable(cap)
        GL.glShadeModel(GL.GL_FLAT)
        GL.glPolygonMode(GL.GL_FRONT_AND_BACK, GL.GL_FILL)
        GL.glLineWidth(1.0)
        GL.glPixelStorei(GL.GL_PACK_ALIGNMENT, 1)
        self.window_space()

    def window_space(self):
        GL, low, span = self.GL, self.low, self.span
        GL.glViewport(low, self.H - low - span, span, span)
        GL.glMatrixMode(GL.GL_PROJECTION)
        GL.glLoadIdentity()
        GL.glOrtho(low, low + span, low + span, low, -1, 1)
        GL.glMatrixMode(GL.GL_MODELVIEW)
        GL.glLoadIdentity()

    def arrays(self, mode, prims, colours, dims=2):
        """Draws `prims` (lists of vertices) as `mode`, primitive k in colours[k]."""
        GL, np = self.GL, self.np
        if not prims:
            return
        verts = np.array([v for p in prims for v in p], dtype=np.float32).reshape(-1, dims)
        cols = np.array([c for p, c in zip(prims, colours) for _ in p], dtype=np.uint8).reshape(-1, 4)
        GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
        GL.glEnableClientState(GL.GL_COLOR_ARRAY)
        GL.glVertexPointer(dims, GL.GL_FLOAT, 0, verts)
        GL.glColorPointer(4, GL.GL_UNSIGNED_BYTE, 0, cols)
        GL.glDrawArrays(mode, 0, len(verts))
        GL.glDisableClientState(GL.GL_COLOR_ARRAY)
        GL.glDisableClientState(GL.GL_VERTEX_ARRAY)

    def fan(self, contour):
        return [(contour[0], contour[k], contour[k + 1]) for k in range(1, len(contour) - 1)]

    def stencil_base(self):
        """The stencil test every colour draw takes: inside the clip window, if any."""
        GL = self.GL
        if self.clip is None:
            GL.glDisable(GL.GL_STENCIL_TEST)
        else:
            GL.glEnable(GL.GL_STENCIL_TEST)
            GL.glStencilMask(0)
            GL.glStencilFunc(GL.GL_EQUAL, CLIP_BIT, CLIP_BIT)
            GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_KEEP)

    def draw(self, colour_of):
        """Every primitive in id order; `colour_of(id)` gives its RGBA."""
        GL = self.GL
        GL.glStencilMask(0xFF)
        GL.glClearStencil(0)
        GL.glClearColor(0, 0, 0, 0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_STENCIL_BUFFER_BIT)
        if self.clip is not None:
            GL.glColorMask(False, False, False, False)
            GL.glEnable(GL.GL_STENCIL_TEST)
            GL.glStencilMask(CLIP_BIT)
            GL.glStencilFunc(GL.GL_ALWAYS, CLIP_BIT, CLIP_BIT)
            GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_REPLACE)
            self.arrays(GL.GL_TRIANGLES, self.fan(self.clip), [(0, 0, 0, 0)] * (len(self.clip) - 2))
            GL.glColorMask(True, True, True, True)
        self.stencil_base()
        next_id = 0
        self.arrays(GL.GL_TRIANGLES, self.tris, [colour_of(next_id + k) for k in range(len(self.tris))])
        next_id += len(self.tris)
        self.arrays(GL.GL_LINES, self.lines, [colour_of(next_id + k) for k in range(len(self.lines))])
        next_id += len(self.lines)
        for contours, rule in self.polys:
            self.polygon(contours, rule, colour_of(next_id))
            next_id += 1
        if self.clip_space:
            GL.glMatrixMode(GL.GL_PROJECTION)
            GL.glLoadIdentity()
            GL.glMatrixMode(GL.GL_MODELVIEW)
            GL.glLoadIdentity()
            x, y, w, h = self.viewport
            GL.glViewport(x, self.H - y - h, w, h)
            self.arrays(GL.GL_TRIANGLES, self.clip_space,
                        [colour_of(next_id + k) for k in range(len(self.clip_space))], dims=4)
            self.window_space()
        GL.glFinish()

    def polygon(self, contours, rule, rgba):
        """Stencil, then cover, contour by contour, as the scene judges a polygon: a pixel
        is inside when the outline holds its sample under the rule and no hole does.
        Each contour's fan goes into the winding bits (nonzero: +1 front, -1 back faces,
        mod 64; even-odd: bit 0 inverted), then a cover pass turns "winding bits not zero"
        into INSIDE_BIT set (the outline) or cleared (a hole), zeroing the winding bits;
        the colour is drawn where INSIDE_BIT is set, clearing it."""
        GL = self.GL
        xs = [v[0] for c in contours for v in c]
        ys = [v[1] for c in contours for v in c]
        x0, y0, x1, y1 = min(xs) - 1, min(ys) - 1, max(xs) + 1, max(ys) + 1
        quad = [((x0, y0), (x1, y0), (x1, y1)), ((x0, y0), (x1, y1), (x0, y1))]
        GL.glEnable(GL.GL_STENCIL_TEST)
        for k, contour in enumerate(contours):
            GL.glColorMask(False, False, False, False)
            GL.glStencilMask(WINDING_BITS if rule == "nonzero" else 0x01)
            if self.clip is None:
                GL.glStencilFunc(GL.GL_ALWAYS, 0, 0)
            else:
                GL.glStencilFunc(GL.GL_EQUAL, CLIP_BIT, CLIP_BIT)
            if rule == "nonzero":
                GL.glStencilOpSeparate(GL.GL_FRONT, GL.GL_KEEP, GL.GL_KEEP, GL.GL_INCR_WRAP)
                GL.glStencilOpSeparate(GL.GL_BACK, GL.GL_KEEP, GL.GL_KEEP, GL.GL_DECR_WRAP)
            else:
                GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_INVERT)
            fans = self.fan(contour)
            self.arrays(GL.GL_TRIANGLES, fans, [(0, 0, 0, 0)] * len(fans))
            # Where the winding bits are not zero (outside the clip window they stayed
            # zero): the stencil's INSIDE and winding bits become INSIDE_BIT (the outline)
            # or 0 (a hole).
            GL.glStencilMask(INSIDE_BIT | WINDING_BITS)
            GL.glStencilFunc(GL.GL_NOTEQUAL, INSIDE_BIT if k == 0 else 0, WINDING_BITS)
            GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_REPLACE)
            self.arrays(GL.GL_TRIANGLES, quad, [(0, 0, 0, 0)] * 2)
        GL.glColorMask(True, True, True, True)
        GL.glStencilMask(INSIDE_BIT)
        GL.glStencilFunc(GL.GL_EQUAL, INSIDE_BIT, INSIDE_BIT)
        GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_ZERO)
        self.arrays(GL.GL_TRIANGLES, quad, [rgba, rgba])
        self.stencil_base()

    def read(self):
        """The colour buffer, top row first, as an H x W x 4 uint8 array."""
        GL, np = self.GL, self.np
        data = GL.glReadPixels(0, 0, self.W, self.H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        rows = np.frombuffer(bytes(data), dtype=np.uint8).reshape(self.H, self.W, 4)
        return rows[::-1].copy()


def viewport_square(kind, side, max_dims):
    """(L, S): the scene square [L, L + S)^2 that becomes GL's viewport."""
    if kind == "canvas":
        span = 1
        while span < side:
            span *= 2
        if span > max_dims:
            raise Refused(f"canvas side {side}: its power-of-two viewport {span} exceeds "
                          f"GL_MAX_VIEWPORT_DIMS {max_dims}")
        return 0, span
    span = 1
    while 2 * span <= max_dims:
        span *= 2
    if span < side:
        raise Refused(f"canvas side {side}: larger than GL_MAX_VIEWPORT_DIMS {max_dims}")
    return (-(span // 2) if side <= span // 2 else 0), span


class Mesa:
    """One OSMesa context of the requested driver, made current on a buffer the size of
    each scene in turn (per-scene use makes one per scene; --serve keeps one)."""

    def __init__(self, driver):
        os.environ["PYOPENGL_PLATFORM"] = "osmesa"
        os.environ["GALLIUM_DRIVER"] = driver
        try:
            import numpy as np
            from OpenGL import GL, osmesa
            from PIL import Image
        except Exception as e:  # ImportError, or PyOpenGL failing to load libOSMesa
            raise Refused(f"cannot load the OSMesa Python stack ({e}); install libosmesa6 python3-opengl "
                          f"python3-numpy python3-pil and run /usr/bin/python3") from e
        self.np, self.GL, self.osmesa, self.Image = np, GL, osmesa, Image
        self.ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 0, 8, 0, None)
        if not self.ctx:
            raise Refused("OSMesaCreateContextExt failed")
        self.current(1, 1)
        renderer_name = GL.glGetString(GL.GL_RENDERER).decode()
        version = GL.glGetString(GL.GL_VERSION).decode()
        print(f"{NAME}: renderer: {renderer_name}; {version}", file=sys.stderr)
        if not renderer_name.startswith(driver):
            self.close()
            raise Refused(f"asked for {driver}, but GL_RENDERER is {renderer_name!r}")
        if GL.glGetIntegerv(GL.GL_STENCIL_BITS) < 8:
            self.close()
            raise Refused("the context has fewer than 8 stencil bits")
        self.max_dims = min(int(d) for d in GL.glGetIntegerv(GL.GL_MAX_VIEWPORT_DIMS))

    def current(self, W, H):
        """Makes the context current on a fresh W x H buffer."""
        self.buf = self.np.zeros((H, W, 4), dtype=self.np.uint8)
        if not self.osmesa.OSMesaMakeCurrent(self.ctx, self.buf, self.GL.GL_UNSIGNED_BYTE, W, H):
            raise Refused(f"OSMesaMakeCurrent failed for a {W}x{H} buffer")

    def draw(self, scene, viewport, source):
        """The ids PNG of `scene` as a PIL image."""
        GL, np = self.GL, self.np
        W, H = scene["width"], scene["height"]
        self.current(W, H)
        low, span = viewport_square(viewport, max(W, H), self.max_dims)
        to_f32 = F32(np)
        r = Renderer(GL, np, scene, to_f32, low, span)
        r.setup()
        r.draw(colour)
        ids = r.read()
        GL.glEnable(GL.GL_BLEND)
        GL.glBlendEquation(GL.GL_FUNC_ADD)
        GL.glBlendFunc(GL.GL_ONE, GL.GL_ONE)
        r.draw(lambda _id: (1, 0, 0, 0))
        counts = r.read()[:, :, 0]
        GL.glDisable(GL.GL_BLEND)
        ids[:, :, 3][counts >= 2] = 254
        if to_f32.inexact:
            print(f"{NAME}: note: {to_f32.inexact} coordinate(s) of {source} are not f32-exact; "
                  f"rounded to the nearest f32", file=sys.stderr)
        return self.Image.fromarray(ids, "RGBA")

    def close(self):
        self.osmesa.OSMesaDestroyContext(self.ctx)


def render(args):
    scene = load_scene(args.scene)
    mesa = Mesa(args.driver)
    try:
        image = mesa.draw(scene, args.viewport, args.scene)
    finally:
        mesa.close()
    try:
        image.save(args.out, format="PNG")
    except (OSError, ValueError) as e:
        raise Refused(f"{args.out}: cannot write the PNG: {e}") from e


def serve(args):
    """The stay-alive protocol (adapters/python/rasterproof_adapter.py): one context for
    every scene, resized per scene."""
    import rasterproof_adapter
    mesa = Mesa(args.driver)
    try:
        rasterproof_adapter.serve(lambda raw: mesa.draw(scene_from_raw(raw, "scene"), args.viewport, "the scene"),
                                  NAME, parse_number=JsonNumber)
    finally:
        mesa.close()


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        print(f"{NAME}: {message}", file=sys.stderr)
        sys.exit(2)


def main(argv):
    p = Parser(prog=NAME, description="Render a rasterproof scene with Mesa (OSMesa) into an ids PNG.")
    p.add_argument("scene", nargs="?", help="the scene file (JSON)")
    p.add_argument("out", nargs="?", help="the ids PNG to write")
    p.add_argument("--serve", action="store_true",
                   help="stay alive: read one JSON request per line on stdin and answer each on stdout "
                        "(rasterproof hunt --serve; docs/oracle.md)")
    p.add_argument("--driver", choices=DRIVERS, default="llvmpipe", help="the Gallium driver (default llvmpipe)")
    p.add_argument("--viewport", choices=("canvas", "wide"), default="canvas",
                   help="GL's viewport: the canvas widened to a power of two (default), or the "
                        "largest GL allows, centred on the origin")
    args = p.parse_args(argv)
    if args.serve != (args.scene is None and args.out is None) or (not args.serve and args.out is None):
        p.error("give SCENE.json OUT.png, or --serve alone")
    try:
        if args.serve:
            serve(args)
        else:
            render(args)
    except Refused as e:
        print(f"{NAME}: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
