"""Blender's half of scripts/compare_blender.sh (Patina's default view of a sphere, rendered by
Eevee) and of scripts/compare_cycles.sh (a glTF model rendered by Cycles to a linear image).

Run inside Blender (Eevee needs a GL context, so a display: compare_blender.sh starts an Xvfb):

    blender -b --factory-startup --python scripts/blender_render.py -- \
        --hdri studio.exr --material presets/gold.json --out eevee.png [--reruns 5]
    blender -b --factory-startup --python scripts/blender_render.py -- \
        --hdri studio.exr --model BoxTextured.glb --out eevee.png [--reruns 5]
    blender -b --factory-startup --python scripts/blender_render.py -- \
        --hdri studio.exr --model F.glb --out eevee.png --camera EX EY EZ TX TY TZ FOV \
        --sun DX DY DZ STRENGTH ANGLE --ground
    blender -b --factory-startup --python scripts/blender_render.py -- --hdri studio.exr --probe
    blender -b --factory-startup --python scripts/blender_render.py -- --hdri studio.exr \
        --model BoxTextured.gltf --render-cycles [--local] [--base-color] [--samples 512] [--seed 0] \
        --width 512 --height 512 --camera EX EY EZ TX TY TZ FOV --out cycles.exr
    blender -b --factory-startup --python scripts/blender_render.py -- --hdri x --model F.gltf --bounds

The scene is Patina's default view converted to Blender's axes: Patina is +Y up, Blender +Z up,
and a Patina point (x, y, z) is the Blender point (x, -z, y). So the camera at Patina's
(0, 0.6, 3.4) stands at (0, -3.4, 0.6), looking at the origin with a vertical field of view of
45 degrees (--camera gives another eye, target and field of view, in Patina's axes); the UV sphere of radius 1 has Patina's tessellation (64 rings, 128 segments), smooth
shaded. The world is the HDRI at strength 1, turned by --world-rotation degrees about +Z (see
--probe), with the pixels Patina sets to 0 (a NaN, infinite or negative value) set to 0 here
too, and the film uses the Standard view transform, as Patina's "none" tone map.

With --model, a glTF model takes the sphere's place, imported by Blender's own glTF importer
(which turns glTF's +Y up into Blender's +Z up as above) with its materials and texture maps; the
re-renders change its first material's roughness, as the editor's Roughness slider changes the
selected part's factor.

With --sun (compare_blender.sh --shadows) a Sun lamp lights the scene besides the HDRI, along
Patina's directional light's direction, its strength the same irradiance as that light's
intensity, with Eevee's soft shadows (the lamp's angle makes the penumbra); with --ground a
plane of Patina's floor's size, place and material lies under the model.

Render mode times, in this one process, the first render (bpy.ops.render.render with
write_still, so Eevee's shader compilation and the world's probe are in it) and then re-renders
after a roughness change (every one to another value, so each is a change; the median is what
compare_blender.sh reports). The first image is rendered at the preset's roughness and is the
one compared; the re-renders go to a scratch file.

Cycles mode (--render-cycles) renders once, on the CPU, without denoising or adaptive sampling,
each pixel at its centre (a box filter 0.01 pixels wide, as Patina's ground truth samples it),
to a 32-bit float OpenEXR of scene-linear Rec. 709 (no view transform). --local hides the model
from every ray but the camera's (diffuse, glossy, transmission, volume and shadow rays), so each
point is lit by the whole environment, unshadowed, as Patina shades it. --base-color shows each
Principled BSDF's Base Color input (its map times its factor) as emission instead, to hold
against Patina's `--channel base-color`. Bounds mode (--bounds) prints the imported model's
world-space bounding box in Patina's axes, from which compare_cycles.sh places its cameras.

Probe mode checks the orientation instead of assuming it: the world becomes an image whose
pixels hold their own (u, v), a 2-degree camera looks along a few of Patina's directions, and the
(u, v) Eevee shows there must be the one Patina's equirect convention (docs/FORMATS.md) gives for
that direction. It exits with status 1 when they differ.

Results are printed as lines "PATINA_COMPARE key value" for the shell script to read.
"""
import argparse
import json
import math
import statistics
import sys
import time

