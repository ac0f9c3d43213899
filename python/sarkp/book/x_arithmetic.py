"""Program X's kinematics, forces and dynamics (L7499-7633) in another arithmetic: the
ES EVM's truncating hexadecimal REAL*4 (:class:`sarkp.book.es_evm.Real4`) or IEEE single
precision (numpy.float32).

Evidence, not the library: the main program's loop DO 30 and the printed routines it
calls (DPRM1, DPRM2, DSKOR1, DSKOR2, DUSKR1, DUSKR2, DNMAF2, DNMAF1, DSMVKT, DMOMNT,
DVKT, DUGL2-5, DUGOL, DOMEGA: L551-698, L1479-2400, L6994-7096; DZKNDV, DMHVK, DINTGR,
DFRNCL: L7560-7620, L462-503) and IBM SSP's GELG, statement by statement and left to right
as written, every operation in the chosen arithmetic; library functions (SIN, COS, ...)
and the program's decimal constants (0.15, 9.81, ...) are the exact values converted to
it (truncated for the ES EVM, as :class:`es_evm.Real4` converts every number: the
machine's own library and compiler conversions are not known digit for digit, which is
one reason an emulated cell can miss where the printed run did not).  Independent of sarkp's Fortran.  The printed
run's own errors are kept as the printed figures have them: DUSKR1's ``ABS(Y(1))``
(E-DUSKR1-1), omega2 passed for omega4 (E-X-W4), the m3 term counted twice
(E-X-IPR-1), delta = 0.01 (E-X-DELTA-1); the 13-argument DPRM2 call (L7512) is read
as sarkp reads it (E-X-DPRM2-1).  The link lengths are :data:`sarkp.book.x_data.FITTED_LINKS`
(E-X-LINKS-1) converted to the arithmetic.

``run(arithmetic)`` returns the stages "kinematics", "forces", "dynamics" as
:func:`sarkp.book.x_stages.stage_cells` takes them; ``figure_cells(number, arithmetic)``
Figs. 91, 94, 96 as cells.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from . import es_evm, x_data, x_stages
from .prog_ii_13 import _gelg_es_evm

#: the arithmetics this module runs ("double": the same statements in IEEE double, the
#: check that they are the program sarkp runs)
ARITHMETICS = ("es-evm", "ieee-single", "double")
#: the figures it computes
FIGURES = ("91", "94", "96")


def _number(arithmetic: str):
    if arithmetic == "es-evm":
        return es_evm.Real4, es_evm.fn
    if arithmetic == "ieee-single":
        def fn(function):
            return lambda *x: np.float32(function(*(float(v) for v in x)))
        return np.float32, fn
    if arithmetic == "double":
        return float, lambda function: function
    raise ValueError(f"arithmetic must be one of {', '.join(ARITHMETICS)}, "
                     f"not {arithmetic!r}")


def _power(x, n):
    """X ** N of a FORTRAN integer constant N: multiplications by repeated squaring."""
    if n == 1:
        return x
    half = _power(x, n // 2)
    return half * half if n % 2 == 0 else half * half * x


def run(arithmetic: str = "es-evm", lengths: dict | None = None) -> dict:
    """The stages kinematics, forces, dynamics of program X in ``arithmetic`` (the ES
    EVM's under the library model in force, :func:`sarkp.book.es_evm.rounded`), with the
    link lengths ``lengths`` ({ROA, RAB, ROC, RCD, RDE}; default the fitted ones,
    :data:`sarkp.book.x_data.FITTED_LINKS`; scripts/fit_x_links.py refits with them)."""
    key = None if lengths is None else tuple(float(lengths[n]) for n in LENGTHS)
    return _run(arithmetic, es_evm.rounded() if arithmetic == "es-evm" else None, key)


#: the link lengths :func:`run` takes
LENGTHS = ("ROA", "RAB", "ROC", "RCD", "RDE")


@lru_cache(maxsize=64)
def _run(arithmetic: str, model, lengths) -> dict:
    R, fn = _number(arithmetic)
    if arithmetic == "es-evm":                        # the stated library model
        sin, cos, tan, atan, acos, sqrt = (es_evm.SIN, es_evm.COS, es_evm.TAN, es_evm.ATAN,
                                           es_evm.ACOS, es_evm.SQRT)
    else:
        sin, cos, tan, atan, acos, sqrt = (fn(math.sin), fn(math.cos), fn(math.tan),
                                           fn(math.atan), fn(math.acos), fn(math.sqrt))
    zero, one, two = R(0.0), R(1.0), R(2.0)

    def sign(a, b):                                   # FORTRAN SIGN
        return R(abs(a)) if b >= 0.0 else R(-abs(a))

    pi_local = R(3.14159)                             # DUGOL's, DUGL5's, DZKNDV's own PI
    pi = R(3.14159)                                   # COMMON /PRMTR/ (L7276-7277)
    pid2 = pi / two

    def dvkt(x1, y1, x2, y2):                         # II.11
        rz = sqrt(_power(x2 - x1, 2) + _power(y2 - y1, 2))
        if rz == 0.0:
            return rz, zero
        return rz, sign(acos((x2 - x1) / rz), y2 - y1)

    def dugl2(x1, y1, x2, y2):                        # II.4
        dl = sqrt(_power(x2 - x1, 2) + _power(y2 - y1, 2))
        return sign(acos((x2 - x1) / dl), y2 - y1)

    def dugl3(ugol1, ugold, vel):                     # II.5
        return ugol1 + sign(ugold, vel)

    def dugl4(ugol1, ugold, vel):                     # II.6
        return ugol1 - ugold if vel < 0.0 else ugol1

    def dugl5(prx, pry):                              # II.7
        if abs(prx) == 0.0:
            return sign(pi_local / two, pry)
        d = pry / prx
        return atan(d) if prx >= 0.0 else pi_local + atan(d)

    def dugol(fi):                                    # II.8
        return fi if fi >= 0.0 else fi + two * pi_local

    def domega(razmer, vektor, ugol):                 # II.10
        return sign(vektor / razmer, ugol)

    def dsmvkt(l1, fi1, l2, fi2):                     # II.12
        lx = l1 * cos(fi1) + l2 * cos(fi2)
        ly = l1 * sin(fi1) + l2 * sin(fi2)
        return sqrt(_power(lx, 2) + _power(ly, 2)), dugl5(lx, ly)

    def dmomnt(r, fi, f, g):                          # II.9
        return r * cos(fi) * f * sin(g) - r * sin(fi) * f * cos(g)

    def gelg(y, x):                                   # 2 x 2, EPS = 0.0001
        return _gelg_es_evm(y, [x[0][0], x[1][0], x[0][1], x[1][1]], 2, R(0.0001), R)

    def dprm1(xa, ya, xc, yc, rz2, rz3, p):           # IV.1
        rzac, fiac = dvkt(xa, ya, xc, yc)
        fiac = dugol(fiac)
        ugbac = acos((_power(rz2, 2) + _power(rzac, 2) - _power(rz3, 2)) / (two * rz2 * rzac))
        ugbca = acos((_power(rz3, 2) + _power(rzac, 2) - _power(rz2, 2)) / (two * rz3 * rzac))
        fi2 = dugol(fiac - p * ugbac)
        fi3 = dugol(fiac + p * ugbca - p * pi)
        return fi2, fi3, xa + rz2 * cos(fi2), ya + rz2 * sin(fi2)

    def dprm2(xa, ya, xk, yk, fim, rz2, rz3, t):      # IV.2
        uk1 = tan(fim)
        xo1 = ((xa + _power(uk1, 2) * xk) - uk1 * (yk - ya)) / (_power(uk1, 2) + one)
        yo1 = ((yk + _power(uk1, 2) * ya) - uk1 * (xk - xa)) / (_power(uk1, 2) + one)
        r = sqrt(_power(xa - xo1, 2) + _power(ya - yo1, 2)) - rz3 * sin(t)
        fir = dugl2(xa, ya, xo1, yo1)
        b = sqrt(_power(rz2, 2) - _power(r, 2))
        x = r * cos(fir) + b * cos(fim)
        y = r * sin(fir) + b * sin(fim)
        fi2 = dugl5(x, y)
        return xa + rz2 * cos(fi2), ya + rz2 * sin(fi2), fi2

    def dskor1(rz2, fi2, rz3, fi3, va, ala, vc, alc):  # IV.5
        x = [[cos(fi2 + pid2), -cos(fi3 + pid2)], [sin(fi2 + pid2), -sin(fi3 + pid2)]]
        y = gelg([vc * cos(alc) - va * cos(ala), vc * sin(alc) - va * sin(ala)], x)
        alba, vba = dugl3(fi2, pid2, y[0]), R(abs(y[0]))
        albc, vbc = dugl3(fi3, pid2, y[1]), R(abs(y[1]))
        vb, alb = dsmvkt(va, ala, vba, alba)
        return (vba, alba, vbc, albc, vb, alb, domega(rz2, vba, alba - fi2),
                domega(rz3, vbc, albc - fi3))

    def dskor2(va, ala, vbm, albm, rz2, fi2, fim):    # IV.6 with VBA, ALBA (E-DSKOR2-1)
        x = [[cos(fi2 + pid2), -cos(fim)], [sin(fi2 + pid2), -sin(fim)]]
        y = gelg([vbm * cos(albm) - va * cos(ala), vbm * sin(albm) - va * sin(ala)], x)
        alba, vba = dugl3(fi2, pid2, y[0]), R(abs(y[0]))
        albbm, vbbm = dugl4(fim, pi, y[1]), R(abs(y[1]))
        w2 = domega(rz2, vba, alba - fi2)
        vb, alb = dsmvkt(va, ala, vba, alba)
        return vba, alba, vbbm, albbm, vb, alb, w2

    def duskr1(aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3):      # IV.10
        x = [[cos(fi2 + pid2), -cos(fi3 + pid2)], [sin(fi2 + pid2), -sin(fi3 + pid2)]]
        y = gelg([ac * cos(bc) + _power(w3, 2) * rz3 * cos(fi3 - pi) - aa * cos(ba)
                  - _power(w2, 2) * rz2 * cos(fi2 - pi),
                  ac * sin(bc) + _power(w3, 2) * rz3 * sin(fi3 - pi) - aa * sin(ba)
                  - _power(w2, 2) * rz2 * sin(fi2 - pi)], x)
        bbat, abat = dugl3(fi2, pid2, y[0]), R(abs(y[0]))
        bbct, abct = dugl3(fi3, pid2, y[1]), R(abs(y[0]))         # E-DUSKR1-1
        a, b = dsmvkt(aa, ba, _power(w2, 2) * rz2, fi2 - pi)
        ab, bb = dsmvkt(a, b, abat, bbat)
        return ab, bb, domega(rz2, abat, bbat - fi2), domega(rz3, abct, bbct - fi3)

    def duskr2(aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim):   # IV.11
        x = [[cos(fi2 + pid2), -cos(fim)], [sin(fi2 + pid2), -sin(fim)]]
        y = gelg([abm * cos(bvm) + abk * cos(bvk) - aa * cos(ba)
                  - _power(w2, 2) * rz2 * cos(fi2 - pi),
                  abm * sin(bvm) + abk * sin(bvk) - aa * sin(ba)
                  - _power(w2, 2) * rz2 * sin(fi2 - pi)], x)
        vbat, abat = dugl3(fi2, pid2, y[0]), R(abs(y[0]))
        e2 = domega(rz2, abat, vbat - fi2)
        a, b = dsmvkt(aa, ba, _power(w2, 2) * rz2, fi2 - pi)
        ab, bb = dsmvkt(a, b, abat, vbat)
        return e2, ab, bb

    def dnmaf2(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3):  # VII.1
        f12m = -(f2 * cos(g2 - fim) + f3 * cos(g3 - fim))
        g12m = dugl4(fim, pi, f12m)
        r, fi = dvkt(xb, yb, xa, ya)
        rbs2, fibs2 = dvkt(xb, yb, xs2, ys2)
        f12nm = -(t2 + rbs2 * f2 * sin(g2 - fibs2) + r * R(abs(f12m)) * sin(g12m - fi)) / (
            r * sin(fim + pid2 - fi))
        g12nm = dugl3(fim, pid2, f12nm)
        f12, g = dsmvkt(R(abs(f12m)), g12m, R(abs(f12nm)), g12nm)
        f23, g23 = dsmvkt(f12, g, f2, g2)
        f34, g34 = dsmvkt(f23, g23, f3, g3)
        return f12, g - pi, f23, g23, f34, g34

    def dnmaf1(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3):  # VII.2
        rbs2, fibs2 = dvkt(xb, yb, xs2, ys2)
        rcs2, fics2 = dvkt(xc, yc, xs2, ys2)
        rcs3, fics3 = dvkt(xc, yc, xs3, ys3)
        rca, fica = dvkt(xc, yc, xa, ya)
        r, fi = dvkt(xa, ya, xb, yb)
        f12t = -(rbs2 * f2 * sin(g2 - fibs2) + t2) / r
        g12t = dugl4(fi - pid2, -pi, f12t)
        f12t = R(abs(f12t))
        f12n = -(f12t * rca * sin(g12t - fica) + f2 * rcs2 * sin(g2 - fics2)
                 + f3 * rcs3 * sin(g3 - fics3) + t2 + t3) / (rca * sin(fi - fica))
        g12n = dugl4(fi, pi, f12n)
        f21, g = dsmvkt(R(abs(f12t)), g12t, R(abs(f12n)), g12n)
        f23, g23 = dsmvkt(f21, g, f2, g2)
        f34, g34 = dsmvkt(f23, g23, f3, g3)
        return f21, g - pi, f23, g23, f34, g34

    from .. import as_printed
    with as_printed():
        links = x_stages.synthesis()
    if lengths is not None:
        links.update(zip(LENGTHS, lengths))
    roa, r2, roc = R(links["ROA"]), R(links["RAB"]), R(links["ROC"])
    rcd = rcb = R(links["RCD"])
    rde = R(links["RDE"])
    h5, delta, w1 = R(x_data.H5), R(x_data.DELTA), R(x_data.W1)
    g, ml = R(x_data.G), R(x_data.ML)
    kin = {n: [] for n in ("FI1", "FI2", "FICB", "XE", "FIDE", "XB", "YB", "W2", "W3",
                           "VE", "ALE", "W4", "E2", "E3", "E4", "AE", "BE")}
    fo = {n: [] for n in ("F43", "G43", "F45", "G45", "F50", "G50", "F21", "G21", "F23",
                          "G23", "F30", "G30", "M1")}
    ipr = []
    df = two * pi / R(36.0)                           # L7500-7502
    f = -df
    xc = -roc * sin(delta)
    yc = roc * cos(delta)
    m4 = ml * rde                                     # L7543-7550
    m5 = two * m4
    m3 = two * rcd * ml
    m2 = ml * r2
    is4 = m4 * _power(rde, 2)
    is3 = m3 * _power(two * rcd, 2)
    is2 = m2 * _power(r2, 2)
    is1 = (ml * roa) * _power(roa, 2)
    for _ in range(x_data.POSITIONS):                 # DO 30 K = 1, 37
        f = f + df
        xa, ya = roa * cos(f), roa * sin(f)
        fi2, ficb, xb, yb = dprm1(xa, ya, xc, yc, r2, rcb, R(-1.0))
        xd = xc + rcd * cos(ficb + pi)
        yd = yc + rcd * sin(ficb + pi)
        xe, ye, fide = dprm2(xd, yd, zero, h5 + yc, zero, rde, zero, pid2)  # E-X-DPRM2-1
        va = w1 * roa
        ala = f + pid2
        vba, alba, vbc, albc, vb, alb, w2, w3 = dskor1(r2, fi2, rcb, ficb, va, ala, zero,
                                                       zero)
        vd = rcd * R(abs(w3))
        ald = dugl3(ficb + pi, pid2, w3)
        ved, aled, veg, aleg, ve, ale, w4 = dskor2(vd, ald, zero, zero, rde, fide, zero)
        aa = _power(w1, 2) * roa
        ba = f + pi
        ab, bb, e2, e3 = duskr1(aa, ba, zero, zero, r2, fi2, rcb, ficb, w2, w3)
        ad = rcd * sqrt(_power(w3, 4) + _power(e3, 2))
        bd = dugl3(ficb + pi, pi - atan(R(abs(e3)) / _power(w3, 2)), e3)
        e4, ae, be = duskr2(ad, bd, zero, zero, zero, zero, rde, fide, w2, zero)  # E-X-W4
        for name, v in zip(kin, (f, fi2, ficb, xe, fide, xb, yb, w2, w3, ve, ale, w4, e2,
                                 e3, e4, ae, be)):
            kin[name].append(v)
        # forces, L7551-7566
        fs = R(2000.0) if w3 < 0.0 else R(400.0)
        f5, g5 = dsmvkt(fs, pi, two * g * m4, -pid2)
        xs4 = xd + R(0.3) * rde * cos(fide)
        ys4 = yd + R(0.3) * rde * sin(fide)
        f43, g43, f45, g45, f50, g50 = dnmaf2(xd, yd, xe, ye, zero, xs4, ys4, g * m4, -pid2,
                                              xe, ye, f5, g5, zero, zero)
        f3, g3 = dsmvkt(f43, g43, g * m3, -pid2)
        t3 = dmomnt(R(0.85) * rcd, ficb + pi, f43, g43)
        f21, g21, f23, g23, f30, g30 = dnmaf1(
            xa, ya, xb, yb, xc, yc, xa + R(0.5) * r2 * cos(fi2), ya + R(0.5) * r2 * sin(fi2),
            g * m2, -pid2, xc + R(0.15) * rcd * cos(ficb + pi),
            yc + R(0.15) * rcd * sin(ficb + pi), f3, g3, zero, t3)
        m1 = dmomnt(roa, f, f21, g21)
        for name, v in zip(fo, (f43, g43, f45, g45, f50, g50, f21, g21, f23, g23, f30,
                                g30, m1)):
            fo[name].append(v)
        # the reduced moment of inertia, L7573-7579 (E-X-IPR-1: the m3 term twice)
        vs4, _ = dsmvkt(vd, ald, R(abs(w4)) * R(0.3) * rde, aled)
        vs2, _ = dsmvkt(va, ala, R(abs(w2)) * r2 / two, alba)
        ipr.append((m5 * _power(ve, 2) + m4 * _power(vs4, 2) + is4 * _power(w4, 2)
                    + m3 * _power(w3 * R(0.15) * rcd, 2)
                    + (is3 + m3 * _power(R(0.15) * rcd, 2)) * _power(w3, 2)
                    + m2 * _power(vs2, 2) + is2 * _power(w2, 2)) / _power(w1, 2))

    n = x_data.POSITIONS

    def dzkndv(isc):                                  # VIII.1 with DINTGR, DFRNCL
        zm = R(float(n))
        h = two * pi_local / (zm - one)
        as_ = [zero]
        for k in range(1, n):                         # DINTGR, NOMER = 2
            as_.append(as_[k - 1] + R(0.5) * h * (fo["M1"][k - 1] + fo["M1"][k]))
        dad = as_[n - 1] / (zm - one)
        z, asum, ev, dec = R(-1.0), [], [], []
        for k in range(n):
            z = z + one
            asum.append(as_[k] - dad * z)
            ev.append(ipr[k] * _power(w1, 2) / two)
            dec.append(asum[k] - ev[k])
        ddd = dec[0]
        dec = [d - ddd for d in dec]
        c1, c2 = max(dec), min(dec)
        decsr = (c1 + c2) / two
        wpr = [w1 + (d - decsr) / w1 / isc for d in dec]
        epr = [zero] + [(wpr[k + 1] - wpr[k]) / h for k in range(n - 1)]   # DFRNCL
        return as_, asum, ev, dec, wpr, epr

    as_, asum, ev, dec, wpr, epr = dzkndv(is1)
    c1, c2 = max(dec), min(dec)                       # VIII.2 DMHVK(37, 0.01, ...)
    imh = (c1 + R(abs(c2))) / R(0.01) / _power(w1, 2) - is1
    *_, wprm, eprm = dzkndv(is1 + imh)

    def arrays(d):
        return {k: np.array([float(v) for v in vs]) for k, vs in d.items()}
    kinematics = arrays(kin)
    forces = {"FI1": kinematics["FI1"], **arrays(fo)}
    dynamics = {"FI1": kinematics["FI1"], **arrays({
        "IPR": ipr, "AS": as_, "ASUM": asum, "EV": ev, "DEC": dec, "WPR": wpr, "EPR": epr,
        "WPRM": wprm, "EPRM": eprm}), "IMH": float(imh)}
    return {"kinematics": kinematics, "forces": forces, "dynamics": dynamics}


def figure_cells(number: str, arithmetic: str = "es-evm") -> dict:
    """Fig. ``number`` (91, 94 or 96) of program X in ``arithmetic``, as cells."""
    stage = {"91": "kinematics", "94": "forces", "96": "dynamics"}[str(number)]
    return x_stages.stage_cells(stage, run(arithmetic)[stage])
