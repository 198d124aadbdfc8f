# Runs inside Blender (blender -b --factory-startup -P cycles_render.py -- SCENE.gltf OUT.exr W H SPP):
# imports Inlay's glTF export and renders it with Cycles under the same model as Inlay's path
# tracer: Lambertian room and diffuse objects (a Diffuse BSDF instead of the Principled BSDF,
# whose Disney diffuse and 0.5 specular are not Lambertian), emitters as exported, the exported
# camera with its principal point, 8 bounces, no clamping, no denoising, the same pixel
# filter (box, 1 px: Inlay's), linear float EXR.
import json
import sys

import bpy
import numpy

# Debian's Blender 3.4 glTF importer still uses numpy.bool, which Debian's numpy (1.24) removed:
# restore the alias before importing.
if "bool" not in vars(numpy):
    numpy.bool = bool

argv = sys.argv[sys.argv.index("--") + 1:]
gltf_path, out_path = argv[0], argv[1]
width, height, spp = int(argv[2]), int(argv[3]), int(argv[4])
threads = int(argv[5]) if len(argv) > 5 else 0

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=gltf_path)
scene = bpy.context.scene
doc = json.load(open(gltf_path))
extras = doc["cameras"][0]["extras"]

# Camera: the exported one, with the photo's focal length and principal point.
cam = next(o for o in scene.objects if o.type == "CAMERA")
scene.camera = cam
W, H = extras["width_px"], extras["height_px"]
cam.data.sensor_fit = "HORIZONTAL" if W >= H else "VERTICAL"
cam.data.sensor_width = 36.0
cam.data.sensor_height = 36.0
cam.data.lens = extras["focal_px"] * 36.0 / max(W, H)
cx, cy = extras["principal_px"]
cam.data.shift_x = (W / 2 - cx) / max(W, H)
cam.data.shift_y = (cy - H / 2) / max(W, H)


def to_lambert(mat):
    """Principled BSDF without transmission, metal or emission -> Diffuse BSDF on the same colour."""
    nt = mat.node_tree
    p = next((n for n in nt.nodes if n.type == "BSDF_PRINCIPLED"), None)
    if p is None:
        return "none"
    emission = p.inputs["Emission Strength"].default_value
    emission_colour = p.inputs["Emission"]
    if emission > 0 and (emission_colour.is_linked or max(emission_colour.default_value[:3]) > 0):
        # An emitter: black base, emission as exported (colour x strength).
        p.inputs["Base Color"].default_value = (0, 0, 0, 1)
        p.inputs["Specular"].default_value = 0.0
        return "emitter %.4g" % emission
    # Inlay's diffuse exports roughness 1 and no metal or transmission; anything else (glossy,
    # metal, glass) keeps the Principled BSDF, the nearest Cycles has to Inlay's models.
    if (p.inputs["Metallic"].default_value > 0.5 or p.inputs["Transmission"].default_value > 0.5
            or p.inputs["Roughness"].default_value < 0.999):
        return "kept"
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Roughness"].default_value = 0.0  # Lambert
    base = p.inputs["Base Color"]
    if base.is_linked:
        nt.links.new(base.links[0].from_socket, d.inputs["Color"])
    else:
        d.inputs["Color"].default_value = base.default_value
    nt.links.new(d.outputs["BSDF"], out.inputs["Surface"])
    return "lambert"


for mat in bpy.data.materials:
    if mat.use_nodes:
        print("material", mat.name, to_lambert(mat))

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
c.samples = spp
c.use_adaptive_sampling = False
c.use_denoising = False
c.max_bounces = 8
c.diffuse_bounces = 8
c.glossy_bounces = 8
c.transmission_bounces = 8
c.transparent_max_bounces = 8
c.caustics_reflective = True
c.caustics_refractive = True
c.sample_clamp_direct = 0.0
c.sample_clamp_indirect = 0.0
c.blur_glossy = 0.0
c.pixel_filter_type = "BOX"  # Inlay averages each pixel's square
c.filter_width = 1.0
c.seed = 1
if threads > 0:
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
scene.view_settings.view_transform = "Standard"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
print("rendered", out_path)
