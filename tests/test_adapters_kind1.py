"""DSKOR1 and DUSKR1 (corrected mode) are adapters over the kind-1 kernel's velocity and
acceleration stages (fortran/groups.f90: rrr_velocity, rrr_acceleration), the stages
DKNMA1 and sarkp.Mechanism run (issue 25, "one home for each Assur group kind").

Checked here: fed the same Cartesian data they give DKNMA1's bits; their values against
mpmath (the book's vector equations solved at 50 digits on the exact double inputs, and
the derivatives of a four-bar's closed-form positions); their statuses against the true
error on the way into a dead centre.  As printed they keep the book's sequence (the
figure tests pin it)."""

import math
import sys
import warnings
from pathlib import Path

import mpmath
import numpy as np
import pytest

import sarkp

sys.path.insert(0, str(Path(__file__).resolve().parent))   # --import-mode=importlib
from test_book_adapters import _polar_exact  # noqa: E402
from test_reliability import DELTAS, bound, e, kx, mpf, raw, rel_err, solve, vec  # noqa: E402

U = 2.0**-53


def _random_group(rng):
    """A kind-1 group with A at the origin and C on the x axis (so that B - A and B - C
    are DKNMA1's XB, YB and XB - XC, YB to the bit), polar velocities and accelerations."""
    d = rng.uniform(0.5, 2.0)
    l2, l3 = d * rng.uniform(0.5, 1.2), d * rng.uniform(0.5, 1.2)
    return dict(XA=0.0, YA=0.0, XC=d, YC=0.0, RZ2=l2, RZ3=l3,
                VA=rng.uniform(0.1, 3.0), ALA=rng.uniform(-4.0, 4.0),
                VC=rng.uniform(0.0, 3.0), ALC=rng.uniform(-4.0, 4.0),
                AA=rng.uniform(0.1, 30.0), BA=rng.uniform(-4.0, 4.0),
                AC=rng.uniform(0.0, 30.0), BC=rng.uniform(-4.0, 4.0),
                P=float(rng.choice([-1.0, 1.0])))


def _bits(x):
    return np.float64(x).view(np.uint64)


def test_dskor1_and_duskr1_give_dknma1s_bits():
    # Where the links' vectors RZ e(FI) that DSKOR1/DUSKR1 build are the kernel's B - A,
    # B - C to the bit (a polar pair near atan2 reproduces them for ~40% of vectors), the
    # velocity and acceleration stages see DKNMA1's data: W, E and v_B, a_B are its bits.
    rng = np.random.default_rng(2511)
    compared = 0
    for _ in range(800):
        g = _random_group(rng)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error", sarkp.SignificanceWarning)
                k = sarkp.DKNMA1(**g)
        except (sarkp.SarkpError, sarkp.SignificanceWarning):
            continue                                    # no assembly, or digits lost
        p2 = _polar_exact(k.XB, k.YB)
        p3 = _polar_exact(k.XB - g["XC"], k.YB)
        if p2 is None or p3 is None:
            continue
        (m2, f2), (m3, f3) = p2, p3
        v = sarkp.DSKOR1(m2, f2, m3, f3, g["VA"], g["ALA"], g["VC"], g["ALC"])
        a = sarkp.DUSKR1(g["AA"], g["BA"], g["AC"], g["BC"], m2, f2, m3, f3, v.W2, v.W3)
        for mine, book in [(v.W2, k.W2), (v.W3, k.W3), (v.VB, k.VB), (v.ALB, k.ALB),
                           (a.E2, k.E2), (a.E3, k.E3), (a.AB, k.AB), (a.BB, k.BB)]:
            assert _bits(mine) == _bits(book), (g, mine, book)
        compared += 1
    assert compared >= 40


def _ref_velocities(rz2, fi2, rz3, fi3, va, ala, vc, alc):
    """W2, W3 of v_A + W2 k x RZ2 e(FI2) = v_C + W3 k x RZ3 e(FI3), exact for the doubles."""
    r2, r3 = mpf(rz2) * e(mpf(fi2)), mpf(rz3) * e(mpf(fi3))
    w2, w3 = solve(kx(r2), -kx(r3), vec(vc, alc) - vec(va, ala))
    return r2, r3, w2, w3


