"""load / loads / set / toml, and errors: the CLI's loader and messages through Python."""
import subprocess

import pytest

import rollspin
from conftest import CLI, SCENES, run_cli


def test_bare_name_is_the_bundled_scene(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # from any folder
    by_name = rollspin.load("lollipop")
    assert by_name.name == "lollipop"
    assert by_name.toml() .split("\n", 1)[1] == rollspin.load(SCENES / "lollipop.toml").toml().split("\n", 1)[1]


def test_toml_is_scene_print():
    path = SCENES / "storyboard.toml"
    assert rollspin.load(path).toml() == run_cli("scene", path, "--print")


def test_set_is_the_cli_set():
    path = SCENES / "lollipop.toml"
    scene = rollspin.load(path).set("path.radius", 2.5).set("render.title", 'a "quoted" title')
    expected = run_cli("scene", path, "--print", "--set", "path.radius=2.5", "--set", 'render.title="a \\"quoted\\" title"')
    assert scene.toml() == expected
    assert scene.length == pytest.approx(2 * 3.141592653589793 * 2.5)


def test_set_indexes_segments():
    path = SCENES / "storyboard.toml"
    scene = rollspin.load(path)
    changed = scene.set("segment[2].path.radius", 2.5)
    assert changed.length == pytest.approx(scene.length - 2 * 3.141592653589793 * 0.5)
    assert changed.toml() == run_cli("scene", path, "--print", "--set", "segment[2].path.radius=2.5")


def test_set_returns_a_new_scene(lollipop):
    before = lollipop.toml()
    lollipop.set("ball.radius", 0.5)
    assert lollipop.toml() == before


def test_loads_matches_load():
    text = (SCENES / "berry.toml").read_text()
    a, b = rollspin.loads(text), rollspin.load(SCENES / "berry.toml")
    assert (a.solve().quaternion == b.solve().quaternion).all()


def cli_error(*args):
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 2
    return done.stderr.strip().removeprefix("rollspin: error: ")


def test_bad_value_in_a_file_has_the_cli_message(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[ball]\nradius = -1.0\n")
    with pytest.raises(rollspin.SceneError) as caught:
        rollspin.load(bad)
    e = caught.value
    assert isinstance(e, ValueError)
    assert str(e) == cli_error("solve", bad)
    assert (e.file, e.line, e.key) == (str(bad), 2, "ball.radius")
    assert e.column >= 1


def test_bad_set_names_the_override(lollipop):
    with pytest.raises(rollspin.SceneError) as caught:
        lollipop.set("render.width", -3)
    e = caught.value
    assert e.file == "--set render.width=-3" and e.key == "render.width" and e.line is None
    assert str(e) == cli_error("solve", SCENES / "lollipop.toml", "--set", "render.width=-3")
    with pytest.raises(rollspin.SceneError) as caught:
        lollipop.set("no.such_key", 1)
    assert "no" in str(caught.value)


def test_syntax_error_has_line_and_column():
    with pytest.raises(rollspin.SceneError) as caught:
        rollspin.loads("[ball\nradius = 1", name="inline.toml")
    assert caught.value.file == "inline.toml" and caught.value.line == 1


def test_missing_file():
    with pytest.raises(rollspin.SceneError):
        rollspin.load("no-such-scene")
    with pytest.raises(rollspin.SceneError):
        rollspin.load("/nonexistent/x.toml")


@pytest.mark.parametrize("call", [
    lambda s: s.set("render.width", 10 ** 30),
    lambda s: s.set("ball.radius", float("nan")),
    lambda s: s.set("path", {"kind": "circle", "radius": 0}),
    lambda s: s.set("segment[0].hold", 1),
    lambda s: s.set("path.radius", [1, 2]),
    lambda s: s.set("", 1),
    lambda s: s.set("a..b", 1),
    lambda s: s.set("solver.steps", -5).solve(),
    lambda s: s.solve(method="nope"),
    lambda s: s.solve(steps=0),
    lambda s: s.timeline(samples=1),
    lambda s: s.field([float("nan")]),
    lambda s: s.field([-1.0]),
    lambda s: s.still(at=-1.0, width=16, height=16),
    lambda s: s.still(at="middle", width=16, height=16),
    lambda s: s.still(width=0, height=16),
    lambda s: s.still(width=16, height=100000),
    lambda s: s.still(width=16, height=16, no_such_key=1),
    lambda s: s.render("/nonexistent-folder/x.mp4", width=16, height=16),
    lambda s: s.render("x.unknown", width=16, height=16),
    lambda s: s.render("x.mp4", width=15, height=16),
    lambda s: s.render("x.mp4", frames="9:1", width=16, height=16),
    lambda s: s.render("x.mp4", quality="ultra"),
])
def test_bad_input_raises_scene_error(lollipop, call, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(rollspin.SceneError):
        call(lollipop)


def test_wrong_types_raise_type_error(lollipop):
    with pytest.raises(TypeError):
        rollspin.loads(b"[ball]")
    with pytest.raises(TypeError):
        lollipop.set("ball.radius", object())
    with pytest.raises(TypeError):
        lollipop.set(3, 1)


def test_import_loads_no_heavy_module():
    # A script that renders one still starts about as fast as the CLI
    # (bench/bench_python.py): numpy, pandas, QuTiP, IPython, matplotlib,
    # typing and re load when first used, not with `import rollspin`.
    import sys
    heavy = {"numpy", "pandas", "qutip", "IPython", "matplotlib", "ipywidgets", "typing", "re", "pathlib"}

    def modules(code):
        done = subprocess.run([sys.executable, "-c", code + "; print(' '.join(sys.modules))"], capture_output=True,
                              text=True, check=True)
        return set(done.stdout.split())

    added = modules("import sys, rollspin") - modules("import sys")  # a site hook may load some anyway
    assert heavy.isdisjoint(added), heavy & added
