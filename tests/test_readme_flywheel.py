"""The README's flywheel example (section "A flywheel in the default mode") runs in the
default mode, and what it computes is right."""

import pathlib
import re

import numpy as np
import pytest

import sarkp

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def _flywheel_example():
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## A flywheel in the default mode"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def _printed():
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## A flywheel in the default mode"):]
    return re.search(r"It prints:\n\n```text\n(.*?)```", section, re.S).group(1)


def test_flywheel_example_runs_and_is_right(capsys):
    """The README's flywheel example, in the default (corrected) mode: the stall, DEC
    kept, the exact flywheel's delta (DZKNDV rerun and sarkp.flywheel), and the start-up
    from rest against an independent time integration (scipy's solve_ivp)."""
    from scipy.integrate import solve_ivp

    assert sarkp.get_mode() == "corrected"
    ns = {}
    exec(compile(_flywheel_example(), "README.md", "exec"), ns)
    out = capsys.readouterr().out
    assert out == _printed()                 # what the README says it prints
    assert out.splitlines()[0] == "REQUIREMENT"
    assert "delta 0.010000" in out.splitlines()[1]
    r, exact, W1 = ns["r"], ns["exact"], ns["W1"]
    assert np.isnan(r.WPR).all()
    run = sarkp.DZKNDV(37, 37.0, W1, ns["ISC"] + exact.IMHVK, ns["MPR"], ns["ISPR"])
    assert np.array_equal(run.DEC, r.DEC)
    assert (run.WPR.max() - run.WPR.min()) / W1 == pytest.approx(0.01, rel=1e-12)
    fw = ns["fw"]
    steady = sarkp.motion(ns["phi"], ns["J"] + fw.J_flywheel, ns["Mred"], omega_mean=W1)
    assert steady.delta == pytest.approx(0.01, rel=1e-12)
    start, turns = ns["start"], ns["turns"]
    jf = ns["ISC"] + fw.J_flywheel

    def rhs(t, y):
        p, w = y
        j = jf + 4.0 + 3.0 * np.sin(p) ** 2
        m = 15.0 + 300 * np.sin(p) + 80 * np.cos(2 * p)
        return [w, (m - 0.5 * 3.0 * np.sin(2 * p) * w * w) / j]

    sol = solve_ivp(rhs, (0.0, start.t[-1]), [0.0, 0.0], t_eval=start.t[::60],
                    method="DOP853", rtol=1e-12, atol=1e-12)
    assert np.abs(sol.y[0] - turns[::60]).max() < 1e-8
    assert np.abs(sol.y[1] - start.omega[::60]).max() < 1e-8
