# Makes the MikkTSpace reference meshes of core.mesh.BlenderTangents: Blender's own primitives
# (and a seeded, bumpy, anisotropically mapped grid; a mirrored half of Suzanne), triangulated and
# exported as binary glTF with the tangents Blender computes (its MikkTSpace, mesh.calc_tangents),
# so that the test compares this project's tangent frames with an independent implementation on the
# very same vertices. Run outside CI, with Blender 3.4 (Debian 12: apt-get install blender):
#
#   blender --background --factory-startup --python make-blender-tangents.py -- OUT_DIR
#
# and commit OUT_DIR/*.glb. Blender's version goes into each file's asset.generator.
import math
import random
import sys

import bmesh
import bpy

out_dir = sys.argv[sys.argv.index("--") + 1]


def clear():
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def finish(name, smooth=True):
    obj = bpy.context.active_object
    if smooth:
        bpy.ops.object.shade_smooth()
    else:
        bpy.ops.object.shade_flat()
    triangulate = obj.modifiers.new("triangulate", "TRIANGULATE")
    triangulate.quad_method = "FIXED"  # the same diagonals every run
    bpy.ops.object.modifier_apply(modifier=triangulate.name)
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
    bpy.ops.export_scene.gltf(
        filepath=f"{out_dir}/{name}.glb",
        export_format="GLB",
        use_selection=True,
        export_normals=True,
        export_texcoords=True,
        export_tangents=True,
        export_materials="NONE",
        export_colors=False,
        export_apply=True,
    )
    print(f"{name}: {len(obj.data.vertices)} vertices, {len(obj.data.polygons)} triangles")


def uv_sphere():
    clear()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=8, calc_uvs=True)
    finish("uv-sphere")


def torus():
    clear()
    bpy.ops.mesh.primitive_torus_add(major_segments=24, minor_segments=10, generate_uvs=True)
    finish("torus")


def suzanne():
    clear()
    bpy.ops.mesh.primitive_monkey_add(calc_uvs=True)
    finish("suzanne")


def mirrored_suzanne():
    # The right half kept and mirrored onto the left, the two halves sharing their uv, as
    # artists mirror a model: the left half's triangles are uv-mirrored (handedness -1) and
    # meet the right half's on the centre line.
    clear()
    bpy.ops.mesh.primitive_monkey_add(calc_uvs=True)
    obj = bpy.context.active_object
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    bmesh.ops.delete(bm, geom=[v for v in bm.verts if v.co.x < -1e-4], context="VERTS")
    bm.to_mesh(obj.data)
    bm.free()
    mirror = obj.modifiers.new("mirror", "MIRROR")
    mirror.use_mirror_u = False
    mirror.use_clip = True
    bpy.ops.object.modifier_apply(modifier=mirror.name)
    finish("suzanne-mirrored")


def flat_cube():
    clear()
    bpy.ops.mesh.primitive_cube_add(calc_uvs=True)
    finish("cube-flat", smooth=False)


def bumpy_grid():
    # Seeded heights and a uv stretched 3:1 and sheared: tangents that are not the grid's axes.
    clear()
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=14, y_subdivisions=14, calc_uvs=True)
    obj = bpy.context.active_object
    rng = random.Random(31)
    for v in obj.data.vertices:
        v.co.z = 0.15 * rng.uniform(-1.0, 1.0) + 0.2 * math.sin(3.0 * v.co.x)
    for loop in obj.data.uv_layers.active.data:
        u, v = loop.uv
        loop.uv = (3.0 * u + 0.4 * v, v)
    finish("grid-bumpy")


for make in (uv_sphere, torus, suzanne, mirrored_suzanne, flat_cube, bumpy_grid):
    make()
