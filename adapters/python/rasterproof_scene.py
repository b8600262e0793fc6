"""Reading a rasterproof scene exactly in Python, for the adapters: every coordinate a
fractions.Fraction from its text (JSON numbers, "1/3", "0.1"), the fields checked, and a
`Refused` exception naming the file, field and value for what an adapter cannot draw.

    scene = load_scene("scene.json")            # from a file
    scene = scene_from_raw(raw, "scene")        # a stay-alive request's scene, parsed with
                                                # parse_number=JsonNumber

A scene is plain data: {"width", "height", "triangles": [[(x, y)] * 3], "lines": [(from,
to, rule)], "polygons": [(outline, holes, fill_rule)], "clip_space_triangles",
"viewport", "clip", "preset"}.
"""

import json
import re
from fractions import Fraction

MAX_CANVAS = 16384


class Refused(Exception):
    """A scene, option or environment the adapter cannot render: exit 2 with the message."""


# ---- the scene: exact numbers ----------------------------------------------------------

FRACTION_RE = re.compile(r"[+-]?[0-9]+/[0-9]+")
DECIMAL_RE = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE]([+-]?[0-9]+))?")
MAX_EXPONENT = 1000


def exact(value, what):
    """A scene coordinate (a JSON number, kept as text, or a string) as a Fraction."""
    if isinstance(value, JsonNumber):
        value = value.text
    elif not isinstance(value, str):
        raise Refused(f"{what}: {json.dumps(value)} is not a number")
    if FRACTION_RE.fullmatch(value):
        num, den = value.split("/")
        if int(den) == 0:
            raise Refused(f"{what}: {value} has a zero denominator")
        return Fraction(int(num), int(den))
    m = DECIMAL_RE.fullmatch(value)
    if not m:
        raise Refused(f"{what}: {json.dumps(value)} is not a decimal or a fraction")
    if m.group(3) is not None and abs(int(m.group(3))) > MAX_EXPONENT:
        raise Refused(f"{what}: {value} has an exponent beyond +-{MAX_EXPONENT}")
    return Fraction(value)


class JsonNumber:
    """A JSON number as written (so that 0.1 stays 1/10)."""

    def __init__(self, text):
        self.text = text


def integer(value, what, low, high):
    """An integer field within [low, high]."""
    if isinstance(value, JsonNumber):
        q = exact(value, what)
        if q.denominator == 1 and low <= q <= high:
            return int(q)
    raise Refused(f"{what}: {json.dumps(getattr(value, 'text', value))} is not an integer in {low}..={high}")


def fields(obj, what, allowed):
    """`obj` must be a JSON object with no key outside `allowed`."""
    if not isinstance(obj, dict):
        raise Refused(f"{what}: not a JSON object")
    unknown = sorted(set(obj) - set(allowed))
    if unknown:
        raise Refused(f"{what}: unknown field {json.dumps(unknown[0])} (this adapter does not draw it)")
    return obj


def point(value, what, dims=2):
    if not isinstance(value, list) or len(value) != dims:
        raise Refused(f"{what}: not a list of {dims} coordinates")
    return tuple(exact(c, f"{what}[{k}]") for k, c in enumerate(value))


def points(value, what, dims=2, at_least=3):
    if not isinstance(value, list) or len(value) < at_least:
        raise Refused(f"{what}: not a list of at least {at_least} points")
    return [point(p, f"{what}[{k}]", dims) for k, p in enumerate(value)]


