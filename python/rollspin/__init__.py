"""rollspin — the rolling ball and the spin-1/2, from Python.

The same C++ core as the `rollspin` program (its scene loader, solver,
timeline, still, figure and animation jobs), reached without a subprocess or
a CSV:

    >>> import rollspin
    >>> scene = rollspin.load("lollipop")              # a bundled scene, or a path
    >>> scene.solve().quaternion                        # qw, qx, qy, qz (sign kept)
    >>> t = scene.timeline(samples=1000); t["qw"]       # numpy, the CSV's columns
    >>> scene.set("render.azimuth_deg", 30).still(at=1.5)   # an Image; shown inline
    >>> scene.render("lollipop.mp4")                    # any clip format

In IPython, `%load_ext rollspin` adds the `%%rollspin` cell magic. See
docs/python.md for the whole API.
"""
from __future__ import annotations

# Imports are few and cheap here: numpy, pathlib, base64 come when first
# used, and typing (with re, which it imports) only for type checkers, since
# the annotations are never evaluated (the __future__ import). A script that
# renders one still starts about as fast as the CLI (bench/bench_python.py).
import math
import os
import sys

from . import _rollspin as _core
from ._errors import RenderError, RollspinError, SceneError

__all__ = ["load", "loads", "Scene", "Solution", "Timeline", "Image", "Clip", "SceneError", "RenderError",
           "RollspinError", "scene_dirs", "load_ipython_extension"]

TYPE_CHECKING = False  # mypy and pyright take any `if TYPE_CHECKING:` as true
if TYPE_CHECKING:
    from pathlib import Path
    from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

    import numpy as np

    PathLike = Union[str, "os.PathLike[str]"]


def _numpy() -> Any:
    # numpy is imported when an array is first needed, not by `import rollspin`:
    # a script that only renders does not pay for it.
    import numpy
    return numpy


def _program_scene_folders() -> "List[str]":
    """This package's own bundled-scene folders (after ``$ROLLSPIN_SCENE_PATH``)."""
    here = os.path.dirname(os.path.abspath(__file__))
    folders = []
    old = os.environ.get("ROLLSPIN_SCENE_DIR")
    if old:
        import warnings
        warnings.warn("ROLLSPIN_SCENE_DIR is deprecated: use ROLLSPIN_SCENE_PATH (':'-separated folders), "
                      "as the rollspin program does", FutureWarning, stacklevel=4)
        folders.append(old)
    if os.path.basename(os.path.dirname(here)) in ("site-packages", "dist-packages"):
        # Installed: by pip (the scenes inside the package) or by `cmake --install`
        # (<prefix>/lib/python3.X/dist-packages/rollspin → <prefix>/share/rollspin/scenes).
        inside = os.path.join(here, "scenes")
        prefix = os.path.normpath(os.path.join(here, "..", "..", "..", ".."))
        folders.append(inside if os.path.isdir(inside) else os.path.join(prefix, "share", "rollspin", "scenes"))
    else:
        folders.append(_core.SOURCE_SCENES)  # a build tree's package: the source tree it was built from
    return folders


def _find_scenes_here() -> None:
    # The C++ loader's search would otherwise start from /proc/self/exe, python3.
    _core.set_scene_folders(_program_scene_folders())


_find_scenes_here()


def scene_dirs() -> "List[Path]":
    """The folders that hold bundled scenes, in the order a bare name (``load("lollipop")``) is looked for.

    ``$ROLLSPIN_SCENE_PATH`` (':'-separated, as for the rollspin program), then
    the package's own: its ``scenes/`` once installed by pip,
    ``<prefix>/share/rollspin/scenes`` once installed by ``cmake --install``, or
    the source tree's ``scenes/`` for a build tree's package. Existing folders only.
    """
    from pathlib import Path
    _find_scenes_here()
    return [Path(folder) for folder in _core.scene_folders()]


# Files rollspin writes that remember their scene (`rollspin scene --from`).
_OUTPUT_SUFFIXES = {".png", ".jpg", ".jpeg", ".pdf", ".svg", ".gif", ".mp4", ".webm", ".mov",
                    ".csv", ".json", ".npy", ".npz", ".gltf", ".glb", ".html", ".htm"}


