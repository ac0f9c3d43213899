"""The README's section "Designing a linkage" runs, and what it prints is right: the
function generator against Freudenstein's equation solved here by Cramer's rule and its
structural error against the circles' intersection; the path generator's error and
transmission angles against a solve of the found mechanism."""

import math
import pathlib
import re

import numpy as np
import pytest

README = pathlib.Path(__file__).resolve().parents[1] / "README.md"


def blocks():
    text = README.read_text(encoding="utf-8")
    section = text[text.index("## Designing a linkage"):]
    section = section[:section.index("\n## ", 3)]
    return re.findall(r"```python\n(.*?)```", section, re.S)


@pytest.fixture(scope="module")
def run():
    ns = {}
    for block in blocks():
        exec(compile(block, "README.md", "exec"), ns)
    return ns


def test_function_generation_example(run, capsys):
    ns = run
    x = ns["x"]
    phi, psi = ns["crank"](x), ns["rocker"](x)
    M = np.column_stack([np.cos(psi), -np.cos(phi), np.ones(3)])
    r = np.cos(phi - psi)
    det = np.linalg.det(M)
    K = [np.linalg.det(np.column_stack([r if j == i else M[:, j] for j in range(3)])) / det
         for i in range(3)]
    a, c = 1.0 / K[0], 1.0 / K[1]
    b = math.sqrt(a * a + c * c + 1.0 - 2 * a * c * K[2])
    L = ns["fg"].lengths
    assert max(abs(L["a"] - a), abs(L["b"] - b), abs(L["c"] - c)) <= 1e-12
    # the printed structural error, from the circles' intersection
    xs = np.linspace(1.0, 2.0, 201)
    f = ns["crank"](xs)
    A = np.column_stack([a * np.cos(f), a * np.sin(f)])
    u = np.array([1.0, 0.0]) - A
    d = np.hypot(*u.T)
    s = (b * b - c * c + d * d) / (2 * d)
    h = np.sqrt(b * b - s * s) * ns["fg"].branch
    e = u / d[:, None]
    B = A + s[:, None] * e + h[:, None] * np.column_stack([-e[:, 1], e[:, 0]])
    err = np.angle(np.exp(1j * (np.arctan2(B[:, 1], B[:, 0] - 1.0) - ns["rocker"](xs))))
    assert abs(np.abs(err).max() - np.abs(ns["error"]).max()) <= 1e-12
    exec(compile(blocks()[0], "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert f"structural error over [1, 2]: {np.degrees(np.abs(err).max()):.2f} deg" in out


def test_path_generation_example(run):
    pg, targets, phi = run["pg"], run["targets"], run["phi"]
    P = pg.mechanism.solve(phi, need="positions").position("P")
    assert np.max(np.hypot(*(P - targets).T)) <= 1e-8
    turn = pg.mechanism.solve(np.linspace(0, 2 * math.pi, 3600), need="positions")
    A, B, C = (turn.position(k) for k in "ABC")
    u, v = A - B, C - B
    mu = np.degrees(np.arccos((u * v).sum(1) / np.hypot(*u.T) / np.hypot(*v.T)))
    assert mu.min() >= 30.0 and mu.max() <= 150.0
