#!/usr/bin/env python3
"""Writes bench/scenes/box_on_floor.gltf: the bundled glTF scene with a second UV set.

A 6 m floor and a 1 m box standing on it, as one glTF 2.0 mesh (glTF's frame: right-handed,
+Y up) with POSITION, NORMAL, TEXCOORD_0 (each face's own square) and TEXCOORD_1, the
lightmap UVs: six charts (the floor and the box's five visible faces) packed without overlap
into [0, 1]^2 with gaps of 0.04 (2.56 texels at 64 x 64: no texel holds two charts, and the
default padding of 2 rings fits), in glTF's UV
convention (v down from the top). bench/scenes/box_lightmap.json bakes its lightmap.

Standard library only; run from anywhere: python3 scripts/make_lightmap_example.py
"""
import base64
import json
import pathlib
import struct

# Each face: its corners counter-clockwise seen from outside (glTF's front face), its normal,
# and its chart's square in TEXCOORD_1 (u0, v0, size).
FACES = [
    # floor, y = 0, facing +y
    ([(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)], (0, 1, 0), (0.04, 0.04, 0.60)),
    # box top, y = 1
    ([(-0.5, 1, 0.5), (0.5, 1, 0.5), (0.5, 1, -0.5), (-0.5, 1, -0.5)], (0, 1, 0), (0.68, 0.04, 0.28)),
    # +x side
    ([(0.5, 0, 0.5), (0.5, 0, -0.5), (0.5, 1, -0.5), (0.5, 1, 0.5)], (1, 0, 0), (0.68, 0.36, 0.28)),
    # -x side
    ([(-0.5, 0, -0.5), (-0.5, 0, 0.5), (-0.5, 1, 0.5), (-0.5, 1, -0.5)], (-1, 0, 0), (0.04, 0.68, 0.28)),
    # +z side
    ([(-0.5, 0, 0.5), (0.5, 0, 0.5), (0.5, 1, 0.5), (-0.5, 1, 0.5)], (0, 0, 1), (0.36, 0.68, 0.28)),
    # -z side
    ([(0.5, 0, -0.5), (-0.5, 0, -0.5), (-0.5, 1, -0.5), (0.5, 1, -0.5)], (0, 0, -1), (0.68, 0.68, 0.28)),
]
CORNER_UV = [(0, 1), (1, 1), (1, 0), (0, 0)]  # a face's square, v down (glTF)


def main() -> None:
    positions, normals, uv0, uv1, indices = [], [], [], [], []
    for corners, normal, (u0, v0, size) in FACES:
        base = len(positions)
        for corner, (s, t) in zip(corners, CORNER_UV):
            positions.append(corner)
            normals.append(normal)
            uv0.append((s, t))
            uv1.append((u0 + s * size, v0 + t * size))
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]

    def floats(rows):
        return b"".join(struct.pack("<%df" % len(r), *r) for r in rows)

    blobs = [floats(positions), floats(normals), floats(uv0), floats(uv1),
             struct.pack("<%dH" % len(indices), *indices)]
    views, offset = [], 0
    for blob in blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob)})
        offset += (len(blob) + 3) // 4 * 4
    data = b"".join(blob + b"\0" * ((4 - len(blob) % 4) % 4) for blob in blobs)
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    n = len(positions)
    gltf = {
        "asset": {"version": "2.0", "generator": "shpack scripts/make_lightmap_example.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "box_on_floor"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3},
                                    "indices": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5126, "count": n, "type": "VEC2"},
            {"bufferView": 4, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    out = pathlib.Path(__file__).resolve().parent.parent / "bench" / "scenes" / "box_on_floor.gltf"
    out.write_text(json.dumps(gltf, indent=1) + "\n")
    print(out)


if __name__ == "__main__":
    main()
