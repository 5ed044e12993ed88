# Writes blender_shafts.glb, the glTF test fixture that Blender's own exporter produces
# (docs/scene-format.md "glTF scenes"). Run once by hand, never by setup or CI:
#
#   blender -b --factory-startup -P tests/data/gltf/make_blender_scene.py -- tests/data/gltf/blender_shafts.glb
#
# Made with Debian's blender 3.4.1 (glTF exporter 3.4.50). Blender is z-up; the exporter
# turns the scene y-up (export_yup). A floor, two columns under a turned empty (a node
# hierarchy), a block, a spot with a soft edge behind the columns, a weak sun, a camera,
# and the fog as the scene's custom property "airlight", which the exporter writes to the
# glTF scene's extras. The exporter needs python3-numpy besides blender.
import math
import sys

import bpy
from mathutils import Vector

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def material(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*rgb, 1.0)
    return m


def box(name, location, size, rgb, rotation_z_deg=0.0, parent=None):
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=location)
    o = bpy.context.object
    o.name = name
    o.scale = size
    o.rotation_euler = (0.0, 0.0, math.radians(rotation_z_deg))
    o.data.materials.append(material(name, rgb))
    if parent is not None:
        o.parent = parent  # its location and rotation now relative to the parent's
    return o


def aim(o, target):
    o.rotation_euler = (Vector(target) - o.location).to_track_quat("-Z", "Y").to_euler()


bpy.ops.mesh.primitive_plane_add(size=10.0, location=(0, 0, 0))
floor = bpy.context.object
floor.name = "Floor"
floor.data.materials.append(material("Floor", (0.6, 0.6, 0.6)))

# The columns hang under an empty turned 10° and moved, so their world transforms compose.
colonnade = bpy.data.objects.new("Colonnade", None)
colonnade.location = (0.0, 0.5, 0.0)
colonnade.rotation_euler = (0.0, 0.0, math.radians(10.0))
scene.collection.objects.link(colonnade)
box("ColumnLeft", (-1.5, 0.0, 1.25), (0.5, 0.5, 2.5), (0.8, 0.7, 0.6), parent=colonnade)
box("ColumnRight", (1.5, 0.0, 1.25), (0.5, 0.5, 2.5), (0.8, 0.7, 0.6), rotation_z_deg=30.0, parent=colonnade)
box("Block", (0.0, 1.8, 0.5), (1.2, 0.6, 1.0), (0.5, 0.6, 0.8))

# Radiant power P: the exporter writes P / (4π) · 683 cd (gltf2_blender_gather_lights.py).
spot = bpy.data.lights.new("Spot", type="SPOT")
spot.energy = 2500.0                 # W: 199 W/sr
spot.spot_size = math.radians(50.0)  # full angle: outer cone 25°
spot.spot_blend = 0.3                # inner cone 25° · (1 − 0.3) = 17.5°
spot_object = bpy.data.objects.new("Spot", spot)
spot_object.location = (0.0, 3.5, 5.0)
scene.collection.objects.link(spot_object)
aim(spot_object, (0.0, 0.0, 0.0))

sun = bpy.data.lights.new("Sun", type="SUN")
sun.energy = 0.3  # W/m²: the exporter writes 0.3 · 683 lux
sun.color = (1.0, 0.9, 0.8)
sun_object = bpy.data.objects.new("Sun", sun)
sun_object.rotation_euler = (math.radians(40.0), 0.0, math.radians(-30.0))
scene.collection.objects.link(sun_object)

camera = bpy.data.cameras.new("Camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = math.radians(50.0)
camera.clip_start = 0.1
camera.clip_end = 40.0
camera_object = bpy.data.objects.new("Camera", camera)
camera_object.location = (0.0, -8.0, 3.0)
scene.collection.objects.link(camera_object)
aim(camera_object, (0.0, 0.5, 1.2))
scene.camera = camera_object

# airlight's fog keys, as in a scene file (docs/scene-format.md).
scene["airlight"] = {
    "medium": {"scattering": 0.08, "absorption": 0.01, "phase": {"type": "henyey_greenstein", "g": 0.3}},
    "ambient": 0.02,
}

bpy.ops.export_scene.gltf(filepath=out, export_format="GLB", export_lights=True, export_cameras=True,
                          export_extras=True, export_yup=True, export_apply=True)