@pytest.mark.parametrize("seed", range(3))
def test_dskor1_and_duskr1_against_mpmath(seed):
    # Away from a dead centre (|sin(FI2 - FI3)| >= 0.2: the system's condition number is
    # at most ~10) the results are exact to a few roundings of the data's size.
    rng = np.random.default_rng(seed)
    checked = 0
    while checked < 30:
        rz2, rz3 = rng.uniform(0.1, 3.0, 2)
        fi2, fi3 = rng.uniform(-7.0, 7.0, 2)
        if abs(math.sin(fi2 - fi3)) < 0.2:
            continue
        va, vc = rng.uniform(0.0, 3.0, 2)
        ala, alc = rng.uniform(-7.0, 7.0, 2)
        aa, ac = rng.uniform(0.0, 30.0, 2)
        ba, bc = rng.uniform(-7.0, 7.0, 2)
        v = sarkp.DSKOR1(rz2, fi2, rz3, fi3, va, ala, vc, alc)
        r2, r3, w2, w3 = _ref_velocities(rz2, fi2, rz3, fi3, va, ala, vc, alc)
        scale = max(va + vc, abs(v.W2) * rz2 + abs(v.W3) * rz3)
        tol = 64 * U * scale / abs(math.sin(fi2 - fi3))
        assert abs(v.W2 - w2) * rz2 <= tol and abs(v.W3 - w3) * rz3 <= tol, (v, w2, w3)
        vb = vec(va, ala) + v.W2 * kx(r2)                       # v_B from the exact W2
        assert abs(v.VB - mpmath.norm(vb)) <= 2 * tol
        assert abs(v.VBA - abs(w2) * rz2) <= tol and abs(v.VBC - abs(w3) * rz3) <= tol
        # the book's directions: VBA along FI2 + pi/2 turned by the sign of W2
        assert v.ALBA == fi2 + math.copysign(math.pi / 2, v.W2)
        # accelerations with the exact W2, W3 given as doubles
        w2d, w3d = float(w2), float(w3)
        a = sarkp.DUSKR1(aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2d, w3d)
        e2, e3 = solve(kx(r2), -kx(r3), vec(ac, bc) - vec(aa, ba) - mpf(w3d)**2 * r3
                       + mpf(w2d)**2 * r2)
        scale = aa + ac + w2d**2 * rz2 + w3d**2 * rz3
        tol = 64 * U * scale / abs(math.sin(fi2 - fi3))
        assert abs(a.E2 - e2) * rz2 <= tol and abs(a.E3 - e3) * rz3 <= tol, (a, e2, e3)
        ab = vec(aa, ba) + a.E2 * kx(r2) - mpf(w2d)**2 * r2
        assert abs(a.AB - mpmath.norm(ab)) <= 2 * tol
        assert abs(a.ABCT - abs(e3) * rz3) <= tol               # E-DUSKR1-1 corrected
        checked += 1


def _fourbar_positions(phi, r, l2, l3, xc):
    """A four-bar O = (0, 0), A = r e(phi), C = (xc, 0), B on the left of A -> C (DPRM1's
    P = -1): the directions FI2 of A -> B and FI3 of C -> B, in mpmath."""
    A = mpmath.matrix([r * mpmath.cos(phi), r * mpmath.sin(phi)])
    C = mpmath.matrix([xc, 0])
    d = mpmath.norm(C - A)
    fac = mpmath.atan2(C[1] - A[1], C[0] - A[0])
    anga = mpmath.acos((d**2 + l2**2 - l3**2) / (2 * d * l2))
    B = A + l2 * e(fac + anga)
    return mpmath.atan2(B[1] - A[1], B[0] - A[0]), mpmath.atan2(B[1] - C[1], B[0] - C[0])


