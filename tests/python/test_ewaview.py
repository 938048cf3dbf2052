"""The Python module against the command line: the same pictures for the same settings, and the
same one-line messages, raised as exceptions, for bad input."""
import json

import numpy as np
import pytest

import ewaview
from conftest import assert_same_picture, differs, read_png

SMALL = dict(resolution=(96, 72))


def cli_words(options):
    """The command-line words for keyword options, written out by hand (not by the module)."""
    words = []
    for key, value in options.items():
        name = "--" + key.replace("_", "-")
        if value is True:
            words.append(name)
        elif isinstance(value, (tuple, list)):
            words += [name, ",".join(str(v) for v in value)]
        else:
            words += [name, str(value)]
    return words


def tooth(shared_data):
    path = shared_data / "tooth" / "tooth.nrrd"
    if not path.exists():
        pytest.skip(f"shared data absent: {path}")
    return path


@pytest.mark.parametrize("options", [
    dict(),
    dict(renderer="shearwarp", preintegrated=True),
    dict(render_mode="mip", camera_position=(200, 120, 300), camera_view_up=(0, 0, 1)),
    dict(shading=True, filter="swan", background=(0.1, 0.2, 0.3), camera_view_angle=40),
    dict(render_mode="xray", xray_map="sum", xray_scale=0.02, camera_orthographic=True),
], ids=["splat", "shearwarp", "mip-camera", "shaded-swan", "xray-ortho"])
def test_render_equals_the_command_line_picture(cli, shared_data, options):
    path = tooth(shared_data)
    options = dict(SMALL, **options)
    scene = ewaview.Scene(path)
    image = scene.render(**options)
    assert image.dtype == np.uint8 and image.shape == (72, 96, 3)
    expected = cli.picture("tooth_" + "_".join(options)[:60], path, *cli_words(options))
    assert_same_picture(image, expected)
    assert image.max() > 40  # not an empty picture that would equal any other empty one


def test_kept_options_and_overrides_are_the_command_line_s(cli):
    scene = ewaview.Scene(synthetic="marschner-lobb:24", **SMALL)
    scene.set(filter="swan", camera_position=(60, 30, 70))
    assert scene.options["filter"] == "swan"
    expected = cli.picture("ml_override", "--synthetic", "marschner-lobb:24", "--resolution",
                           "96,72", "--filter", "swan", "--camera-position", "60,30,70",
                           "--shading")
    assert_same_picture(scene.render(shading=True), expected)
    assert_same_picture(scene.render(shading=np.bool_(True)), expected)
    # The override was for one render only, and switching renderers back and forth works.
    assert differs(scene.render(), expected)
    splat = scene.render()
    assert differs(scene.render(renderer="shearwarp"), splat)
    assert_same_picture(scene.render(), splat)


