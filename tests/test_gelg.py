"""GELG over LAPACK: solutions, and the SSP meaning of IER."""

import numpy as np
import pytest

import sarkp
from sarkp import GELG, _sarkp


@pytest.mark.parametrize("m", range(1, 9))
@pytest.mark.parametrize("n", [1, 2, 3])
def test_random_well_conditioned_systems(m, n):
    rng = np.random.default_rng(100 * m + n)
    for _ in range(20):
        a = rng.standard_normal((m, m)) + m * np.eye(m)
        r = rng.standard_normal((m, n))
        x, ier = GELG(r, a, m, n, 1e-4)
        assert ier == 0
        exact = np.linalg.solve(a, r)
        np.testing.assert_allclose(x, exact, rtol=1e-12, atol=1e-12 * np.abs(exact).max())


def test_the_books_call_shape():
    # CALL GELG(C, A, 2, 1, 0.0001, IER) with C(2): one right-hand side as a vector
    x, ier = GELG([1.0, 2.0], [[2.0, 1.0], [1.0, 3.0]], 2, 1, 0.0001)
    assert ier == 0 and x.shape == (2,)
    np.testing.assert_allclose(x, [0.2, 0.6], rtol=1e-15)


def test_exactly_singular_gives_minus_one_and_leaves_r():
    r = np.array([1.0, 2.0, 3.0])
    a = np.array([[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [1.0, 0.0, 1.0]])
    x, ier = GELG(r, a, 3, 1, 1e-4)
    assert ier == -1
    np.testing.assert_array_equal(x, r)


def test_zero_matrix_gives_minus_one():
    assert GELG([1.0], [[0.0]], 1, 1, 1e-4).IER == -1


@pytest.mark.parametrize("m", [0, -3, 2.5, float("nan"), float("inf")])
def test_m_out_of_range_is_named(m):
    """SSP returned IER = -1 for M < 1; here M is checked against the arrays first."""
    with pytest.raises(ValueError, match="GELG: M = "):
        GELG([1.0], [[1.0]], m, 1, 1e-4)


@pytest.mark.parametrize("m, rank", [(2, 1), (3, 1), (3, 2), (5, 3), (8, 6)])
def test_nearly_singular_reports_the_numerical_rank(m, rank):
    """A = U diag(s) V^T with m - rank singular values of 1e-9: SSP's IER = rank."""
    rng = np.random.default_rng(m * 10 + rank)
    u, _ = np.linalg.qr(rng.standard_normal((m, m)))
    v, _ = np.linalg.qr(rng.standard_normal((m, m)))
    s = np.r_[np.linspace(2.0, 1.0, rank), np.full(m - rank, 1e-9)]
    a = u @ np.diag(s) @ v.T
    r = rng.standard_normal(m)
    x, ier = GELG(r, a, m, 1, 1e-4)
    assert ier == rank
    # the solution is still returned, and solves the system as well as rounding allows
    np.testing.assert_allclose(a @ x, r, atol=1e-6 * np.abs(x).max() * np.abs(a).max())


def test_the_tolerance_decides_the_warning():
    a = [[1.0, 0.0], [0.0, 1e-3]]
    assert GELG([1.0, 1.0], a, 2, 1, 1e-4).IER == 0
    assert GELG([1.0, 1.0], a, 2, 1, 1e-2).IER == 1


def test_one_by_one_never_warns():
    # SSP warns at step K+1 with IER = K: a 1x1 system has no second step
    assert GELG([3.0], [[1e-10]], 1, 1, 1e-4) == (pytest.approx([3e10]), 0)


def test_lapack_errors_never_print_or_stop():
    """XERBLA is ours: a bad LAPACK argument comes back as INFO < 0, nothing printed."""
    before = int(_sarkp.gelg_mod.xerbla_calls)
    assert _sarkp.gelg_mod.lapack_probe() == -1
    assert int(_sarkp.gelg_mod.xerbla_calls) == before + 1
    assert bytes(_sarkp.gelg_mod.xerbla_last_routine).strip() == b"DGETRF"


def test_bad_input():
    with pytest.raises(ValueError, match="A"):
        GELG([1.0, 1.0], [[1.0, np.nan], [0.0, 1.0]], 2, 1, 1e-4)
    with pytest.raises(ValueError, match="shape"):
        GELG([1.0, 1.0], [[1.0, 0.0]], 2, 1, 1e-4)
    assert issubclass(sarkp.SingularError, sarkp.SarkpError)


def _systems(rng, n):
    """2x2 systems of every kind: random over 200 decades of scale (a few overflow or
    underflow), nearly singular, exactly singular, with zeros and with ties among the
    largest elements."""
    scale = 10.0 ** rng.integers(-150, 150, (n, 1, 1))
    a = rng.standard_normal((n, 2, 2)) * scale
    c = rng.standard_normal((n, 2)) * scale[:, 0] * 10.0 ** rng.integers(-20, 20, (n, 1))
    k = n // 5
    a[:k, 1] = 2.0 * a[:k, 0]                                             # nearly singular
    a[:k, 1, 1] *= 1 + 10.0 ** rng.integers(-17, -3, k)
    a[k:2 * k, 1] = 2.0 * a[k:2 * k, 0]                                   # singular
    a[2 * k:3 * k][rng.random((k, 2, 2)) < 0.4] = 0.0                    # zeros
    a[3 * k:4 * k] = rng.integers(-2, 3, (k, 2, 2))                      # ties
    c[3 * k:4 * k] = rng.integers(-2, 3, (k, 2))
    return a, c


def test_two_by_two_path_is_bit_for_bit_gelg():
    """gelg2, the 2x2 GELG every group solves, written out without LAPACK calls: the same
    solutions, bit for bit, and the same IER as GELG over LAPACK DGETC2/DGESC2."""
    rng = np.random.default_rng(7)
    a, c = _systems(rng, 20000)
    kinds = {0: 0, 3: 0, 2: 0}
    for k in range(len(a)):
        aa, cc = np.asfortranarray(a[k]), c[k].copy()
        st = _sarkp.gelg_mod.gelg2(aa, cc)
        try:
            ref = GELG(c[k], a[k], 2, 1, 1e-4)
        except sarkp.RangeError:                  # the solution overflows
            ref = None
        if ref is None or ref.IER < 0 or not np.all(np.isfinite(ref.R)):
            assert st == 2 and np.all(cc == 0.0), (a[k], c[k])
        else:
            assert st == (3 if ref.IER > 0 else 0), (a[k], c[k], ref)
            assert cc.tobytes() == ref.R.tobytes(), (a[k], c[k], cc, ref.R)
        kinds[st] += 1
    assert min(kinds.values()) > 1000          # every outcome was exercised


def test_one_elimination_for_two_right_hand_sides():
    """DKNMA1 solves its velocities and accelerations with one matrix: gelg2_lu once, then
    gelg2_solve for each right-hand side, is bit for bit two gelg2 calls (solution and
    status), on the same edge cases (near-singular, singular, zeros, ties)."""
    rng = np.random.default_rng(11)
    a, c = _systems(rng, 5000)
    c2 = rng.standard_normal(c.shape) * 10.0 ** rng.integers(-3, 4, (len(c), 1))
    for k in range(len(a)):
        lu = np.asfortranarray(a[k])
        ipv, jpv, amax, r, st_lu = _sarkp.gelg_mod.gelg2_lu(lu)
        for rhs in (c[k], c2[k]):
            ref, got = rhs.copy(), rhs.copy()
            st_ref = _sarkp.gelg_mod.gelg2(np.asfortranarray(a[k]), ref)
            if st_lu == 0:
                st = _sarkp.gelg_mod.gelg2_solve(lu, ipv, jpv, amax, r, got)
            else:
                st, got = st_lu, np.zeros(2)
            assert st == st_ref and got.tobytes() == ref.tobytes(), (a[k], rhs)
