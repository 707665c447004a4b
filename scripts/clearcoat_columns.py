#!/usr/bin/env python3
"""compare_cycles.sh's ClearCoatTest, column by column: what the coat adds in each renderer, and
Patina's distance to Cycles over the "Base layer" and the "Coated" column.

    python3 scripts/clearcoat_columns.py strip IN.gltf OUT_DIR
        OUT_DIR/NAME.gltf: IN without KHR_materials_clearcoat (its buffers and images copied: Patina
        refuses a link that leads outside the model's folder)
    python3 scripts/clearcoat_columns.py measure PATINA DIR [--tonemap pbr-neutral] [--downsample 2] [--erode 1]

DIR is the scene's folder of compare_cycles.sh's --work-dir: coverage.pfm, gltf.pfm,
cycles-local.exr, cycles.exr, and the same rendered of the stripped model (gltf-nocoat.pfm,
cycles-local-nocoat.exr, cycles-nocoat.exr). Khronos's ClearCoatTest lays its patches out in
columns (the labels, "Base layer", "Coated", "Coating only"): the runs of the coverage's covered
columns. Each column's own coverage is measured with `patina difference` as
scripts/sphere_grid_cells.py measures a sphere. "The coat adds": each renderer's image against
its image of the stripped model (mean signed difference: the light the coat adds, in levels of
255), on the Coated column and on the Base layer column (where nothing changed: the control).
Only the standard library.
"""
import argparse
import array
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphere_grid_cells import read_pfm, write_pfm, runs  # noqa: E402

COLUMNS = {"Base layer": 1, "Coated": 2}
RENDERERS = [("Patina gltf", "gltf"), ("Cycles, local", "cycles-local"), ("Cycles", "cycles")]


def strip(source, out_dir):
    with open(source) as file:
        model = json.load(file)
    for material in model.get("materials", []):
        material.get("extensions", {}).pop("KHR_materials_clearcoat", None)
    for key in ("extensionsUsed", "extensionsRequired"):
        if "KHR_materials_clearcoat" in model.get(key, []):
            model[key].remove("KHR_materials_clearcoat")
    os.makedirs(out_dir, exist_ok=True)
    for item in model.get("buffers", []) + model.get("images", []):
        uri = item.get("uri")
        link = os.path.join(out_dir, uri or "")
        if uri and not uri.startswith("data:") and not os.path.exists(link):
            shutil.copyfile(os.path.join(os.path.dirname(os.path.abspath(source)), uri), link)
    with open(os.path.join(out_dir, os.path.basename(source)), "w") as file:
        json.dump(model, file)


def column_masks(path):
    width, height, channels, coverage = read_pfm(path)
    covered = [any(coverage[(y * width + x) * channels + c] != 0.0 for c in range(channels))
               for y in range(height) for x in range(width)]
    columns = runs([any(covered[y * width + x] for y in range(height)) for x in range(width)])
    if len(columns) != 4:
        sys.exit(f"{path}: {len(columns)} columns of patches, not the 4 of ClearCoatTest")
    masks = {}
    for name, index in COLUMNS.items():
        x0, x1 = columns[index]
        mask = array.array("f", bytes(len(coverage) * 4))
        for y in range(height):
            begin, end = (y * width + x0) * channels, (y * width + x1 + 1) * channels
            mask[begin:end] = coverage[begin:end]
        masks[name] = (width, height, channels, mask)
    return masks


def measure(options):
    def image(stem):
        return os.path.join(options.dir, stem + (".exr" if stem.startswith("cycles") else ".pfm"))

    def difference(mask_path, first, second):
        csv = subprocess.run([options.patina, "difference", image(first), image(second), "--coverage", mask_path,
                              "--downsample", options.downsample, "--erode", options.erode,
                              "--tonemap", options.tonemap], check=True, capture_output=True, text=True).stdout
        fields = csv.splitlines()[1].split(",")
        return "%.1f (%+.1f)" % (float(fields[3]), float(fields[4]))

    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for column, mask in column_masks(os.path.join(options.dir, "coverage.pfm")).items():
            mask_path = os.path.join(scratch, "column.pfm")
            write_pfm(mask_path, *mask)
            added = [difference(mask_path, stem + "-nocoat", stem) for _, stem in RENDERERS]
            distance = [difference(mask_path, against, "gltf") for against in ("cycles-local", "cycles")]
            rows.append((column, added, distance))
    print("ClearCoatTest column by column, mean |sRGB difference| (mean signed), levels of 255\n")
    print("| column | the coat adds: " + " | ".join(name for name, _ in RENDERERS) +
          " | Patina gltf to Cycles, local | Patina gltf to Cycles |")
    print("|---|" + "---:|" * (len(RENDERERS) + 2))
    for column, added, distance in rows:
        print(f"| {column} | " + " | ".join(added + distance) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    verbs = parser.add_subparsers(dest="verb", required=True)
    stripping = verbs.add_parser("strip")
    stripping.add_argument("source")
    stripping.add_argument("out_dir")
    measuring = verbs.add_parser("measure")
    measuring.add_argument("patina")
    measuring.add_argument("dir")
    measuring.add_argument("--tonemap", default="pbr-neutral")
    measuring.add_argument("--downsample", default="2")
    measuring.add_argument("--erode", default="1")
    options = parser.parse_args()
    if options.verb == "strip":
        strip(options.source, options.out_dir)
    else:
        measure(options)


main()
