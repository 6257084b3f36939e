"""rollspin in Jupyter: the %%rollspin cell magic, Scene.explore() and the render progress bar.

The magic works like Manim's %%manim: the cell is a scene in TOML, the line
holds the CLI's render options, and the cell shows the clip (or, with
--still, the picture):

    %load_ext rollspin

    %%rollspin --width 320 --height 180 --set animation.duration=1
    [path]
    kind = "circle"
    radius = 3
"""
from __future__ import annotations

import argparse
import shlex
import time
from pathlib import Path
from typing import Any, Callable, Optional, Tuple

import rollspin


def progress_bar(description: str) -> Tuple[Any, Optional[Callable[[int, int], None]]]:
    """An ipywidgets progress bar and the callback that moves it (at most ~10 updates a second)."""
    try:
        import ipywidgets
        from IPython.display import display
    except ImportError:
        return None, None
    bar = ipywidgets.IntProgress(value=0, min=0, max=1, description="rollspin")
    label = ipywidgets.Label(description)
    box = ipywidgets.HBox([bar, label])
    display(box)
    last = [0.0]

    def on_frame(done: int, total: int) -> None:
        now = time.monotonic()
        if done < total and now - last[0] < 0.1:
            return
        last[0] = now
        bar.max = max(total, 1)
        bar.value = done
        label.value = f"{description}: frame {done} of {total}"

    class Closer:
        def close(self) -> None:
            box.close()

    return Closer(), on_frame


def _magic_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="%%rollspin", add_help=True,
                                     description="Render the cell (a scene in TOML) and show it.")
    parser.add_argument("--still", action="store_true", help="one still image instead of a clip")
    parser.add_argument("--viewer", action="store_true", help="the interactive web viewer instead of a clip")
    parser.add_argument("--at", help="with --still: s=ARC_LENGTH or fraction=F")
    parser.add_argument("-o", "--output", help="output file (default: rollspin_media/<name>.mp4 or .png)")
    parser.add_argument("--width", type=int)
    parser.add_argument("--height", type=int)
    parser.add_argument("--quality", help="low | medium | high | 4k (clips)")
    parser.add_argument("--frames", help="FIRST:LAST (clips)")
    parser.add_argument("--transparent", action="store_true")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="override a scene key (repeatable), as on the CLI")
    parser.add_argument("--name", default="cell", help="the scene's name in messages and default file names")
    return parser


def rollspin_magic(line: str, cell: str) -> Any:
    """%%rollspin [options]: the cell is a scene (TOML); shows the clip, the still with --still, the viewer with --viewer."""
    from IPython.display import display
    parser = _magic_parser()
    try:
        args = parser.parse_args(shlex.split(line))
    except SystemExit:  # --help or a bad option: argparse has printed why
        return None
    scene = rollspin.loads(cell, name=f"<{args.name}>")
    if args.set:
        # Each --set exactly as on the command line (TOML value, or a bare word as a string).
        scene = rollspin.Scene(scene._core.with_overrides(list(args.set)))
    if args.viewer:
        viewer = scene.viewer()
        if args.output:
            viewer.save(args.output)
        display(viewer)
        return None
    if args.still:
        image = scene.still(args.at, width=args.width, height=args.height, transparent=args.transparent)
        if args.output:
            image.save(args.output)
        display(image)
        return None
    output = Path(args.output) if args.output else Path("rollspin_media") / f"{args.name}.mp4"
    if output.parent != Path(""):
        output.parent.mkdir(parents=True, exist_ok=True)
    clip = scene.render(output, frames=args.frames, quality=args.quality, width=args.width, height=args.height,
                        transparent=args.transparent)
    display(clip)
    return None


def register_magic(ipython: Any) -> None:
    ipython.register_magic_function(rollspin_magic, magic_kind="cell", magic_name="rollspin")


def explore(scene: "rollspin.Scene", width: int, height: int) -> Any:
    """Sliders over s and the camera's azimuth; each move redraws the still on the Scene's GL context."""
    import ipywidgets
    s_slider = ipywidgets.FloatSlider(value=0.5 * scene.length, min=0.0, max=scene.length,
                                      step=scene.length / 200.0, description="s", continuous_update=True)
    azimuth = ipywidgets.FloatSlider(value=float(scene._core.azimuth_deg), min=-180.0, max=180.0, step=1.0,
                                     description="azimuth °", continuous_update=True)
    picture = ipywidgets.Image(format="png", width=width, height=height)

    def redraw(*_: Any) -> None:
        image = scene.still(s_slider.value, width=width, height=height, azimuth_deg=azimuth.value)
        picture.value = image._repr_png_()

    s_slider.observe(redraw, names="value")
    azimuth.observe(redraw, names="value")
    redraw()
    return ipywidgets.VBox([picture, s_slider, azimuth])
