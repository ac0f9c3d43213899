"""Generate, from one chapter module, its drivers and its Python wrappers (run by meson).

    python gen_drivers.py CHAPTER.f90 DRIVERS.f90 WRAPPERS.py [ROUTINE ...]

The interface of each book routine is written once, beside its Fortran: after the
routine statement (and its ``!sarkp`` directives), one *argument line* per input, in the
order of the Python signature, as MINPACK documents each argument::

    !: XA, YA : real -- centre of the external revolute A, m
    !: RZ2, RZ3 : length -- link lengths AB and CB, m
    !: P : branch -- assembly branch: -1 B on the left of A -> C, +1 the mirror image
    !:     (a line that does not start with NAMES : begins is a continuation)
    !: AAA : flag -- the book's print flag; unused

Argument lines that several routines share are written once, as a block before them
(``!:define NAME``, the lines, ``!:end``), and stand in each routine as ``!:insert NAME``.

``NAMES : KIND -- meaning``.  A KIND is ``[table(D1[, D2])] RULE [= DEFAULT]``, with
RULE one of ``real`` (a finite number), ``length`` (a length, > 0), ``real > 0``,
``real >= 0``, ``real != 0``, ``branch`` (an assembly branch, -1 or +1),
``integer LO..HI`` (an integer in that range; a count of tables too) or ``flag`` (the
book's print flag AAA, a real, default 1.0); several RULEs separated by ``;`` give the
names their rules one by one.  ``table(M)`` is an array of the routine's declared shape
(``M`` an input, the count); ``destroyed`` after the RULE marks an inout table that the
routine overwrites and the Python result leaves out.

From these lines and the Fortran declarations this writes

* DRIVERS.f90, module ``drv_<module>``, for each routine NAME:

  - ``NAME_1(sarkp_mode, <inputs>, <outputs>, <COMMON results>, [fres,] status,
    sarkp_bad[, sarkp_at])``: one call in the caller's mode;
  - ``NAME_n(sarkp_mode, sarkp_n, sarkp_inc, sarkp_nan, <inputs as arrays>, sarkp_out,
    sarkp_status, sarkp_bad)`` for routines whose arguments are scalars or fixed-size
    arrays: a loop over ``sarkp_n`` positions.  Results of position i go to
    ``sarkp_out(i, k)``, k in the order of NAME_1's results.  Input k of position i is
    element ``1 + (i-1)*sarkp_inc(k)`` (``sarkp_inc(k) = 0``: the same at every
    position, passed once).  ``sarkp_status`` comes in holding the positions the caller
    has already ruled out (a nonzero status: skipped) and goes out with every status.

  THE INPUT RULES LIVE HERE, ONCE: every input value (scalar, table element, position
  of a sweep) is screened by ``screen`` against its RULE before the routine runs, in
  both drivers.  A NaN is a missing input (status st_missing; in a sweep only where
  ``sarkp_nan`` allows it, and the position is skipped); any other value outside its
  rule stops the call before any work and is reported as ``sarkp_bad`` = the input's
  number (its element in ``sarkp_at``, or position in ``sarkp_bad(2)`` of a sweep).
  A sweep first tests each input's elements against its rule in one pass
  (``sarkp_valid``); when all keep it (the common case) its loop screens nothing, else
  it screens every position as described, which finds and words the first bad input.
  Integer inputs are passed as reals and converted only after the screen, so that a NaN,
  an inf or a huge value can never reach an integer conversion.  Shapes and counts of
  tables are the Python layer's (library.py), which also words every message.

  THE OUTPUTS OF A FAILED POSITION ARE SET HERE, ONCE: NaN in every real result (the
  routines leave them as they are).  A result that is not a finite number while the
  routine reported success gives st_range (a sweep tests the sum of the differences
  x - x of its results: +0 when all are finite, NaN otherwise).

  Every driver sets the mode (prmtr's ``set_mode``) inside the same call and releases
  the GIL (f2py ``threadsafe``), except those of routines with COMMON results.

* WRAPPERS.py, module ``sarkp._wrap_<module>``: for each routine a typed Python
  function with the book's signature, the Parameters section of its docstring, and
  result classes; the chapter module (python/sarkp/<chapter>.py) adds the prose, the
  checks and the report with :func:`sarkp.library.describe`.

Directives: ``!sarkp common: x, y`` names module variables returned with the routine
(``a => zpc_a`` returns ``zpc_a`` as ``a``); ``!sarkp ier-is-output`` keeps a trailing
IER as an ordinary output; ``!sarkp kept: 4 => as, dec`` names the outputs that stay
valid when the routine fails with status 4 (they are not set to NaN, and the error
raised carries that result as ``.result``).  A public routine without argument lines gets no drivers.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

TYPES = {"real(dp)": "real(dp)", "integer": "integer"}
INT_MAX = 2**31 - 1

# screen kinds (the numbers ``screen`` takes; library.py words them)
K_REAL, K_POSITIVE, K_NONNEGATIVE, K_NONZERO, K_BRANCH, K_INTEGER = range(6)


@dataclass
class Arg:
    name: str
    type: str
    intent: str = ""            # in, out, inout ('' for a module variable)
    dims: tuple = ()            # bounds as written, e.g. ("m", "n") or ("3",)

    @property
    def fixed(self) -> bool:
        """Scalar or an array whose bounds are literal numbers."""
        return all(d.isdigit() for d in self.dims)

    def decl(self, intent=None, dims=None, type=None) -> str:
        intent = self.intent if intent is None else intent
        dims = self.dims if dims is None else dims
        shape = f"({', '.join(dims)})" if dims else ""
        text = f"{type or self.type}"
        if intent:
            text += f", intent({intent})"
        return f"{text} :: {self.name}{shape}"


@dataclass
class Rule:
    """One input's rule, from its argument line."""
    book: str                   # the book's name, as Python spells it (upper case)
    kind: int                   # K_*
    word: str                   # the RULE as written: real, length, real > 0, ...
    lo: int = 0
    hi: int = 0
    table: tuple = ()           # dims of a table, as written (lower case)
    default: str | None = None
    destroyed: bool = False
    meaning: str = ""
    group: tuple = ()           # the names documented together with this one


