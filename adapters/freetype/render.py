#!/usr/bin/python3
"""FreeType adapter: renders a rasterproof scene's shapes with FreeType's smooth
(anti-aliasing) rasterizer, ftgrays.c, through FT_Outline_Get_Bitmap into an 8-bit grey
bitmap, and writes it as a grey PNG, so that `rasterproof compare SCENE.json OUT.png --as
grey` can judge it against the exact area coverage.

    /usr/bin/python3 adapters/freetype/render.py SCENE.json OUT.png
    /usr/bin/python3 adapters/freetype/render.py --serve

Needs Debian's libfreetype6 (libfreetype.so.6, called through ctypes: no binding package)
and python3-pil.

What it draws: each triangle and polygon of the scene as its own outline (a polygon's
outline and holes as written, one FT_Outline of on-curve points, no curves), filled under
its rule (FT_OUTLINE_EVEN_ODD_FILL for even-odd) by FT_Outline_Get_Bitmap into a bitmap of
its own; the shapes' 8-bit levels are added, saturating at 255 (a renderer compositing its
glyphs additively). Lines, clip windows, clip-space triangles and viewports are refused.

How coordinates are mapped: FreeType's points are 26.6 fixed point with y up, and the
bitmap's origin is its lower-left corner (pitch > 0: its first row in memory is the top
one). A scene point (x, y) (y down, origin top left, H the canvas height) becomes

    (round(64 x), round(64 (H - y)))

each rounded to the nearest 1/64 px, ties away from zero (FreeType's input precision; the adapter
says on stderr how many coordinates were not on the 1/64 grid). The bitmap's row r (from
the top) is then the scene's row r.

Exit status: 0 when the PNG was written; 2 with a message on stderr otherwise.
"""

import argparse
import ctypes
import os
import sys
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from rasterproof_scene import JsonNumber, Refused, load_scene, scene_from_raw  # noqa: E402

NAME = "freetype/render.py"
FT_CURVE_TAG_ON = 1
FT_OUTLINE_EVEN_ODD_FILL = 0x2
FT_PIXEL_MODE_GRAY = 2
MAX_POINTS = 32767  # FT_Outline's n_points is a 16-bit count
MAX_POS = 1 << 31  # 26.6 values within a 32-bit long, as FreeType's rasterizers assume


class Vector(ctypes.Structure):
    _fields_ = [("x", ctypes.c_long), ("y", ctypes.c_long)]


class Outline(ctypes.Structure):
    _fields_ = [("n_contours", ctypes.c_short), ("n_points", ctypes.c_short),
                ("points", ctypes.POINTER(Vector)), ("tags", ctypes.POINTER(ctypes.c_ubyte)),
                ("contours", ctypes.POINTER(ctypes.c_short)), ("flags", ctypes.c_int)]


class Bitmap(ctypes.Structure):
    _fields_ = [("rows", ctypes.c_uint), ("width", ctypes.c_uint), ("pitch", ctypes.c_int),
                ("buffer", ctypes.POINTER(ctypes.c_ubyte)), ("num_grays", ctypes.c_ushort),
                ("pixel_mode", ctypes.c_ubyte), ("palette_mode", ctypes.c_ubyte),
                ("palette", ctypes.c_void_p)]


