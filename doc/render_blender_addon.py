"""The README's picture of the add-on's result, rendered headless:

  blender -b --factory-startup --python doc/render_blender_addon.py -- ADDON.zip MESH.off OUT.png [y|z [TURN]]

(y|z: the mesh's up axis, y by default; TURN: the model's turn about the
vertical, in radians, 0 by default)

Installs the add-on's zip, loads the mesh, runs "Unwrap with optimized seams"
with its defaults, and renders with Workbench: a checker texture through the
new UVs and the seams the add-on marked as orange tubes. Left: the mesh;
right: its UV layout (drawn as a flat mesh at the UVs)."""
import math
import os
import sys

import bpy
import numpy as np
from mathutils import Vector

args = sys.argv[sys.argv.index("--") + 1:]
zip_path, mesh_path, out_path = args[:3]
up = args[3] if len(args) > 3 else "y"

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="uv_unwrap_seams")

# the mesh (OFF), upright, unit size
tokens = [t for line in open(mesh_path) for t in line.split("#")[0].split()]
n, m = int(tokens[1]), int(tokens[2])
V = np.array(tokens[4:4 + 3 * n], dtype=float).reshape(n, 3)
faces, i = [], 4 + 3 * n
for _ in range(m):
    k = int(tokens[i])
    faces.append([int(x) for x in tokens[i + 1:i + 1 + k]])
    i += 1 + k
if up == "y":  # Blender's up is z
    V = V[:, [0, 2, 1]] * np.array([1.0, -1.0, 1.0])
V = (V - V.mean(axis=0)) / np.ptp(V, axis=0).max()
mesh = bpy.data.meshes.new("model")
mesh.from_pydata(V.tolist(), [], faces)
obj = bpy.data.objects.new("model", mesh)
bpy.context.scene.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
obj.select_set(True)
for p in mesh.polygons:
    p.use_smooth = True

assert bpy.ops.uv.unwrap_optimized_seams() == {'FINISHED'}

# checker texture through the UVs
image = bpy.data.images.new("checker", 1024, 1024)
image.generated_type = 'UV_GRID'
material = bpy.data.materials.new("checker")
material.use_nodes = True
node = material.node_tree.nodes.new("ShaderNodeTexImage")
node.image = image
bsdf = material.node_tree.nodes["Principled BSDF"]
material.node_tree.links.new(node.outputs["Color"], bsdf.inputs["Base Color"])
obj.data.materials.append(material)

# the seams as tubes
seam_edges = [e.vertices[:] for e in mesh.edges if e.use_seam]
seam_mesh = bpy.data.meshes.new("seams")
seam_mesh.from_pydata(V.tolist(), seam_edges, [])
seams = bpy.data.objects.new("seams", seam_mesh)
bpy.context.scene.collection.objects.link(seams)
bpy.ops.object.select_all(action='DESELECT')
seams.select_set(True)
bpy.context.view_layer.objects.active = seams
bpy.ops.object.convert(target='CURVE')
seams.data.bevel_depth = 0.004
orange = bpy.data.materials.new("seam")
orange.diffuse_color = (1.0, 0.35, 0.0, 1.0)
seams.data.materials.append(orange)

# the UV layout as a flat mesh beside the model, same checker
uv = np.empty(2 * len(mesh.loops), dtype=np.float32)
mesh.uv_layers.active.data.foreach_get("uv", uv)
uv = uv.reshape(-1, 2)
flat_V, flat_F = [], []
for p in mesh.polygons:
    ids = []
    for l in p.loop_indices:
        ids.append(len(flat_V))
        flat_V.append((0.75 + uv[l][0], 0.0, uv[l][1] - 0.5))
    flat_F.append(ids)
flat_mesh = bpy.data.meshes.new("layout")
flat_mesh.from_pydata(flat_V, [], flat_F)
layer = flat_mesh.uv_layers.new(name="UVMap")
layer.data.foreach_set("uv", uv.ravel())
flat_mesh.materials.append(material)
flat = bpy.data.objects.new("layout", flat_mesh)
bpy.context.scene.collection.objects.link(flat)

# a three-quarter view of the model, turned toward the side its seams are on
turn = float(args[4]) if len(args) > 4 else 0.0
obj.rotation_euler[2] = seams.rotation_euler[2] = turn

# camera and Workbench
scene = bpy.context.scene
camera_data = bpy.data.cameras.new("camera")
camera_data.type = 'ORTHO'
camera_data.ortho_scale = 2.6
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
camera.location = (0.6, -5.0, 0.0)
camera.rotation_euler = (math.pi / 2, 0.0, 0.0)
scene.camera = camera
scene.render.engine = 'BLENDER_WORKBENCH'
scene.display.shading.light = 'STUDIO'
scene.display.shading.color_type = 'TEXTURE'
scene.display.shading.show_cavity = False
scene.render.resolution_x, scene.render.resolution_y = 1000, 500
scene.render.image_settings.compression = 100
scene.render.film_transparent = False
scene.render.filepath = os.path.abspath(out_path)
bpy.ops.render.render(write_still=True)
print("wrote", out_path)
