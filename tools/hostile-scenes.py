#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A hostile run of scene files through stin-render (docs/fuzzing.md).

From a seed and a count, makes mutated scene files out of the repository's
scenes (JSON-aware: numbers to extremes, keys deleted or repeated, types
swapped, arrays emptied or grown, csg entries repeated, self-referencing or
deepened, materials' surface/opacity/displacement, lights, model and texture
paths), renders each with a sanitised stin-render (make build/stin-render-san)
under a time and a memory bound on one or more profiles, and classes every
outcome against the contract of docs/scene-format.md: exit 0 with the image,
or exit 2 with one line naming the file and where, and no image. Every
failing input is kept, with its output, under OUT/failed/ for replay.

  tools/hostile-scenes.py --seed 1 --count 600
  tools/hostile-scenes.py --replay OUT/failed/0042.json --profile gl21

No dependency beyond python3; the mutations depend on the seed only, so a run
is reproduced by its seed and count (and the repository's scenes)."""

import argparse
import concurrent.futures
import glob
import json
import math
import os
import random
import re
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The older surfaces (shadows, surface detail, lights) and the newer ones
# (CSG trees, transparency, displacement, model materials and embedded
# textures). The spheres-* scenes are left out: benchmarks, seconds each.
OLD_SCENES = ["four-lights", "shadow-*", "stone-wall", "terminator-*", "torus"]
NEW_SCENES = ["csg", "csg/*", "glass-panes", "peel/*", "deep-*", "displace-*", "meshes/quads-*"]
MODEL_FILES = ["meshes/quads.glb", "meshes/quads.gltf", "meshes/quad-mtl.obj", "meshes/octahedron.obj",
               "meshes/open-box.obj", "meshes/sphere-pair.obj", "meshes/quads-missing-texture.gltf",
               "bad/truncated.glb", "bad/degenerate.obj", "bad/out-of-range-face.ply",
               "bad/truncated-header.ply", "meshes/quads-cells.png", "meshes/quads.bin"]
TEXTURE_FILES = ["meshes/quads-cells.png", "deep-window.png", "bad/truncated.png", "meshes/quads.glb"]
JUNK_PATHS = ["", ".", "..", "/", "/dev/zero", "/dev/null", "/proc/self/mem", "missing.obj",
              "x" * 300, "a/../../../../../../etc/passwd", "meshes\\quads.glb", "nul\u0001.obj"]
SURFACES = ["pom", "parallax", "normal", "dot3", "plain", "", "vdsm", "csg-off", "deep", "depth-peel",
            "displace-tess", "POM", "pom ", "map-pcf"]


class Raw:
    """A token written as it is (NaN, 1e999, a huge integer)."""

    def __init__(self, text):
        self.text = text


class Obj:
    """A JSON object as its list of [key, value] pairs: keys may repeat."""

    def __init__(self, pairs):
        self.pairs = [list(p) for p in pairs]

    def get(self, key, default=None):
        for k, v in self.pairs:
            if k == key:
                return v
        return default

    def set(self, key, value):
        for p in self.pairs:
            if p[0] == key:
                p[1] = value
                return
        self.pairs.append([key, value])


def dump(v):
    if isinstance(v, Raw):
        return v.text
    if isinstance(v, Obj):
        return "{" + ", ".join(json.dumps(k) + ": " + dump(x) for k, x in v.pairs) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(dump(x) for x in v) + "]"
    if isinstance(v, float) and not math.isfinite(v):
        return "1e999" if v > 0 else "-1e999" if v < 0 else "NaN"
    return json.dumps(v)


def walk(v, out, parent=None, key=None):
    """Every value as (parent, key, value), parents before children."""
    if parent is not None:
        out.append((parent, key, v))
    if isinstance(v, Obj):
        for i, (_, x) in enumerate(v.pairs):
            walk(x, out, v, i)
    elif isinstance(v, list):
        for i, x in enumerate(v):
            walk(x, out, v, i)
    return out


def put(parent, key, value):
    if isinstance(parent, Obj):
        parent.pairs[key][1] = value
    else:
        parent[key] = value


def extreme_number(rng, x):
    picks = [0, -0.0, -1, -x if isinstance(x, (int, float)) else -1, 1e-30, 1e-7, 0.5, 1e6, 1000001,
             1e308, Raw("1e999"), Raw("-1e999"), Raw("NaN"), "NaN", "inf", 2 ** 31, 2 ** 31 - 1, 2 ** 32,
             2 ** 53 + 1, Raw("99999999999999999999999"), -2 ** 31, 16384, 16385, 8192, 65536, 1024, 1025,
             3, 2, 1, 257, Raw("1.0e-400"), Raw("-0")]
    v = rng.choice(picks)
    if isinstance(x, (int, float)) and not isinstance(x, bool) and rng.random() < 0.3:
        v = x * rng.choice([1e3, 1e-3, -1, 10, 1.0000001])
    return v


def pick(rng, valid, invalid):
    """Mostly a value the loader takes (so the frame runs on it), else one it must refuse."""
    return rng.choice(valid if rng.random() < 0.7 or not invalid else invalid)


def closed_objects(doc):
    """Objects whose mesh is a closed primitive, one instance: csg operands stin takes."""
    meshes, objs = doc.get("meshes"), doc.get("objects")
    if not isinstance(meshes, Obj) or not isinstance(objs, list):
        return []
    closed = {k for k, m in meshes.pairs if isinstance(m, Obj) and m.get("primitive") in ("box", "sphere", "torus")
              or isinstance(m, Obj) and m.get("primitive") == "cylinder" and m.get("capped", True) is True}
    return [o.get("name") for o in objs if isinstance(o, Obj) and o.get("mesh") in closed
            and isinstance(o.get("name"), str) and o.get("repeat") is None]


def other_type(rng, v):
    return rng.choice(["x", "", 1, 0, -1, True, False, None, [], [1, 2], Obj([]), Obj([["a", 1]]),
                       [[0, 0, 0]], "0.5", [None] * 3])


def scene_names(doc):
    def keys(name):
        o = doc.get(name)
        return [k for k, _ in o.pairs] if isinstance(o, Obj) else []
    objs = doc.get("objects")
    objects = [o.get("name") for o in objs if isinstance(o, Obj) and isinstance(o.get("name"), str)] \
        if isinstance(objs, list) else []
    csg = doc.get("csg")
    entries = [c.get("name") for c in csg if isinstance(c, Obj) and isinstance(c.get("name"), str)] \
        if isinstance(csg, list) else []
    return {"meshes": keys("meshes"), "materials": keys("materials"), "textures": keys("textures"),
            "objects": objects, "csg": entries}


def named_objects(doc, rng):
    """The scene's objects, each given a name if it has none (csg needs them)."""
    objs = doc.get("objects")
    if not isinstance(objs, list):
        return []
    names = []
    for i, o in enumerate(objs):
        if isinstance(o, Obj):
            if not isinstance(o.get("name"), str):
                o.set("name", "o%d" % i)
            names.append(o.get("name"))
    return names


# ---- mutations: each changes doc in place and says what it did -------------

def m_number(rng, doc, ctx):
    nums = [(p, k, v) for p, k, v in walk(doc, []) if isinstance(v, (int, float)) and not isinstance(v, bool)]
    if not nums:
        return None
    p, k, v = rng.choice(nums)
    if rng.random() < 0.4:  # nearby, mostly still in range
        v = v * rng.choice([0.5, 2, 0.999, 1.001, 10, 0.1]) if isinstance(v, float) else v + rng.choice([-1, 1, 2])
        put(p, k, v)
        return "number-near"
    put(p, k, extreme_number(rng, v))
    return "number"


def m_delete_key(rng, doc, ctx):
    objs = [v for _, _, v in walk(doc, []) if isinstance(v, Obj) and v.pairs] + [doc]
    o = rng.choice(objs)
    if not o.pairs:
        return None
    del o.pairs[rng.randrange(len(o.pairs))]
    return "delete-key"


def m_duplicate_key(rng, doc, ctx):
    objs = [v for _, _, v in walk(doc, []) if isinstance(v, Obj) and v.pairs] + [doc]
    o = rng.choice(objs)
    k, v = rng.choice(o.pairs)
    o.pairs.insert(rng.randrange(len(o.pairs) + 1), [k, v if rng.random() < 0.5 else other_type(rng, v)])
    return "duplicate-key"


def m_type(rng, doc, ctx):
    vals = walk(doc, [])
    p, k, v = rng.choice(vals)
    put(p, k, other_type(rng, v))
    return "type"


def m_array(rng, doc, ctx):
    arrays = [(p, k, v) for p, k, v in walk(doc, []) if isinstance(v, list)]
    if not arrays:
        return None
    p, k, v = rng.choice(arrays)
    r = rng.random()
    if r < 0.3 or not v:
        put(p, k, [])
    elif r < 0.5:
        put(p, k, v[:-1])
    else:
        put(p, k, v + [v[rng.randrange(len(v))] for _ in range(rng.choice([1, 2, 40, 300]))])
    return "array"


def m_csg(rng, doc, ctx):
    objs = named_objects(doc, rng)
    if len(objs) < 1:
        return None
    closed = closed_objects(doc)
    if closed and rng.random() < 0.8:
        objs = closed
    csg = doc.get("csg")
    if not isinstance(csg, list):
        csg = [Obj([["name", "c0"], ["op", "subtract"], ["a", objs[0]], ["b", objs[-1]]])]
        doc.set("csg", csg)
    entries = [c for c in csg if isinstance(c, Obj)]
    operands = objs + [c.get("name") for c in entries if isinstance(c.get("name"), str)]
    kind = rng.choice(["duplicate", "self", "deepen", "doubled", "wide", "op", "operand", "unnamed", "cycle"])
    n = len(csg)
    if kind == "duplicate" and entries:
        csg.append(Obj(rng.choice(entries).pairs))
    elif kind == "self" and entries:
        e = rng.choice(entries)
        if not isinstance(e.get("name"), str):
            e.set("name", "self")
        e.set(rng.choice(["a", "b"]), e.get("name"))
    elif kind in ("deepen", "doubled"):
        depth = rng.choice([2, 30, 300, 1023, 1100, 5000] if kind == "deepen" else [3, 14, 28, 40])
        prev = rng.choice(operands)
        for i in range(depth):
            other = prev if kind == "doubled" else rng.choice(objs)
            csg.append(Obj([["name", "d%d_%d" % (n, i)], ["op", rng.choice(["union", "intersect", "subtract"])],
                            ["a", prev], ["b", other]]))
            prev = "d%d_%d" % (n, i)
    elif kind == "wide":
        prev = objs[0]
        for i in range(rng.choice([4, 256, 257, 600])):
            csg.append(Obj([["name", "w%d_%d" % (n, i)], ["op", "union"], ["a", prev], ["b", rng.choice(objs)]]))
            prev = "w%d_%d" % (n, i)
    elif kind == "op" and entries:
        rng.choice(entries).set("op", rng.choice(["", "xor", "Union", "difference", 1, None, "union "]))
    elif kind == "operand" and entries:
        names = ctx["meshes"] + ctx["materials"] + ["", "missing", "x" * 64]
        rng.choice(entries).set(rng.choice(["a", "b"]), rng.choice(names + operands))
    elif kind == "unnamed" and entries:
        e = rng.choice(entries)
        e.pairs = [p for p in e.pairs if p[0] != "name"]
    elif kind == "cycle" and len(entries) >= 1:
        first = entries[0]
        if not isinstance(first.get("name"), str):
            first.set("name", "first")
        csg.append(Obj([["name", "last"], ["op", "union"], ["a", first.get("name")], ["b", objs[0]]]))
        first.set("b", "last")
    else:
        return None
    return "csg-" + kind


def some_material(rng, doc):
    mats = doc.get("materials")
    if not isinstance(mats, Obj):
        mats = Obj([])
        doc.set("materials", mats)
    if not mats.pairs or rng.random() < 0.2:
        mats.pairs.append(["default", Obj([["color", [0.5, 0.5, 0.5]]])])
    name, m = rng.choice(mats.pairs)
    if not isinstance(m, Obj):
        return name, None
    return name, m


def m_material(rng, doc, ctx):
    name, m = some_material(rng, doc)
    if m is None:
        return None
    key = rng.choice(["surface", "opacity", "displace", "height_scale", "height_bias", "self_shadow",
                      "two_sided", "height", "normal", "albedo", "shininess"])
    if key == "surface":
        v = pick(rng, SURFACES[:6], SURFACES[6:])
    elif key == "opacity":
        v = pick(rng, [0, 1e-6, 0.01, 0.5, 0.999, 1], [1.0000001, -0.1, Raw("NaN"), "0.5"])
    elif key in ("displace", "two_sided"):
        v = pick(rng, [True, False], ["yes", 1, None])
    elif key in ("height_scale", "height_bias"):
        v = pick(rng, [0, 1e-9, 0.04, 1, 100, 1e6], [-0.5, 1e7])
    elif key == "self_shadow":
        v = pick(rng, ["off", "hard", "soft"], ["Soft", "", True])
    elif key == "shininess":
        v = pick(rng, [0, 128], [129, -1, 1e6])
    else:
        v = rng.choice(ctx["textures"] + ["missing", ""]) if ctx["textures"] or rng.random() < 0.5 else "none"
    m.set(key, v)
    # an object to wear it, sometimes a csg operand
    objs = doc.get("objects")
    if isinstance(objs, list) and objs and rng.random() < 0.7:
        o = rng.choice(objs)
        if isinstance(o, Obj):
            o.set("material", name)
    return "material-" + key


def m_light(rng, doc, ctx):
    lights = doc.get("lights")
    if not isinstance(lights, list):
        lights = []
        doc.set("lights", lights)
    if not lights or rng.random() < 0.15:
        lights.append(Obj([["type", "point"], ["position", [1, 3, 1]]]))
    r = rng.random()
    if r < 0.08:
        lights.extend(Obj(lights[-1].pairs) if isinstance(lights[-1], Obj) else 1
                      for _ in range(rng.choice([31, 32, 40])))
        return "light-many"
    light = rng.choice(lights)
    if not isinstance(light, Obj):
        return None
    kind = light.get("type")
    keys = {"point": ["radius", "pcf_kernel", "range", "attenuation", "intensity", "position"],
            "spot": ["radius", "pcf_kernel", "range", "attenuation", "intensity", "position", "cutoff",
                     "exponent", "shadow_offset", "direction"],
            "directional": ["pcf_kernel", "shadow_offset", "intensity", "direction"]}.get(kind, [])
    key = rng.choice(keys if keys and rng.random() < 0.7 else
                     ["radius", "type", "cutoff", "pcf_kernel", "range", "shadow_offset", "attenuation",
                      "exponent", "intensity", "direction", "position"])
    v = {"radius": [0, 1e-9, 0.05, 1, 50, 1e6, -1, Raw("NaN")],
         "type": ["point", "spot", "directional", "area", "", 1],
         "cutoff": [0, 1e-6, 45, 90, 90.0001, 180, -5],
         "pcf_kernel": [0, 1, 2, 3, 5, 7, -1],
         "range": [0, 1e-6, 0.5, 1e6, -1],
         "shadow_offset": [[0, 0], [1e6, 1e6], [-1e6, 0], [0], [Raw("NaN"), 1]],
         "attenuation": [[0, 0, 0], [1, 0, 0], [0, 0, 1e6], [1e-30, 0, 0], [-1, 0, 0]],
         "exponent": [0, 128, 129, -1],
         "intensity": [0, 1e6, -1],
         "direction": [[0, 0, 0], [0, -1, 0], [1e-30, 0, 0], [1e6, 1e6, 1e6]],
         "position": [[0, 0, 0], [1e6, 1e6, 1e6], [0, 0.5, 0], [Raw("1e999"), 0, 0]]}[key]
    light.set(key, rng.choice(v))
    return "light-" + key


def m_model(rng, doc, ctx):
    rel = ctx["rel"]
    files = [rel(f) for f in MODEL_FILES] + JUNK_PATHS
    tex_files = [rel(f) for f in TEXTURE_FILES] + JUNK_PATHS
    meshes = doc.get("meshes")
    if not isinstance(meshes, Obj):
        return None
    r = rng.random()
    if r < 0.4 or not meshes.pairs:
        name = "model%d" % len(meshes.pairs)
        meshes.pairs.append([name, Obj([["file", rng.choice(files)]])])
        objs = doc.get("objects")
        if isinstance(objs, list):
            obj = Obj([["name", name], ["mesh", name]])
            if rng.random() < 0.4:
                mat, _ = some_material(rng, doc)
                obj.set("material", mat)
            objs.append(obj)
            csg = doc.get("csg")
            if isinstance(csg, list) and rng.random() < 0.5:
                csg.append(Obj([["op", rng.choice(["union", "subtract", "intersect"])], ["a", name],
                                ["b", rng.choice(named_objects(doc, rng))]]))
        return "model-add"
    if r < 0.75:
        _, m = rng.choice(meshes.pairs)
        if isinstance(m, Obj):
            m.pairs = [["file", rng.choice(files)]] + ([["radius", 1]] if rng.random() < 0.1 else [])
        return "model-path"
    texs = doc.get("textures")
    if not isinstance(texs, Obj):
        texs = Obj([])
        doc.set("textures", texs)
    texs.pairs.append(["t%d" % len(texs.pairs), Obj([["file", rng.choice(tex_files)]])])
    _, m = some_material(rng, doc)
    if m is not None:
        m.set(rng.choice(["albedo", "normal", "height"]), texs.pairs[-1][0])
    return "texture-path"


def m_camera(rng, doc, ctx):
    cam = doc.get("camera")
    if not isinstance(cam, Obj):
        return None
    key = rng.choice(["near", "far", "fovy", "eye", "target", "up"])
    v = {"near": [1e-30, 1e-7, 1e-6, 0, 99, 1e6], "far": [1e-6, 1e6, 0.1, 1e7],
         "fovy": [0, 1e-6, 179.9999, 180, 90], "eye": [[0, 0.5, 0], [1e6, 1e6, 1e6], [0, 0, 0]],
         "target": [cam.get("eye"), [0, -1e6, 0]], "up": [[0, 0, 0], [0, 1, 0], [1, 0, 0]]}[key]
    cam.set(key, rng.choice(v))
    return "camera-" + key


def m_top(rng, doc, ctx):
    key = rng.choice(["width", "height", "shadow_map_size", "ambient", "background"])
    v = {"width": [0, 1, 16384, 16385], "height": [0, 1, 16384, 16385],
         "shadow_map_size": [16, 8, 8192, 16384, 1000, 64],
         "ambient": [[1, 1, 1], [2, 0, 0]], "background": [[0, 0, 0, 1], [0, 0, 0]]}[key]
    doc.set(key, rng.choice(v))
    return "top-" + key


GENERIC = [m_number, m_delete_key, m_duplicate_key, m_type, m_array, m_camera, m_top, m_light]
NEWER = [m_csg, m_csg, m_csg, m_material, m_material, m_model, m_light]


def make_input(path, seed, index, newer, rel):
    """One mutated scene from the source at path: its text and the mutations."""
    rng = random.Random(seed * 1000003 + index)
    with open(path, encoding="utf-8") as f:
        doc = json.load(f, object_pairs_hook=Obj)
    base = os.path.dirname(path)
    # file names made relative to where the mutated file is written
    for key in ("meshes", "textures"):
        group = doc.get(key)
        if isinstance(group, Obj):
            for _, v in group.pairs:
                if isinstance(v, Obj) and isinstance(v.get("file"), str):
                    v.set("file", os.path.relpath(os.path.join(base, v.get("file")), rel.out))
    done = []
    for _ in range(rng.choice([1, 1, 1, 2, 2, 3])):
        pool = NEWER * 2 + GENERIC[:5] if newer else GENERIC + [m_material, m_light, m_model]
        ctx = scene_names(doc)
        ctx["rel"] = rel
        what = rng.choice(pool)(rng, doc, ctx)
        if what:
            done.append(what)
    return dump(doc) + "\n", done


class Rel:
    def __init__(self, out):
        self.out = out

    def __call__(self, name):
        return os.path.relpath(os.path.join(ROOT, "tests/scenes", name), self.out)


# ---- running and classing -------------------------------------------------

SANITIZER = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer|MemorySanitizer)|runtime error:|"
                       r"UndefinedBehaviorSanitizer")
