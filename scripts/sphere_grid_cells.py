#!/usr/bin/env python3
"""compare_cycles.sh's sphere grid, sphere by sphere: each image's mean |sRGB difference| to the
ground truth over one sphere at a time, as a table of roughness across and metallic down.

    python3 scripts/sphere_grid_cells.py PATINA DIR [--tonemap pbr-neutral] [--downsample 2] [--erode 1]
        [--roughness 0,0.25,0.5,0.75,1] [--metallic 0,0.5,1] [--images gltf,epic,gltf-single,cycles-local]
        [--names "a,b;c,d"]

DIR is the spheres scene's folder of compare_cycles.sh's --work-dir (coverage.pfm, reference.pfm,
epic.pfm, gltf.pfm, gltf-single.pfm, cycles-local.exr). The spheres are found in the coverage
image (rendered by `render --channel geometry-normal --reference --hdr`): the runs of its
covered columns and rows are the grid's columns and rows, and a sphere's own coverage is the
coverage left inside its cell with every other pixel set to 0. `patina difference` then measures
each cell with the options compare_cycles.sh uses (docs/LIGHTING.md, "5. Side by side with
Cycles"). --names gives the spheres names instead (columns split by ",", rows by ";", for the
layer grid, tests/data/layers): the table is then a sphere a row, an image a column. Only the
standard library.
"""
import argparse
import array
import os
import subprocess
import sys
import tempfile

IMAGES = ["gltf", "epic", "gltf-single", "cycles-local"]


def read_pfm(path):
    """(width, height, channels, floats) of a PFM, rows bottom to top as stored."""
    with open(path, "rb") as file:
        kind = file.readline().strip()
        width, height = (int(v) for v in file.readline().split())
        scale = float(file.readline())
        channels = {b"PF": 3, b"Pf": 1}.get(kind)
        if channels is None:
            sys.exit(f"{path}: not a PFM")
        values = array.array("f")
        values.frombytes(file.read(width * height * channels * 4))
        if (scale < 0) != (sys.byteorder == "little"):
            values.byteswap()
    return width, height, channels, values


def write_pfm(path, width, height, channels, values):
    with open(path, "wb") as file:
        file.write(b"%s\n%d %d\n%s\n" % (b"PF" if channels == 3 else b"Pf", width, height,
                                          b"-1.0" if sys.byteorder == "little" else b"1.0"))
        values.tofile(file)


def runs(flags):
    """[first, last] of each run of True."""
    found, start = [], None
    for index, flag in enumerate(flags + [False]):
        if flag and start is None:
            start = index
        elif not flag and start is not None:
            found.append((start, index - 1))
            start = None
    return found


def cells(width, height, channels, coverage):
    covered = [any(coverage[(y * width + x) * channels + c] != 0.0 for c in range(channels))
               for y in range(height) for x in range(width)]
    columns = runs([any(covered[y * width + x] for y in range(height)) for x in range(width)])
    rows = runs([any(covered[y * width + x] for x in range(width)) for y in range(height)])
    return columns, rows[::-1]   # rows top first (a PFM is stored bottom to top)


def numbers(text):
    return [float(part) for part in text.split(",")]


def print_table(options, result):
    """The Markdown table of result[row, column, image] = (mean |difference|, mean signed)."""
    print("mean |sRGB difference| (mean signed) to the reference, sphere by sphere\n")
    if options.names:
        print("| sphere | " + " | ".join(options.images) + " |")
        print("|---|" + "---:|" * len(options.images))
        for row, names in enumerate(options.names):
            for column, sphere in enumerate(names):
                print(f"| {sphere} | " + " | ".join("%.1f (%+.1f)" % result[row, column, name]
                                                    for name in options.images) + " |")
        return
    print("| image | metallic | " + " | ".join(f"r = {r:g}" for r in options.roughness) + " |")
    print("|---|---:|" + "---:|" * len(options.roughness))
    for name in options.images:
        for row, metallic in enumerate(options.metallic):
            print(f"| {name} | {metallic:g} | " + " | ".join(
                "%.1f (%+.1f)" % result[row, column, name] for column in range(len(options.roughness))) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("patina")
    parser.add_argument("dir")
    parser.add_argument("--tonemap", default="pbr-neutral")
    parser.add_argument("--downsample", default="2")
    parser.add_argument("--erode", default="1")
    parser.add_argument("--roughness", type=numbers, default=[0.0, 0.25, 0.5, 0.75, 1.0])
    parser.add_argument("--metallic", type=numbers, default=[0.0, 0.5, 1.0])
    parser.add_argument("--images", type=lambda text: text.split(","), default=IMAGES)
    parser.add_argument("--names", type=lambda text: [row.split(",") for row in text.split(";")])
    options = parser.parse_args()
    if options.names:   # the grid's shape from the names
        options.metallic, options.roughness = options.names, options.names[0]
    width, height, channels, coverage = read_pfm(os.path.join(options.dir, "coverage.pfm"))
    columns, rows = cells(width, height, channels, coverage)
    if (len(columns), len(rows)) != (len(options.roughness), len(options.metallic)):
        sys.exit(f"the coverage shows {len(columns)} x {len(rows)} spheres, not "
                 f"{len(options.roughness)} x {len(options.metallic)}")
    paths = [os.path.join(options.dir, name + (".exr" if name.startswith("cycles") else ".pfm"))
             for name in ["reference"] + options.images]
    result = {}
    with tempfile.TemporaryDirectory() as scratch:
        cell_path = os.path.join(scratch, "cell.pfm")
        for row, (y0, y1) in enumerate(rows):
            for column, (x0, x1) in enumerate(columns):
                cell = array.array("f", bytes(len(coverage) * 4))
                for y in range(y0, y1 + 1):
                    begin, end = (y * width + x0) * channels, (y * width + x1 + 1) * channels
                    cell[begin:end] = coverage[begin:end]
                write_pfm(cell_path, width, height, channels, cell)
                csv = subprocess.run([options.patina, "difference", *paths, "--names", "reference", *options.images,
                                      "--coverage", cell_path, "--downsample", options.downsample, "--erode",
                                      options.erode, "--tonemap", options.tonemap],
                                     check=True, capture_output=True, text=True).stdout
                for line in csv.splitlines()[1:]:
                    fields = line.split(",")
                    result[row, column, fields[1]] = (float(fields[3]), float(fields[4]))
    print_table(options, result)


if __name__ == "__main__":   # scripts/clearcoat_columns.py imports its PFM helpers
    main()
