"""Program X's printouts in the book's layout (FORMATs of L7339-7650), one renderer per
stage of :mod:`sarkp.book.prog_x`: each takes the stage's results and returns the text."""

from __future__ import annotations

import sarkp

from ..report import fortran_write
from .x_data import CAM_POINTS


def render_synthesis(s: dict) -> str:
    return "\n".join([
        fortran_write("(1X,'РАЗМЕРЫ ЗВЕНЬЕВ МАНИПУЛЯТОРА'//"
                      "'RCD = ',F7.3,' RDE = ',F7.3,' FICD = ',F7.3//)",
                      [s["RCD"], s["RDE"], s["FICD1"]]),
        fortran_write("('ROA = ',F7.3,' RAB = ',F7.3,' ROC = ',F7.3//)",
                      [s["ROA"], s["RAB"], s["ROC"]])])


def render_teeth(t: dict) -> str:
    return "\n".join(sarkp.gears.dzbpl_report(args["KS"], args["SHEMA"],
                                              None if result is None else list(result))
                     for args, result in t["variants"])


def render_gears(g: dict) -> str:
    args, k = g["DKRKT"]
    # with AAA = 1 DKRKT prints only its input line (FORMAT 25, two records)
    parts = ["\n".join(sarkp.gears.dkrkt_report(args).split("\n")[:2]),
             fortran_write("(1X,'КОЭФФИЦИЕНТЫ СМЕЩЕНИЯ КОЛЕС:'/' X1 = ',F7.3,"
                           "' X2 = ',F7.3/' УГОЛ ЗАЦЕПЛЕНИЯ AL12 = ',F8.4)",
                           [k.X1, k.X2, k.ALFAW])]
    for name, routine in (("DGMTZK1", sarkp.DGMTZK), ("DGMTZK2", sarkp.DGMTZK),
                          ("DGMZPC", sarkp.DGMZPC), ("DGMZVN", sarkp.DGMZVN)):
        args, result = g[name]
        parts.append(routine.spec.report(args, list(result)))
    return "\n".join(parts)


def render_cam(c: dict) -> str:
    lines = [fortran_write("(1X,'КИНЕМАТИЧЕСКИЕ ХАРАКТЕРИСТИКИ ДВИЖЕНИЯ ','ТОЛКАТЕЛЯ'/5X,"
                           "'FIK',8X,'AT',8X,'VT',8X,'ST')")]
    lines += [fortran_write("(1X,4F10.4)", [c[n][k] for n in ("FIK", "AT", "VT", "ST")])
              for k in range(CAM_POINTS)]
    lines.append(fortran_write("(1X//'РАДИУС КУЛАЧКОВОЙ ШАЙБЫ - RKSH = ',F7.4//)",
                               [c["RKSH"]]))
    lines.append(fortran_write("(1X,'ХАРАКТЕРИСТИКИ ПРОФИЛЯ КУЛАЧКА'//5X,'FIK',7X,'X',"
                               "9X,'Y',9X,'RK',7X,'DLT',7X,'ROK')"))
    lines += [fortran_write("(1X,6F10.4)",
                            [c[n][k] for n in ("FIK", "X", "Y", "RK", "DLT", "ROK")])
              for k in range(CAM_POINTS)]
    return "\n".join(lines)


def render_kinematics(k: dict) -> str:
    n = len(k["FI1"])
    lines = [fortran_write("(1X,'КИНЕМАТИЧЕСКИЙ РАСЧЕТ МЕХАНИЗМА ','МАНИПУЛЯТОРА'//5X,"
                           "'ЛИНЕЙНЫЕ И УГЛОВЫЕ ПЕРЕМЕЩЕНИЯ ЗВЕНЬЕВ'/3X,'FI1',5X,'FI2',"
                           "6X,'FICB',6X,'XE',6X,'FIDE',6X,'XB',7X,'YB'/)")]
    cols = ("FI1", "FI2", "FICB", "XE", "FIDE", "XB", "YB")
    lines += [fortran_write("(7F9.4)", [k[c][i] for c in cols]) for i in range(n)]
    lines.append(fortran_write("(5X//'ЛИНЕЙНЫЕ И УГЛОВЫЕ СКОРОСТИ ЗВЕНЬЕВ'/3X,'FI1',6X,"
                               "'W2',7X,'W3',7X,'VE',7X,'ALE',6X,'W4'/)"))
    cols = ("FI1", "W2", "W3", "VE", "ALE", "W4")
    lines += [fortran_write("(6F9.4)", [k[c][i] for c in cols]) for i in range(n)]
    lines.append(fortran_write("(5X//'ЛИНЕЙНЫЕ И УГЛОВЫЕ УСКОРЕНИЯ ЗВЕНЬЕВ'/3X,'FI1',6X,"
                               "'E2',7X,'E3',7X,'E4',7X,'AE',7X,'BE'/)"))
    cols = ("FI1", "E2", "E3", "E4", "AE", "BE")
    lines += [fortran_write("(6F9.4)", [k[c][i] for c in cols]) for i in range(n)]
    return "\n".join(lines)