def test_dskor1_and_duskr1_are_the_derivatives_of_the_positions():
    # The four-bar of the benchmarks (OA 0.1, AB 0.35, CB 0.3, OC 0.4) driven at omega,
    # epsilon: W = dFI/dt and E = d2FI/dt2 of its closed-form positions (mpmath.diff),
    # DSKOR1/DUSKR1 fed DPRM1's directions and the crank's polar velocity and acceleration.
    r, l2, l3, xc, omega, eps = 0.1, 0.35, 0.3, 0.4, 10.0, -4.0
    mpmath.mp.dps = 50
    for phi in np.linspace(-3.0, 3.0, 7):
        p = sarkp.DPRM1(r * math.cos(phi), r * math.sin(phi), xc, 0.0, l2, l3, -1.0)
        v = sarkp.DSKOR1(l2, p.FI2, l3, p.FI3, omega * r, phi + math.pi / 2, 0.0, 0.0)
        an, at = omega**2 * r, eps * r
        a = sarkp.DUSKR1(math.hypot(an, at), phi + math.atan2(at, -an), 0.0, 0.0,
                         l2, p.FI2, l3, p.FI3, v.W2, v.W3)
        for k, (w, ep) in enumerate([(v.W2, a.E2), (v.W3, a.E3)]):
            f = lambda t: _fourbar_positions(t, r, l2, l3, xc)[k]  # noqa: E731
            d1, d2 = mpmath.diff(f, mpf(phi), 1), mpmath.diff(f, mpf(phi), 2)
            w_ref, e_ref = omega * d1, omega**2 * d2 + eps * d1
            assert abs(w - w_ref) <= 1e-13 * abs(omega), (phi, k, w, w_ref)
            assert abs(ep - e_ref) <= 1e-12 * omega**2, (phi, k, ep, e_ref)


def test_duskr1_dead_centre_sequence():
    # FI3 = FI2 + pi - delta: the links stretch out; the status vouches for the digits
    # it states (1e-8 when silent) of (E2 RZ2, E3 RZ3) against mpmath
    def make(d):
        return [2.0, 0.5, 1.0, -1.0, 1.0, 0.3, 1.5, 0.3 + math.pi - d, 0.7, -0.4, 1.0]

    returned = 0
    for delta in DELTAS:
        args = make(delta)
        out, ier = raw("DUSKR1", *args)
        if ier == 2:
            continue
        returned += 1
        aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3 = args[:10]
        r2, r3 = mpf(rz2) * e(mpf(fi2)), mpf(rz3) * e(mpf(fi3))
        e2, e3 = solve(kx(r2), -kx(r3), vec(ac, bc) - vec(aa, ba) - mpf(w3)**2 * r3
                       + mpf(w2)**2 * r2)
        scale = (aa + ac + w2**2 * rz2 + w3**2 * rz3) / math.sqrt(2)
        err = rel_err([out[6] * rz2, out[7] * rz3], [e2 * mpf(rz2), e3 * mpf(rz3)], scale)
        assert err <= bound(ier), (delta, ier, err)
    assert 3 <= returned < len(DELTAS)
    with pytest.raises(sarkp.SingularError):
        sarkp.DUSKR1(2.0, 0.5, 1.0, -1.0, 1.0, 0.3, 1.5, 0.3 + math.pi, 0.7, -0.4)


def test_dskor1_warns_with_the_digits_it_keeps():
    # near the dead centre the result is kept with a SignificanceWarning whose digits the
    # true error (mpmath) does not belie
    args = (1.0, 0.3, 1.5, 0.3 + math.pi - 1e-9, 1.0, 0.0, 0.5, 2.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        v = sarkp.DSKOR1(*args)
    digits = [w.message.digits for w in caught
              if issubclass(w.category, sarkp.SignificanceWarning)]
    assert len(digits) == 1 and 1 <= digits[0] <= 7
    _, _, w2, w3 = _ref_velocities(*args)
    err = rel_err([v.W2 * 1.0, v.W3 * 1.5], [w2, w3 * mpf(1.5)], 1.5 / math.sqrt(2))
    assert err <= 10.0 ** -digits[0]