def test_numpy_array_equals_the_same_voxels_read_as_raw(cli, out_dir):
    z, y, x = np.mgrid[0:20, 0:24, 0:28].astype(np.float64)
    # A ball off centre along x, so a transposed axis would move it.
    ball = np.sqrt((x - 18) ** 2 + ((y - 12) * 1.5) ** 2 + ((z - 10) * 2) ** 2)
    data = np.clip(4000 - 250 * ball, 0, None).astype(np.uint16)
    raw = out_dir / "ball.raw"
    data.tofile(raw)
    scene = ewaview.Scene(data, spacing=(1, 1.5, 2))
    assert scene.info["dims"] == [28, 24, 20] and scene.info["spacing"] == [1, 1.5, 2]
    expected = cli.picture("ball", raw, "--raw-dims", "28,24,20", "--raw-type", "uint16",
                           "--raw-spacing", "1,1.5,2", "--resolution", "96,72")
    image = scene.render(**SMALL)
    assert_same_picture(image, expected)
    assert image.max() > 40
    # A file's spacing replaced, as --spacing does: the raw file read with spacing 1 becomes the
    # same picture.
    plain = ewaview.Scene(raw, raw_dims="28,24,20", raw_type="uint16", spacing=(1, 1.5, 2))
    assert plain.info["spacing"] == [1, 1.5, 2]
    assert_same_picture(plain.render(**SMALL), expected)
    with pytest.raises(ValueError, match="spacing: give it when the scene is made"):
        plain.set(spacing="1,1,1")
    with pytest.raises(ValueError, match="origin goes with an array volume"):
        ewaview.Scene(raw, origin=(0, 0, 0))
    # save_volume writes what --save-volume writes: the same voxels and spacing read back.
    saved = out_dir / "ball.nrrd"
    plain.save_volume(str(saved))
    again = ewaview.Scene(saved)
    assert again.info["spacing"] == [1, 1.5, 2] and np.array_equal(again.array, data)
    # crop= keeps the voxels whose centres lie in the box: x 2..5, y 3..9 (rows 2..6 at 1.5 a
    # row), z -1..4.5 (slices 0..2 at 2 a slice), where they were.
    plain.save_volume(str(out_dir / "part.nrrd"), crop=(2, 5, 3, 9, -1, 4.5))
    part = ewaview.Scene(out_dir / "part.nrrd")
    assert part.info["dims"] == [4, 5, 3] and part.info["origin"] == [2, 3, 0]
    assert np.array_equal(part.array, data[0:3, 2:7, 2:6])
    # As NIfTI (gzip) the same voxels, in the same place.
    plain.save_volume(str(out_dir / "part.nii.gz"), crop=(2, 5, 3, 9, -1, 4.5))
    nifti = ewaview.Scene(out_dir / "part.nii.gz")
    assert nifti.info["dims"] == [4, 5, 3] and nifti.info["spacing"] == [1, 1.5, 2]
    assert np.allclose(nifti.info["origin"], [2, 3, 0])
    assert np.array_equal(nifti.array, data[0:3, 2:7, 2:6])
    with pytest.raises(ValueError, match="keeps no voxel"):
        plain.save_volume(str(out_dir / "none.nrrd"), crop=(40, 50, 0, 1, 0, 1))
    with pytest.raises(ValueError, match="--crop"):
        plain.save_volume(str(out_dir / "none.nrrd"), crop=(5, 2, 0, 1, 0, 1))
    # As OME-TIFF the same voxels, spacing and place (the Plane positions).
    plain.save_volume(str(out_dir / "part.tif"), crop=(2, 5, 3, 9, -1, 4.5))
    tiff = ewaview.Scene(out_dir / "part.tif")
    assert tiff.info["dims"] == [4, 5, 3] and tiff.info["spacing"] == [1, 1.5, 2]
    assert tiff.info["origin"] == [2, 3, 0]
    assert np.array_equal(tiff.array, data[0:3, 2:7, 2:6])
    # NIfTI's patient axes TIFF cannot keep: a warning says so, and the voxels are written.
    with pytest.warns(UserWarning, match="TIFF keeps no patient axes"):
        nifti.save_volume(str(out_dir / "patient.tif"))
    assert np.array_equal(ewaview.Scene(out_dir / "patient.tif").array, nifti.array)
    with pytest.raises(ValueError, match="must end in .nrrd, .nii, .nii.gz, .mha, .mhd, .tif or .tiff"):
        plain.save_volume(str(out_dir / "ball.png"))
    # float64 arrays become float32 volumes; non-contiguous views are copied in [z, y, x] order.
    assert ewaview.Scene(data.astype(np.float64)).info["type"] == "float32"
    flipped = ewaview.Scene(data[:, :, ::-1].copy()).render(**SMALL)
    assert_same_picture(ewaview.Scene(data[:, :, ::-1]).render(**SMALL), flipped)


def test_array_gives_the_voxels_back(shared_data):
    """scene.array: a scene's voxels as loaded, [z, y, x] in the volume's type; an array scene's
    are its own array (a copy), a file's the file's voxels."""
    rng = np.random.default_rng(7)
    for dtype in (np.uint8, np.int16, np.uint16, np.float32):
        data = (rng.random((5, 6, 7)) * 1000).astype(dtype)
        back = ewaview.Scene(data).array
        assert back.dtype == dtype and back.shape == (5, 6, 7)
        assert np.array_equal(back, data)
    # As the loaders read them: int8 as int16, 32- and 64-bit integers and float64 as float32.
    for dtype, kept in ((np.int8, np.int16), (np.int32, np.float32), (np.uint64, np.float32),
                        (np.float64, np.float32)):
        data = (rng.random((5, 6, 7)) * 100).astype(dtype)
        back = ewaview.Scene(data).array
        assert back.dtype == kept and np.array_equal(back, data.astype(kept))
    scene = ewaview.Scene(np.zeros((2, 3, 4), np.uint8))
    scene.array[0, 0, 0] = 9  # a new array each time: the scene's voxels are not touched
    assert scene.array[0, 0, 0] == 0
    raw = shared_data / "engine" / "engine.raw"
    if not raw.exists():
        pytest.skip(f"shared data absent: {raw}")
    engine = ewaview.Scene(shared_data / "engine" / "engine.nhdr").array
    assert engine.shape == (128, 256, 256)
    assert np.array_equal(engine, np.fromfile(raw, np.uint8).reshape(128, 256, 256))


