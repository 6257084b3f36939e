"""The example notebooks run from top to bottom without an error (nbclient)."""
from pathlib import Path

import pytest

from conftest import SOURCE_DIR

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

NOTEBOOKS = sorted((SOURCE_DIR / "examples").glob("*.ipynb"))


class Client(nbclient.NotebookClient):
    """nbclient, tolerant of Debian 12's ipywidgets 6, whose comms open without the
    `state` that nbclient's widget mirror reads (the widgets still work in the kernel)."""

    def on_comm_open_jupyter_widget(self, msg):
        if "state" not in msg["content"].get("data", {}):
            return None
        return super().on_comm_open_jupyter_widget(msg)


def test_there_are_examples():
    assert len(NOTEBOOKS) >= 2


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs(notebook, tmp_path):
    nb = nbformat.read(notebook, as_version=4)
    client = Client(nb, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError on any error
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    # Something was shown inline: a picture or a clip.
    shown = [o for o in outputs if o.get("output_type") in ("display_data", "execute_result")]
    assert any("image/png" in o.get("data", {}) or "text/html" in o.get("data", {}) for o in shown)