@dataclass
class Procedure:
    name: str
    kind: str                   # subroutine | function
    argnames: list
    args: dict = field(default_factory=dict)
    commons: list = field(default_factory=list)
    common_names: dict = field(default_factory=dict)
    ier_is_output: bool = False
    lines: list = field(default_factory=list)   # raw argument lines
    kept: dict = field(default_factory=dict)    # status -> outputs still valid then
    rules: dict = field(default_factory=dict)   # fortran name -> Rule, in Python order
    result_type: str = ""

    @property
    def status_arg(self):
        last = self.argnames[-1] if self.argnames else None
        if (last == "ier" and not self.ier_is_output and self.args[last].type == "integer"
                and self.args[last].intent == "out"):
            return last
        return None

    @property
    def sweepable(self) -> bool:
        return all(a.fixed and a.intent != "inout" for a in self.args.values())

    @property
    def inputs(self):
        """Fortran names of the inputs, in the Python order (the argument lines')."""
        return list(self.rules)

    @property
    def counts(self):
        return {d for r in self.rules.values() for d in r.table if not d.isdigit()}


def logical_lines(text: str):
    """Statements with continuations joined and comments dropped; ``!sarkp`` and
    argument lines (``!:``) kept, argument-line blocks expanded: the lines between
    ``!:define NAME`` and ``!:end`` (written once, before the routines that share them)
    stand wherever a routine has ``!:insert NAME``."""
    out, pending = [], ""
    blocks: dict[str, list[str]] = {}
    defining = None
    for raw in text.splitlines():
        stripped = raw.strip()
        if stripped.startswith("!:define "):
            defining = blocks.setdefault(stripped.split()[1], [])
            continue
        if defining is not None:
            if stripped == "!:end":
                defining = None
            elif stripped.startswith("!:"):
                defining.append(stripped)
            else:
                raise SystemExit(f"gen_drivers: argument-line block: {stripped!r} is not "
                                 f"an argument line (close the block with !:end)")
            continue
        if stripped.startswith("!:insert "):
            name = stripped.split()[1]
            if name not in blocks:
                raise SystemExit(f"gen_drivers: !:insert {name}: no such block defined "
                                 f"above it")
            out.extend(blocks[name])
            continue
        if stripped.lower().startswith("!sarkp") or stripped.startswith("!:"):
            out.append(stripped)
            continue
        line = _strip_comment(raw).rstrip()
        if not line.strip():
            continue
        if pending:
            line = pending + " " + line.strip().lstrip("&").strip()
        if line.endswith("&"):
            pending = line[:-1].rstrip()
            continue
        pending = ""
        out.append(line.strip())
    return out


def _strip_comment(line: str) -> str:
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i]
    return line


def split_top(text: str):
    """Split on commas outside parentheses."""
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


DECL = re.compile(r"^(real\(dp\)|integer)\s*((?:,[^:]*)?)::\s*(.*)$", re.I)
HEAD = re.compile(r"^(?:(?:pure|elemental|recursive|impure)\s+)*(?:(real\(dp\)|integer)\s+)?"
                  r"(subroutine|function)\s+(\w+)\s*\(([^)]*)\)", re.I)
END = re.compile(r"^end\s*(subroutine|function)\b", re.I)
ARGLINE = re.compile(r"^([A-Z][A-Z0-9_]*(?:\s*,\s*[A-Z][A-Z0-9_]*)*)\s*:\s*(.*?)\s+--\s+(.*)$")
RULE = re.compile(r"^(?:table\(([^)]*)\)\s*)?(real\s*(?:>=|>|!=)\s*0|real|length|branch|flag|"
                  r"integer\s+(-?\d+)\s*\.\.\s*(-?\d+))(\s+destroyed)?"
                  r"(?:\s*=\s*(\S+))?$")


def parse_entities(rest: str):
    for ent in split_top(rest):
        ent = ent.split("=")[0].strip()
        m = re.match(r"(\w+)\s*(?:\((.*)\))?$", ent)
        if not m:
            raise SystemExit(f"gen_drivers: cannot read the declaration {ent!r}")
        dims = tuple(d.strip().lower() for d in split_top(m.group(2))) if m.group(2) else ()
        yield m.group(1).lower(), dims


def parse_rule(where, text):
    m = RULE.match(text.strip())
    if not m:
        raise SystemExit(f"gen_drivers: {where}: cannot read the rule {text!r}")
    table = tuple(d.strip().lower() for d in m.group(1).split(",")) if m.group(1) else ()
    word = re.sub(r"\s+", " ", m.group(2))
    lo = hi = 0
    if word.startswith("integer"):
        kind, lo, hi = K_INTEGER, int(m.group(3)), int(m.group(4))
        word = f"integer {lo}..{hi}"
    else:
        kind = {"real": K_REAL, "flag": K_REAL, "length": K_POSITIVE,
                "real > 0": K_POSITIVE, "real >= 0": K_NONNEGATIVE,
                "real != 0": K_NONZERO, "branch": K_BRANCH}[word.replace(" ", " ")]
    default = m.group(6)
    if word == "flag" and default is None:
        default = "1.0"
    return Rule("", kind, word, lo, hi, table, default, bool(m.group(5)))


def read_rules(where, p):
    """The Rules of ``p`` from its argument lines."""
    entries = []
    for raw in p.lines:
        text = raw[2:].strip()
        m = ARGLINE.match(text)
        if m:
            entries.append([m.group(1), m.group(2), m.group(3).strip()])
        elif entries:
            entries[-1][2] += " " + text
        else:
            raise SystemExit(f"gen_drivers: {where}: an argument line must begin "
                             f"NAMES : KIND -- meaning, not {raw!r}")
    for names, kinds, meaning in entries:
        names = [n.strip() for n in names.split(",")]
        kinds = [k.strip() for k in kinds.split(";")]
        if len(kinds) == 1:
            kinds *= len(names)
        if len(kinds) != len(names):
            raise SystemExit(f"gen_drivers: {where}: {len(names)} names, {len(kinds)} rules")
        for name, kind in zip(names, kinds):
            rule = parse_rule(f"{where}: {name}", kind)
            rule.book, rule.meaning, rule.group = name, meaning, tuple(names)
            low = name.lower()
            arg = p.args.get(low)
            if arg is None or arg.intent not in ("in", "inout"):
                raise SystemExit(f"gen_drivers: {where}: {name} is not an input of {p.name}")
            if low in p.rules:
                raise SystemExit(f"gen_drivers: {where}: {name} has two argument lines")
            if tuple(arg.dims) != rule.table and not (arg.fixed and rule.table == arg.dims):
                raise SystemExit(f"gen_drivers: {where}: {name} is declared with dims "
                                 f"{arg.dims}, its argument line says table{rule.table}")
            if rule.kind == K_INTEGER and arg.dims:
                raise SystemExit(f"gen_drivers: {where}: {name}: integer tables are not "
                                 f"supported")
            p.rules[low] = rule
    fortran = [a for a in p.argnames if p.args[a].intent in ("in", "inout")]
    missing = [a for a in fortran if a not in p.rules]
    if not missing and list(p.rules) != fortran:
        raise SystemExit(f"gen_drivers: {where}: the argument lines must follow the "
                         f"Fortran order of the inputs, {', '.join(fortran)}")
    if missing:
        raise SystemExit(f"gen_drivers: {where}: no argument line for {', '.join(missing)}")
    for c in p.counts:
        if c not in p.rules or p.rules[c].kind != K_INTEGER:
            raise SystemExit(f"gen_drivers: {where}: the count {c} must be an integer input")