import bmesh
import bpy
from mathutils import Vector

TAG = "PATINA_COMPARE"


def report(key, value):
    print(f"{TAG} {key} {value}", flush=True)


def parse_arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender_render.py")
    parser.add_argument("--hdri", required=True, help="the equirect environment (.exr or .hdr)")
    parser.add_argument("--material", help="a Patina material preset (JSON) on the sphere")
    parser.add_argument("--model", help="a glTF model (.gltf or .glb) instead of the sphere, with its own materials")
    parser.add_argument("--out", help="the first render's PNG")
    parser.add_argument("--scratch", help="the re-renders' PNG (default: beside --out)")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--reruns", type=int, default=5)
    parser.add_argument("--samples", type=int, help="Eevee's render samples (default: Blender's, 64); "
                        "with --render-cycles, Cycles' samples per pixel (default 256)")
    parser.add_argument("--world-rotation", type=float, default=-90.0,
                        help="degrees about +Z applied to the world lookup (default: Patina's orientation)")
    parser.add_argument("--probe", action="store_true", help="check the orientation and exit")
    # compare_cycles.sh: a linear image by Cycles from a camera of its choosing.
    parser.add_argument("--render-cycles", action="store_true",
                        help="one Cycles render to --out as a linear OpenEXR (no timing, no re-renders)")
    parser.add_argument("--local", action="store_true",
                        help="--render-cycles: the model hidden from every ray but the camera's (no shadow, no "
                             "interreflection: each point lit by the whole environment, as Patina shades it)")
    parser.add_argument("--seed", type=int, default=0, help="--render-cycles: the sampling pattern's seed")
    parser.add_argument("--base-color", action="store_true",
                        help="--render-cycles: each material's base colour (its map times its factor) as emission "
                             "instead of its BSDF, to hold against Patina's --channel base-color: where the two "
                             "differ, the view, the UVs or the texture filtering do")
    parser.add_argument("--width", type=int, help="the image's width (default --size)")
    parser.add_argument("--height", type=int, help="the image's height (default --size)")
    parser.add_argument("--camera", type=float, nargs=7, metavar=("EX", "EY", "EZ", "TX", "TY", "TZ", "FOV"),
                        default=[0.0, 0.6, 3.4, 0.0, 0.0, 0.0, 45.0],
                        help="eye, target (Patina's axes, +Y up) and vertical field of view in degrees "
                             "(default Patina's default view)")
    parser.add_argument("--bounds", action="store_true",
                        help="print the --model's bounding box in Patina's axes and exit")
    # compare_blender.sh --shadows: one shadow-casting lamp and a floor, as in Patina's scene.
    parser.add_argument("--sun", type=float, nargs=5, metavar=("DX", "DY", "DZ", "STRENGTH", "ANGLE"),
                        help="render mode: a Sun lamp casting Eevee's soft shadows, travelling along (DX, DY, DZ) "
                             "(Patina's axes, as a directional light's direction), of STRENGTH (irradiance, as "
                             "Patina's intensity) and ANGLE degrees across (the penumbra)")
    parser.add_argument("--ground", action="store_true",
                        help="render mode: Patina's display.ground \"floor\" under the model (scene/ground.cpp)")
    options = parser.parse_args(argv)
    if options.bounds and not options.model:
        parser.error("--bounds needs --model")
    if not (options.probe or options.bounds) and not ((options.material or options.model) and options.out):
        parser.error("--material or --model, and --out, are needed unless --probe or --bounds")
    return options


def patina_to_blender(x, y, z):
    return Vector((x, -z, y))


def empty_scene(width, height):
    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene.render.engine = "BLENDER_EEVEE"
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.display_settings.display_device = "sRGB"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"
    return scene


