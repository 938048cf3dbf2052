"""The module's __version__ is the newest release CHANGELOG.md names."""
import pathlib
import re

import ewaview


def test_version_is_the_changelogs_newest_release():
    changelog = pathlib.Path(__file__).resolve().parents[2] / "CHANGELOG.md"
    releases = re.findall(r"^## \[(\d+\.\d+\.\d+)\]", changelog.read_text(), re.MULTILINE)
    assert releases, "CHANGELOG.md has no '## [X.Y.Z]' heading"
    assert ewaview.__version__ == releases[0]