def parse(path: Path):
    lines = logical_lines(path.read_text(encoding="utf-8"))
    module, public, variables, procs = None, set(), {}, []
    in_contains, current = False, None
    for line in lines:
        low = line.lower()
        if module is None:
            m = re.match(r"module\s+(\w+)$", low)
            if m:
                module = m.group(1)
            continue
        if current is not None:
            if line.startswith("!:"):
                current.lines.append(line)
                continue
            if low.startswith("!sarkp"):
                directive = low[len("!sarkp"):].strip()
                if directive.startswith("common:"):
                    for c in (c.strip() for c in directive[7:].split(",")):
                        if c:
                            result, _, var = c.rpartition("=>")
                            var = var.strip()
                            current.commons.append(var)
                            current.common_names[var] = result.strip() or var
                elif directive == "ier-is-output":
                    current.ier_is_output = True
                elif directive.startswith("kept:"):
                    code, _, names = directive[5:].partition("=>")
                    current.kept[int(code)] = [n.strip() for n in names.split(",")]
                continue
            if END.match(low):
                procs.append(current)
                current = None
                continue
            m = DECL.match(line)
            if m:
                attrs = m.group(2).lower()
                im = re.search(r"intent\s*\(\s*(in\s*out|inout|in|out)\s*\)", attrs)
                dm = re.search(r"dimension\s*\((.*)\)", attrs)
                for name, dims in parse_entities(m.group(3)):
                    if name in current.argnames:
                        if dm and not dims:
                            dims = tuple(d.strip() for d in split_top(dm.group(1)))
                        current.args[name] = Arg(name, m.group(1).lower(),
                                                 im.group(1).replace(" ", "") if im else "",
                                                 dims)
            continue
        if line.startswith("!:"):
            continue
        if low == "contains":
            in_contains = True
            continue
        if not in_contains:
            m = re.match(r"public\s*::\s*(.*)$", low)
            if m:
                public |= {p.strip() for p in m.group(1).split(",")}
                continue
            m = DECL.match(line)
            if m and "public" in m.group(2).lower():
                for name, dims in parse_entities(m.group(3)):
                    variables[name] = Arg(name, m.group(1).lower(), "", dims)
                    public.add(name)
            continue
        m = HEAD.match(line)
        if m:
            argnames = [a.strip().lower() for a in m.group(4).split(",") if a.strip()]
            current = Procedure(m.group(3).lower(), m.group(2).lower(), argnames)
            current.result_type = (m.group(1) or "").lower()
    procs = [p for p in procs if p.name in public and p.lines]
    for p in procs:
        missing = [a for a in p.argnames if a not in p.args or not p.args[a].intent]
        if missing:
            raise SystemExit(f"gen_drivers: {path.name}: {p.name}: no intent declared for "
                             f"{', '.join(missing)}")
        for c in p.commons:
            if c not in variables:
                raise SystemExit(f"gen_drivers: {path.name}: {p.name}: COMMON result {c} is "
                                 f"not a public module variable")
        read_rules(f"{path.name}: {p.name}", p)
    return module, procs, variables


# ---------------------------------------------------------------------------------------
# the drivers
# ---------------------------------------------------------------------------------------

def finite_test(items):
    """The test that every (expression, is_array) in ``items`` is a finite number."""
    tests = [f"all(abs({e}) <= huge(1.0_dp))" if array else f"abs({e}) <= huge(1.0_dp)"
             for e, array in items]
    return " .and. &\n          ".join(tests)


def sum_test(names):
    """The test that every real ``names`` is a finite number, in one comparison: x - x is
    +0 for a finite x and NaN for an infinite or NaN one, and a sum of terms one of which
    is NaN is NaN (no reassociation: the build has no -ffast-math).  Summed pairwise, so
    that the additions do not wait on one another in a chain."""
    terms = [f"({e} - {e})" for e in names]
    while len(terms) > 1:
        terms = [f"({terms[i]} + {terms[i + 1]})" if i + 1 < len(terms) else terms[i]
                 for i in range(0, len(terms), 2)]
    text = terms[0] + " == 0.0_dp"
    lines, line = [], "          "
    for piece in re.split(r"(?<= \+) ", text):
        if len(line) + len(piece) > 86 and line.strip():
            lines.append(line.rstrip())
            line = "          "
        line += piece + " "
    lines.append(line.rstrip())
    return " &\n".join(lines).lstrip()


def _fast_screen(p, ins):
    """The sweep's fast path: each input's elements tested against its rule in one pass
    (sarkp_valid); all valid -- the common case -- and the loop screens nothing
    (sarkp_screen = 0).  Else, or with a table input, the loop screens every position as
    before, which finds the first bad input and words it (a NaN fails the pass too)."""
    if any(p.args[a].dims for a in ins):
        return ["    sarkp_screen = 1"]
    w = ["    sarkp_screen = 0"]
    for k, a in enumerate(ins, 1):
        rule = p.rules[a]
        w.append(f"    if (.not. sarkp_valid({a}, sarkp_inc({k}), sarkp_n, {rule.kind}, "
                 f"{_real(rule.lo)}, {_real(rule.hi)})) sarkp_screen = 1")
    return w


def wrap_list(names, indent="      "):
    """Names separated by commas, in lines of at most about 90 characters."""
    lines, cur = [], ""
    for n in names:
        piece = n if not cur else cur + ", " + n
        if len(piece) > 80 and cur:
            lines.append(cur + ",")
            cur = n
        else:
            cur = piece
    lines.append(cur)
    return (" &\n" + indent).join(lines)


