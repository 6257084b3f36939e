"""Stills, clips and the notebook magic through Python: the CLI's pixels and files."""
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rollspin
from conftest import SCENES, run_cli

matplotlib_image = pytest.importorskip("matplotlib.image")


def test_still_is_the_cli_still(lollipop, tmp_path):
    png = tmp_path / "cli.png"
    run_cli("render", SCENES / "lollipop.toml", "--still", "--at", "s=2.5", "--width", 160, "--height", 90, "-o", png,
            "--quiet")
    image = lollipop.still(at=2.5, width=160, height=90)
    assert image.array.shape == (90, 160, 4) and image.array.dtype == np.uint8
    theirs = np.rint(matplotlib_image.imread(png)[:, :, :3] * 255).astype(np.uint8)
    assert np.array_equal(image.array[:, :, :3], theirs)
    assert (image.array[:, :, 3] == 255).all()
    # A second still on the kept context: the same pixels again.
    again = lollipop.still(at=2.5, width=160, height=90)
    assert np.array_equal(again.array, image.array)
    assert lollipop.still(fraction=0.5, width=160, height=90).s == pytest.approx(0.5 * lollipop.length)


def test_render_keys_and_save_formats(lollipop, tmp_path):
    image = lollipop.still("fraction=0.25", width=96, height=64, azimuth_deg=30)
    assert not np.array_equal(image.array, lollipop.still("fraction=0.25", width=96, height=64).array)
    for suffix, magic in [(".png", b"\x89PNG"), (".jpg", b"\xff\xd8"), (".pdf", b"%PDF"), (".svg", b"<?xml")]:
        written = image.save(tmp_path / f"still{suffix}")
        assert written.read_bytes().startswith(magic), suffix
    assert image._repr_png_().startswith(b"\x89PNG")
    clear = lollipop.still(width=32, height=32, transparent=True)
    assert clear.array[0, 0, 3] == 0  # the background is transparent


def test_render_clip_and_html(lollipop, tmp_path):
    short = lollipop.set("animation.duration", 0.5).set("animation.fps", 8)
    clip = short.render(tmp_path / "clip.mp4", width=64, height=36)
    assert clip.path.is_file() and 0 < clip.frames_written == clip.frames_requested
    assert '<video' in clip._repr_html_() and "base64," in clip._repr_html_()
    gif = short.render(tmp_path / "clip.gif", width=64, height=36)
    assert gif.path.read_bytes().startswith(b"GIF8") and "<img" in gif._repr_html_()
    # Stills still work after an animation made its own context.
    assert short.still(width=32, height=32).array.shape == (32, 32, 4)


def test_ctrl_c_leaves_the_cli_partial_file(lollipop, tmp_path):
    scene = lollipop.set("animation.duration", 2.0).set("animation.fps", 10)
    seen = []

    def interrupt_at_third(done, total):
        seen.append(done)
        if done == 3:
            os.kill(os.getpid(), signal.SIGINT)  # what Ctrl-C (or a kernel interrupt) sends

    out = tmp_path / "cut.mp4"
    with pytest.raises(KeyboardInterrupt) as caught:
        scene.render(out, width=64, height=36, on_frame=interrupt_at_third)
    assert max(seen) < 20
    assert "shorter clip" in str(caught.value)
    partial = [p for p in tmp_path.iterdir()]
    assert len(partial) == 1 and partial[0].stat().st_size > 0  # a playable shorter file, no temporary left
    assert not out.exists() or out == partial[0]
    # Python's own Ctrl-C handling is back afterwards.
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_magic_renders_the_cell(tmp_path, monkeypatch):
    shell_module = pytest.importorskip("IPython.core.interactiveshell")
    monkeypatch.chdir(tmp_path)
    shell = shell_module.InteractiveShell.instance()
    shell.run_line_magic("load_ext", "rollspin")
    cell = (SCENES / "lollipop.toml").read_text()
    shell.run_cell_magic("rollspin", "--still --width 48 --height 32 -o still.png", cell)
    assert (tmp_path / "still.png").read_bytes().startswith(b"\x89PNG")
    shell.run_cell_magic("rollspin", "--width 48 --height 32 --set animation.duration=0.25 -o clip.mp4", cell)
    assert (tmp_path / "clip.mp4").stat().st_size > 0


def _fresh_still(tmp_path, name, tunables):
    """A still in a fresh interpreter; what it marked for huge pages (bytes)."""
    out = tmp_path / name
    code = ("import sys, rollspin, rollspin._rollspin as core; "
            "rollspin.load(sys.argv[1]).still(width=160, height=90).save(sys.argv[2]); "
            "print(core.huge_pages_marked())")
    env = dict(os.environ, GLIBC_TUNABLES=tunables)
    done = subprocess.run([sys.executable, "-c", code, str(SCENES / "lollipop.toml"), str(out)], env=env,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return int(done.stdout), out.read_bytes()


def test_huge_pages_as_the_cli_without_a_restart(tmp_path):
    # The first GL context's buffers come from heap memory marked for huge
    # pages, as the CLI's restart with glibc.malloc.hugetlb=1 gives them; a
    # user's own setting wins, and the pixels do not depend on it.
    if "[madvise]" not in Path("/sys/kernel/mm/transparent_hugepage/enabled").read_text():
        pytest.skip("transparent huge pages are not in madvise mode here")
    if "vgpreload" in os.environ.get("LD_PRELOAD", "") or "asan" in os.environ.get("LD_PRELOAD", ""):
        pytest.skip("malloc is not glibc's here")
    marked, huge = _fresh_still(tmp_path, "huge.png", "")
    assert marked >= 32 << 20
    kept, small = _fresh_still(tmp_path, "small.png", "glibc.malloc.hugetlb=0")
    assert kept == 0
    assert huge == small and huge.startswith(b"\x89PNG")


def test_figure_stills_are_the_cli_figures(lollipop, tmp_path):
    # An SVG is drawn as `render --still` draws a figure (its text laid out
    # for the printed size), and a PNG still of a scene with [figure] keys
    # keeps that composition: the same bytes as the CLI's.
    run_cli("render", SCENES / "lollipop.toml", "--still", "--width", 320, "--height", 180, "-o", tmp_path / "cli.svg",
            "--quiet")
    lollipop.still(width=320, height=180).save(tmp_path / "py.svg")

    def numbered_ids_as_n(svg):  # cairo numbers its images over the process's life
        return re.sub(rb'((?:id="|#)[A-Za-z_-]+)\d+', rb"\1N", svg.read_bytes())

    assert numbered_ids_as_n(tmp_path / "py.svg") == numbered_ids_as_n(tmp_path / "cli.svg")
    run_cli("render", SCENES / "lollipop.toml", "--still", "--width", 320, "--height", 180, "--set",
            'figure.width="column"', "-o", tmp_path / "cli.png", "--quiet")
    lollipop.set("figure.width", "column").still(width=320, height=180).save(tmp_path / "py.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