def render_forces(fo: dict) -> str:
    n = len(fo["FI1"])
    lines = [fortran_write("(//'ОПРЕДЕЛЕНИЕ УСИЛИЙ В КИНЕМАТИЧЕСКИХ'/'ПАРАХ МЕХАНИЗМА "
                           "МАНИПУЛЯТОРА'//10X,'ВЕЛИЧИНЫ УСИЛИЙ И МОМЕНТ СОПРОТИВЛЕНИЯ'/"
                           "4X,'FI1',5X,'F43',6X,'F45',6X,'F50',6X,'F30',6X,'F23',6X,"
                           "'F21',6X,'M1')")]
    cols = ("FI1", "F43", "F45", "F50", "F30", "F23", "F21", "M1")
    lines += [fortran_write("(F8.3,6F9.1,F8.1)", [fo[c][i] for c in cols]) for i in range(n)]
    lines.append(fortran_write("(/10X,'НАПРАВЛЯЮЩИЕ УГЛЫ ВЕКТОРОВ СИЛ'/4X,'FI1',5X,'G43',"
                               "6X,'G45',6X,'G50',6X,'G30',6X,'G23',6X,'G21')"))
    cols = ("FI1", "G43", "G45", "G50", "G30", "G23", "G21")
    lines += [fortran_write("(F8.3,6F9.3)", [fo[c][i] for c in cols]) for i in range(n)]
    return "\n".join(lines)


TRAPEZOIDS = " ИСПОЛЬЗУЕТСЯ МЕТОД ТРАПЕЦИЙ"          # DINTGR's message, once per DZKNDV


def render_dynamics(d: dict) -> str:
    n = len(d["FI1"])
    lines = [TRAPEZOIDS, TRAPEZOIDS,
             fortran_write("(//1X,'РЕЗУЛЬТАТЫ РЕШЕНИЯ УРАВНЕНИЯ ДВИЖЕНИЯ'/8X,'МЕХАНИЗМА "
                           "МАНИПУЛЯТОРА'/2X,'FI1',4X,'IPR',5X,'AS',4X,'ASUM',4X,'EV',5X,"
                           "'DEC',3X,'WPR',5X,'EPR',2X,'WPRM',4X,'EPRM'/)")]
    cols = ("FI1", "IPR", "AS", "ASUM", "EV", "DEC", "WPR", "EPR", "WPRM", "EPRM")
    if d.get("STALLS"):     # corrected mode: no steady motion without the flywheel
        lines += [fortran_write("(F6.3,5F7.1,A7,A8,F6.2,F8.2)",
                                [d[c][i] for c in cols[:6]] + ["  stall", "   stall"]
                                + [d["WPRM"][i], d["EPRM"][i]]) for i in range(n)]
    else:
        lines += [fortran_write("(F6.3,5F7.1,F7.2,F8.2,F6.2,F8.2)", [d[c][i] for c in cols])
                  for i in range(n)]
    lines.append(fortran_write("(//1X,'МОМЕНТ ИНЕРЦИИ МАХОВИКА - IMH = ',F7.2)",
                               [d["IMH"]]))
    return "\n".join(lines)


RENDER = {"synthesis": render_synthesis, "teeth": render_teeth, "gears": render_gears,
          "cam": render_cam, "kinematics": render_kinematics, "forces": render_forces,
          "dynamics": render_dynamics}