def _commons(p, variables):
    """The COMMON results of ``p`` as (Arg named by its result name, module variable)."""
    return [(Arg(p.common_names[c], variables[c].type, "", variables[c].dims), c)
            for c in p.commons]


def _real(x):
    return f"{float(x)!r}_dp".replace("e+", "e").replace("inf", "huge(1.0_dp)")


def _screen_call(rule, value, nan, k, j, bad):
    return (f"screen({value}, {rule.kind}, {_real(rule.lo)}, {_real(rule.hi)}, {nan}, "
            f"{k}, {j}, {bad})")


def results_of(p, variables):
    """NAME_1's results after the inputs: (Arg, module variable or None), in order."""
    outs = [(p.args[a], None) for a in p.argnames
            if p.args[a].intent == "out" and a != p.status_arg]
    outs += [(c, var) for c, var in _commons(p, variables)]
    if p.kind == "function":
        outs.append((Arg("fres", p.result_type or "real(dp)", "out"), None))
    return outs


def returned(p, variables):
    """The Fortran names of everything NAME_1 returns before its status, in order (f2py
    returns an intent(in,out) input at its place among the arguments)."""
    names = []
    for a in p.argnames:
        arg = p.args[a]
        if a == p.status_arg:
            continue
        if arg.intent == "out" or (arg.intent == "inout" and not p.rules[a].destroyed):
            names.append(a)
    names += [c.name for c, _ in _commons(p, variables)]
    if p.kind == "function":
        names.append("fres")
    return names


def scalar_driver(mod, p, variables):
    w = []
    pairs = _commons(p, variables)
    commons = [c for c, _ in pairs]
    status = p.status_arg or "sarkp_status"
    tables = bool(p.counts)
    names = (["sarkp_mode"] + [a for a in p.argnames if a != p.status_arg]
             + [c.name for c in commons])
    if p.kind == "function":
        names.append("fres")
    names += ["sarkp_skip", status, "sarkp_bad"] + (["sarkp_at"] if tables else [])
    w.append(f"  subroutine {p.name}_1({wrap_list(names)})")
    if not p.commons:
        w.append("    !f2py threadsafe")
    w.append("    integer, intent(in) :: sarkp_mode, sarkp_skip")
    w.append("    !f2py integer optional, intent(in) :: sarkp_skip = 0")
    ints = [a for a in p.inputs if p.args[a].type == "integer" and a not in p.counts]
    for a in p.argnames:
        arg = p.args[a]
        if a in p.rules and p.rules[a].table:
            dims = arg.dims if arg.fixed else ("*",)
            w.append("    " + arg.decl(dims=dims))
            if arg.intent == "inout":
                # the Python layer passes a copy: the routine overwrites it
                w.append(f"    !f2py intent({'in' if p.rules[a].destroyed else 'in,out'}) :: {a}")
        elif a in ints:
            w.append("    " + arg.decl(type="real(dp)"))       # screened, then converted
        else:
            w.append("    " + arg.decl())
            if arg.intent == "inout":
                w.append(f"    !f2py intent(in,out) :: {a}")
    for c in commons:
        w.append("    " + Arg(c.name, c.type, "out", c.dims).decl())
    if p.kind == "function":
        w.append(f"    {p.result_type or 'real(dp)'}, intent(out) :: fres")
    if p.status_arg is None:
        w.append("    integer, intent(out) :: sarkp_status")
    w.append("    integer, intent(out) :: sarkp_bad" + (", sarkp_at" if tables else ""))
    w.append("    integer :: sarkp_t, sarkp_bads(3)"
             + (", sarkp_l" if any(r.table for r in p.rules.values()) else ""))
    w += ["    sarkp_bads = 0", "    sarkp_t = 0"]
    # the screen: the first input out of its rule (a NaN, when no other is, as missing)
    for k, a in enumerate(p.inputs, 1):
        rule = p.rules[a]
        if a in p.counts:
            continue                                    # counts: the Python layer's
        if rule.table:
            size = "*".join(f"({d})" for d in p.args[a].dims)
            w += [f"    do sarkp_l = 1, {size}",
                  "      sarkp_t = max(sarkp_t, &",
                  f"          {_screen_call(rule, f'{a}(sarkp_l)', 1, k, 'sarkp_l', 'sarkp_bads')})",
                  "    end do"]
        else:
            w += ["    sarkp_t = max(sarkp_t, &",
                  f"        {_screen_call(rule, a, 1, k, 1, 'sarkp_bads')})"]
    w += ["    sarkp_bad = sarkp_bads(1)"]
    if tables:
        w.append("    sarkp_at = sarkp_bads(2)")
    w += ["    call set_mode(sarkp_mode)",
          "    if (sarkp_t /= 0) then",
          f"      {status} = st_missing"]
    w += _nan_results(p, variables, lambda r: r, indent="      ")
    w += ["      return", "    end if",
          "    if (sarkp_skip /= 0) then                ! ruled out by the caller's checks",
          f"      {status} = sarkp_skip"]
    w += _nan_results(p, variables, lambda r: r, indent="      ")
    w += ["      return", "    end if"]
    actual = [f"int({a})" if a in ints else a for a in p.argnames]
    if p.kind == "function":
        w.append(f"    fres = {p.name}({wrap_list(actual)})")
    else:
        w.append(f"    call {p.name}({wrap_list(actual)})")
    if p.status_arg is None:
        w.append("    sarkp_status = st_ok")
    for c, var in pairs:
        w.append(f"    {c.name} = {mod}_{var}")
    real_out = [(_whole(p, a), bool(p.args[a].dims)) for a in p.argnames
                if p.args[a].intent in ("out", "inout") and p.args[a].type == "real(dp)"
                and not (a in p.rules and p.rules[a].destroyed)]
    real_out += [(c.name, bool(c.dims)) for c in commons if c.type == "real(dp)"]
    if p.kind == "function" and (p.result_type or "real(dp)") == "real(dp)":
        real_out.append(("fres", False))
    if real_out:
        # a result that is not a finite number: st_range, and sarkp_bad = -(the mask of
        # the results that are not, bit k - 1 for result k of the first 30) for the message
        kinds = {a: (p.args[a].type, bool(p.args[a].dims)) for a in p.argnames}
        kinds.update({c.name: (c.type, bool(c.dims)) for c in commons})
        kinds["fres"] = (p.result_type or "real(dp)", False)
        w.append(f"    if (succeeded({status})) then")
        w.append(f"      if (.not. ({finite_test(real_out)})) {status} = st_range")
        w.append("    end if")
        w.append(f"    if ({status} == st_range) then     ! found here, or by the routine")
        for k, a in enumerate(returned(p, variables)[:30]):
            if kinds[a][0] == "real(dp)":
                test = finite_test([(_whole(p, a) if a in p.args else a, kinds[a][1])])
                w.append(f"      if (.not. ({test})) sarkp_bad = sarkp_bad - {2**k}")
        w.append("    end if")
    w.append(f"    if (.not. succeeded({status})) then")
    w += _nan_results(p, variables, lambda r: r, indent="      ", status=status)
    w.append("    end if")
    w.append(f"  end subroutine {p.name}_1")
    return w