def add_camera(scene, position, target, fov_y_degrees):
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    scene.camera = camera
    camera.location = position
    # The camera looks down its -Z with +Y up; Blender's up is +Z, Patina's +Y.
    camera.rotation_euler = (target - position).to_track_quat("-Z", "Y").to_euler()
    camera.data.sensor_fit = "VERTICAL"
    camera.data.angle_y = math.radians(fov_y_degrees)
    camera.data.clip_start = 0.05
    # A model hundreds of units across (2CylinderEngine) is framed from as far away.
    camera.data.clip_end = max(100.0, 10.0 * (target - position).length)
    return camera


def set_world(scene, image, rotation_degrees, interpolation="Linear"):
    """Generated coordinates (the world direction) -> Mapping (turn about +Z) -> Environment Texture."""
    world = bpy.data.worlds.new("patina world")
    scene.world = world
    world.use_nodes = True
    nodes = world.node_tree.nodes
    links = world.node_tree.links
    nodes.clear()
    coordinates = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "POINT"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(rotation_degrees))
    environment = nodes.new("ShaderNodeTexEnvironment")
    environment.image = image
    environment.projection = "EQUIRECTANGULAR"
    environment.interpolation = interpolation
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = 1.0
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], environment.inputs["Vector"])
    links.new(environment.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], output.inputs["Surface"])


def patina_uv(direction):
    """Patina's equirect lookup (docs/FORMATS.md, "Environment images"): v from the top row."""
    x, y, z = direction
    length = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / length, y / length, z / length
    return 0.5 + math.atan2(x, -z) / (2.0 * math.pi), math.acos(max(-1.0, min(1.0, y))) / math.pi


def probe(options):
    scene = empty_scene(8, 8)
    width, height = 512, 256
    image = bpy.data.images.new("uv probe", width, height, float_buffer=True)
    pixels = []
    for row in range(height):   # Blender's rows run bottom-up
        for column in range(width):
            pixels += [(column + 0.5) / width, (row + 0.5) / height, 0.0, 1.0]
    image.pixels = pixels
    set_world(scene, image, options.world_rotation, interpolation="Closest")
    camera = add_camera(scene, Vector((0.0, 0.0, 0.0)), Vector((0.0, 1.0, 0.0)), 2.0)
    scene.render.image_settings.file_format = "OPEN_EXR"   # linear: the values themselves
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "32"
    path = bpy.app.tempdir + "probe.exr"
    worst = 0.0
    # Directions in Patina's axes, away from the image's seam (Patina's +Z) and poles.
    for name, direction in [("-Z (behind the sphere)", (0, 0, -1)), ("+X", (1, 0, 0)), ("-X", (-1, 0, 0)),
                            ("(1, 1, -1)", (1, 1, -1)), ("(-1, -0.5, 0.3)", (-1, -0.5, 0.3))]:
        target = patina_to_blender(*direction)
        camera.rotation_euler = target.to_track_quat("-Z", "Z" if abs(target.z) < 0.9 else "Y").to_euler()
        bpy.ops.render.render()
        bpy.data.images["Render Result"].save_render(path)
        result = bpy.data.images.load(path, check_existing=False)
        values = result.pixels[:]
        centre = ((4 * 8) + 4) * 4
        u, v = values[centre], 1.0 - values[centre + 1]
        bpy.data.images.remove(result)
        want_u, want_v = patina_uv(direction)
        error = max(abs((u - want_u + 0.5) % 1.0 - 0.5), abs(v - want_v))
        worst = max(worst, error)
        print(f"probe: Patina direction {name}: Eevee shows (u, v) = ({u:.3f}, {v:.3f}), "
              f"Patina ({want_u:.3f}, {want_v:.3f})", flush=True)
    report("probe_worst_error", f"{worst:.4f}")
    return 0 if worst < 0.01 else 1


def import_model(path):
    """The model through Blender's glTF importer; the first material's Principled BSDF."""
    import numpy
    if not hasattr(numpy, "bool"):
        numpy.bool = bool   # Blender 3.4's importer still says numpy.bool, gone from numpy 1.24
    before = set(bpy.data.materials)   # factory startup's own "Material" is not the model's
    bpy.ops.import_scene.gltf(filepath=path)
    for material in bpy.data.materials:
        if material not in before and material.node_tree:
            for node in material.node_tree.nodes:
                if node.type == "BSDF_PRINCIPLED":
                    return node
    raise RuntimeError(f"{path}: the import made no Principled BSDF")


