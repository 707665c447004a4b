#!/usr/bin/env python3
"""Writes spheres.gltf beside this script: two UV spheres of radius 1 for Patina's
KHR_materials_anisotropy tests (issue 36). "brushed" (a grey metal, roughness 0.4) has TANGENT,
the sphere's own dP/dphi (round the y axis, w = 1), anisotropyStrength 0.8, anisotropyRotation
0.5 rad and a white anisotropyTexture; "satin" (a dielectric) has no TANGENT, so the importer
makes MikkTSpace ones, anisotropyStrength 0.6 and the default rotation 0.
Run: python3 make_spheres.py (no arguments)."""
import base64
import importlib.util
import json
import math
import os
import struct

# The UV sphere and the white 2 x 2 PNG of tests/data/transmission/make_spheres.py, loaded by path.
_spec = importlib.util.spec_from_file_location(
    "transmission_spheres", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "transmission",
                                         "make_spheres.py"))
_transmission = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_transmission)
uv_sphere, white_png = _transmission.sphere, _transmission.white_png


def sphere():
    positions, uvs, indices = uv_sphere()
    # d(position)/d(phi), unit: along u, which grows with phi = 2 pi u (also at the poles).
    tangents = [(math.cos(2.0 * math.pi * u), 0.0, -math.sin(2.0 * math.pi * u), 1.0) for u, _ in uvs]
    return positions, uvs, tangents, indices


def main():
    positions, uvs, tangents, indices = sphere()
    position_bytes = b"".join(struct.pack("<3f", *p) for p in positions)   # normals: the same unit vectors
    uv_bytes = b"".join(struct.pack("<2f", *uv) for uv in uvs)
    tangent_bytes = b"".join(struct.pack("<4f", *t) for t in tangents)
    index_bytes = b"".join(struct.pack("<H", i) for i in indices)
    data = position_bytes + uv_bytes + tangent_bytes + index_bytes
    offsets = [0, len(position_bytes), len(position_bytes) + len(uv_bytes),
               len(position_bytes) + len(uv_bytes) + len(tangent_bytes)]
    document = {
        "asset": {"version": "2.0", "generator": "tests/data/anisotropy/make_spheres.py (Patina, issue 36)"},
        "extensionsUsed": ["KHR_materials_anisotropy"],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": offsets[0], "byteLength": len(position_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[1], "byteLength": len(uv_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[2], "byteLength": len(tangent_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": offsets[3], "byteLength": len(index_bytes), "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [-1.0, -1.0, -1.0], "max": [1.0, 1.0, 1.0]},
            {"bufferView": 1, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 2, "componentType": 5126, "count": len(tangents), "type": "VEC4"},
            {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(white_png()).decode()}],
        "textures": [{"source": 0}],
        "materials": [
            {"name": "brushed",
             "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1.0], "metallicFactor": 1.0,
                                      "roughnessFactor": 0.4},
             "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.8, "anisotropyRotation": 0.5,
                                                         "anisotropyTexture": {"index": 0}}}},
            {"name": "satin",
             "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.1, 0.1, 1.0], "metallicFactor": 0.0,
                                      "roughnessFactor": 0.3},
             "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": 0.6}}},
        ],
        "meshes": [
            {"name": "brushed sphere",
             "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 0, "TEXCOORD_0": 1, "TANGENT": 2},
                             "indices": 3, "material": 0}]},
            {"name": "satin sphere",
             "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 0, "TEXCOORD_0": 1}, "indices": 3,
                             "material": 1}]},
        ],
        "nodes": [
            {"name": "brushed", "mesh": 0, "translation": [-1.2, 0.0, 0.0]},
            {"name": "satin", "mesh": 1, "translation": [1.2, 0.0, 0.0]},
        ],
        "scenes": [{"nodes": [0, 1]}],
        "scene": 0,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "spheres.gltf"), "w") as out:
        json.dump(document, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