def _whole(p, a):
    """The whole of argument ``a`` in the scalar driver (an input table is declared
    there of assumed size, ``(*)``: its extent is written out)."""
    arg = p.args[a]
    if a in p.rules and p.rules[a].table and not arg.fixed:
        return f"{a}(1:{'*'.join(f'({d})' for d in arg.dims)})"
    return a


def _nan_results(p, variables, ref, indent, status=None):
    """Statements that set every real result of NAME_1 to NaN (a failed call); with
    ``status``, those the routine keeps for that status (``!sarkp kept:``) stay."""
    w = []
    for r, _ in results_of(p, variables):
        if r.type == "real(dp)":
            codes = [str(c) for c, names in p.kept.items() if r.name in names]
            if status and codes:
                w.append(f"{indent}if (all({status} /= [{', '.join(codes)}])) "
                         f"{ref(r.name)} = sarkp_nan_value()")
            else:
                w.append(f"{indent}{ref(r.name)} = sarkp_nan_value()")
    for a in p.argnames:                                # returned inout tables
        arg = p.args[a]
        if arg.intent == "inout" and not p.rules[a].destroyed and arg.type == "real(dp)":
            size = "*".join(f"({d})" for d in arg.dims) if arg.dims else None
            w.append(f"{indent}{a}(1:{size}) = sarkp_nan_value()" if size else
                     f"{indent}{a} = sarkp_nan_value()")
    return w


def sweep_driver(mod, p, variables):
    pairs = _commons(p, variables)
    ins = p.inputs
    results = [r for r, _ in results_of(p, variables)]
    for r in results:
        if r.dims or r.type not in TYPES:
            raise ValueError(f"{p.name}: the sweep packs scalar results only, not {r.name}")
    column = {r.name: k for k, r in enumerate(results, 1)}
    ints_out = [r.name for r in results if r.type == "integer"]
    ints_in = [a for a in ins if p.args[a].type == "integer"]
    names = (["sarkp_mode", "sarkp_n", "sarkp_inc", "sarkp_nan"] + ins
             + ["sarkp_out", "sarkp_status", "sarkp_bad"])
    w = [f"  subroutine {p.name}_n({wrap_list(names)})"]
    if not p.commons:
        w.append("    !f2py threadsafe")
    w += ["    integer, intent(in) :: sarkp_mode, sarkp_n, sarkp_nan",
          f"    integer, intent(in) :: sarkp_inc({len(ins)})"]
    for a in ins:
        arg = p.args[a]
        w.append("    " + arg.decl(dims=arg.dims + ("*",), type="real(dp)"))
    w += [f"    real(dp), intent(inout) :: sarkp_out(sarkp_n, {len(results)})",
          "    integer, intent(inout) :: sarkp_status(sarkp_n)",
          "    integer, intent(out) :: sarkp_bad(3)",
          "    integer :: sarkp_i, sarkp_state, sarkp_once, sarkp_t, sarkp_j, sarkp_screen"
          + (", sarkp_l" if any(p.args[a].dims for a in ins) else "")]
    if ints_out:
        w.append(f"    integer :: {', '.join('sarkp_' + n for n in ints_out)}")
    w += ["    sarkp_bad = 0",
          "    call set_mode(sarkp_mode)",
          "    sarkp_once = 0"]
    w += _fast_screen(p, ins)
    w += ["    do sarkp_i = 1, sarkp_n",
          "      ! the inputs of position i: a NaN is a missing input (status 5) when allowed;",
          "      ! anything else out of its rule stops the loop and is reported.  An input",
          "      ! passed once (inc 0) is screened at position 1 only, in its turn;",
          "      ! sarkp_once keeps what it found (0, or 1 for a missing input).",
          "      sarkp_state = sarkp_once",
          "      if (sarkp_screen /= 0) then"]
    first = len(w)
    for k, a in enumerate(ins, 1):
        arg, rule = p.args[a], p.rules[a]
        w.append(f"      if (sarkp_inc({k}) /= 0 .or. sarkp_i == 1) then")
        w.append(f"        sarkp_j = 1 + (sarkp_i - 1)*sarkp_inc({k})")
        if arg.dims:
            w += ["        sarkp_t = 0",
                  f"        do sarkp_l = 1, {arg.dims[0]}",
                  "          sarkp_t = max(sarkp_t, &",
                  "              " + _screen_call(rule, f"{a}(sarkp_l, sarkp_j)", "sarkp_nan",
                                                  k, f"(sarkp_j - 1)*{arg.dims[0]} + sarkp_l",
                                                  "sarkp_bad") + ")",
                  "        end do"]
        else:
            w += ["        sarkp_t = &",
                  "            " + _screen_call(rule, f"{a}(sarkp_j)", "sarkp_nan", k,
                                                "sarkp_j", "sarkp_bad")]
        w.append("        sarkp_state = max(sarkp_state, sarkp_t)")
        w.append(f"        if (sarkp_inc({k}) == 0) sarkp_once = max(sarkp_once, sarkp_t)")
        w.append("      end if")
    w[first:] = ["  " + line for line in w[first:]]
    w += ["      end if",
          "      if (sarkp_state == 2) return",
          "      if (sarkp_state == 1) sarkp_status(sarkp_i) = st_missing",
          "      if (sarkp_status(sarkp_i) /= st_ok) then       ! missing, or ruled out",
          "        sarkp_out(sarkp_i, :) = sarkp_nan_value()",
          "        cycle",
          "      end if"]

    def ref(a):
        if a in ins:
            arg = p.args[a]
            r = f"{a}({':, ' * len(arg.dims)}1 + (sarkp_i - 1)*sarkp_inc({ins.index(a) + 1}))"
            return f"int({r})" if a in ints_in else r
        if a in ints_out:
            return f"sarkp_{a}"
        return f"sarkp_out(sarkp_i, {column[a]})"

    actual = [("sarkp_status(sarkp_i)" if a == p.status_arg else ref(a)) for a in p.argnames]
    call = wrap_list(actual, indent="          ")
    if p.kind == "function":
        w.append(f"      {ref('fres')} = {p.name}({call})")
    else:
        w.append(f"      call {p.name}({call})")
    if p.status_arg is None:
        w.append("      sarkp_status(sarkp_i) = st_ok")
    for c, var in pairs:
        w.append(f"      {ref(c.name)} = {mod}_{var}")
    for n in ints_out:                              # an integer result is stored as a real
        w.append(f"      sarkp_out(sarkp_i, {column[n]}) = real(sarkp_{n}, dp)")
    real_out = [f"sarkp_out(sarkp_i, {column[r.name]})" for r in results
                if r.type == "real(dp)"]
    if real_out:
        w.append("      if (succeeded(sarkp_status(sarkp_i))) then")
        w.append(f"        if (.not. ({sum_test(real_out)})) sarkp_status(sarkp_i) = st_range")
        w.append("      end if")
    if p.kept:
        w.append("      if (.not. succeeded(sarkp_status(sarkp_i))) then")
        for r in results:
            codes = [str(c) for c, names in p.kept.items() if r.name in names]
            test = f"if (all(sarkp_status(sarkp_i) /= [{', '.join(codes)}])) " if codes else ""
            w.append(f"        {test}sarkp_out(sarkp_i, {column[r.name]}) = sarkp_nan_value()")
        w.append("      end if")
    else:
        w.append("      if (.not. succeeded(sarkp_status(sarkp_i))) sarkp_out(sarkp_i, :) = "
                 "sarkp_nan_value()")
    w.append("    end do")
    w.append("    sarkp_bad(1:2) = 0                   ! a NaN that was allowed is no bad input")
    w.append("    sarkp_bad(3) = count(sarkp_status /= st_ok)   ! 0: nothing to look at")
    w.append(f"  end subroutine {p.name}_n")
    return w


