"""rollspin.load(FILE) accepts an output rollspin wrote (issue 53): the scene
it remembers, validated by the same loader, with the job's scene name."""
import pytest

import rollspin

from conftest import run_cli


def test_load_accepts_a_still_and_a_timeline(tmp_path):
    png = tmp_path / "fig.png"
    run_cli("render", "torus", "--still", "--width", "64", "--height", "48", "-o", png)
    scene = rollspin.load(png)
    assert scene.name == "torus"
    assert scene.source.endswith("fig.png[rollspin:scene]")
    # The same scene as the CLI prints (the first line names the source).
    assert scene.toml().split("\n", 1)[1] == rollspin.loads(run_cli("scene", "--from", png)).toml().split("\n", 1)[1]
    assert scene.length == pytest.approx(rollspin.load("torus").length, rel=1e-15)
    csv = tmp_path / "t.csv"
    run_cli("timeline", "lollipop", "--set", "ball.radius=0.5", "-o", csv)
    assert rollspin.load(csv).ball_radius == 0.5


def test_load_of_an_output_without_metadata_is_a_scene_error(tmp_path):
    png = tmp_path / "bare.png"
    run_cli("render", "torus", "--still", "--width", "64", "--height", "48", "--no-metadata", "-o", png)
    with pytest.raises(rollspin.SceneError, match="no rollspin metadata"):
        rollspin.load(png)


def test_what_python_writes_remembers_the_scenes_name(tmp_path):
    # A scene from text is "scene"; one read back from an output keeps the
    # name its job recorded, through a still and a clip written from Python.
    text = '[ball]\nradius = 0.5\n[path]\nkind = "circle"\nradius = 2\n[animation]\nduration = 1\nfps = 4\nhold = 0\n'
    still = tmp_path / "still.png"
    rollspin.loads(text).still(width=64, height=48).save(still)
    assert rollspin.load(still).name == "scene"
    png = tmp_path / "fig.png"
    run_cli("render", "torus", "--still", "--width", "64", "--height", "48", "-o", png)
    clip = tmp_path / "again.gif"
    rollspin.load(png).render(clip, width=64, height=48, frames="0:1")
    assert rollspin.load(clip).name == "torus"
    again = tmp_path / "again.png"
    rollspin.load(clip).still(width=64, height=48).save(again)
    assert rollspin.load(again).name == "torus"