def test_transfer_function_dict_equals_the_tf_file(cli, out_dir):
    tf = {"opacity": [[0, 0], [0.3, 0], [1, 0.6]],
          "color": [[0, 0.2, 0.4, 1], [1, 1, 0.6, 0.1]], "opacity_unit_distance": 2}
    path = out_dir / "tf.json"
    path.write_text(json.dumps(tf))
    scene = ewaview.Scene(synthetic="sphere:24")
    scene.transfer_function = tf
    assert scene.transfer_function["opacity"] == tf["opacity"]
    expected = cli.picture("sphere_tf", "--synthetic", "sphere:24", "--tf", path,
                           "--resolution", "96,72")
    assert_same_picture(scene.render(**SMALL), expected)
    # tf= when the scene is made is --tf.
    assert_same_picture(ewaview.Scene(synthetic="sphere:24", tf=path).render(**SMALL), expected)


def test_presets_change_the_picture():
    scene = ewaview.Scene(synthetic="marschner-lobb:24", **SMALL)
    before = scene.render()
    assert "CT bone" in ewaview.presets()
    scene.transfer_function = "Viridis (colour map)"
    after = scene.render()
    assert differs(before, after)
    with pytest.raises(ValueError, match="no such"):
        scene.transfer_function = "no such preset"
    # The command line's keys name them too.
    scene.transfer_function = "viridis"
    assert_same_picture(scene.render(), after)


def test_tf_preset_list_is_the_command_line_s_in_order(cli, shared_data):
    bonsai = shared_data / "bonsai" / "bonsai.nhdr"
    if not bonsai.exists():
        pytest.skip("shared data absent")
    expected = cli.picture("tf_presets", bonsai, "--tf-preset", "mr", "--tf-preset", "inferno",
                           "--resolution", "96,72")
    image = ewaview.Scene(bonsai, tf_preset=["mr", "inferno"]).render(**SMALL)
    assert_same_picture(image, expected)
    assert differs(image, ewaview.Scene(bonsai, tf_preset="mr").render(**SMALL))
    with pytest.raises(ValueError, match="--tf-preset: bone not in"):
        ewaview.Scene(bonsai, tf_preset="bone")


def test_repr_png_is_the_rendered_picture():
    scene = ewaview.Scene(synthetic="sphere:16", **SMALL)
    assert_same_picture(read_png(scene._repr_png_())[:, :, :3], scene.render())
    assert repr(scene) == "<ewaview.Scene sphere:16 16x16x16 uint8>"


def message(run):
    """The command line's one error line without the program name and usage hint."""
    line = run.stderr.strip()
    assert "\n" not in line
    return line.removeprefix("ewaview: ").removesuffix(" (see --help)")


def test_bad_input_raises_the_command_line_s_messages(cli, out_dir):
    missing = out_dir / "no-such-volume.nrrd"
    run = cli.run(missing, "--info")
    assert run.returncode == 1
    with pytest.raises(RuntimeError) as e:
        ewaview.Scene(missing)
    assert str(e.value) == message(run)

    run = cli.run("--synthetic", "sphere:8", "--cutoff", "-1", "--info")
    assert run.returncode == 2
    scene = ewaview.Scene(synthetic="sphere:8")
    with pytest.raises(ValueError) as e:
        scene.set(cutoff=-1)
    assert str(e.value) == message(run)
    with pytest.raises(ValueError) as e:
        scene.render(render_mode="blurry")
    assert str(e.value) == message(cli.run("--render-mode", "blurry"))
    with pytest.raises(ValueError, match="not-an-option"):
        scene.render(not_an_option=1)
    assert "cutoff" not in scene.options  # a rejected set() keeps nothing

    with pytest.raises(ValueError, match="output: not an option"):
        scene.render(output="x.png")
    with pytest.raises(ValueError, match="tf: give it when the scene is made"):
        scene.set(tf="x.json")
    with pytest.raises(ValueError, match="opacity"):
        scene.transfer_function = {"opacity": [[0, 2.5]]}
    with pytest.raises(ValueError, match="dtype complex64"):
        ewaview.Scene(np.zeros((2, 2, 2), np.complex64))
    with pytest.raises(ValueError, match="3 dimensions"):
        ewaview.Scene(np.zeros((2, 2), np.uint8))
    with pytest.raises(ValueError, match="spacing must be positive"):
        ewaview.Scene(np.zeros((2, 2, 2), np.uint8), spacing=(1, -1, 1))
    with pytest.raises(ValueError, match="spacing: needs three numbers"):
        ewaview.Scene(np.zeros((2, 2, 2), np.uint8), spacing=(1, 1))


