#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the small glTF test models of tests/cli/test_render.sh into
tests/scenes/meshes/ (run from the repository root; the outputs are committed):

  quads.gltf + quads.bin + quads-cells.png   external buffer and texture
  quads.glb                                  the same, the PNG embedded
  quads-missing-texture.gltf                 its image names no file
  quad-mtl.obj + quad-mtl.mtl                a unit quad with Kd (0, 0.5, 1)

Three nodes, each a unit quad in z = 0 facing +z, with its own transform and
material:
  red    base colour (1, 0, 0, 1), OPAQUE            node: translate (-1, 0, 0)
  cells  base-colour texture (2x2 cells, see CELLS)  node: parent 'group'
         (translate (1, 0, 0)) times its own scale 0.5 and translate (0, 0.5, 0)
  veil   base colour (0, 0, 1, 0.5), BLEND           node: translate (-1, 0, 0.25),
                                                     scale (0.5, 1, 1)
No other dependency than the standard library (struct, zlib, json)."""
import base64
import json
import struct
import sys
import zlib

# Texel rows top to bottom as stored in the PNG (glTF uv (0,0) is the top left).
CELLS = [[(255, 255, 0), (0, 255, 255)],   # top: yellow | cyan
         [(0, 255, 0), (255, 0, 255)]]     # bottom: green | magenta
CELL_TEXELS = 8


def png(rows):
    """rows: list of rows of (r, g, b) bytes, top first -> PNG file bytes."""
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def texture_rows():
    rows = []
    for cy in range(2):
        for _ in range(CELL_TEXELS):
            rows.append([CELLS[cy][cx] for cx in range(2) for _ in range(CELL_TEXELS)])
    return rows


def quad_buffer():
    """One quad shared by all nodes: positions, normals, uvs, indices."""
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    nrm = [(0, 0, 1)] * 4
    uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
    idx = [0, 1, 2, 0, 2, 3]
    data = b"".join(struct.pack("<3f", *p) for p in pos)
    data += b"".join(struct.pack("<3f", *n) for n in nrm)
    data += b"".join(struct.pack("<2f", *t) for t in uv)
    data += struct.pack("<6H", *idx) + b"\0\0"  # pad to 4 bytes
    return data


def document(buffer_len, image):
    views = [(0, 48, 34962), (48, 48, 34962), (96, 32, 34962), (128, 12, 34963)]
    doc = {
        "asset": {"version": "2.0", "generator": "stin tools/make-model-assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "red", "mesh": 0, "translation": [-1, 0, 0]},
            {"name": "group", "translation": [1, 0, 0], "children": [3]},
            {"name": "veil", "mesh": 2, "translation": [-1, 0, 0.25], "scale": [0.5, 1, 1]},
            {"name": "cells", "mesh": 1, "translation": [0, 0.5, 0], "scale": [0.5, 0.5, 0.5]},
        ],
        "meshes": [
            {"name": "red", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                            "indices": 3, "material": 0}]},
            {"name": "cells", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                              "indices": 3, "material": 1}]},
            {"name": "veil", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                             "indices": 3, "material": 2}]},
        ],
        "materials": [
            {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1],
                                                     "metallicFactor": 0}},
            {"name": "cells", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                       "metallicFactor": 0}},
            {"name": "veil", "alphaMode": "BLEND",
             "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 0.5], "metallicFactor": 0}},
        ],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],  # NEAREST: crisp cells
        "images": [image],
        "buffers": [{"byteLength": buffer_len}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n, "target": t}
                        for o, n, t in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
        ],
    }
    return doc


def pad(b, fill):
    return b + fill * (-len(b) % 4)


def main(out):
    tex = png(texture_rows())
    geo = quad_buffer()
    with open(out + "/quads-cells.png", "wb") as f:
        f.write(tex)
    with open(out + "/quads.bin", "wb") as f:
        f.write(geo)
    doc = document(len(geo), {"uri": "quads-cells.png"})
    doc["buffers"][0]["uri"] = "quads.bin"
    with open(out + "/quads.gltf", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    # .glb: the PNG follows the geometry in the one binary chunk.
    binary = pad(geo, b"\0") + tex
    doc = document(len(binary), {"bufferView": 4, "mimeType": "image/png"})
    doc["bufferViews"].append({"buffer": 0, "byteOffset": len(pad(geo, b"\0")), "byteLength": len(tex)})
    text = pad(json.dumps(doc, separators=(",", ":")).encode(), b" ")
    binary = pad(binary, b"\0")
    body = (struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(binary), b"BIN\0") + binary)
    with open(out + "/quads.glb", "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)
    # For the test of a missing texture: the .gltf pointing at no file.
    doc = document(len(geo), {"uri": "no-such-texture.png"})
    doc["buffers"][0]["uri"] = "quads.bin"
    with open(out + "/quads-missing-texture.gltf", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    with open(out + "/quad-mtl.obj", "w") as f:
        f.write("# A unit quad in z = 0 facing +z with an MTL colour (tools/make-model-assets.py)\n"
                "mtllib quad-mtl.mtl\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\n"
                "vn 0 0 1\nusemtl sky\nf 1//1 2//1 3//1 4//1\n")
    with open(out + "/quad-mtl.mtl", "w") as f:
        f.write("newmtl sky\nKd 0 0.5 1\nKs 0 0 0\nd 1\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/scenes/meshes")
