"""The Python bindings (python/eikon_module.cpp), run by ctest `python_bindings` with the module on
PYTHONPATH and EIKON_BINARY naming the command line: a render as numpy equals the CLI's image
byte for byte, the live smoke stepped reads as a numpy density, bad scenes raise eikon.Error with
the CLI's one-line message, the GIL is free while a frame renders."""
import os
import pathlib
import subprocess
import threading

import numpy as np
import pytest

import eikon

ROOT = pathlib.Path(__file__).resolve().parents[2]
EIKON = os.environ.get("EIKON_BINARY", str(ROOT / "build" / "apps" / "eikon"))
FOG = str(ROOT / "data" / "scenes" / "glass_sphere_fog.json")
SMOKE = str(ROOT / "data" / "scenes" / "smoke_glass_mesh.json")


def test_a_render_as_numpy_is_the_command_lines_image(tmp_path):
    session = eikon.Session.open(FOG, eikon.Device.CPU)
    session.set_image_size(48, 32)
    image = session.render(0)
    assert image.rgb.shape == (32, 48, 3) and image.rgb.dtype == np.float32
    assert image.srgb8.shape == (32, 48, 3) and image.srgb8.dtype == np.uint8
    assert image.transmittance.shape == (32, 48)
    # A view of the image's memory, not a copy; read-only.
    assert not image.rgb.flags.owndata and not image.rgb.flags.writeable
    image.write(str(tmp_path / "py.png"))
    image.write(str(tmp_path / "py.exr"))
    subprocess.run([EIKON, "render", FOG, "-o", str(tmp_path / "cli.png"), "--size", "48x32",
                    "--backend", "cpu", "--exr", "--quiet"], check=True)
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    assert (tmp_path / "py.exr").read_bytes() == (tmp_path / "cli.exr").read_bytes()
    cli = eikon.read_image(str(tmp_path / "cli.png"))
    assert np.array_equal(cli.srgb8, image.srgb8)
    exr = eikon.read_image(str(tmp_path / "cli.exr"))
    assert np.array_equal(exr.rgb, image.rgb)
    metrics = eikon.compare_images(image, exr)
    assert metrics["max_abs"] == 0.0 and metrics["ssim"] == pytest.approx(1.0)


def test_the_live_smoke_stepped_reads_as_a_numpy_density():
    session = eikon.Session.open(SMOKE, eikon.Device.CPU)
    session.step_to(3)
    assert "density" in session.field_names()
    density, origin = session.field("density")
    assert density.ndim == 3 and density.dtype == np.float32
    assert len(origin) == 3
    assert density.sum() > 0.0 and density.min() >= 0.0


def test_a_bad_scene_raises_eikon_error_with_the_command_lines_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"camera": {"fov": 40}')
    with pytest.raises(eikon.Error) as raised:
        eikon.Session.open(str(bad), eikon.Device.CPU)
    assert isinstance(raised.value, RuntimeError)
    assert str(raised.value).startswith(str(bad) + ":")
    cli = subprocess.run([EIKON, "render", str(bad)], capture_output=True, text=True)
    assert cli.returncode == 1
    assert cli.stderr.strip() == "eikon: " + str(raised.value)
    with pytest.raises(eikon.Error):
        eikon.Session.open(FOG, eikon.Device.CPU).material("no such material")


