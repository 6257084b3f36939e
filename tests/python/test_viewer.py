"""The web viewer through Python: Scene.viewer() and `%%rollspin --viewer` give the CLI's page."""
import html
import re

import pytest

import rollspin

from conftest import SCENES, run_cli


def _timeline_json(page):
    return re.search(r'id="rollspin-timeline">(.*?)</script>', page, re.S).group(1)


def test_viewer_is_the_cli_page(lollipop, tmp_path):
    viewer = lollipop.viewer()
    out = tmp_path / "cli.html"
    run_cli("render", SCENES / "lollipop.toml", "-o", out, "--quiet")
    cli = out.read_text(encoding="utf-8")
    # The same job: the same timeline, meshes and bundle; only the scene's header line (its name) may differ.
    assert _timeline_json(viewer.html) == _timeline_json(cli)
    for part in ('id="rollspin-glb"', "<script>"):
        assert viewer.html.split(part, 1)[1] == cli.split(part, 1)[1], part
    saved = viewer.save(tmp_path / "saved.html")
    assert saved.read_text(encoding="utf-8") == viewer.html
    assert not list(tmp_path.glob(".*.tmp"))


def test_viewer_shows_inline_as_an_iframe(lollipop):
    shown = lollipop.viewer(height=400)._repr_html_()
    assert shown.startswith("<iframe srcdoc=\"") and "height: 400px" in shown
    srcdoc = re.match(r'<iframe srcdoc="(.*?)" style=', shown, re.S).group(1)
    assert '"' not in srcdoc and html.unescape(srcdoc) == lollipop.viewer().html


def test_magic_shows_the_viewer(tmp_path, monkeypatch):
    shell_module = pytest.importorskip("IPython.core.interactiveshell")
    monkeypatch.chdir(tmp_path)
    shell = shell_module.InteractiveShell.instance()
    shell.run_line_magic("load_ext", "rollspin")
    shell.run_cell_magic("rollspin", "--viewer -o page.html", (SCENES / "lollipop.toml").read_text())
    assert (tmp_path / "page.html").read_text(encoding="utf-8").startswith("<!DOCTYPE html>")


def test_export_is_the_cli_glb(lollipop, tmp_path):
    # One job behind both doors: the same bytes as `rollspin export`.
    out = tmp_path / "cli.glb"
    run_cli("export", SCENES / "lollipop.toml", "-o", out)
    written = lollipop.export(tmp_path / "python.glb")
    assert written == tmp_path / "python.glb"
    assert written.read_bytes() == out.read_bytes()
    assert not list(tmp_path.glob(".*.tmp"))
    bare = lollipop.export(tmp_path / "bare.gltf", metadata=False)
    assert b"resolved: every default filled in" not in bare.read_bytes() and (tmp_path / "bare.bin").exists()
    assert b"resolved: every default filled in" in written.read_bytes()


def test_export_refuses_an_unknown_extension(lollipop, tmp_path):
    with pytest.raises(rollspin.RollspinError, match=r"\.glb"):
        lollipop.export(tmp_path / "model.obj")
    assert not list(tmp_path.iterdir())
