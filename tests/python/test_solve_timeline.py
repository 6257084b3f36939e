"""solve() and timeline() give the CLI's numbers, bit for bit, as numpy."""
import json

import numpy as np
import pytest

import rollspin
from conftest import SCENES, run_cli


def test_solve_is_the_cli_solve(lollipop):
    cli = json.loads(run_cli("solve", SCENES / "lollipop.toml", "--json"))
    sol = lollipop.solve()
    assert sol.quaternion.shape == (4,) and sol.quaternion.dtype == np.float64
    assert sol.quaternion.tolist() == cli["quaternion"]  # %.17g round-trips: the same doubles
    assert (sol.method, sol.steps, sol.length) == (cli["method"], cli["steps"], cli["length"])
    assert sol.seconds >= 0.0
    # The same a posteriori estimate as the CLI's (its basis named), and small: automatic means accurate.
    assert sol.error_estimate_basis == cli["error_estimate_basis"]
    assert 0.0 <= sol.error_estimate < 1e-10 and sol.error_estimate == pytest.approx(cli["error_estimate"], rel=1e-6)


def test_error_estimate_can_be_skipped_by_its_key(lollipop):
    # solver.error_estimate = false: no second solve; the estimate is NaN, the basis says why, U(L) is unchanged.
    sol = lollipop.set("solver.error_estimate", False).solve()
    assert np.isnan(sol.error_estimate)
    assert sol.error_estimate_basis == "skipped (solver.error_estimate = false)"
    assert sol.quaternion.tolist() == lollipop.solve().quaternion.tolist()


def test_sign_is_kept():
    # r = √3 R: δ = 4π and U = −1 exactly (scenes/lollipop.toml's comment).
    sol = rollspin.load(SCENES / "lollipop.toml").set("path.radius", 3 ** 0.5).solve()
    assert sol.quaternion[0] == pytest.approx(-1.0, abs=1e-10)
    assert np.allclose(sol.rotation_matrix, np.eye(3), atol=1e-10)
    assert sol.angle == pytest.approx(2 * np.pi, abs=1e-9)


def test_solution_forms_agree(lollipop):
    sol = lollipop.solve()
    qw, qx, qy, qz = sol.quaternion
    u = sol.unitary
    assert np.allclose(u.conj().T @ u, np.eye(2), atol=1e-12)
    assert np.allclose(sol.spinor, u[:, 0])
    # R(U) from the C++ core against R v = U (v·σ) U† done here.
    sigma = [np.array([[0, 1], [1, 0]]), np.array([[0, -1j], [1j, 0]]), np.array([[1, 0], [0, -1]])]
    for j in range(3):
        rotated = u @ sigma[j] @ u.conj().T
        column = [0.5 * np.trace(rotated @ sigma[i]).real for i in range(3)]
        assert np.allclose(sol.rotation_matrix[:, j], column, atol=1e-12)


def test_solve_options_go_through_the_loader(lollipop):
    sol = lollipop.solve(method="rk4", steps=640)
    assert (sol.method, sol.steps) == ("rk4", 640)
    assert np.allclose(sol.quaternion, lollipop.solve().quaternion, atol=1e-9)


def test_timeline_is_the_cli_csv(tmp_path):
    for name in ("lollipop", "storyboard", "torus-to-floor"):
        path = SCENES / f"{name}.toml"
        csv = tmp_path / f"{name}.csv"
        run_cli("timeline", path, "-o", csv, "--set", "timeline.samples=157")
        lines = csv.read_text().split("\n")
        header = lines[0].split(",")  # the header row first; the solve's numbers in the sidecar
        assert "error_estimate" in json.loads((tmp_path / f"{name}.csv.json").read_text())
        table = np.loadtxt(csv, delimiter=",", skiprows=1)
        t = rollspin.load(path).timeline(samples=157)
        assert t.columns == header and len(t) == 157 == table.shape[0]
        for k, column in enumerate(header):
            assert (np.asarray(t[column], dtype=float) == table[:, k]).all(), column
    assert "segment" in t and t["segment"].dtype.kind == "i"
    # torus-to-floor: a surface per row, 0 on the torus then 1 on the floor.
    assert t.columns[-2:] == ["segment", "surface"] and t["surface"].dtype.kind == "i"
    assert t["surface"][0] == 0 and t["surface"][-1] == 1 and (np.diff(t["surface"]) >= 0).all()
    assert "surface" not in rollspin.load(SCENES / "storyboard.toml").timeline(samples=9)


def test_timeline_helpers(lollipop):
    t = lollipop.timeline()
    assert t["s"][0] == 0.0 and t["s"][-1] == pytest.approx(lollipop.length)
    assert np.array_equal(t.s, t["s"])
    with pytest.raises(KeyError):
        t["nope"]
    q = t.quaternions()
    assert np.allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-12)
    assert np.allclose(np.linalg.norm(t.bloch_vectors(), axis=1), 1.0, atol=1e-12)
    frame = t.to_pandas()
    assert list(frame.columns) == t.columns and len(frame) == len(t)
    assert (frame["qw"].to_numpy() == t["qw"]).all()


def test_field_is_the_timeline_field(lollipop):
    t = lollipop.timeline(samples=33)
    b = lollipop.field(t.s)
    assert b.shape == (33, 3)
    assert (b == np.stack([t["Bx"], t["By"], t["Bz"]], axis=1)).all()
    assert lollipop.field(1.0).shape == (1, 3)
