"""Imports VDB files into Blender the way its users do (File > Import > OpenVDB, that is
bpy.ops.object.volume_import) and prints what Blender sees in each: the grids with their data
types and channels, the bounding box, and the frames of a sequence. Blender is not a project
dependency; this checks by hand that caches Eikon writes open in it (docs/interop.md records a
run).

Usage (Blender 3.x or 4.x):
    blender --background --factory-startup --python-exit-code 1 \
        --python scripts/blender_import_check.py -- out/plume/smoke_plume_0001.vdb [more.vdb ...]
A file named like name_0001.vdb is imported as a sequence, as Blender's importer does.
Exits non-zero when a file does not import or has no grid.
"""
import os
import sys

import bpy


def files_from_argv():
    if "--" not in sys.argv:
        sys.exit("usage: blender --background --python scripts/blender_import_check.py -- FILE.vdb ...")
    return sys.argv[sys.argv.index("--") + 1:]


def check(path):
    path = os.path.abspath(path)
    before = set(bpy.data.objects)
    bpy.ops.object.volume_import(
        filepath=path,
        directory=os.path.dirname(path),
        files=[{"name": os.path.basename(path)}],
        use_sequence_detection=True,
    )
    added = [o for o in bpy.data.objects if o not in before]
    if not added or added[0].type != "VOLUME":
        print(f"{path}: Blender imported no volume object")
        return False
    volume = added[0].data
    loaded = volume.grids.load()  # the grids are read lazily
    print(f"{path}: Blender {bpy.app.version_string}, object '{added[0].name}', "
          f"sequence: {volume.is_sequence}, frames: "
          f"{volume.frame_duration if volume.is_sequence else 1}, grids read: {loaded}")
    if volume.grids.error_message:
        print(f"  error: {volume.grids.error_message}")
    for grid in volume.grids:
        print(f"  grid '{grid.name}': {grid.data_type}, {grid.channels} channel(s)")
    corners = [tuple(round(c, 4) for c in corner) for corner in added[0].bound_box]
    print(f"  bound box: {corners[0]} .. {corners[6]}")
    return len(volume.grids) > 0 and not volume.grids.error_message


def main():
    ok = all([check(path) for path in files_from_argv()])
    sys.exit(0 if ok else 1)


main()
