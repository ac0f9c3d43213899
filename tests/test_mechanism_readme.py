"""The README's section "Your own mechanism" runs, and what it prints is right: the
stroke against the group-by-group routines (DPRM1, DPRM2), J_red against its direct sum,
the flywheel's realized delta; the dask recipe's worst transmission angles against the
closed form of the four-bar's extreme transmission angles."""

import math
import pathlib
import re

import numpy as np
import pytest

import sarkp

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def blocks():
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## Your own mechanism"):]
    section = section[:section.index("\n## ", 3)]
    return re.findall(r"```python\n(.*?)```", section, re.S)


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import os
    here = os.getcwd()
    os.chdir(tmp_path_factory.mktemp("readme"))
    ns = {}
    try:
        exec(compile(blocks()[0], "README.md", "exec"), ns)
        ns["png"] = pathlib.Path("sixbar.png").stat().st_size
    finally:
        os.chdir(here)
    return ns


def test_example_prints_checked_values(example, capsys):
    ns = example
    r, phi = ns["r"], ns["phi"]
    # the stroke of E from the chapter 4 routines, group by group
    xa, ya = 0.1 * np.cos(phi), 0.1 * np.sin(phi)
    p1 = sarkp.DPRM1(xa, ya, -0.25, 0.35, 0.5, 0.3, -1.0)       # P = -1: B left of A->C
    xd, yd = -0.25 + 0.3 * np.cos(p1.FI3 + math.pi), 0.35 + 0.3 * np.sin(p1.FI3 + math.pi)
    p2 = sarkp.DPRM2(xd, yd, 0.0, 0.5, 0.0, 0.4, 0.0, 0.0)
    np.testing.assert_allclose(r.position("E")[:, 0], p2.XB, rtol=0, atol=1e-14)
    assert ns["png"] > 10_000
    assert ns["fw"].delta == pytest.approx(0.02, rel=1e-9)
    # J_red: the sum over the links, from the result's own velocities
    m = ns["m"]
    m.point("S2", "A", "B", 0.25)
    m.point("S4", "D", "E", 0.2)
    rs = m.solve(phi, omega=1.0, need="velocities")
    J = (2.5 * np.sum(rs.velocity("S2") ** 2, -1) + 0.05 * rs.omega("A", "B") ** 2
         + 0.09 * rs.omega("C", "B") ** 2
         + 2.0 * np.sum(rs.velocity("S4") ** 2, -1) + 0.03 * rs.omega("D", "E") ** 2
         + 5.0 * np.sum(rs.velocity("E") ** 2, -1))
    np.testing.assert_allclose(r.reduced_inertia, J, rtol=1e-13)


def test_dask_recipe_local_scheduler():
    pytest.importorskip("dask")
    ns = {"sarkp": sarkp, "np": np, "math": math}
    exec(compile(blocks()[1], "README.md", "exec"), ns)
    # the four-bar's transmission angle is extreme where the crank is along O-C: the
    # diagonal B-D... A-C is then OC -+ OA, and the cosine law gives the angle at B
    oc = math.hypot(-0.25, 0.35)
    assert len(ns["worst"]) == 10 ** 4
    for (rab, rcb), worst in zip(ns["grid"], ns["worst"]):
        cos = [(rab**2 + rcb**2 - d**2) / (2 * rab * rcb) for d in (oc - 0.1, oc + 0.1)]
        if max(abs(c) for c in cos) > 1:
            assert worst == 0.0                   # does not turn all round
            continue
        expected = min(90.0 - abs(90.0 - math.degrees(math.acos(c))) for c in cos)
        assert worst == pytest.approx(expected, abs=0.05), (rab, rcb)
