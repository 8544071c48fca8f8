# Blender's Line Art on one OBJ model, timed as tools/bench_lineart.sh compares it with
# haloplot's hidden-line stage. Run by Blender, not by Python:
#   blender -b --factory-startup -t THREADS --python tools/bench_lineart.py -- \
#       MODEL.obj AZ EL RUNS OUT.txt
# The model is read as haloplot reads an OBJ (y up, turned to z up: world = (x, -z, y)) and
# seen through an orthographic camera along haloplot's --view AZ,EL direction
# (core/include/haloplot/view/projection.h: screen x along (cos az, -sin az, 0), screen y along
# (sin az sin el, cos az sin el, cos el), toward the viewer w = ex x ey). A Grease Pencil
# object's Line Art modifier draws the model's visible lines: contours, every edge whose faces
# are not flat (crease threshold 179.9 degrees, as haloplot keeps every edge but flat ones),
# and the lines where faces cross (haloplot draws them by default). Each run tags the Grease
# Pencil object and re-evaluates the dependency graph, so only the modifier runs again; the
# mesh is not rebuilt. The mesh is evaluated first with the modifier off; then the modifier's
# first evaluation in the process is timed ("first": Line Art's code run for the first time,
# as haloplot's stage is in a fresh `plot`), then RUNS runs that each evaluate twice, Line
# Art's default (back faces kept), then with back-face culling (the same lines on a closed
# mesh, less work): warm, as a user's Blender re-evaluates it. OUT.txt gets one line an
# evaluation: "first|default|culled eval_wall_ms eval_cpu_ms", then the strokes and points
# drawn each way. Blender's own timers (bpy.app.debug_value 4000) print Line Art's loading,
# intersection and total times on standard output, one set an evaluation in the same order;
# the shell script reads them from there.
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector


def read_obj(path):
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                x, y, z = (float(t) for t in line.split()[1:4])
                verts.append((x, -z, y))
            elif line.startswith("f "):
                faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return verts, faces


def add_camera(scene, verts, az_deg, el_deg):
    az, el = math.radians(az_deg), math.radians(el_deg)
    ex = Vector((math.cos(az), -math.sin(az), 0))
    ey = Vector((math.sin(az) * math.sin(el), math.cos(az) * math.sin(el), math.cos(el)))
    w = ex.cross(ey)
    lo = Vector([min(v[a] for v in verts) for a in range(3)])
    hi = Vector([max(v[a] for v in verts) for a in range(3)])
    centre, radius = (lo + hi) / 2, (hi - lo).length / 2
    data = bpy.data.cameras.new("camera")
    data.type = "ORTHO"
    data.ortho_scale = 2.2 * radius  # the whole model in frame, as haloplot fits it
    data.clip_start = 0.01 * radius
    data.clip_end = 10 * radius
    camera = bpy.data.objects.new("camera", data)
    eye = centre + 3 * radius * w
    # A camera looks along its -z with its y up: columns ex, ey, w.
    camera.matrix_world = Matrix(
        ((ex.x, ey.x, w.x, eye.x), (ex.y, ey.y, w.y, eye.y), (ex.z, ey.z, w.z, eye.z), (0, 0, 0, 1))
    )
    scene.collection.objects.link(camera)
    scene.camera = camera
    scene.render.resolution_x = scene.render.resolution_y = 2000


def add_line_art(scene, model):
    gpd = bpy.data.grease_pencils.new("lines")
    layer = gpd.layers.new("lines")
    layer.frames.new(scene.frame_current)
    ink = bpy.data.materials.new("ink")
    bpy.data.materials.create_gpencil_data(ink)
    gpd.materials.append(ink)
    lines = bpy.data.objects.new("lines", gpd)
    scene.collection.objects.link(lines)
    md = lines.grease_pencil_modifiers.new("line art", "GP_LINEART")
    md.source_type = "OBJECT"
    md.source_object = model
    md.target_layer = "lines"
    md.target_material = ink
    md.use_contour = md.use_crease = md.use_intersection = True
    md.crease_threshold = math.radians(179.9)
    md.use_multiple_levels = False
    md.level_start = 0  # visible lines only: haloplot's hidden-removed
    return lines


def main():
    args = sys.argv[sys.argv.index("--") + 1 :]
    path, az, el, runs, out = args[0], float(args[1]), float(args[2]), int(args[3]), args[4]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    verts, faces = read_obj(path)
    mesh = bpy.data.meshes.new("model")
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    model = bpy.data.objects.new("model", mesh)
    scene.collection.objects.link(model)
    add_camera(scene, verts, az, el)
    lines = add_line_art(scene, model)
    md = lines.grease_pencil_modifiers[0]
    md.show_viewport = False  # the mesh's own first evaluation, without Line Art
    depsgraph = bpy.context.evaluated_depsgraph_get()
    depsgraph.update()
    md.show_viewport = True
    drawn = {}
    with open(out, "w") as f:
        warm = [(s, s) for _ in range(runs) for s in ("default", "culled")]
        evaluations = [("first", "default")] + warm
        for name, setting in evaluations:
            md.use_back_face_culling = setting == "culled"
            lines.update_tag(refresh={"DATA"})
            bpy.app.debug_value = 4000  # Line Art's own timers, this evaluation
            t0, c0 = time.perf_counter(), time.process_time()
            depsgraph.update()
            t1, c1 = time.perf_counter(), time.process_time()
            bpy.app.debug_value = 0
            f.write("%s %.3f %.3f\n" % (name, (t1 - t0) * 1000, (c1 - c0) * 1000))
            if name not in drawn:
                data = lines.evaluated_get(depsgraph).data
                strokes = [s for l in data.layers for fr in l.frames for s in fr.strokes]
                drawn[name] = (len(strokes), sum(len(s.points) for s in strokes))
        for setting, (strokes, points) in drawn.items():
            f.write("drawn %s strokes %d points %d\n" % (setting, strokes, points))


main()