def load(path: PathLike) -> "Scene":
    """A scene from a TOML file, a bundled scene by name (``"lollipop"``),
    found as the CLI finds it, or an output rollspin wrote (a PNG, JPEG, PDF,
    SVG, GIF, MP4, WebM or MOV, a timeline's CSV, .npy or .npz with its
    sidecar, or its JSON), which remembers the scene it was made from.

    Raises SceneError (a ValueError) with the CLI's message when the file is
    missing (where it looked, and the nearest bundled name) or invalid, or an
    output carries no rollspin metadata.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"load() expects a scene file's path or a bundled scene's name (str or os.PathLike), "
                        f"got {type(path).__name__}")
    text = os.fspath(path)
    if os.path.splitext(text)[1].lower() in _OUTPUT_SUFFIXES:
        return Scene(_core.Scene.load_output(text))
    _find_scenes_here()  # $ROLLSPIN_SCENE_DIR may have been set since import
    return Scene(_core.Scene.load(text))


def loads(text: str, name: str = "<string>") -> "Scene":
    """A scene from TOML text; `name` is what error messages call it."""
    if not isinstance(text, str):
        raise TypeError(f"loads() expects the scene's TOML text as str, got {type(text).__name__}")
    return Scene(_core.Scene.loads(text, name))


def _toml_value(value: Any) -> str:
    """A Python value as the right-hand side of a --set override (TOML)."""
    if type(value).__module__ == "numpy":
        value = value.tolist()  # a numpy scalar or array as Python numbers
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(int(value))
    if isinstance(value, float):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\t", "\\t")
        return f'"{escaped}"'
    if isinstance(value, os.PathLike):
        return _toml_value(os.fspath(value))
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_toml_value(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"cannot use a {type(value).__name__} as a scene value (use bool, int, float, str, list or dict)")


def _override(key: str, value: Any) -> str:
    if not isinstance(key, str):
        raise TypeError(f"a scene key is a str like 'path.radius', got {type(key).__name__}")
    return f"{key}={_toml_value(value)}"


def _argument(function: str, name: str, value: Any, kind: type, takes: str) -> Any:
    """`value` as `kind` (None passes), or a TypeError naming the argument and what it takes.

    Without it the extension's binding refuses a wrong type with its whole
    overload signature, which names neither.
    """
    if value is None:
        return None
    if kind is int:
        import operator
        try:
            if not isinstance(value, bool):
                return operator.index(value)  # int and numpy integers, not 640.0 or "640"
        except TypeError:
            pass
    elif isinstance(value, kind):
        return value
    raise TypeError(f"{function}(): {name} takes {takes}, got {type(value).__name__} {value!r}")


_AT_TAKES = 'an arc length (float) or a str like "s=1.5" or "fraction=0.25"'


def _number(function: str, name: str, value: Any, takes: str) -> float:
    """A real number (int, float, numpy scalar) as float, or a TypeError naming the argument."""
    if not isinstance(value, (str, bytes, bool, complex)):
        try:
            return float(value)
        except (TypeError, ValueError):
            pass
    raise TypeError(f"{function}(): {name} takes {takes}, got {type(value).__name__} {value!r}")


def _size_arguments(function: str, width: Any, height: Any) -> Tuple[Optional[int], Optional[int]]:
    return (_argument(function, "width", width, int, "a whole number of pixels (int) or None"),
            _argument(function, "height", height, int, "a whole number of pixels (int) or None"))


def _in_notebook() -> bool:
    shell = sys.modules.get("IPython")
    if shell is None:
        return False
    ip = shell.get_ipython()  # type: ignore[attr-defined]
    return ip is not None and "IPKernelApp" in getattr(ip, "config", {})


class Scene:
    """A validated scene: a scene file (or text) plus its overrides.

    Immutable: ``set()`` returns a new Scene. A Scene keeps its model and, once
    it has drawn a still, its drawing job, so further stills cost a solve to s
    and one GL frame.
    """

    __slots__ = ("_core", "_variants")

    def __init__(self, core: Any) -> None:
        self._core = core
        self._variants: Dict[Tuple[str, ...], Any] = {}

    # -- what it is -------------------------------------------------------
    @property
    def name(self) -> str:
        """The scene's name (its file's stem)."""
        return self._core.name

    @property
    def source(self) -> str:
        """The scene file as given to load(), or the name given to loads()."""
        return self._core.source

    @property
    def overrides(self) -> List[str]:
        """The --set overrides laid over the file, in order ("key=value")."""
        return list(self._core.overrides)

    @property
    def length(self) -> float:
        """The path's length L (the arc length s runs over [0, L])."""
        return self._core.length

    @property
    def ball_radius(self) -> float:
        return self._core.ball_radius

    def __repr__(self) -> str:
        extra = f", {len(self.overrides)} override(s)" if self.overrides else ""
        return f"<rollspin.Scene {self.name!r} from {self.source!r}{extra}: {self._core.describe}, length {self.length:.6g}>"

    def set(self, key: str, value: Any) -> "Scene":
        """A new Scene with `key` set to `value` (the CLI's ``--set key=value``).

        Keys are dotted paths: ``"path.radius"``, ``"render.azimuth_deg"``,
        ``"segment[2].path.radius"``. The new scene is validated by the same
        loader; a bad key or value raises SceneError naming it.
        """
        return Scene(self._core.with_overrides([_override(key, value)]))

    def toml(self) -> str:
        """The resolved scene as TOML (``rollspin scene --print``)."""
        return self._core.toml()

    def _with(self, overrides: Sequence[str]) -> Any:
        """The core scene with these overrides added, made once and kept."""
        key = tuple(overrides)
        if not key:
            return self._core
        found = self._variants.get(key)
        if found is None:
            if len(self._variants) > 32:
                self._variants.clear()
            found = self._variants[key] = self._core.with_overrides(list(key))
        return found

    # -- numbers ----------------------------------------------------------
    def solve(self, method: Optional[str] = None, steps: Optional[int] = None,
              tolerance: Optional[float] = None) -> "Solution":
        """U(L): the spinor after the whole path (``rollspin solve``).

        method, steps, tolerance override solver.method / .steps / .tolerance.
        """
        overrides = []
        if method is not None:
            overrides.append(_override("solver.method", method))
        if steps is not None:
            overrides.append(_override("solver.steps", steps))
        if tolerance is not None:
            overrides.append(_override("solver.tolerance", tolerance))
        core = self._with(overrides)
        quaternion, method_name, step_count, seconds, length, unitarity, rotation, estimate, basis = core.solve()
        return Solution(quaternion, rotation, length, method_name, step_count, seconds, unitarity, estimate, basis)

    def timeline(self, samples: Optional[int] = None) -> "Timeline":
        """The orientation timeline (``rollspin timeline``) as numpy columns.

        samples overrides timeline.samples (default: 60 per turn + 1).
        """
        core = self._with([_override("timeline.samples", samples)] if samples is not None else [])
        names, values, segments, method, steps, seconds, surfaces = core.timeline()
        return Timeline(names, values, segments, method, steps, seconds, surfaces)

    def field(self, s: Union[float, Sequence[float], "np.ndarray"]) -> "np.ndarray":
        """The field B(s) = −ω(s) at arc lengths s, shape (N, 3) (the solver's own field code).

        The spinor obeys i dU/ds = −½ B(s)·σ U: the Hamiltonian is H(s) = −½ B(s)·σ.
        """
        np = _numpy()
        return self._core.field(np.atleast_1d(np.asarray(s, dtype=float)).ravel())

    # -- pictures ---------------------------------------------------------
    def still(self, at: Union[None, float, str] = None, *, fraction: Optional[float] = None,
              width: Optional[int] = None, height: Optional[int] = None, transparent: bool = False,
              **render_keys: Any) -> "Image":
        """One still (``rollspin render --still``) as an Image.

        at: an arc length s (float), or "s=1.5" / "fraction=0.25" as on the CLI;
        default the middle of the path (its end for a strobe). Other keyword
        arguments set render keys: ``azimuth_deg=30`` is ``render.azimuth_deg=30``.
        """
        if at is not None and fraction is not None:
            raise ValueError("give at= or fraction=, not both")
        width, height = _size_arguments("still", width, height)
        where: Optional[str]
        if fraction is not None:
            where = f"fraction={_number('still', 'fraction', fraction, 'a fraction of the path in [0, 1]')!r}"
        elif at is None or isinstance(at, str):
            where = at
        else:
            where = f"s={_number('still', 'at', at, _AT_TAKES)!r}"
        core = self._with([_override("render." + k, v) for k, v in render_keys.items()])
        return Image(_core.still(core, where, width, height, bool(transparent)))

    def render(self, path: PathLike, *, frames: Optional[str] = None, quality: Optional[str] = None,
               width: Optional[int] = None, height: Optional[int] = None, transparent: bool = False,
               progress: Optional[bool] = None, on_frame: Optional[Callable[[int, int], None]] = None,
               **render_keys: Any) -> "Clip":
        """An animation (``rollspin render``): MP4, WebM, GIF, MOV, or a folder of PNG frames.

        The format comes from render.format or the extension of `path`.
        frames="A:B" renders part of the clip; quality is low | medium | high | 4k.
        In a notebook a progress bar shows while it renders (progress=False: none;
        progress=True outside a notebook: the CLI's bar on stderr). Ctrl-C
        (KeyboardInterrupt) stops between frames and leaves the CLI's shorter,
        playable file; the KeyboardInterrupt then names it. on_frame(done, total)
        is called after each frame.
        """
        from . import _notebook
        width, height = _size_arguments("render", width, height)
        frames = _argument("render", "frames", frames, str, 'a str of frame numbers "A:B"')
        quality = _argument("render", "quality", quality, str, 'a str: "low", "medium", "high" or "4k"')
        if on_frame is not None and not callable(on_frame):
            raise TypeError(f"render(): on_frame takes a function f(done, total), got {type(on_frame).__name__}")
        core = self._with([_override("render." + k, v) for k, v in render_keys.items()])
        notebook = _in_notebook()
        callbacks = [on_frame] if on_frame is not None else []
        bar = None
        if notebook and progress is not False:
            bar, moved = _notebook.progress_bar(f"rendering {os.fspath(path)}")
            if moved is not None:
                callbacks.append(moved)

        def each_frame(done: int, total: int) -> None:
            for callback in callbacks:
                callback(done, total)

        quiet = not (progress and not notebook)
        try:
            written, done, requested, signal_number = _core.render(core, os.fspath(path), frames, quality, width,
                                                                   height, bool(transparent), quiet,
                                                                   each_frame if callbacks else None)
        finally:
            if bar is not None:
                bar.close()
        from pathlib import Path
        clip = Clip(Path(written) if written else None, done, requested, signal_number != 0)
        if signal_number != 0:
            raise KeyboardInterrupt(
                f"rendering stopped after {done} of {requested} frames"
                + (f"; wrote a shorter clip {written}" if written else "; nothing written"))
        return clip

    def export(self, path: Optional[PathLike] = None, *, metadata: bool = True) -> "Path":
        """The scene as glTF 2.0 (``rollspin export``): a ``.glb``, or a ``.gltf`` beside its ``.bin``.

        The same file as the CLI's, made by the same C++ job: the surface, the
        path, the textured ball and its Bloch-sphere twin, the animation "roll"
        in the clip's seconds, and (metadata=True) the resolved scene in the
        ball's extras. path=None writes output/<scene>.glb. Returns the path written.
        """
        from pathlib import Path
        target = "" if path is None else os.fspath(path)
        return Path(_core.export_gltf(self._core, target, bool(metadata)))

    def viewer(self, height: int = 560) -> "Viewer":
        """The interactive web viewer (``rollspin render SCENE -o NAME.html``), inline in a notebook.

        The same page as the CLI's, made by the same C++ job: the ball and its
        Bloch-sphere twin side by side, a scrubber over arc length, chapters.
        Shown in an iframe of `height` pixels; ``.html`` is the page itself and
        ``.save(path)`` writes it.
        """
        return Viewer(_core.viewer_html(self._core), height)

    def explore(self, width: int = 640, height: int = 360) -> Any:
        """Sliders over s and the camera's azimuth that redraw the still (ipywidgets)."""
        from . import _notebook
        return _notebook.explore(self, width, height)


