"""rollspin's exceptions: the C++ core's rollspin::Error, with its source location.

Bad input (a scene key, a --set override, an argument) raises SceneError, a
ValueError; a failure of the environment (no GL context, a disk error) raises
RenderError, a RuntimeError. str(error) is the message the CLI prints after
"rollspin: error: ".
"""
from __future__ import annotations

TYPE_CHECKING = False  # typing only for type checkers: `import rollspin` stays cheap
if TYPE_CHECKING:
    from typing import Optional

__all__ = ["RollspinError", "SceneError", "RenderError"]

# "render.width: expected ..." or "segment[2].path.radius: ..." — the key a message is about.
_KEY_AT_START = r"^([A-Za-z_][\w-]*(?:\[\d+\])?(?:\.[A-Za-z_][\w-]*(?:\[\d+\])?)*):\s"


class RollspinError(Exception):
    """An error from rollspin's core; `file`, `line`, `column`, `key` say where."""

    def __init__(self, text: str, message: str = "", file: Optional[str] = None, line: Optional[int] = None,
                 column: Optional[int] = None, key: Optional[str] = None) -> None:
        super().__init__(text)
        self.message = message or text
        self.file = file
        self.line = line
        self.column = column
        self.key = key


class SceneError(RollspinError, ValueError):
    """Bad input: a scene file, a key set with Scene.set(), or an argument (the CLI's exit code 2)."""


class RenderError(RollspinError, RuntimeError):
    """A runtime failure: no GL context, an encoder or disk error (the CLI's exit code 1)."""


def _key_of(message: str, file: str) -> Optional[str]:
    import re  # only when an error is raised
    found = re.match(_KEY_AT_START, message)
    if found:
        return found.group(1)
    if file.startswith("--set "):
        return file[len("--set "):].split("=", 1)[0]
    return None


def _from_core(bad_input: bool, text: str, message: str, file: str, line: int, column: int) -> RollspinError:
    """Called by the extension's exception translator."""
    kind = SceneError if bad_input else RenderError
    return kind(text, message, file or None, line or None, column or None, _key_of(message, file))