SCREEN = f"""
  ! The input rules, the only place they are applied.  The state of input number k,
  ! element j: 0 valid; 1 NaN, a missing input (allowed when nan /= 0); 2 outside its
  ! rule -- kind {K_REAL} a finite number, {K_POSITIVE} > 0, {K_NONNEGATIVE} >= 0, {K_NONZERO} not 0, {K_BRANCH} an assembly
  ! branch (-1 or +1), {K_INTEGER} an integer in lo..hi.  The first input in state 2 (a NaN too,
  ! when not allowed) is recorded in bad = (k, j); with none, the first NaN is.
  integer function screen(x, kind, lo, hi, nan, k, j, bad)
    real(dp), intent(in) :: x, lo, hi
    integer, intent(in) :: kind, nan, k, j
    integer, intent(inout) :: bad(3)
    screen = 0
    if (x /= x) then
      screen = 1
      if (nan == 0) screen = 2
    else if (abs(x) > huge(x)) then
      screen = 2
    else
      select case (kind)
      case ({K_POSITIVE})
        if (.not. x > 0.0_dp) screen = 2
      case ({K_NONNEGATIVE})
        if (x < 0.0_dp) screen = 2
      case ({K_NONZERO})
        if (x == 0.0_dp) screen = 2
      case ({K_BRANCH})
        if (x /= 1.0_dp .and. x /= -1.0_dp) screen = 2
      case ({K_INTEGER})
        if (x < lo .or. x > hi .or. x /= aint(x)) screen = 2
      end select
    end if
    if (screen == 2 .and. bad(3) /= 2) then
      bad(1) = k
      bad(2) = j
      bad(3) = 2
    else if (screen == 1 .and. bad(1) == 0) then
      bad(1) = k
      bad(2) = j
    end if
  end function screen

  ! Whether the elements 1, 1 + inc, ..., 1 + (n - 1) inc of x (inc 0: x(1) alone) all
  ! keep the rule of kind (screen's kinds; a NaN keeps none): the sweeps' fast path.
  logical function sarkp_valid(x, inc, n, kind, lo, hi)
    real(dp), intent(in) :: x(*), lo, hi
    integer, intent(in) :: inc, n, kind
    integer :: i, m
    logical :: ok
    m = 1 + (n - 1)*inc
    if (n < 1) m = 0
    ok = .true.
    select case (kind)
    case ({K_REAL})
      do i = 1, m, max(inc, 1)
        ok = ok .and. abs(x(i)) <= huge(1.0_dp)
      end do
    case ({K_POSITIVE})
      do i = 1, m, max(inc, 1)
        ok = ok .and. x(i) > 0.0_dp .and. x(i) <= huge(1.0_dp)
      end do
    case ({K_NONNEGATIVE})
      do i = 1, m, max(inc, 1)
        ok = ok .and. x(i) >= 0.0_dp .and. x(i) <= huge(1.0_dp)
      end do
    case ({K_NONZERO})
      do i = 1, m, max(inc, 1)
        ok = ok .and. x(i) /= 0.0_dp .and. abs(x(i)) <= huge(1.0_dp)
      end do
    case ({K_BRANCH})
      do i = 1, m, max(inc, 1)
        ok = ok .and. (x(i) == 1.0_dp .or. x(i) == -1.0_dp)
      end do
    case default
      do i = 1, m, max(inc, 1)
        ok = ok .and. x(i) >= lo .and. x(i) <= hi .and. x(i) == aint(x(i))
      end do
    end select
    sarkp_valid = ok
  end function sarkp_valid
"""