def add_sphere(scene, options):
    """Patina's sphere with the preset's material; its Principled BSDF."""
    with open(options.material, encoding="utf-8") as file:
        preset = json.load(file)
    # Patina's tessellation: 64 rings, 128 segments, smooth shaded.
    mesh_data = bpy.data.meshes.new("sphere")
    sphere = bpy.data.objects.new("sphere", mesh_data)
    scene.collection.objects.link(sphere)
    mesh = bmesh.new()
    bmesh.ops.create_uvsphere(mesh, u_segments=128, v_segments=64, radius=1.0)
    mesh.to_mesh(mesh_data)
    mesh.free()
    mesh_data.polygons.foreach_set("use_smooth", [True] * len(mesh_data.polygons))
    mesh_data.update()

    material = bpy.data.materials.new(preset.get("name", "material"))
    material.use_nodes = True
    bsdf = next(node for node in material.node_tree.nodes if node.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Base Color"].default_value = (*preset["baseColor"], 1.0)   # linear, as Patina's
    bsdf.inputs["Roughness"].default_value = preset["roughness"]
    bsdf.inputs["Specular"].default_value = preset["specular"]
    bsdf.inputs["Metallic"].default_value = preset["metallic"]
    mesh_data.materials.append(material)
    return bsdf


def image_size(options):
    return options.width or options.size, options.height or options.size


def add_view(scene, options):
    """The camera of --camera (Patina's axes) and the world of --hdri, turned by --world-rotation."""
    eye, target, fov = options.camera[0:3], options.camera[3:6], options.camera[6]
    add_camera(scene, patina_to_blender(*eye), patina_to_blender(*target), fov)
    set_world(scene, load_environment(options.hdri), options.world_rotation)


def load_environment(path):
    """The HDRI as Patina reads it: a pixel with a NaN, infinite or negative value is set to 0
    (environment/equirect.h, replaceInvalidPixels), so both renderers are lit by the same image."""
    import numpy
    image = bpy.data.images.load(path, check_existing=False)
    pixels = numpy.empty(len(image.pixels), dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    rgba = pixels.reshape(-1, 4)
    bad = ~numpy.isfinite(rgba[:, :3]).all(axis=1) | (numpy.nan_to_num(rgba[:, :3]) < 0.0).any(axis=1)
    report("environment_invalid_pixels", int(bad.sum()))
    if bad.any():
        rgba[:, :3] = numpy.where(numpy.isfinite(rgba[:, :3]) & (rgba[:, :3] >= 0.0), rgba[:, :3], 0.0)
        image.pixels.foreach_set(pixels)   # the buffer in memory, which the render reads
    return image


def world_vertices():
    """Every mesh's vertices in world space, Patina's axes, as one (N, 3) array."""
    import numpy
    parts = []
    for obj in model_objects():
        local = numpy.empty(3 * len(obj.data.vertices), dtype=numpy.float64)
        obj.data.vertices.foreach_get("co", local)
        matrix = numpy.array(obj.matrix_world)
        world = local.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
        parts.append(numpy.stack([world[:, 0], world[:, 2], -world[:, 1]], axis=1))   # Blender (x, y, z) -> Patina
    return numpy.concatenate(parts)


def add_ground(scene):
    """Patina's floor (engine/scene/ground.cpp, groundUnder): a square level with the model's lowest
    point, centred under its box, reaching 6 radii of its bounding sphere each way; its material
    the floor's defaults (docs/FORMATS.md display.groundColor, groundRoughness): base colour 0.5,
    roughness 0.8, metallic 0, specular 0.5."""
    import numpy
    points = world_vertices()
    low, high = points.min(axis=0), points.max(axis=0)
    middle = 0.5 * (low + high)
    half = max(6.0 * 0.5 * float(numpy.linalg.norm(high - low)), 1e-3)
    corners = [patina_to_blender(middle[0] + sx * half, low[1], middle[2] + sz * half)
               for sx, sz in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    mesh_data = bpy.data.meshes.new("ground")
    mesh_data.from_pydata([tuple(c) for c in corners], [], [(0, 1, 2, 3)])
    mesh_data.update()
    if mesh_data.polygons[0].normal.z < 0.0:   # facing up, Blender's +Z
        mesh_data.flip_normals()
    ground = bpy.data.objects.new("ground", mesh_data)
    scene.collection.objects.link(ground)
    material = bpy.data.materials.new("ground")
    material.use_nodes = True
    bsdf = next(node for node in material.node_tree.nodes if node.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Base Color"].default_value = (0.5, 0.5, 0.5, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.8
    bsdf.inputs["Specular"].default_value = 0.5
    bsdf.inputs["Metallic"].default_value = 0.0
    mesh_data.materials.append(material)
    report("ground", f"y={low[1]:.6g} centre=({middle[0]:.6g}, {middle[2]:.6g}) half_size={half:.6g}")


def add_sun(scene, options):
    """A Sun lamp with Eevee's soft shadows; its cascades reach just past the model from the camera."""
    import numpy
    dx, dy, dz, strength, angle = options.sun
    sun = bpy.data.lights.new("sun", "SUN")
    sun.energy = strength   # W/m^2: irradiance on a surface facing it, as Patina's directional intensity
    sun.angle = math.radians(angle)
    sun.use_shadow = True
    sun.use_contact_shadow = False
    points = world_vertices()
    eye = numpy.array(options.camera[0:3])
    reach = float(numpy.linalg.norm(points - eye, axis=1).max())
    radius = 0.5 * float(numpy.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    sun.shadow_cascade_max_distance = reach + radius   # the shadows the model casts on the floor too
    lamp = bpy.data.objects.new("sun", sun)
    scene.collection.objects.link(lamp)
    lamp.rotation_euler = patina_to_blender(dx, dy, dz).to_track_quat("-Z", "Y").to_euler()   # shines along -Z
    scene.eevee.use_soft_shadows = True
    report("eevee_shadow_settings", f"sun strength={sun.energy:g} angle={angle:g}deg "
           f"cascade_size={scene.eevee.shadow_cascade_size} cascades={sun.shadow_cascade_count} "
           f"cascade_max_distance={sun.shadow_cascade_max_distance:.4g} soft_shadows={scene.eevee.use_soft_shadows} "
           f"high_bitdepth={scene.eevee.use_shadow_high_bitdepth}")


def render(options):
    scene = empty_scene(*image_size(options))
    bsdf = import_model(options.model) if options.model else add_sphere(scene, options)
    add_view(scene, options)

    if options.sun:
        add_sun(scene, options)
    if options.ground:
        add_ground(scene)

    eevee = scene.eevee
    if options.samples:
        eevee.taa_render_samples = options.samples
    report("eevee_settings", f"taa_render_samples={eevee.taa_render_samples} "
           f"soft_shadows={eevee.use_soft_shadows} ssr={eevee.use_ssr} gtao={eevee.use_gtao} "
           f"bloom={eevee.use_bloom} gi_cubemap_resolution={eevee.gi_cubemap_resolution} "
           f"gi_filter_quality={eevee.gi_filter_quality:g} view_transform={scene.view_settings.view_transform}")

    scene.render.filepath = options.out
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    first = time.perf_counter() - start
    report("first_image_written_epoch", f"{time.time():.6f}")
    report("first_render_s", f"{first:.4f}")
    import gpu   # only now: before Eevee has made its GL context, asking crashes Blender 3.4
    report("gl_renderer", gpu.platform.renderer_get())

    scene.render.filepath = options.scratch or options.out + ".rerender.png"
    roughness = bsdf.inputs["Roughness"]
    times = []
    for index in range(options.reruns):
        roughness.default_value = [0.5, 0.35, 0.6, 0.3, 0.45][index % 5]
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        times.append(time.perf_counter() - start)
    report("rerender_s", " ".join(f"{t:.4f}" for t in times))
    report("rerender_median_s", f"{statistics.median(times):.4f}")
    return 0


def model_objects():
    return [obj for obj in bpy.data.objects if obj.type == "MESH"]


def bounds(options):
    """The imported model's world-space bounding box, in Patina's axes."""
    empty_scene(8, 8)
    import_model(options.model)
    corners = [obj.matrix_world @ Vector(corner) for obj in model_objects() for corner in obj.bound_box]
    # Blender (x, y, z) is Patina (x, z, -y).
    patina = [(c.x, c.z, -c.y) for c in corners]
    low = [min(p[i] for p in patina) for i in range(3)]
    high = [max(p[i] for p in patina) for i in range(3)]
    report("bounds", " ".join(f"{v:.6g}" for v in low + high))
    return 0


def show_base_color():
    """Every Principled BSDF's output replaced by an Emission of what feeds its Base Color."""
    for material in bpy.data.materials:
        if not material.node_tree:
            continue
        nodes, links = material.node_tree.nodes, material.node_tree.links
        for bsdf in [node for node in nodes if node.type == "BSDF_PRINCIPLED"]:
            emission = nodes.new("ShaderNodeEmission")
            base = bsdf.inputs["Base Color"]
            if base.is_linked:
                links.new(base.links[0].from_socket, emission.inputs["Color"])
            else:
                emission.inputs["Color"].default_value = base.default_value
            for link in list(bsdf.outputs["BSDF"].links):
                links.new(emission.outputs["Emission"], link.to_socket)


def cycles(options):
    """One Cycles render of the model to --out, linear (scene-referred Rec. 709) OpenEXR."""
    width, height = image_size(options)
    scene = empty_scene(width, height)
    if options.model:
        import_model(options.model)
    else:
        add_sphere(scene, options)
    add_view(scene, options)
    scene.render.engine = "CYCLES"
    settings = scene.cycles
    settings.device = "CPU"
    settings.samples = options.samples or 256
    settings.use_adaptive_sampling = False   # the same samples everywhere: noise measured once holds
    settings.use_denoising = False
    settings.seed = options.seed
    # Each pixel at its centre, as Patina's ground truth (and its GPU's texture reads) take it:
    # compare_cycles.sh renders everything at twice the size and shrinks it by a box, which is
    # then the one pixel filter of all three renderers.
    settings.pixel_filter_type = "BOX"
    settings.filter_width = 0.01
    if options.base_color:
        show_base_color()
    if options.local:
        for obj in model_objects():
            obj.visible_diffuse = obj.visible_glossy = obj.visible_transmission = False
            obj.visible_volume_scatter = obj.visible_shadow = False
    distributions = sorted({node.distribution for material in bpy.data.materials if material.node_tree
                            for node in material.node_tree.nodes if node.type == "BSDF_PRINCIPLED"})
    report("cycles_settings", f"samples={settings.samples} max_bounces={settings.max_bounces} "
           f"clamp_direct={settings.sample_clamp_direct:g} clamp_indirect={settings.sample_clamp_indirect:g} "
           f"filter={settings.pixel_filter_type} width={settings.filter_width:g}px seed={settings.seed} "
           f"local={options.local} base_color={options.base_color} "
           f"principled_distribution={','.join(distributions)}")
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.filepath = options.out
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    report("cycles_render_s", f"{time.perf_counter() - start:.2f}")
    return 0


def main():
    options = parse_arguments()
    try:
        if options.probe:
            status = probe(options)
        elif options.bounds:
            status = bounds(options)
        elif options.render_cycles:
            status = cycles(options)
        else:
            status = render(options)
    except Exception as error:   # Blender keeps running after a script's exception: exit non-zero
        import traceback
        traceback.print_exc()
        print(f"blender_render.py: {error}", file=sys.stderr, flush=True)
        status = 1
    sys.stdout.flush()
    sys.exit(status)   # Blender 3.4 in -b mode exits with this status


main()
