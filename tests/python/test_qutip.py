"""rollspin against QuTiP: the spinor along a scene equals qutip.sesolve on H(s) = −½ B(s)·σ,
with B(s) taken from rollspin's field code through the binding (never re-derived here)."""
import numpy as np
import pytest

import rollspin
from conftest import SCENES

qutip = pytest.importorskip("qutip")


@pytest.mark.parametrize("name", ["cornu", "berry"])
def test_spinor_matches_sesolve(name):
    scene = rollspin.load(SCENES / f"{name}.toml")
    t = scene.timeline(samples=41)
    cache = {}

    def field(s):
        if s not in cache:
            cache.clear()
            cache[s] = scene.field(min(max(s, 0.0), scene.length))[0]
        return cache[s]

    # i dψ/ds = H ψ with H = −½ B·σ (ħ = 1, s as time).
    h = [[-0.5 * qutip.sigmax(), lambda s, args: field(s)[0]],
         [-0.5 * qutip.sigmay(), lambda s, args: field(s)[1]],
         [-0.5 * qutip.sigmaz(), lambda s, args: field(s)[2]]]
    options = qutip.Options(atol=1e-13, rtol=1e-12, nsteps=100000, max_step=scene.length / 400)
    result = qutip.sesolve(h, qutip.basis(2, 0), t.s, options=options)
    theirs = np.array([state.full().ravel() for state in result.states])
    ours = t.spinors()
    assert np.max(np.abs(ours - theirs)) < 1e-8
    # The Bloch vectors are the same states' ⟨σ⟩.
    expect = np.array([[qutip.expect(op, state) for op in (qutip.sigmax(), qutip.sigmay(), qutip.sigmaz())]
                       for state in result.states])
    assert np.max(np.abs(t.bloch_vectors() - expect)) < 1e-8


def test_to_qutip_is_u_of_l():
    scene = rollspin.load(SCENES / "lollipop.toml")
    sol = scene.solve()
    u = sol.to_qutip()
    assert isinstance(u, qutip.Qobj) and u.shape == (2, 2)
    assert np.allclose((u.dag() * u).full(), np.eye(2), atol=1e-12)
    assert np.allclose((u * qutip.basis(2, 0)).full().ravel(), sol.spinor, atol=1e-15)
    last = scene.timeline().quaternions()[-1]
    assert np.allclose(last, sol.quaternion, atol=1e-12)
