"""crop= and clip_planes= in the Python module: the command line's pictures and messages."""
import numpy as np
import pytest

import ewaview
from conftest import assert_same_picture, differs


@pytest.mark.parametrize("renderer", ["splat", "shearwarp"])
def test_crop_and_planes_equal_the_command_line_picture(cli, renderer):
    scene = ewaview.Scene(synthetic="sphere:32", resolution=(80, 64), renderer=renderer)
    image = scene.render(crop=(-5, 20, -5, 40, 8, 40), clip_planes=[(16, 16, 16, 1, 1, 0)])
    expected = cli.picture(f"clip_{renderer}", "--synthetic", "sphere:32", "--resolution", "80,64",
                           "--renderer", renderer, "--crop", "-5,20,-5,40,8,40",
                           "--clip-plane=16,16,16,1,1,0")
    assert_same_picture(image, expected)
    whole = scene.render()
    assert image.max() > 40 and differs(image, whole)
    # Cut away: fewer lit pixels than the whole ball.
    assert (image.sum(axis=2) > 30).sum() < 0.8 * (whole.sum(axis=2) > 30).sum()


def test_bad_crop_and_planes_raise_the_command_line_s_messages(cli):
    scene = ewaview.Scene(synthetic="sphere:8")
    run = cli.run("--synthetic", "sphere:8", "--crop", "0,1,0,1,0", "--info")
    assert run.returncode == 2
    with pytest.raises(ValueError) as e:
        scene.render(crop=(0, 1, 0, 1, 0))
    assert str(e.value) in run.stderr
    assert "expected 6 comma-separated numbers, got 5" in str(e.value)
    with pytest.raises(ValueError, match="the normal is zero"):
        scene.render(clip_planes=[(0, 0, 0, 0, 0, 0)])
    with pytest.raises(ValueError, match="at most 6 planes"):
        scene.render(clip_planes=[(0, 0, 0, 1, 0, 0)] * 7)
    with pytest.raises(ValueError, match="clip_planes: a list"):
        scene.render(clip_planes="0,0,0,1,0,0")