class Solution:
    """The end of a solve: U(L) and how it was found."""

    __slots__ = ("quaternion", "rotation_matrix", "length", "method", "steps", "seconds", "unitarity_error",
                 "error_estimate", "error_estimate_basis")

    def __init__(self, quaternion: "np.ndarray", rotation_matrix: "np.ndarray", length: float, method: str, steps: int,
                 seconds: float, unitarity_error: float, error_estimate: float = float("nan"),
                 error_estimate_basis: str = "") -> None:
        self.quaternion = quaternion            #: (4,) qw, qx, qy, qz of U = qw·1 − i(q·σ); the sign is kept
        self.rotation_matrix = rotation_matrix  #: (3, 3) R(U), worldFromBody
        self.length = length                    #: the path's length L
        self.method = method                    #: the solver method used
        self.steps = steps                      #: its steps (0 for the closed form)
        self.seconds = seconds                  #: the solve's wall time
        #: a posteriori estimate of the rotation error of U(L), radians (docs/solver.md)
        self.error_estimate = error_estimate
        self.error_estimate_basis = error_estimate_basis  #: how it was estimated
        self.unitarity_error = unitarity_error

    @property
    def spinor(self) -> "np.ndarray":
        """U(L)|↑⟩ as a complex (2,) array: (qw − i qz, qy − i qx)."""
        qw, qx, qy, qz = self.quaternion
        return _numpy().array([complex(qw, -qz), complex(qy, -qx)])

    @property
    def unitary(self) -> "np.ndarray":
        """U(L) = qw·1 − i(qx σx + qy σy + qz σz) as a complex (2, 2) array."""
        return _unitaries(self.quaternion.reshape(1, 4))[0]

    @property
    def angle(self) -> float:
        """The spinor angle ψ in [0, 4π), as ``rollspin solve`` prints it (docs/conventions.md).

        U = cos(ψ/2)·1 − i sin(ψ/2) (axis·σ) for ``axis``: ψ is R(U)'s rotation angle
        (in [0, π]) on the positive sheet and that angle + 2π on the negative one
        (qw < 0, U ≈ −1); ψ = 2π is U = −1, the ball turned once.
        """
        return _core.spinor_angle(*(float(v) for v in self.quaternion))[0]

    @property
    def axis(self) -> "np.ndarray":
        """The unit axis of R(U)'s rotation (x̂ when there is none), the axis of ``angle``."""
        return _numpy().array(_core.spinor_angle(*(float(v) for v in self.quaternion))[1])

    def to_qutip(self) -> Any:
        """U(L) as a qutip.Qobj (2 × 2 unitary operator)."""
        import qutip
        return qutip.Qobj(self.unitary)

    def __repr__(self) -> str:
        q = ", ".join(f"{v:.12g}" for v in self.quaternion)
        return (f"<rollspin.Solution quaternion=[{q}] method={self.method} steps={self.steps} length={self.length:.6g} "
                f"error_estimate={self.error_estimate:.2g} rad>")


