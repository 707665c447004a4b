#!/usr/bin/env python3
"""A glTF 2.0 file of spheres: roughness across, metallic down, one plain base colour.

    python3 scripts/sphere_grid.py OUT.gltf [--roughness 0,0.25,0.5,0.75,1] [--metallic 0,0.5,1]

scripts/compare_cycles.sh renders it with Patina, its ground truth and Blender's Cycles
(docs/LIGHTING.md, "Side by side with Cycles"). Column c holds roughness[c], row r (from the top)
metallic[r]; the spheres have radius 0.4 and stand 1 apart in the XY plane (glTF's +Y up), the
grid centred on the origin, so that a camera on +Z sees them all and, in a path tracer, one
sphere hides little of the sky from its neighbours. Every sphere is the same UV sphere (64
segments, 32 rings, smooth normals) with a material of its own named "r0.25 m0.5"; the base
colour is linear (0.8, 0.45, 0.2), saturated enough for a metal's tint to show. The buffer is
embedded as a data: URI, so the file stands alone. Only the standard library: Debian's python3
without numpy runs it.
"""
import argparse
import base64
import json
import math
import struct

RADIUS = 0.4
SPACING = 1.0
SEGMENTS, RINGS = 64, 32
BASE_COLOUR = [0.8, 0.45, 0.2, 1.0]


def numbers(text):
    values = [float(part) for part in text.split(",") if part.strip()]
    if not values or any(not 0.0 <= value <= 1.0 for value in values):
        raise argparse.ArgumentTypeError(f"{text!r}: give numbers in [0, 1] separated by commas")
    return values


def sphere():
    """Positions (radius RADIUS), unit normals and triangle indices of a UV sphere, +Y its axis."""
    positions, normals, indices = [], [], []
    for ring in range(RINGS + 1):
        polar = math.pi * ring / RINGS
        for segment in range(SEGMENTS + 1):
            azimuth = 2.0 * math.pi * segment / SEGMENTS
            normal = (math.sin(polar) * math.sin(azimuth), math.cos(polar), math.sin(polar) * math.cos(azimuth))
            normals.append(normal)
            positions.append(tuple(RADIUS * n for n in normal))
    row = SEGMENTS + 1
    for ring in range(RINGS):
        for segment in range(SEGMENTS):
            a, b = ring * row + segment, (ring + 1) * row + segment
            # Counter-clockwise seen from outside; the triangles at the poles that would have no
            # area are left out.
            if ring != 0:
                indices += [a, b, a + 1]
            if ring != RINGS - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, indices


def grid(roughness, metallic):
    positions, normals, indices = sphere()
    position_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    normal_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
    index_bytes = b"".join(struct.pack("<I", i) for i in indices)
    buffer = position_bytes + normal_bytes + index_bytes
    document = {
        "asset": {"version": "2.0", "generator": "Patina scripts/sphere_grid.py"},
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode("ascii")}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(position_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(position_bytes), "byteLength": len(normal_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(position_bytes) + len(normal_bytes), "byteLength": len(index_bytes),
             "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [-RADIUS] * 3, "max": [RADIUS] * 3},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
        ],
        "materials": [], "meshes": [], "nodes": [], "scenes": [{"nodes": []}], "scene": 0,
    }
    for row, m in enumerate(metallic):
        for column, r in enumerate(roughness):
            index = len(document["nodes"])
            document["materials"].append({
                "name": f"r{r:g} m{m:g}",
                "pbrMetallicRoughness": {"baseColorFactor": BASE_COLOUR, "metallicFactor": m, "roughnessFactor": r},
            })
            document["meshes"].append({"name": f"sphere r{r:g} m{m:g}", "primitives": [
                {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": index}]})
            x = (column - (len(roughness) - 1) / 2.0) * SPACING
            y = ((len(metallic) - 1) / 2.0 - row) * SPACING
            document["nodes"].append({"name": f"r{r:g} m{m:g}", "mesh": index, "translation": [x, y, 0.0]})
            document["scenes"][0]["nodes"].append(index)
    return document


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="the .gltf to write")
    parser.add_argument("--roughness", type=numbers, default=[0.0, 0.25, 0.5, 0.75, 1.0])
    parser.add_argument("--metallic", type=numbers, default=[0.0, 0.5, 1.0])
    options = parser.parse_args()
    with open(options.out, "w", encoding="utf-8") as file:
        json.dump(grid(options.roughness, options.metallic), file)
        file.write("\n")


main()
