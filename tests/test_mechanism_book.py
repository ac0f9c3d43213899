"""The book's programs on sarkp.Mechanism: program X's six-bar (x_mechanism), IV.15's
and VII.10's mechanism of Fig. 29/57 (kinds 1-5), against their group-by-group corrected
paths (the chapter 4 and 7 routines called one group at a time), to 1e-13 relative."""

import math

import numpy as np
import pytest

import sarkp
from sarkp.book import prog_x, x_mechanism

TOL = 1e-13


def close(a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = np.max(np.abs(b)) if scale is None else scale
    return np.max(np.abs(a - b)) <= TOL * s


def same_angle(a, b):
    return np.max(np.abs(np.remainder(a - b + math.pi, 2 * math.pi) - math.pi)) <= TOL * 10


@pytest.fixture(scope="module")
def x_paths():
    with sarkp.mode("corrected"):
        links = prog_x.synthesis()
        kin = prog_x.kinematics(links)
        fo = prog_x.forces(links, kin)
        ipr = prog_x.reduced_inertia(links, kin)
        ours = x_mechanism.solve(links)
    return links, kin, fo, ipr, ours


def test_program_x_kinematics(x_paths):
    links, kin, fo, ipr, ours = x_paths
    for name in ("XE", "YE", "XB", "YB", "XD", "YD", "W2", "W3", "W4", "VE", "E2", "E3",
                 "E4", "AE"):
        assert close(ours[name], kin[name]), name
    for name in ("FI2", "FICB", "FIDE", "ALE", "BE"):
        assert same_angle(ours[name], kin[name]), name


def test_program_x_forces_and_reduced_inertia(x_paths):
    links, kin, fo, ipr, ours = x_paths
    scale = max(np.max(fo[f]) for f in ("F43", "F45", "F50", "F21", "F23", "F30"))
    for name in ("F43", "F45", "F50", "F21", "F23", "F30"):
        book = np.stack([fo[name] * np.cos(fo["G" + name[1:]]),
                         fo[name] * np.sin(fo["G" + name[1:]])], -1)
        assert close(ours["vectors"][name], book, scale), name
    assert close(ours["M1"], fo["M1"])
    assert close(ours["IPR"], ipr)