def _unitaries(q: "np.ndarray") -> "np.ndarray":
    qw, qx, qy, qz = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    u = _numpy().empty((len(q), 2, 2), dtype=complex)
    u[:, 0, 0] = qw - 1j * qz
    u[:, 0, 1] = -qy - 1j * qx
    u[:, 1, 0] = qy - 1j * qx
    u[:, 1, 1] = qw + 1j * qz
    return u


class Timeline:
    """The orientation timeline: the CSV's columns as numpy arrays.

    ``t["qw"]``, ``t["Bx"]``, ``t.s`` …; ``len(t)`` rows; ``t.columns`` the
    names in the CSV's order (a storyboard adds "segment", one of several
    surfaces "surface" too).
    """

    def __init__(self, names: List[str], values: "np.ndarray", segments: Optional["np.ndarray"], method: str, steps: int,
                 seconds: float, surfaces: Optional["np.ndarray"] = None) -> None:
        self._index = {name: k for k, name in enumerate(names)}
        self._values = values  # (columns, rows): each column contiguous
        self._segments = segments
        self._surfaces = surfaces
        self.columns: List[str] = (list(names) + (["segment"] if segments is not None else [])
                                   + (["surface"] if surfaces is not None else []))
        self.method = method
        self.steps = steps
        self.seconds = seconds

    def __len__(self) -> int:
        return self._values.shape[1]

    def __getitem__(self, column: str) -> "np.ndarray":
        if column == "segment" and self._segments is not None:
            return self._segments
        if column == "surface" and self._surfaces is not None:
            return self._surfaces
        if column not in self._index:
            raise KeyError(f"no column {column!r}; the columns are {', '.join(self.columns)}")
        return self._values[self._index[column]]

    def __contains__(self, column: object) -> bool:
        return column in self.columns

    def __iter__(self):  # like a mapping: the column names
        return iter(self.columns)

    def keys(self) -> List[str]:
        return list(self.columns)

    @property
    def s(self) -> "np.ndarray":
        return self["s"]

    def quaternions(self) -> "np.ndarray":
        """(N, 4): qw, qx, qy, qz per row."""
        return _numpy().stack([self["qw"], self["qx"], self["qy"], self["qz"]], axis=1)

    def spinors(self) -> "np.ndarray":
        """(N, 2) complex: U(s)|↑⟩ per row."""
        return _unitaries(self.quaternions())[:, :, 0]

    def bloch_vectors(self) -> "np.ndarray":
        """(N, 3): the Bloch vector of U(s)|↑⟩, i.e. R(U(s)) ẑ."""
        qw, qx, qy, qz = self["qw"], self["qx"], self["qy"], self["qz"]
        return _numpy().stack([2.0 * (qx * qz + qw * qy), 2.0 * (qy * qz - qw * qx), 1.0 - 2.0 * (qx * qx + qy * qy)], axis=1)

    def to_pandas(self) -> Any:
        """A pandas.DataFrame with the CSV's columns."""
        import pandas
        return pandas.DataFrame({name: self[name] for name in self.columns})

    def __repr__(self) -> str:
        return f"<rollspin.Timeline {len(self)} rows × {len(self.columns)} columns ({self.method}, {self.steps} steps)>"