def load_scene(path):
    """The scene file as plain Python data with Fraction coordinates."""
    try:
        with open(path, "rb") as f:
            text = f.read().decode("utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise Refused(f"{path}: cannot read: {e}") from e
    try:
        raw = json.loads(text, parse_float=JsonNumber, parse_int=JsonNumber, parse_constant=bad_constant)
    except ValueError as e:
        raise Refused(f"{path}: not JSON: {e}") from e
    return scene_from_raw(raw, path)


def scene_from_raw(raw, path):
    """A scene parsed with JsonNumber numbers (from a file, or a stay-alive request) as
    plain Python data with Fraction coordinates; `path` names it in messages."""
    top = fields(raw, path, ("width", "height", "preset", "subpixel_bits", "rounding", "tie_rule",
                             "pixel_centre", "triangles", "lines", "polygons", "clip_space_triangles",
                             "viewport", "clip"))
    scene = {
        "width": integer(top.get("width"), f"{path}: width", 1, MAX_CANVAS),
        "height": integer(top.get("height"), f"{path}: height", 1, MAX_CANVAS),
        "triangles": [],
        "lines": [],
        "polygons": [],
        "clip_space_triangles": [],
        "viewport": None,
        "clip": None,
    }
    for k, t in enumerate(top.get("triangles", [])):
        what = f"{path}: triangles[{k}]"
        fields(t, what, ("v", "colors"))
        scene["triangles"].append(points(t.get("v"), f"{what}.v", at_least=3))
        if len(scene["triangles"][-1]) != 3:
            raise Refused(f"{what}.v: a triangle has 3 vertices")
    for k, line in enumerate(top.get("lines", [])):
        what = f"{path}: lines[{k}]"
        fields(line, what, ("from", "to", "rule", "tie"))
        rule = line.get("rule", "bresenham")
        if rule not in ("bresenham", "diamond"):
            raise Refused(f"{what}.rule: {json.dumps(rule)} is not bresenham or diamond")
        scene["lines"].append((point(line.get("from"), f"{what}.from"), point(line.get("to"), f"{what}.to"), rule))
    for k, poly in enumerate(top.get("polygons", [])):
        what = f"{path}: polygons[{k}]"
        fields(poly, what, ("v", "holes", "fill_rule"))
        rule = poly.get("fill_rule", "nonzero")
        if rule not in ("nonzero", "even-odd"):
            raise Refused(f"{what}.fill_rule: {json.dumps(rule)} is not nonzero or even-odd")
        holes = poly.get("holes", [])
        if not isinstance(holes, list):
            raise Refused(f"{what}.holes: not a list")
        scene["polygons"].append((points(poly.get("v"), f"{what}.v"),
                                  [points(h, f"{what}.holes[{j}]") for j, h in enumerate(holes)], rule))
    for k, t in enumerate(top.get("clip_space_triangles", [])):
        what = f"{path}: clip_space_triangles[{k}]"
        fields(t, what, ("v", "colors"))
        vs = points(t.get("v"), f"{what}.v", dims=4)
        if len(vs) != 3:
            raise Refused(f"{what}.v: a triangle has 3 vertices")
        scene["clip_space_triangles"].append(vs)
    if "viewport" in top:
        vp = fields(top["viewport"], f"{path}: viewport", ("x", "y", "width", "height", "ndc_y", "depth"))
        scene["viewport"] = {k: exact(vp[k], f"{path}: viewport.{k}") for k in ("x", "y", "width", "height")
                             if k in vp}
        scene["viewport"]["ndc_y"] = vp.get("ndc_y")
        scene["viewport"]["depth"] = vp.get("depth")
    scene["preset"] = top.get("preset", "d3d11")
    if "clip" in top:
        clip = fields(top["clip"], f"{path}: clip", ("rect", "convex"))
        if "rect" in clip:
            r = clip["rect"]
            if not isinstance(r, list) or len(r) != 4:
                raise Refused(f"{path}: clip.rect: not [xmin, ymin, xmax, ymax]")
            x0, y0, x1, y1 = (exact(c, f"{path}: clip.rect[{k}]") for k, c in enumerate(r))
            scene["clip"] = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        elif "convex" in clip:
            scene["clip"] = points(clip["convex"], f"{path}: clip.convex")
        else:
            raise Refused(f"{path}: clip: neither rect nor convex")
    return scene


def bad_constant(name):
    raise ValueError(f"{name} is not JSON (write a number or a string)")
