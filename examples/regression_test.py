"""A regression test of your own scenes with Eikon's Python module: copy this file, point SCENE at
your scene and FRAMES at the frames that matter, write the references once, commit them.

    PYTHONPATH=build/python /usr/bin/python3 -m pytest examples/regression_test.py
    EIKON_UPDATE_REFERENCES=1 PYTHONPATH=build/python /usr/bin/python3 -m pytest \
        examples/regression_test.py           # (re)write the references, then review them

Images are judged with the metrics of `eikon regress` (docs/regress.md): here the 8-bit picture
may move by one level in a few pixels (a driver's rounding) but must look the same (SSIM).
"""
import os
import pathlib

import pytest

import eikon

ROOT = pathlib.Path(__file__).resolve().parents[1]
SCENE = ROOT / "data" / "scenes" / "light_circling_glass.json"  # a spot light circling a glass ball
FRAMES = [0, 12]
SIZE = (64, 48)
REFERENCES = pathlib.Path(__file__).resolve().parent / "references"
UPDATE = os.environ.get("EIKON_UPDATE_REFERENCES") == "1"


@pytest.fixture(scope="module")
def session():
    # The CPU twin gives the same bytes on every machine; a GPU equals it up to float rounding.
    s = eikon.Session.open(str(SCENE), eikon.Device.CPU)
    s.set_image_size(*SIZE)
    return s


@pytest.mark.parametrize("frame", FRAMES)
def test_frame_looks_as_it_did(session, frame):
    image = session.render(frame)
    reference = REFERENCES / f"{SCENE.stem}_{frame:04d}.png"
    if UPDATE:
        REFERENCES.mkdir(exist_ok=True)
        image.write(str(reference))
        pytest.skip(f"wrote {reference}")
    assert reference.exists(), f"no reference {reference}: run once with EIKON_UPDATE_REFERENCES=1"
    metrics = eikon.compare_images(image, eikon.read_image(str(reference)))
    assert metrics["max_abs"] <= 1.0 / 255.0 + 1e-9, metrics
    assert metrics["ssim"] >= 0.999, metrics