MEMORY = re.compile(r"hard rss limit exhausted|allocation-size-too-big|out of memory|"
                    r"requested allocation size|allocator is out of memory|std::bad_alloc")
WARNING = re.compile(r"^stin-render: (stin )?warning: ")


def png_size(path):
    try:
        with open(path, "rb") as f:
            head = f.read(24)
    except OSError:
        return None
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def classify(rc, timed_out, err, image, size, scene):
    """The outcome's class: 'ok', 'refused' or a failure's name."""
    if timed_out:
        return "timeout"
    if MEMORY.search(err):
        return "memory"
    if SANITIZER.search(err):
        return "sanitizer"
    if rc < 0 or rc >= 128:
        return "crash"
    lines = [l for l in err.splitlines() if l.strip() and not WARNING.match(l)]
    if rc == 0:
        return "ok" if png_size(image) == size and not lines else "exit-0-bad-image-or-output"
    if rc == 2:
        if os.path.exists(image):
            return "exit-2-with-image"
        if len(lines) != 1:
            return "exit-2-lines-%d" % len(lines)
        named = lines[0].startswith("stin-render: " + scene + ": ")
        return "refused" if named else "exit-2-not-naming-file"
    return "exit-%d%s" % (rc, "-with-image" if os.path.exists(image) else "")