class FreeType:
    """One FT_Library for every scene."""

    def __init__(self):
        try:
            self.ft = ctypes.CDLL("libfreetype.so.6")
        except OSError as e:
            raise Refused(f"cannot load libfreetype.so.6 (Debian: apt install libfreetype6): {e}") from e
        self.ft.FT_Outline_Get_Bitmap.argtypes = [ctypes.c_void_p, ctypes.POINTER(Outline), ctypes.POINTER(Bitmap)]
        self.library = ctypes.c_void_p()
        error = self.ft.FT_Init_FreeType(ctypes.byref(self.library))
        if error:
            raise Refused(f"FT_Init_FreeType failed with error {error}")
        major, minor, patch = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        self.ft.FT_Library_Version(self.library, ctypes.byref(major), ctypes.byref(minor), ctypes.byref(patch))
        print(f"{NAME}: FreeType {major.value}.{minor.value}.{patch.value}", file=sys.stderr, flush=True)

    def draw(self, scene, what):
        from PIL import Image

        for key in ("lines", "clip_space_triangles"):
            if scene[key]:
                raise Refused(f"{what}: {key}: this adapter draws triangles and polygons only")
        if scene["clip"] is not None or scene["viewport"] is not None:
            raise Refused(f"{what}: clip and viewport: this adapter draws no clip window")
        width, height = scene["width"], scene["height"]
        shapes = [([list(t)], "nonzero") for t in scene["triangles"]]
        shapes += [([outline] + holes, rule) for outline, holes, rule in scene["polygons"]]
        total = [0] * (width * height)
        inexact = 0
        for k, (contours, rule) in enumerate(shapes):
            levels, n = self.outline(contours, rule, width, height, f"{what}: shape {k}")
            inexact += n
            total = [min(255, a + b) for a, b in zip(total, levels)]
        if inexact:
            print(f"{NAME}: {inexact} coordinate(s) not on the 1/64 px grid, rounded to it", file=sys.stderr)
        return Image.frombytes("L", (width, height), bytes(total))

    def outline(self, contours, rule, width, height, what):
        """One shape's 8-bit levels, row by row, and how many coordinates were rounded."""
        points = [p for c in contours for p in c]
        if len(points) > MAX_POINTS:
            raise Refused(f"{what}: {len(points)} points; an FT_Outline holds at most {MAX_POINTS}")
        inexact = 0
        vectors = (Vector * len(points))()
        for k, (x, y) in enumerate(points):
            fx, fy = x * 64, (height - y) * 64
            inexact += (fx.denominator != 1) + (fy.denominator != 1)
            vx, vy = nearest(fx), nearest(fy)
            if abs(vx) >= MAX_POS or abs(vy) >= MAX_POS:
                raise Refused(f"{what}: point ({x}, {y}): beyond FreeType's 26.6 range (|64 v| < 2^31)")
            vectors[k] = Vector(vx, vy)
        tags = (ctypes.c_ubyte * len(points))(*([FT_CURVE_TAG_ON] * len(points)))
        ends, end = [], -1
        for c in contours:
            end += len(c)
            ends.append(end)
        ends_array = (ctypes.c_short * len(ends))(*ends)
        flags = FT_OUTLINE_EVEN_ODD_FILL if rule == "even-odd" else 0
        outline = Outline(len(contours), len(points), vectors, tags, ends_array, flags)
        buffer = (ctypes.c_ubyte * (width * height))()
        bitmap = Bitmap(height, width, width, buffer, 256, FT_PIXEL_MODE_GRAY, 0, None)
        error = self.ft.FT_Outline_Get_Bitmap(self.library, ctypes.byref(outline), ctypes.byref(bitmap))
        if error:
            raise Refused(f"{what}: FT_Outline_Get_Bitmap failed with FreeType error {error}")
        return list(buffer), inexact


def nearest(q):
    """A Fraction rounded to the nearest integer, ties away from zero."""
    n = (abs(q) + Fraction(1, 2)).__floor__()
    return n if q >= 0 else -n


def render(args):
    scene = load_scene(args.scene)
    image = FreeType().draw(scene, args.scene)
    try:
        image.save(args.out, format="PNG")
    except (OSError, ValueError) as e:
        raise Refused(f"{args.out}: cannot write the PNG: {e}") from e


def serve():
    """The stay-alive protocol (adapters/python/rasterproof_adapter.py): one FT_Library."""
    import rasterproof_adapter

    freetype = FreeType()
    rasterproof_adapter.serve(lambda raw: freetype.draw(scene_from_raw(raw, "scene"), "the scene"),
                              NAME, parse_number=JsonNumber)


def main(argv):
    p = argparse.ArgumentParser(prog=NAME, description="Render a rasterproof scene with FreeType's smooth "
                                                       "rasterizer into an 8-bit grey PNG.")
    p.add_argument("scene", nargs="?", help="the scene file (JSON)")
    p.add_argument("out", nargs="?", help="the grey PNG to write")
    p.add_argument("--serve", action="store_true",
                   help="stay alive: read one JSON request per line on stdin and answer each on stdout")
    args = p.parse_args(argv)
    if args.serve != (args.scene is None and args.out is None) or (not args.serve and args.out is None):
        print(f"{NAME}: give SCENE.json OUT.png, or --serve alone", file=sys.stderr)
        return 2
    try:
        if args.serve:
            serve()
        else:
            render(args)
    except Refused as e:
        print(f"{NAME}: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
