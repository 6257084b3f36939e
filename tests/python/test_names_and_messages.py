"""What a new user meets first (issue 54): bundled scene names found as the CLI finds them,
arguments of the wrong type named, one prefix per message, the error estimate in repr, and the
CLI's spinor angle."""
import json
import subprocess
import warnings

import numpy as np
import pytest

import rollspin
from conftest import CLI, SCENES, run_cli


@pytest.fixture
def elsewhere(tmp_path, monkeypatch):
    """A working folder with no scenes, and no scene path from the caller's environment."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("ROLLSPIN_SCENE_PATH", raising=False)
    monkeypatch.delenv("ROLLSPIN_SCENE_DIR", raising=False)
    return tmp_path


def test_bundled_name_with_its_suffix(elsewhere):
    for name in ("lollipop", "lollipop.toml"):
        scene = rollspin.load(name)
        assert scene.name == "lollipop"
        assert scene.toml().split("\n", 1)[1] == run_cli("scene", SCENES / "lollipop.toml", "--print").split("\n", 1)[1]


def test_misspelled_name_says_did_you_mean_and_where_it_looked(elsewhere):
    with pytest.raises(rollspin.SceneError) as caught:
        rollspin.load("lolipop")
    message = str(caught.value)
    assert message.startswith(f"lolipop: cannot read the scene file: there is none; looked in the working directory ({elsewhere})")
    assert "did you mean 'lollipop'?" in message
    assert str(SCENES) in message  # the folder it did find scenes in
    assert "/usr/share/rollspin/scenes" not in message  # python3's prefix, not rollspin's
    # The CLI's words for the same mistake, from the same folder.
    cli = subprocess.run([CLI, "solve", "lolipop"], capture_output=True, text=True, cwd=elsewhere).stderr
    assert cli.startswith(f"rollspin: error: lolipop: cannot read the scene file: there is none; looked in the working directory ({elsewhere})")


def test_extends_a_bundled_name(elsewhere):
    scene = rollspin.loads('extends = "storyboard"\n[render]\ntitle = "mine"\n')
    assert scene.length == pytest.approx(rollspin.load("storyboard").length)


def test_scene_path_is_the_clis_variable(elsewhere, monkeypatch):
    mine = elsewhere / "mine"
    mine.mkdir()
    (mine / "lollipop.toml").write_text("[ball]\nradius = 0.25\n")
    monkeypatch.setenv("ROLLSPIN_SCENE_PATH", f"/nonexistent:{mine}")
    assert rollspin.load("lollipop").ball_radius == 0.25
    assert run_cli("scene", "lollipop", "--print", cwd=elsewhere) == rollspin.load("lollipop").toml()
    assert rollspin.scene_dirs()[0] == mine and SCENES in rollspin.scene_dirs()


def test_old_scene_dir_variable_warns(elsewhere, monkeypatch):
    mine = elsewhere / "old"
    mine.mkdir()
    (mine / "lollipop.toml").write_text("[ball]\nradius = 0.5\n")
    monkeypatch.setenv("ROLLSPIN_SCENE_DIR", str(mine))
    with pytest.warns(FutureWarning, match="ROLLSPIN_SCENE_DIR is deprecated: use ROLLSPIN_SCENE_PATH"):
        assert rollspin.load("lollipop").ball_radius == 0.5
    monkeypatch.delenv("ROLLSPIN_SCENE_DIR")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert rollspin.load("lollipop").ball_radius == 1.0


def test_empty_scene_file(elsewhere):
    (elsewhere / "empty.toml").write_text("# nothing yet\n")
    with pytest.raises(rollspin.SceneError, match="empty scene: .*rollspin scene lollipop --print > empty.toml"):
        rollspin.load("empty.toml")


@pytest.mark.parametrize("call, argument, takes", [
    (lambda s: s.still(width="640"), "width", "a whole number of pixels (int)"),
    (lambda s: s.still(width=640.0, height=360), "width", "a whole number of pixels (int)"),
    (lambda s: s.still(width=64, height="36"), "height", "a whole number of pixels (int)"),
    (lambda s: s.still(at=[1.0]), "at", "an arc length (float)"),
    (lambda s: s.still(fraction="half"), "fraction", "a fraction of the path"),
    (lambda s: s.render("x.mp4", width="640"), "width", "a whole number of pixels (int)"),
    (lambda s: s.render("x.mp4", frames=5), "frames", 'a str of frame numbers "A:B"'),
    (lambda s: s.render("x.mp4", quality=3), "quality", 'a str: "low"'),
    (lambda s: s.render("x.mp4", on_frame=3), "on_frame", "a function"),
])
def test_wrong_argument_type_names_it(lollipop, elsewhere, call, argument, takes):
    with pytest.raises(TypeError) as caught:
        call(lollipop)
    message = str(caught.value)
    assert f"(): {argument} takes {takes}" in message
    assert "incompatible function arguments" not in message and "Invoked with" not in message
    assert not any(elsewhere.iterdir()), "nothing written"


def test_numpy_sizes_are_whole_numbers(lollipop):
    assert lollipop.still(width=np.int64(16), height=16).width == 16


def test_field_message_has_one_prefix(lollipop):
    with pytest.raises(rollspin.SceneError) as caught:
        lollipop.field([1e6])
    message = str(caught.value)
    assert message.startswith("s: expected arc lengths in [0, ") and "s: s:" not in message
    assert caught.value.key == "s"
    with pytest.raises(rollspin.SceneError, match=r"got -1 \(s\[2\]\)$"):
        lollipop.field([0.0, 1.0, -1.0])


def test_repr_shows_the_error_estimate(lollipop):
    sol = lollipop.solve()
    assert f"error_estimate={sol.error_estimate:.2g} rad" in repr(sol)


def test_angle_is_the_clis_spinor_angle():
    # Scenes on both sheets: the CLI's ψ in [0, 4π), and U = cos(ψ/2) − i sin(ψ/2) axis·σ.
    sheets = set()
    for name, sets in [("lollipop", []), ("berry", []), ("lollipop", ["path.radius=1.2"]),
                       ("lollipop", ["path.radius=2.2"])]:
        cli = json.loads(run_cli("solve", SCENES / f"{name}.toml", "--json", *[a for s in sets for a in ("--set", s)]))
        scene = rollspin.load(SCENES / f"{name}.toml")
        for override in sets:
            key, value = override.split("=")
            scene = scene.set(key, float(value))
        sol = scene.solve()
        assert sol.angle == cli["spinor_angle"], (name, sets)
        assert sol.axis.tolist() == cli["axis"]
        half = sol.angle / 2
        assert np.allclose(sol.quaternion, [np.cos(half), *(np.sin(half) * sol.axis)], atol=1e-12)
        sheets.add(sol.angle > 2 * np.pi)
    assert sheets == {False, True}, "both sheets checked"
