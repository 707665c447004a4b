"""Writes layers.glb: a 4 x 2 grid of spheres, one Blender 3.4 Principled BSDF material each,
exported by Blender's own glTF exporter (issue 36, item 6), so that Patina's tests and
scripts/compare_cycles.sh read the KHR_materials_* extensions as artists' files carry them.

Run: blender -b --factory-startup --python tests/data/layers/make_layers.py -- OUT.glb

Top row, opaque on one red base (roughness 0.5):
  plain        the twin of every other sphere: no extension;
  clearcoat    Clearcoat 1, Clearcoat Roughness 0.05       -> KHR_materials_clearcoat;
  sheen        a Velvet BSDF added to the Principled BSDF, its Color and Sigma
               -> KHR_materials_sheen (sheenColorFactor, sheenRoughnessFactor): Blender 3.4's
               exporter reads the sheen from a Velvet node, never from the Principled BSDF's
               own Sheen (which it drops), and its importer builds the same Add Shader;
  specular     Specular 1, Specular Tint 0.5               -> KHR_materials_specular: 3.4 writes
               specularColorFactor only (its F0 over the IOR's), never specularFactor.
Bottom row, white base passing light (Transmission 1):
  transmission smooth (roughness 0.1)                       -> KHR_materials_transmission;
  rough        the same at roughness 0.4;
  ior          transmission at IOR 2.4                      -> KHR_materials_ior: 3.4 writes
               the IOR only beside transmission, volume or specular (an opaque dielectric's
               IOR does not change Blender's Principled v1 F0, so it is not exported alone);
  volume       transmission, the "glTF Material Output" group's Thickness 1.5 and a Volume
               Absorption (colour (1, 0.6, 0.2), density 2) on the output's Volume
               -> KHR_materials_volume (thicknessFactor, attenuationColor, attenuationDistance 0.5).
Every sphere's IOR is 1.5 (glTF's) but the ior one's, since Blender's default 1.45 would write
KHR_materials_ior on every transmissive one. One low-poly UV sphere (24 x 12, smooth) is shared
by all eight objects, no UVs, no textures, so the file stays small; every material is
single-sided (Backface Culling), as the validator asks of a volume's. The script prints each
material's extensions as written, and fails if one it meant to write is missing. Two runs write
the same JSON and the same vertices, but not always in the same order (the exporter's own), so
the committed file is one run's.
"""
import json
import struct
import sys

import bpy
import numpy

numpy.bool = bool   # Blender 3.4's exporter still uses numpy.bool, gone from numpy >= 1.24

RED = (0.8, 0.15, 0.1, 1.0)
WHITE = (0.95, 0.95, 0.95, 1.0)
# name, grid column and row, Principled BSDF inputs, extra nodes, the extensions it must write.
SPHERES = [
    ("plain", 0, 0, {"Base Color": RED, "Roughness": 0.5}, {}, set()),
    ("clearcoat", 1, 0, {"Base Color": RED, "Roughness": 0.5, "Clearcoat": 1.0, "Clearcoat Roughness": 0.05},
     {}, {"KHR_materials_clearcoat"}),
    ("sheen", 2, 0, {"Base Color": RED, "Roughness": 0.5}, {"velvet": ((0.9, 0.9, 0.9, 1.0), 0.5)},
     {"KHR_materials_sheen"}),
    ("specular", 3, 0, {"Base Color": RED, "Roughness": 0.5, "Specular": 1.0, "Specular Tint": 0.5}, {},
     {"KHR_materials_specular"}),
    ("transmission", 0, 1, {"Base Color": WHITE, "Roughness": 0.1, "Transmission": 1.0}, {},
     {"KHR_materials_transmission"}),
    ("rough transmission", 1, 1, {"Base Color": WHITE, "Roughness": 0.4, "Transmission": 1.0}, {},
     {"KHR_materials_transmission"}),
    ("ior", 2, 1, {"Base Color": WHITE, "Roughness": 0.1, "Transmission": 1.0, "IOR": 2.4}, {},
     {"KHR_materials_transmission", "KHR_materials_ior"}),
    ("volume", 3, 1, {"Base Color": WHITE, "Roughness": 0.1, "Transmission": 1.0},
     {"thickness": 1.5, "absorption": ((1.0, 0.6, 0.2, 1.0), 2.0)},
     {"KHR_materials_transmission", "KHR_materials_volume"}),
]
SPACING = 2.5