def generate(source: Path, only):
    module, procs, variables = parse(source)
    if only:
        procs = [p for p in procs if p.name in only]
        if {p.name for p in procs} != set(only):
            raise SystemExit(f"gen_drivers: {source.name} has no public "
                             f"{set(only) - {p.name for p in procs}}")
    renames = [f"{module}_{c} => {c}" for p in procs for c in p.commons]
    uses = sorted({p.name for p in procs}) + sorted(set(renames))
    w = [f"! drv_{module}.f90 -- generated at build time by fortran/gen_drivers.py from",
         f"! {source.name}: do not edit.  The Python drivers of the book routines of module",
         f"! {module}: NAME_1 (one call) and NAME_n (a loop over positions), each in the mode",
         "! the caller passes, each screening its inputs first.",
         f"module drv_{module}",
         "  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan",
         "  use prmtr, only: dp, set_mode, succeeded, st_ok, st_range, st_missing"]
    w.append(f"  use {module}, only: " + wrap_list(uses))
    w += ["  implicit none", "  private",
          "  public :: " + wrap_list(
              [f"{p.name}_1" for p in procs] + [f"{p.name}_n" for p in procs if p.sweepable]),
          "", "contains", ""]
    for p in procs:
        w += scalar_driver(module, p, variables) + [""]
        if p.sweepable:
            w += sweep_driver(module, p, variables) + [""]
    w.append(SCREEN)
    w += ["  ! the value of the real results of a failed position",
          "  real(dp) function sarkp_nan_value()",
          "    sarkp_nan_value = ieee_value(1.0_dp, ieee_quiet_nan)",
          "  end function sarkp_nan_value"]
    w.append(f"end module drv_{module}")
    text = "\n".join(w) + "\n"
    return module, procs, variables, text


# ---------------------------------------------------------------------------------------
# the Python wrappers
# ---------------------------------------------------------------------------------------

def _doc_type(p, rule):
    """The numpydoc type of an input, from its rule."""
    if rule.table:
        dims = ", ".join(d.upper() for d in rule.table) + ("," if len(rule.table) == 1 else "")
        text = f"array_like, shape ({dims})"
    elif rule.kind == K_BRANCH:
        text = "{-1, 1}"
    elif rule.kind == K_INTEGER:
        values = range(rule.lo, rule.hi + 1)
        text = ("{" + ", ".join(map(str, values)) + "}" if len(values) <= 4
                else f"int, {rule.lo}..{rule.hi}")
    else:
        text = "float" if p.counts else "float or array_like"
    extra = {"length": "a length, > 0", "real > 0": "> 0", "real >= 0": ">= 0",
             "real != 0": "not 0"}.get(rule.word)
    if rule.table and rule.word != "real":
        text += f", each {extra}"
    elif extra:
        text += f", {extra}"
    if rule.default is not None:
        text += f", default {rule.default}"
    return text


def _parameters(p):
    """The Parameters section of the docstring, from the argument lines."""
    w = ["    Parameters", "    ----------"]
    done = set()
    for a in p.inputs:
        rule = p.rules[a]
        if rule.book in done:
            continue
        group = [n for n in rule.group]
        types = {_doc_type(p, p.rules[n.lower()]) for n in group}
        if len(types) == 1:
            w.append(f"    {', '.join(group)} : {types.pop()}")
            meaning = rule.meaning
        else:                                       # names with rules of their own
            w.append(f"    {', '.join(group)}")
            rules = "; ".join(f"{n}: {_doc_type(p, p.rules[n.lower()])}" for n in group)
            meaning = f"{rule.meaning} ({rules})"
        done |= set(group)
        w += _wrap_text(meaning, "        ")
    return w


def _wrap_text(text, indent, width=88):
    words, lines, cur = text.split(), [], ""
    for word in words:
        if cur and len(indent) + len(cur) + 1 + len(word) > width:
            lines.append(indent + cur)
            cur = word
        else:
            cur = f"{cur} {word}" if cur else word
    if cur:
        lines.append(indent + cur)
    return lines


def _py_default(rule):
    v = rule.default
    if rule.kind == K_INTEGER or rule.kind == K_BRANCH:
        return str(int(float(v)))
    return repr(float(v))


def wrappers(module, procs, variables, source_name):
    w = [f'"""The generated wrappers of the book routines of fortran/{source_name}.',
         "",
         "Written at build time by fortran/gen_drivers.py from the routines' argument lines:",
         "do not edit.  The prose of each docstring, the checks and the reports are added by",
         "the chapter module (:func:`sarkp.library.describe`).",
         '"""',
         "",
         "from __future__ import annotations",
         "",
         "from typing import TYPE_CHECKING, Any, NamedTuple",
         "",
         "from . import _sarkp",
         "from .library import (ArrayLike, Output, Out, OnError, Routine, Rule, _A, _D, _F,  # noqa: F401",
         "                      _I, _mode, _new)",
         "from .results import result_type",
         "",
         f"_drv = _sarkp.drv_{module}",
         "__all__ = [" + _py_join([f'"{p.name.upper()}"' for p in procs], ",", "           ")
         + "]"]
    for p in procs:
        w += ["", ""] + _wrapper(module, p, variables)
    return "\n".join(w) + "\n"