def test_pick_is_what_the_command_line_prints(cli):
    scene = ewaview.Scene(synthetic="sphere:32", resolution=(80, 60),
                          camera_focal_point=(27, 6, 15.5), camera_position=(27, 6, 110))
    for x, y, extra in [(20, 15, {}), (70, 50, {}), (20, 15, dict(render_mode="mip"))]:
        words = ["--synthetic", "sphere:32", "--resolution", "80,60", "--camera-focal-point",
                 "27,6,15.5", "--camera-position", "27,6,110", "--pick", f"{x},{y}"]
        run = cli.run(*words, *cli_words(extra))
        assert run.returncode == 0, run.stderr
        expected = json.loads(run.stdout)
        got = scene.pick(x, y, **extra)
        assert got == expected
    # The ball is in the upper left, the background in the lower right.
    assert scene.pick(20, 15)["hit"] and not scene.pick(70, 50)["hit"]
    assert set(scene.pick(20, 15)) == {"pixel", "hit", "world", "index", "voxel", "value",
                                       "opacity", "distance"}
    with pytest.raises(ValueError, match="outside the 80x60 picture"):
        scene.pick(80, 10)
    with pytest.raises(ValueError, match="pick: not an option"):
        scene.render(pick=(1, 1))


def test_axis_is_the_command_line_s_and_only_paints_the_corner(cli):
    options = dict(resolution=(96, 72), camera_position=(70, -40, 50), camera_view_up=(0, 0, 1))
    scene = ewaview.Scene(synthetic="sphere:32", **options)
    plain, axes = scene.render(), scene.render(axis=True)
    expected = cli.picture("sphere_axis", "--synthetic", "sphere:32", "--axis",
                           *cli_words(options))
    assert_same_picture(axes, expected)
    changed = np.argwhere((axes != plain).any(axis=2))
    assert len(changed) > 60
    assert changed[:, 0].min() >= 72 // 4 and changed[:, 1].min() >= 96 // 3  # bottom right


def test_turntable_writes_what_the_command_line_writes(cli, out_dir):
    scene = ewaview.Scene(synthetic="marschner-lobb:24", resolution=(48, 40))
    scene.turntable(out_dir / "py_turn", frames=3, renderer="shearwarp")
    run = cli.run("--synthetic", "marschner-lobb:24", "--resolution", "48,40", "--renderer",
                  "shearwarp", "--turntable", 3, "--output", out_dir / "cli_turn")
    assert run.returncode == 0, run.stderr
    for f in range(3):
        name = f"frame_{f:03d}.png"
        assert (out_dir / "py_turn" / name).read_bytes() == (out_dir / "cli_turn" / name).read_bytes()
    scene.turntable(str(out_dir / "py_turn.mp4"), frames=4, fps=10)
    assert (out_dir / "py_turn.mp4").read_bytes()[4:8] == b"ftyp"  # an MP4 (decoded in C++ tests)
    with pytest.raises(RuntimeError, match="not a video format"):
        scene.turntable(str(out_dir / "x.avi"), frames=2)


def test_tour_writes_what_the_command_line_writes(cli, out_dir):
    marks = {"bookmarks": [
        {"name": "front", "position": [11.5, 11.5, 80], "focal_point": [11.5, 11.5, 11.5],
         "view_up": [0, 1, 0], "view_angle": 30, "orthographic": False},
        {"name": "side", "position": [70, 11.5, 11.5], "focal_point": [11.5, 11.5, 11.5],
         "view_up": [0, 1, 0], "view_angle": 30, "orthographic": False,
         "clip": {"crop": {"enabled": True, "min": [0, 0, 0], "max": [23, 23, 11]}}}]}
    bookmarks = out_dir / "ml.bookmarks.json"
    bookmarks.write_text(json.dumps(marks))
    scene = ewaview.Scene(synthetic="marschner-lobb:24", resolution=(48, 40))
    scene.tour(out_dir / "py_tour", frames=3, bookmarks=bookmarks)
    run = cli.run("--synthetic", "marschner-lobb:24", "--resolution", "48,40", "--tour", 3,
                  "--bookmarks", bookmarks, "--output", out_dir / "cli_tour")
    assert run.returncode == 0, run.stderr
    frames = []
    for f in range(3):
        name = f"frame_{f:03d}.png"
        frames.append(read_png((out_dir / "py_tour" / name).read_bytes()))
        assert_same_picture(frames[-1], read_png((out_dir / "cli_tour" / name).read_bytes()))
    assert differs(frames[0], frames[1]) and differs(frames[1], frames[2])
    # A synthetic volume's bookmarks would be where the window keeps them (the settings folder).
    with pytest.raises(RuntimeError, match="bookmarks/synthetic-marschner-lobb:24.*no such"):
        scene.tour(out_dir / "none", frames=3)
    with pytest.raises(ValueError, match="takes the crop box and planes of its bookmarks"):
        scene.tour(out_dir / "none", frames=3, bookmarks=bookmarks, crop=(0, 5, 0, 5, 0, 5))