def run_one(args, scene, profile, index):
    image = os.path.join(args.out, "work", "%04d-%s.png" % (index, profile))
    if os.path.exists(image):
        os.unlink(image)
    cmd = [args.render, scene, "-o", image, "--platform", "egl", "--profile", profile,
           "--size", "%dx%d" % args.size]
    env = dict(os.environ)
    mem = args.mem_mb
    env["ASAN_OPTIONS"] = ("detect_leaks=0:hard_rss_limit_mb=%d:malloc_limit_mb=%d:"
                           "allocator_may_return_null=1:abort_on_error=0" % (mem, mem))
    env["UBSAN_OPTIONS"] = "print_stacktrace=1:halt_on_error=1"
    env["LP_NUM_THREADS"] = "1"

    def limit():
        if not args.sanitized:  # ASan reserves terabytes of address space: it is bound by RSS instead
            import resource
            resource.setrlimit(resource.RLIMIT_AS, (mem << 20, mem << 20))

    t0 = time.monotonic()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         start_new_session=True, preexec_fn=limit)
    timed_out = False
    try:
        out, err = p.communicate(timeout=args.timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
    secs = time.monotonic() - t0
    err = err.decode("utf-8", "replace")
    cls = classify(p.returncode, timed_out, err, image, args.size, scene)
    if os.path.exists(image):
        os.unlink(image)
    return cls, secs, p.returncode, " ".join(cmd), out.decode("utf-8", "replace"), err


def sources(patterns):
    found = []
    for p in patterns:
        found += sorted(glob.glob(os.path.join(ROOT, "tests/scenes", p + ".json")))
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=60, help="inputs; the first half mutate the older scenes")
    ap.add_argument("--render", default=os.path.join(ROOT, "build/stin-render-san"))
    ap.add_argument("--profiles", default="gl21,gl45-core,gl11")
    ap.add_argument("--each", action="store_true", help="every input on every profile (else in turn)")
    ap.add_argument("--size", default="96x72")
    ap.add_argument("--timeout", type=float, default=60, help="seconds a run")
    ap.add_argument("--mem-mb", type=int, default=4096, help="memory a run (RSS under ASan, else ulimit -v)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--out", default=None, help="default build/hostile-SEED")
    ap.add_argument("--replay", help="run one scene file and print its class and output")
    args = ap.parse_args()
    args.size = tuple(int(x) for x in args.size.split("x"))
    with open(args.render, "rb") as f:
        args.sanitized = b"__asan_init" in f.read()
    profiles = args.profiles.split(",")
    if args.replay:
        args.out = os.path.dirname(os.path.abspath(args.replay))
        os.makedirs(os.path.join(args.out, "work"), exist_ok=True)
        worst = 0
        for prof in profiles:
            cls, secs, rc, cmd, out, err = run_one(args, args.replay, prof, 0)
            print("%s: %s (exit %d, %.1f s)\n%s" % (prof, cls, rc, secs, err.strip()))
            worst |= cls not in ("ok", "refused")
        return worst
    args.out = os.path.abspath(args.out or os.path.join(ROOT, "build", "hostile-%d" % args.seed))
    for d in ("work", "failed"):
        os.makedirs(os.path.join(args.out, d), exist_ok=True)
    rel = Rel(os.path.join(args.out, "work"))
    old, new = sources(OLD_SCENES), sources(NEW_SCENES)
    jobs = []
    for i in range(args.count):
        newer = i >= args.count // 2
        pool = new if newer else old
        src = pool[random.Random(args.seed * 7919 + i).randrange(len(pool))]
        text, what = make_input(src, args.seed, i, newer, rel)
        path = os.path.join(args.out, "work", "%04d.json" % i)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        for prof in (profiles if args.each else [profiles[i % len(profiles)]]):
            jobs.append((i, path, prof, os.path.relpath(src, ROOT), what, newer))
    figures = {}
    slowest = (0, "")
    log = open(os.path.join(args.out, "outcomes.tsv"), "w", encoding="utf-8")
    log.write("input\tprofile\tset\tsource\tmutations\tclass\texit\tseconds\n")
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [(j, pool.submit(run_one, args, j[1], j[2], j[0])) for j in jobs]
        for n, (j, fut) in enumerate(futures):
            i, path, prof, src, what, newer = j
            cls, secs, rc, cmd, out, err = fut.result()
            key = ("new" if newer else "old", prof)
            figures.setdefault(key, {}).setdefault(cls, 0)
            figures[key][cls] += 1
            slowest = max(slowest, (secs, "%04d %s" % (i, prof)))
            log.write("%04d\t%s\t%s\t%s\t%s\t%s\t%d\t%.2f\n" % (i, prof, key[0], src, ",".join(what), cls, rc, secs))
            log.flush()
            if cls not in ("ok", "refused"):
                keep = os.path.join(args.out, "failed", "%04d" % i)
                with open(path, encoding="utf-8") as f, open(keep + ".json", "w", encoding="utf-8") as g:
                    g.write(f.read())
                with open(keep + "-%s.txt" % prof, "w", encoding="utf-8") as g:
                    g.write("class: %s\nsource: %s\nmutations: %s\ncommand: %s\n--- stdout\n%s--- stderr\n%s"
                            % (cls, src, ", ".join(what), cmd, out[-4000:], err[-8000:]))
                print("%04d %s: %s (%s; %s)" % (i, prof, cls, src, ", ".join(what)), flush=True)
            if (n + 1) % 50 == 0:
                print("... %d of %d runs" % (n + 1, len(jobs)), flush=True)
    log.close()
    classes = sorted({c for v in figures.values() for c in v}, key=lambda c: (c not in ("ok", "refused"), c))
    print("\nset  profile    runs  " + "  ".join(classes))
    total = {}
    for key in sorted(figures):
        row = figures[key]
        for c in classes:
            total[c] = total.get(c, 0) + row.get(c, 0)
        print("%-4s %-10s %5d  %s" % (key[0], key[1], sum(row.values()),
                                     "  ".join("%*d" % (len(c), row.get(c, 0)) for c in classes)))
    failures = sum(v for c, v in total.items() if c not in ("ok", "refused"))
    print("all  %d inputs, %d runs: %s; %d failures; slowest %.1f s (%s)" % (
        args.count, sum(total.values()), ", ".join("%s %d" % (c, total[c]) for c in classes), failures,
        slowest[0], slowest[1]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
