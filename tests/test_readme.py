"""The README's worked example runs, and what it prints is right: every velocity it
derives is checked against a numerical derivative of the positions."""

import pathlib
import re
import textwrap

import numpy as np
import pytest

import sarkp

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def _example():
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## A worked example"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


@pytest.fixture(scope="module")
def run():
    namespace = {}
    exec(compile(_example(), "README.md", "exec"), namespace)
    return namespace


def test_example_runs_and_prints(run, capsys):
    exec(compile(_example(), "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert "rocker angle 101.42 .. 141.37 deg" in out


def _positions(ns, f):
    xa, ya = ns["roa"] * np.cos(f), ns["roa"] * np.sin(f)
    p = sarkp.DPRM1(xa, ya, ns["xc"], ns["yc"], ns["rab"], ns["rcb"], -1)
    xe, ye = xa + 0.2 * np.cos(p.FI2), ya + 0.2 * np.sin(p.FI2)
    xd = sarkp.DPRM2(p.XB, p.YB, 0.0, 0.55, 0.0, 0.45, 0.0, 0.0).XB
    return p.FI3, xe, ye, xd


def test_example_velocities_are_derivatives(run):
    ns, h = run, 1e-5
    fi, w1 = ns["fi"], ns["w1"]
    plus, minus = _positions(ns, fi + h), _positions(ns, fi - h)
    d = [(p - m) / (2 * h) * w1 for p, m in zip(plus, minus)]
    d[0] = np.angle(np.exp(1j * (plus[0] - minus[0]))) / (2 * h) * w1   # FI3 may wrap
    k, ve, signed = ns["k"], ns["ve"], ns["signed"]
    assert np.max(np.abs(d[0] - k.W3)) < 1e-6
    assert np.max(np.abs(np.hypot(d[1], d[2]) - ve.L)) < 1e-6
    assert np.max(np.abs(d[3] - signed)) < 1e-6


def test_thread_recipe_gives_the_one_call_result():
    """The README's thread-pool recipe: its chunks put together equal one call."""
    text = README.read_text(encoding="utf-8")
    block = re.search(r"\* Threads:.*?```python\n(.*?)```", text, re.S).group(1)
    namespace = {}
    exec(compile(textwrap.dedent(block), "README.md", "exec"), namespace)
    whole = namespace["kinematics"](namespace["fi"])
    assert np.array_equal(namespace["W3"], whole.W3)


def test_out_recipe_writes_into_the_buffer():
    """The README's out= recipe runs (its assert included) and equals a call without it."""
    text = README.read_text(encoding="utf-8")
    block = re.search(r"\* Sweeps over arrays take `out=`:.*?```python\n(.*?)```", text,
                      re.S).group(1)
    namespace = {"np": np, "sarkp": sarkp}
    exec(compile(textwrap.dedent(block), "README.md", "exec"), namespace)
    fi, buf, r = namespace["fi"], namespace["buf"], namespace["r"]
    fresh = sarkp.DPRM1(0.1 * np.cos(fi), 0.1 * np.sin(fi), 0.4, 0.0, 0.35, 0.3, -1.0)
    for k, name in enumerate(fresh._fields):
        assert np.array_equal(getattr(r, name), getattr(fresh, name))
        assert np.array_equal(buf[k], getattr(fresh, name))