def test_write_png_round_trips(out_dir):
    image = (np.arange(5 * 7 * 3) % 256).astype(np.uint8).reshape(5, 7, 3)
    ewaview.write_png(str(out_dir / "array.png"), image)
    assert np.array_equal(read_png((out_dir / "array.png").read_bytes()), image)
    with pytest.raises(ValueError, match="uint8 array"):
        ewaview.write_png(str(out_dir / "bad.png"), np.zeros((4, 4), np.uint8))


def test_the_module_imports_with_only_pythonpath_set():
    import os
    import subprocess
    import sys
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": os.path.dirname(ewaview.__file__)}
    run = subprocess.run([sys.executable, "-c", "import ewaview; print(ewaview.__version__)"],
                         env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == ewaview.__version__


def test_shear_warp_draws_perspective_without_a_note():
    # 64 pixels across: at 32 the few percent wider silhouette is one ring of fringe pixels.
    scene = ewaview.Scene(synthetic="sphere:16", resolution=(64, 64), renderer="shearwarp")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        perspective = scene.render(camera_view_angle=60)
        parallel = scene.render(camera_view_angle=60, camera_orthographic=True)
    # The sphere's silhouette seen from near is wider than its parallel outline.
    assert (perspective.sum(axis=2) > 20).sum() > 1.05 * (parallel.sum(axis=2) > 20).sum()


def test_renders_in_threads_equal_renders_in_turn():
    from concurrent.futures import ThreadPoolExecutor
    scenes = [ewaview.Scene(synthetic=s, **SMALL) for s in ("sphere:16", "marschner-lobb:16")]
    alone = [s.render() for s in scenes] + [scenes[0].render(renderer="shearwarp",
                                                             camera_orthographic=True)]
    with ThreadPoolExecutor(3) as pool:
        together = list(pool.map(lambda job: job(), [
            scenes[0].render, scenes[1].render,
            lambda: scenes[0].render(renderer="shearwarp", camera_orthographic=True)]))
    for a, b in zip(alone, together):
        assert_same_picture(a, b)


def two_channel_nrrd(path):
    """Two overlapping balls, one a channel, in a 4D NRRD whose first axis is the channel."""
    z, y, x = np.mgrid[0:20, 0:20, 0:20]
    balls = [((x - cx) ** 2 + (y - 9.5) ** 2 + (z - 9.5) ** 2 < 25) * 200 for cx in (7, 12)]
    data = np.stack(balls, axis=-1).astype(np.uint8)
    path.write_bytes(b"NRRD0004\ntype: uint8\ndimension: 4\nsizes: 2 20 20 20\n"
                     b"kinds: 2-vector domain domain domain\nencoding: raw\n\n" + data.tobytes())
    return path


def test_channel_all_overlays_as_the_command_line_does(cli, out_dir):
    path = two_channel_nrrd(out_dir / "two_balls.nrrd")
    scene = ewaview.Scene(path, channel="all")
    image = scene.render(**SMALL)
    expected = cli.picture("two_balls_all", path, "--channel", "all", "--resolution", "96,72")
    assert_same_picture(image, expected)
    assert len(scene.transfer_functions) == 2
    assert_same_picture(ewaview.Scene(path, channel=(1, 0)).render(**SMALL), image)  # a list
    # Channel 1 drawn white instead of green: the picture changes, channel 0's function stays.
    tf = scene.transfer_functions[1]
    tf["color"] = [[0, 1, 1, 1]]
    scene.set_transfer_function(tf, channel=1)
    assert scene.transfer_functions[1]["color"] == [[0, 1, 1, 1]]
    assert scene.transfer_function == scene.transfer_functions[0]
    assert differs(scene.render(**SMALL), image)
    with pytest.raises(IndexError, match="channel 2"):
        scene.set_transfer_function(tf, channel=2)
    scene.turntable(out_dir / "two_balls_turn", frames=2, **SMALL)
    assert_same_picture(read_png((out_dir / "two_balls_turn" / "frame_000.png").read_bytes())[:, :, :3],
                        scene.render(**SMALL))