def _wrapper(module, p, variables):
    name = p.name.upper()
    outs = [n.upper() for n in returned(p, variables)]
    if p.kind == "function":
        outs = [name]
    ints_out = {c.name.upper() for c, _ in results_of(p, variables) if c.type == "integer"}
    cls, cls_status = f"{name}Result", f"{name}Status"
    # the classes are sarkp.results' (pickle, a short repr, to_frame); type checkers see
    # them as the named tuples they behave as
    w = ["if TYPE_CHECKING:",
         f"    class {cls}(NamedTuple):",
         f'        """The results of :func:`{name}`, in the book\'s order."""', ""]
    w += [f"        {o}: Output" for o in outs]
    w += ["", "        def to_frame(self) -> Any: ...", "",
          f"    class {cls_status}(NamedTuple):",
          f'        """The results of :func:`{name}` with ``on_error="nan"``."""', ""]
    w += [f"        {o}: Output" for o in outs]
    w += ["        status: Output", "", "        def to_frame(self) -> Any: ...",
          "else:",
          f"    {cls} = result_type({name!r}, {tuple(outs)!r})",
          f"    {cls_status} = result_type({name!r}, {tuple(outs) + ('status',)!r})",
          "", ""]
    tables = bool(p.counts)
    rules = []
    for a in p.inputs:
        r = p.rules[a]
        rules.append(f"Rule({r.book!r}, {r.kind}, {r.word!r}, {r.lo}, {r.hi}, "
                     f"{tuple(d.upper() for d in r.table)!r}, {r.destroyed})")
    w += [f"_{name} = Routine(",
          f"    {name!r}, {module!r}, function={p.kind == 'function'},",
          "    inputs=(" + _py_join(rules, ",", "            ") + ",),",
          f"    outputs={tuple(outs)!r},",
          f"    integer_outputs={tuple(sorted(ints_out))!r},",
          f"    kept={ {c: tuple(n.upper() for n in names) for c, names in p.kept.items()}!r},",
          f"    one=_drv.{p.name}_1, many={'_drv.' + p.name + '_n' if p.sweepable else None},",
          f"    result={cls}, result_with_status={cls_status})", "", ""]
    params = []
    for a in p.inputs:
        r = p.rules[a]
        ann = "ArrayLike" if (r.table or not tables) else (
            "int" if r.kind == K_INTEGER else "float")
        params.append(f"{r.book}: {ann}" + (f" = {_py_default(r)}" if r.default else ""))
    params.append("*")
    params.append("on_error: OnError = 'raise'")
    if not tables:
        params.append("out: Out = None")
    returns = "Output" if p.kind == "function" else cls
    w.append(f"def {name}(" + _py_join(params, ",", " " * (len(name) + 5)) + f") -> {returns}:")
    w.append(f'    """{name}: see the chapter module for the prose.')
    w.append("")
    w += _parameters(p)
    w.append('    """')
    books = [p.rules[a].book for a in p.inputs]
    if not tables:
        # the common case, Python floats and a computed result: one Fortran call (the
        # driver screens the inputs; anything else takes the general path)
        # every real input a float (one chained test), every integer one a float or an
        # int; the flag (no checks, no report) last, since it rarely fails
        reals = [b for a, b in zip(p.inputs, books)
                 if p.rules[a].kind not in (K_INTEGER, K_BRANCH)]
        cond = [" is ".join(["_F"] + [f"type({b})" for b in reals])] if reals else []
        cond += [f"(type({b}) is _F or type({b}) is _I)" for a, b in zip(p.inputs, books)
                 if p.rules[a].kind in (K_INTEGER, K_BRANCH)]
        cond += ["out is None", "on_error == 'raise'", "_" + name + ".fast"]
        call = f"_drv.{p.name}_1(_mode(), " + _py_join(books, ",", " " * 16, 60) + ")"
        result = "_o[0]" if p.kind == "function" else f"_new({cls}, _o[:-2])"
        w += ["    if (" + _py_join(" and ".join(cond).split(" "), "", "            ")
              + "):"]
        ints = any(p.rules[a].kind in (K_INTEGER, K_BRANCH) for a in p.inputs)
        if ints:                                    # a huge int: f2py's OverflowError
            w += ["        try:", f"            _o = {call}", "        except OverflowError:",
                  "            pass", "        else:", "            if _o[-2] == 0:",
                  f"                return {result}"]
        else:
            w += [f"        _o = {call}", "        if _o[-2] == 0:",
                  f"            return {result}"]
        w.append(f"    return _{name}((" + _py_join(books, ",", " " * 8, 60) + ",), on_error, out)"
                 "  # type: ignore[no-any-return]")
    else:
        w += _table_fast_path(p, name, cls, books)
        w.append(f"    return _{name}._call_tables((" + _py_join(books, ",", " " * 8, 60)
                 + ",), on_error)  # type: ignore[no-any-return]")
    return w


def _table_fast_path(p, name, cls, books):
    """The common case of a routine with counted tables: Python ints for the counts
    (in their range), floats for the numbers, float64 arrays of the right shape for the
    one-dimensional tables it only reads: the checks, one driver call and the result.
    Anything else (and any failure) takes the general path."""
    tables = [a for a in p.inputs if p.rules[a].table]
    if any(len(p.rules[a].table) != 1 or p.args[a].intent != "in" or p.rules[a].destroyed
           for a in tables):
        return []
    cond = []
    reals = [p.rules[a].book for a in p.inputs if not p.rules[a].table
             and a not in p.counts and p.rules[a].kind not in (K_INTEGER, K_BRANCH)]
    if reals:
        cond.append(" is ".join(["_F"] + [f"type({b})" for b in reals]))
    for a in p.inputs:
        r = p.rules[a]
        if a in p.counts:
            cond.append(f"type({r.book}) is _I and {r.lo} <= {r.book} <= {r.hi}")
        elif r.table:
            dim = r.table[0]
            size = p.rules[dim].book if dim in p.rules else dim
            cond.append(f"type({r.book}) is _A and {r.book}.dtype is _D and "
                        f"{r.book}.shape == ({size},)")
        elif r.kind in (K_INTEGER, K_BRANCH):
            cond.append(f"(type({r.book}) is _F or type({r.book}) is _I)")
    cond += ["on_error == 'raise'", f"_{name}.report is None"]
    ints = any(p.rules[a].kind in (K_INTEGER, K_BRANCH) and a not in p.counts
               for a in p.inputs)
    named = ", ".join(f"{b}={b}" for b in books)
    call = f"_drv.{p.name}_1(_mode(), " + _py_join(books + ["_k.status if _k else 0"], ",",
                                                    " " * 12, 60) + ")"
    w = ["    if (" + _py_join(" and ".join(cond).split(" "), "", "            ") + "):",
         f"        _k = _{name}._skip(dict(" + _py_join(named.split(" "), "", " " * 12, 60)
         + "), False) if _" + name + ".checks else None"]
    if ints:                                        # a huge int: f2py's OverflowError
        return w + ["        try:", f"            _o = {call}", "        except OverflowError:",
                    "            pass", "        else:",
                    "            if _o[-3] == 0 and _o[-2] == 0:",
                    f"                return _new({cls}, _o[:-3])"]
    return w + [f"        _o = {call}", "        if _o[-3] == 0 and _o[-2] == 0:",
                f"            return _new({cls}, _o[:-3])"]


def _py_join(items, sep, indent, width=88):
    """Python source: ``items`` joined by ``sep`` (and a space), in lines of at most
    ``width`` characters (inside brackets, so no continuation is needed)."""
    lines, cur = [], ""
    for k, item in enumerate(items):
        piece = item + (sep if k < len(items) - 1 else "")
        if cur and len(indent) + len(cur) + 1 + len(piece) > width:
            lines.append(cur)
            cur = piece
        else:
            cur = f"{cur} {piece}" if cur else piece
    lines.append(cur)
    return ("\n" + indent).join(lines)


def main(argv):
    source, out, py, *only = argv
    module, procs, variables, text = generate(Path(source), only)
    Path(out).write_text(text, encoding="utf-8")
    Path(py).write_text(wrappers(module, procs, variables, Path(source).name),
                        encoding="utf-8")


if __name__ == "__main__":
    main(sys.argv[1:])
