"""Textured models made by tools/make_textured_models.py at test time (Pillow writes the images):
popupcore.load_model reads the texture of an OBJ + MTL (TGA, BMP) and the PNG inside a GLB and
warns, naming the texture and the model, when the image is missing or broken; `popup fit` prints
the texture's colours on the sheets, or says the warning and prints the model grey.

Known answers are the colours the script painted (its BLOCKS), never a decoder's output."""

import base64
import io
import os

import numpy as np
import pytest
from PIL import Image

import popupcore
from cli_runner import DATA_DIR, load_tool, read_report, run_design
from test_cli_fit import UPRIGHT
from test_cli_sheet_artwork import print_layer

textured = load_tool("make_textured_models")
BLOCK_COLOURS = [tuple(rgb) for _, _, rgb in textured.BLOCKS.values()]


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("textured")
    textured.write_all(str(folder))
    return folder


def test_textures_beside_the_model_and_inside_it_load_without_warnings(folder):
    for name, texture in (("cube_tga.obj", "texture.tga"), ("cube_bmp.obj", "texture.bmp")):
        mesh = popupcore.load_model(str(folder / name))
        assert mesh.warnings == [], name
        assert mesh.texture == str(folder / texture)
        assert mesh.uvs.shape == (len(mesh.vertices), 2)
    glb = popupcore.load_model(str(folder / "cube_png.glb"))
    assert glb.warnings == []
    assert (glb.texture, glb.texture_format) == ("*0", "png")
    assert glb.texture_bytes == (folder / "texture.png").read_bytes()


@pytest.mark.parametrize(
    "name, texture, why",
    [
        ("cube_missing.obj", "missing.tga", "cannot open the file"),
        ("cube_corrupt.obj", "corrupt.png", "broken image data (stb_image: "),
    ],
)
def test_an_unreadable_texture_is_a_warning_naming_it_and_the_model(folder, name, texture, why):
    mesh = popupcore.load_model(str(folder / name))
    assert len(mesh.triangles) == 12  # the model itself loads
    (warning,) = mesh.warnings
    assert (warning["code"], warning["severity"]) == ("unreadable_texture", "warning")
    assert warning["message"].startswith(f"{folder / name}: texture {folder / texture}: {why}")
    assert warning["message"].endswith("; its artwork is the shaded base colour")


def printed_pixels(sheets):
    """Every opaque pixel of the images on the sheets' print layers, as an N x 3 array."""
    pixels = []
    for svg in sorted(sheets.glob("*.svg")):
        images, _ = print_layer(svg)
        for image in images:
            href = image.get("href", image.get("{http://www.w3.org/1999/xlink}href"))
            png = base64.b64decode(href.split(",", 1)[1])
            rgba = np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))
            pixels.append(rgba[rgba[..., 3] == 255][:, :3])
    return np.concatenate(pixels) if pixels else np.zeros((0, 3), np.uint8)


def count(pixels, rgb):
    return int(np.all(pixels == np.array(rgb, np.uint8), axis=1).sum())


@pytest.fixture(scope="module")
def fitted(folder, tmp_path_factory):
    """{model: (process, report, printed pixels)} of `popup fit` on the TGA and the missing
    texture's cuboid."""
    runs = {}
    for name in ("cube_tga.obj", "cube_missing.obj"):
        out = tmp_path_factory.mktemp(name.split(".")[0])
        proc = run_design("fit", str(folder / name), str(out), *UPRIGHT, "--seed", "3")
        assert proc.returncode == 0, proc.stdout + proc.stderr
        runs[name] = (proc, read_report(out), printed_pixels(out / "sheets"))
    return runs


def test_popup_fit_prints_the_tga_texture_on_the_sheets(fitted):
    proc, report, pixels = fitted["cube_tga.obj"]
    assert "unreadable_texture" not in proc.stderr
    assert report["model"]["warnings"] == []
    # Textures print unshaded: each block's own colour, over whole areas of the faces.
    for rgb in BLOCK_COLOURS:
        assert count(pixels, rgb) > 1000, rgb


def test_popup_fit_says_the_missing_texture_and_prints_grey(fitted, folder):
    proc, report, pixels = fitted["cube_missing.obj"]
    said = f"{folder / 'cube_missing.obj'}: texture {folder / 'missing.tga'}: cannot open the file"
    assert f"popup fit: warning: unreadable_texture: {said}" in proc.stderr
    assert f"warning: unreadable_texture: {said}; the shaded base colour is used" in proc.stderr
    (warning,) = report["model"]["warnings"]
    assert warning["code"] == "unreadable_texture" and said in warning["message"]
    assert len(pixels) > 1000
    assert all(count(pixels, rgb) == 0 for rgb in BLOCK_COLOURS)
    # The MTL's 0.8 grey, shaded: red, green and blue equal on every printed pixel.
    assert np.all(pixels == pixels[:, :1])


def test_the_committed_test_textures_are_what_the_script_writes(folder):
    # The C++ tests read tests/data/textures: the same files, the same answers. Pillow's image
    # bytes may differ between versions, so the images are compared by their pixels.
    committed = os.path.join(DATA_DIR, "textures")
    names = sorted(p.name for p in folder.iterdir())
    assert sorted(set(os.listdir(committed)) - {"README.md"}) == names
    for name in names:
        written, kept = folder / name, os.path.join(committed, name)
        if name.startswith("texture"):
            with Image.open(written) as a, Image.open(kept) as b:
                same = np.asarray(a.convert("RGBA")).astype(int) - np.asarray(b.convert("RGBA"))
                assert np.abs(same).max() <= 1, name  # JPEG encoders may round apart
        elif name != "cube_png.glb":  # it holds the PNG's bytes
            assert written.read_bytes() == open(kept, "rb").read(), name