def settings_group():
    """The exporter's "glTF Material Output" node group (its Thickness socket), made as its
    importer makes it."""
    from io_scene_gltf2.blender.com.gltf2_blender_material_helpers import create_settings_group, get_gltf_node_name
    name = get_gltf_node_name()
    return bpy.data.node_groups.get(name) or create_settings_group(name)


def material(name, inputs, extra):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.use_backface_culling = True   # closed spheres: single-sided, as KHR_materials_volume asks
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    output = nodes["Material Output"]
    bsdf.inputs["IOR"].default_value = 1.5
    for socket, value in inputs.items():
        bsdf.inputs[socket].default_value = value
    if "velvet" in extra:
        velvet = nodes.new("ShaderNodeBsdfVelvet")
        velvet.inputs["Color"].default_value, velvet.inputs["Sigma"].default_value = extra["velvet"]
        add = nodes.new("ShaderNodeAddShader")
        links.new(add.inputs[0], velvet.outputs[0])
        links.new(add.inputs[1], bsdf.outputs[0])
        links.new(output.inputs["Surface"], add.outputs[0])
    if "thickness" in extra:
        group = nodes.new("ShaderNodeGroup")
        group.node_tree = settings_group()
        group.inputs["Thickness"].default_value = extra["thickness"]
    if "absorption" in extra:
        absorption = nodes.new("ShaderNodeVolumeAbsorption")
        absorption.inputs["Color"].default_value, absorption.inputs["Density"].default_value = extra["absorption"]
        links.new(output.inputs["Volume"], absorption.outputs[0])
    return mat


def build():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, radius=1.0)
    template = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    mesh = template.data
    mesh.uv_layers.remove(mesh.uv_layers[0])
    mesh.materials.append(None)
    for name, column, row, inputs, extra, _ in SPHERES:
        obj = template if name == "plain" else template.copy()   # one mesh, each object its own material
        if obj is not template:
            bpy.context.collection.objects.link(obj)
        obj.name = name
        obj.location = (column * SPACING, 0.0, -row * SPACING)   # Blender's Z up: the grid faces -Y
        obj.material_slots[0].link = "OBJECT"
        obj.material_slots[0].material = material(name, inputs, extra)


def glb_json(path):
    with open(path, "rb") as f:
        data = f.read()
    length, = struct.unpack_from("<I", data, 12)
    return json.loads(data[20:20 + length])


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1 or not argv[0].endswith((".glb", ".gltf")):
        sys.exit("usage: blender -b --factory-startup --python make_layers.py -- OUT.glb|OUT.gltf")
    out = argv[0]
    build()
    bpy.ops.export_scene.gltf(filepath=out, export_format="GLB" if out.endswith(".glb") else "GLTF_EMBEDDED",
                              export_texcoords=False, export_materials="EXPORT", export_yup=True)
    document = glb_json(out) if out.endswith(".glb") else json.load(open(out))
    missing = []
    for mat in document["materials"]:
        extensions = mat.get("extensions", {})
        print("make_layers:", mat["name"], json.dumps(extensions, sort_keys=True))
        meant = next(s[5] for s in SPHERES if s[0] == mat["name"])
        if set(extensions) != meant:
            missing.append(f'{mat["name"]}: wrote {sorted(extensions)}, meant {sorted(meant)}')
    if missing:
        sys.exit("make_layers: " + "; ".join(missing))


main()
