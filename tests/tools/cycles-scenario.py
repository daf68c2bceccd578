# Renders a glTF render-fidelity scenario with Blender's Cycles, as linear radiance (EXR), for
# docs/fidelity.md's comparison of `facet render --scenario` with an independent path tracer under
# the same lighting. Written for this project from the harness's conventions (docs/fidelity.md):
# orbit angles in degrees around the target (theta about +Y from +Z, phi from +Y), the model in
# its own units, twice the scenario's dimensions, the HDRI unrotated (Blender's equirect mapping
# and Facet's agree once glTF's +Y up is Blender's +Z), film transparent unless renderSkybox.
#
#   blender -b --factory-startup -noaudio -P tests/tools/cycles-scenario.py -- SAMPLES 'JSON'
#
# JSON is the argument `facet render --scenario` takes; its outputFile should end in .exr.
import json
import math
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still says numpy.bool, which NumPy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

arguments = sys.argv[sys.argv.index("--") + 1:]
samples = int(arguments[0])
request = json.loads(arguments[1])
scenario = request["scenario"]
output = request["outputFile"]
dimensions = scenario.get("dimensions", {})
width = int(dimensions.get("width", 768)) * 2
height = int(dimensions.get("height", 768)) * 2
target = scenario.get("target", {})
orbit = scenario.get("orbit", {})
theta = math.radians(orbit.get("theta", 0.0))
phi = math.radians(orbit.get("phi", 90.0))
radius = orbit.get("radius", 1.0)
fov = math.radians(scenario.get("verticalFoV", 45.0))
skybox = scenario.get("renderSkybox", False)


def blender_point(x, y, z):
    # glTF (+Y up) to Blender (+Z up), as the glTF importer converts.
    return Vector((x, -z, y))


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=scenario["model"])
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.render.film_transparent = not skybox
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGBA"

world = bpy.data.worlds.new("Environment")
scene.world = world
world.use_nodes = True
nodes = world.node_tree.nodes
links = world.node_tree.links
nodes.clear()
environment = nodes.new("ShaderNodeTexEnvironment")
environment.image = bpy.data.images.load(scenario["lighting"])
background = nodes.new("ShaderNodeBackground")
world_output = nodes.new("ShaderNodeOutputWorld")
links.new(environment.outputs["Color"], background.inputs["Color"])
links.new(background.outputs["Background"], world_output.inputs["Surface"])

centre = (target.get("x", 0.0), target.get("y", 0.0), target.get("z", 0.0))
direction = (math.sin(phi) * math.sin(theta), math.cos(phi), math.sin(phi) * math.cos(theta))
eye = [centre[i] + radius * direction[i] for i in range(3)]
look = centre if radius > 0 else [centre[i] - direction[i] for i in range(3)]
camera_data = bpy.data.cameras.new("Camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = fov
camera_data.clip_start = 2.0 * max(radius, 1e-5) / 1000.0
camera_data.clip_end = 1000.0 * max(radius, 1.0)
camera = bpy.data.objects.new("Camera", camera_data)
scene.collection.objects.link(camera)
camera.location = blender_point(*eye)
forward = blender_point(*look) - camera.location
camera.rotation_euler = forward.to_track_quat("-Z", "Y").to_euler()
scene.camera = camera

scene.render.filepath = output
bpy.ops.render.render(write_still=True)
