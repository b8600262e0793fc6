"""The renderer's side of rasterproof's two renderer protocols, for an adapter written in
Python: write a function from a request's scene to an image, and `main` answers both ways
of being called:

    ADAPTER SCENE.json OUT.png      once per scene   (rasterproof hunt --cmd 'ADAPTER {scene} {out}')
    ADAPTER --serve                 kept alive       (rasterproof hunt --serve 'ADAPTER --serve')

Under --serve it reads one JSON request per line on stdin,

    {"rasterproof": 1, "id": 7, "scene": {...}, "out": "/tmp/.../out-7.png", "as": "ids"}

renders the scene, writes the image to `out` and answers one line on stdout:

    {"id": 7, "ok": true}      or      {"id": 7, "ok": false, "error": "why"}

(docs/oracle.md, "The stay-alive protocol"). A request it cannot read or a scene the
function refuses (it raises) is answered "ok": false, and the loop goes on. Only the
answers go to stdout: print anything else to stderr.

`render(scene)` gets the scene as parsed JSON (pass `parse_number` to read its numbers
exactly, e.g. as fractions.Fraction from their text) and returns an object with
`save(path, format="PNG")`, such as a PIL image of the ids PNG (colour id + 1, alpha 255;
transparent black where nothing covers).
"""

import json
import sys

PROTOCOL_VERSION = 1


def serve(render, name, parse_number=None, stdin=None, stdout=None):
    """Answer requests from `stdin` on `stdout` until stdin ends."""
    stdin = stdin or sys.stdin
    stdout = stdout or sys.stdout
    hooks = {} if parse_number is None else {"parse_float": parse_number, "parse_int": parse_number}
    for line in stdin:
        if not line.strip():
            continue
        request_id = None
        try:
            request = json.loads(line, **hooks)
            if not isinstance(request, dict):
                raise ValueError("the request is not a JSON object")
            request_id = _plain(request.get("id"))
            version = _plain(request.get("rasterproof"))
            if version != PROTOCOL_VERSION:
                raise ValueError(f"protocol version {version}: this adapter speaks {PROTOCOL_VERSION}")
            out = request.get("out")
            if not isinstance(out, str) or "scene" not in request:
                raise ValueError('the request needs "scene" and an "out" path')
            render(request["scene"]).save(out, format="PNG")
            answer = {"id": request_id, "ok": True}
        except Exception as e:  # every failure is an answer, never the end of the loop
            print(f"{name}: request {request_id}: {e}", file=sys.stderr, flush=True)
            answer = {"id": request_id, "ok": False, "error": str(e) or type(e).__name__}
        stdout.write(json.dumps(answer) + "\n")
        stdout.flush()


def main(render, name, argv=None, parse_number=None, load=None):
    """`SCENE.json OUT.png` or `--serve`; returns the exit status (0, or 2 with a message).
    `load(path)` reads a scene file for the once-per-scene form (default: JSON with
    `parse_number`)."""
    argv = sys.argv[1:] if argv is None else argv
    if argv == ["--serve"]:
        serve(render, name, parse_number)
        return 0
    if len(argv) != 2:
        print(f"usage: {name} SCENE.json OUT.png, or {name} --serve", file=sys.stderr)
        return 2
    scene_path, out = argv
    try:
        if load is None:
            hooks = {} if parse_number is None else {"parse_float": parse_number, "parse_int": parse_number}
            with open(scene_path, "rb") as f:
                scene = json.loads(f.read().decode("utf-8"), **hooks)
        else:
            scene = load(scene_path)
        render(scene).save(out, format="PNG")
    except Exception as e:
        print(f"{name}: {scene_path}: {e}", file=sys.stderr)
        return 2
    return 0


def _plain(value):
    """A number parsed by a `parse_number` hook, back to a Python int where it is one."""
    text = getattr(value, "text", None)
    if text is not None:
        try:
            return int(text)
        except ValueError:
            return text
    return value