def test_camera_light_and_material_change_between_frames(tmp_path):
    session = eikon.Session.open(FOG, eikon.Device.CPU)
    session.set_image_size(24, 16)
    first = session.render(0)
    first.write(str(tmp_path / "before.exr"))
    before = np.array(first.rgb)
    light = session.light(0)
    light.intensity *= 2.0
    session.set_light(0, light)
    brighter = session.render(0)
    assert np.array(brighter.rgb).sum() > before.sum()
    metrics = eikon.compare_images(brighter, eikon.read_image(str(tmp_path / "before.exr")))
    assert metrics["max_abs"] > 0.0 and metrics["psnr"] < 100.0
    fog = session.material("fog")
    assert fog.abbe == 0.0  # no dispersion
    assert fog.transfer == []  # the field's value itself
    fog.absorption = [4.0 * a for a in fog.absorption]
    session.set_material(fog)
    assert session.material("fog").absorption[0] == pytest.approx(0.8)
    assert np.array(session.render(0).transmittance).mean() < brighter.transmittance.mean()
    dense = np.array(session.render(0).transmittance).mean()
    fog.transfer = [[0.0, 0.0], [1.0, 2.0]]  # twice the density, up to 1
    session.set_material(fog)
    assert session.material("fog").transfer == [[0.0, 0.0], [1.0, 2.0]]
    assert np.array(session.render(0).transmittance).mean() < dense
    fog.transfer = [[0.0, 1.0], [1.0, 1.0]]
    with pytest.raises(eikon.Error, match="maps 0 to 1"):
        session.set_material(fog)
    fog.transfer = []
    session.set_material(fog)
    assert fog.particle_color_map == "" and fog.particle_color_points == []
    plain = np.array(session.render(0).rgb)
    fog.particle_color_points = [[0.0, 1.0, 0.0, 0.0], [1.0, 1.0, 0.0, 0.0]]  # red particles
    session.set_material(fog)
    red = np.array(session.render(0).rgb)
    assert red[..., 1:].sum() < plain[..., 1:].sum()  # green and blue no longer scattered
    assert red[..., 0].sum() == pytest.approx(plain[..., 0].sum(), rel=1e-5)
    fog.particle_color_points = []
    fog.particle_color_map = "viridiss"
    with pytest.raises(eikon.Error, match="unknown colour map 'viridiss'"):
        session.set_material(fog)
    fog.particle_color_map = "inferno"
    fog.particle_color_range = [0.0, 0.5]
    session.set_material(fog)
    assert session.material("fog").particle_color_range == [0.0, 0.5]
    fog.particle_color_map = ""
    session.set_material(fog)
    session.set_image_size(12, 8)
    smaller = session.render(0)
    with pytest.raises(eikon.Error, match="differ in size"):
        eikon.compare_images(smaller, first)
    session.set_image_size(24, 16)
    camera = session.camera
    camera.horizontal_fov_degrees = 20.0
    session.camera = camera
    assert session.camera.horizontal_fov_degrees == pytest.approx(20.0)


def test_other_threads_run_while_a_frame_renders():
    session = eikon.Session.open(FOG, eikon.Device.CPU)
    session.set_image_size(96, 64)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)

    thread = threading.Thread(target=count)
    thread.start()
    try:
        session.render(0)
    finally:
        stop.set()
        thread.join()
    # With the GIL held for the whole render the counter would barely move.
    assert len(ticks) > 1000


def test_a_field_as_a_pyopenvdb_grid():
    pyopenvdb = pytest.importorskip("pyopenvdb")
    session = eikon.Session.open(SMOKE, eikon.Device.CPU)
    session.step_to(2)
    grid = session.field_pyopenvdb("density")
    assert isinstance(grid, pyopenvdb.FloatGrid)
    density, _ = session.field("density")
    assert grid.activeVoxelCount() >= np.count_nonzero(density)


def test_pyopenvdb_imported_first_does_not_disturb_eikon():
    # Both modules load libopenvdb; each must keep its template copies to itself (see
    # python/module_exports.map), whichever is imported first.
    pytest.importorskip("pyopenvdb")
    script = ("import pyopenvdb, eikon\n"
              f"s = eikon.Session.open({FOG!r}, eikon.Device.CPU)\n"
              "s.set_image_size(24, 16)\n"
              "print(s.render(0).srgb8.sum())\n")
    run = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True,
                         env=dict(os.environ), timeout=120)
    assert run.returncode == 0, run.stderr
    assert int(run.stdout) > 0