class Image:
    """A still: ``array`` (H × W × 4 uint8, RGBA), ``save(path)``, shown inline in a notebook."""

    __slots__ = ("_core",)

    def __init__(self, core: Any) -> None:
        self._core = core

    @property
    def array(self) -> "np.ndarray":
        return self._core.array

    @property
    def width(self) -> int:
        return self._core.width

    @property
    def height(self) -> int:
        return self._core.height

    @property
    def s(self) -> float:
        """The arc length shown."""
        return self._core.s

    def save(self, path: PathLike) -> Path:
        """Writes the still: PNG, JPEG, … by extension or render.format; PDF and SVG as a vector figure."""
        from pathlib import Path
        return Path(self._core.save(os.fspath(path)))

    def _repr_png_(self) -> bytes:
        return self._core.png()

    def __repr__(self) -> str:
        return f"<rollspin.Image {self.width}x{self.height} at s={self.s:.6g}>"


_VIDEO_TYPES = {".mp4": "video/mp4", ".webm": "video/webm", ".mov": "video/quicktime"}


class Clip:
    """What Scene.render() wrote; shown inline in a notebook (``_repr_html_``)."""

    def __init__(self, path: Optional[Path], frames_written: int, frames_requested: int, interrupted: bool) -> None:
        self.path = path
        self.frames_written = frames_written
        self.frames_requested = frames_requested
        self.interrupted = interrupted

    def _repr_html_(self) -> str:
        import base64
        import html
        if self.path is None:
            return "<p>rollspin: nothing was written</p>"
        if self.path.is_dir():
            frames = sorted(self.path.glob("*.png"))
            if not frames:
                return f"<p>rollspin: {html.escape(str(self.path))} (no frames)</p>"
            data = base64.b64encode(frames[0].read_bytes()).decode()
            return (f'<p>{len(frames)} frames in {html.escape(str(self.path))}; the first:</p>'
                    f'<img src="data:image/png;base64,{data}"/>')
        data = base64.b64encode(self.path.read_bytes()).decode()
        suffix = self.path.suffix.lower()
        if suffix == ".gif":
            return f'<img src="data:image/gif;base64,{data}"/>'
        kind = _VIDEO_TYPES.get(suffix, "video/mp4")
        return f'<video controls loop autoplay muted><source src="data:{kind};base64,{data}" type="{kind}"></video>'

    def __repr__(self) -> str:
        return f"<rollspin.Clip {self.path} ({self.frames_written} of {self.frames_requested} frames)>"


class Viewer:
    """A scene's web viewer page; shown inline in a notebook (``_repr_html_``: an iframe, no extra dependency)."""

    def __init__(self, page: str, height: int = 560) -> None:
        self.html = page
        self.height = int(height)

    def save(self, path: PathLike) -> Path:
        """Writes the page (one self-contained file; it opens from file:// with no network)."""
        from pathlib import Path
        out = Path(path)
        temporary = out.with_name(f".{out.name}.{os.getpid()}.tmp")
        temporary.write_text(self.html, encoding="utf-8")
        temporary.replace(out)
        return out

    def _repr_html_(self) -> str:
        import html
        return (f'<iframe srcdoc="{html.escape(self.html, quote=True)}" style="width: 100%; height: {self.height}px; '
                'border: 0" allow="fullscreen" title="rollspin web viewer"></iframe>')

    def __repr__(self) -> str:
        return f"<rollspin.Viewer ({len(self.html)} bytes)>"


def load_ipython_extension(ipython: Any) -> None:
    """``%load_ext rollspin``: registers the ``%%rollspin`` cell magic."""
    from . import _notebook
    _notebook.register_magic(ipython)
