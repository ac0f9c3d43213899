"""Generate the Python-facing drivers of one chapter module (run by meson at build time).

    python gen_drivers.py CHAPTER.f90 OUT.f90 [ROUTINE ...]

Reads the public procedures of the Fortran module in CHAPTER.f90 (or only the ROUTINEs
named) and writes module ``drv_<module>`` with, for each book routine NAME:

* ``NAME_1(sarkp_mode, <the book's arguments>, <COMMON results>, sarkp_status)``: one call
  in the caller's mode;
* ``NAME_n(sarkp_mode, sarkp_n, sarkp_inc, sarkp_kind, sarkp_nan, <inputs as arrays>,
  sarkp_out, sarkp_status, sarkp_bad)``: a loop over ``sarkp_n`` positions, for routines
  whose arguments are scalars or fixed-size arrays.  The results of position i go to
  ``sarkp_out(i, k)``, k in the order of NAME_1's results: one array the caller owns (the
  Python layer allocates it, or takes the caller's ``out=``), none per result.  Input k of
  position i is element ``1 + (i-1)*sarkp_inc(k)``, so an input that is the same at every
  position is passed once (``sarkp_inc(k) = 0``).  Each input is screened first, in the
  same loop (an input passed once, at the first position only), by its kind (``screen``:
  finite, length, non-negative, non-zero, branch); the first bad one stops the loop and
  comes back in ``sarkp_bad(1:2)`` = (input, element); ``sarkp_bad(3)`` counts the
  positions whose status is not st_ok.  A NaN gives the position status st_missing when
  ``sarkp_nan`` allows it.

Every driver sets the mode (prmtr's ``set_mode``) inside the same Fortran call.  The
drivers release the GIL (f2py ``threadsafe``): the mode lives in thread-private variables
of prmtr (``!$omp threadprivate``, thread-local storage), and no other module variable is
written, except the COMMON results of the routines that have them, whose drivers keep the
GIL.  ``sarkp_status`` is the routine's trailing IER when
it has one (a prmtr status code), else ``st_ok``; a result that is not a finite number while
the routine reported success becomes ``st_range``.  A book FUNCTION's value is ``fres``.

The chapter modules must follow the conventions of fortran/README (one declaration line per
group of dummy arguments: ``real(dp), intent(in) :: a, b(n)``; ``!sarkp common: x, y`` as the
first line after a subroutine statement names the module variables returned with it, and
``!sarkp common: a => zpc_a`` returns module variable ``zpc_a`` as the result ``a`` (several
such lines may follow one another);
``!sarkp ier-is-output`` keeps a trailing IER as an ordinary output).
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

TYPES = {"real(dp)": "real(dp)", "integer": "integer"}


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

    def decl(self, intent=None, dims=None) -> str:
        intent = self.intent if intent is None else intent
        dims = self.dims if dims is None else dims
        shape = f"({', '.join(dims)})" if dims else ""
        text = f"{self.type}"
        if intent:
            text += f", intent({intent})"
        return f"{text} :: {self.name}{shape}"


@dataclass
class Procedure:
    name: str
    kind: str                   # subroutine | function
    argnames: list
    args: dict = field(default_factory=dict)
    commons: list = field(default_factory=list)
    # result name of each COMMON variable (``!sarkp common: a => zpc_a`` names the result
    # ``a``: two COMMON blocks may share a book name, module variables cannot)
    common_names: dict = field(default_factory=dict)
    ier_is_output: bool = False

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


def logical_lines(text: str):
    """Statements with continuations joined and comments dropped; ``!sarkp`` kept."""
    out, pending = [], ""
    for raw in text.splitlines():
        stripped = raw.strip()
        if stripped.lower().startswith("!sarkp"):
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


def parse_entities(rest: str):
    for ent in split_top(rest):
        ent = ent.split("=")[0].strip()
        m = re.match(r"(\w+)\s*(?:\((.*)\))?$", ent)
        if not m:
            raise SystemExit(f"gen_drivers: cannot read the declaration {ent!r}")
        dims = tuple(d.strip().lower() for d in split_top(m.group(2))) if m.group(2) else ()
        yield m.group(1).lower(), dims


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
    procs = [p for p in procs if p.name in public]
    for p in procs:
        missing = [a for a in p.argnames if a not in p.args or not p.args[a].intent]
        if missing:
            raise SystemExit(f"gen_drivers: {path.name}: {p.name}: no intent declared for "
                             f"{', '.join(missing)}")
        for c in p.commons:
            if c not in variables:
                raise SystemExit(f"gen_drivers: {path.name}: {p.name}: COMMON result {c} is "
                                 f"not a public module variable")
    return module, procs, variables


def finite_test(items):
    """The test that every (expression, is_array) in ``items`` is a finite number."""
    tests = [f"all(abs({e}) <= huge(1.0_dp))" if array else f"abs({e}) <= huge(1.0_dp)"
             for e, array in items]
    return " .and. &\n          ".join(tests)


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


def scalar_driver(mod, p, variables):
    w = []
    pairs = _commons(p, variables)
    commons = [c for c, _ in pairs]
    # the status comes last, after the COMMON results (Python reads it as the last result)
    names = (["sarkp_mode"] + [a for a in p.argnames if a != p.status_arg]
             + [c.name for c in commons])
    if p.kind == "function":
        names.append("fres")
    names.append(p.status_arg or "sarkp_status")
    w.append(f"  subroutine {p.name}_1({wrap_list(names)})")
    if not p.commons:
        w.append("    !f2py threadsafe")
    w.append("    integer, intent(in) :: sarkp_mode")
    for a in p.argnames:
        arg = p.args[a]
        w.append("    " + arg.decl())
        if arg.intent == "inout":
            w.append(f"    !f2py intent(in,out) :: {a}")
    for c in commons:
        w.append("    " + Arg(c.name, c.type, "out", c.dims).decl())
    if p.kind == "function":
        w.append(f"    {p.result_type or 'real(dp)'}, intent(out) :: fres")
    if p.status_arg is None:
        w.append("    integer, intent(out) :: sarkp_status")
    status = p.status_arg or "sarkp_status"
    w.append("    call set_mode(sarkp_mode)")
    if p.kind == "function":
        w.append(f"    fres = {p.name}({wrap_list(p.argnames)})")
    else:
        w.append(f"    call {p.name}({wrap_list(p.argnames)})")
    if p.status_arg is None:
        w.append("    sarkp_status = st_ok")
    for c, var in pairs:
        w.append(f"    {c.name} = {mod}_{var}")
    real_out = [(a, bool(p.args[a].dims)) for a in p.argnames
                if p.args[a].intent in ("out", "inout") and p.args[a].type == "real(dp)"]
    real_out += [(c.name, bool(c.dims)) for c in commons if c.type == "real(dp)"]
    if p.kind == "function" and (p.result_type or "real(dp)") == "real(dp)":
        real_out.append(("fres", False))
    if real_out:
        w.append(f"    if (succeeded({status})) then")
        w.append(f"      if (.not. ({finite_test(real_out)})) {status} = st_range")
        w.append("    end if")
    w.append(f"  end subroutine {p.name}_1")
    return w


def sweep_driver(mod, p, variables):
    pairs = _commons(p, variables)
    commons = [c for c, _ in pairs]
    ins = [a for a in p.argnames if p.args[a].intent == "in"]
    outs = [a for a in p.argnames if p.args[a].intent == "out" and a != p.status_arg]
    # every result of position i goes to column k of sarkp_out(i, k), in the order of the
    # one-call driver's results: the outputs, the COMMON results, a FUNCTION's value
    results = [p.args[a] for a in outs] + commons
    if p.kind == "function":
        results.append(Arg("fres", p.result_type or "real(dp)", "out"))
    for r in results:
        if r.dims or r.type not in TYPES:
            raise ValueError(f"{p.name}: the sweep packs scalar results only, not {r.name}")
    column = {r.name: k for k, r in enumerate(results, 1)}
    ints = [r.name for r in results if r.type == "integer"]
    names = (["sarkp_mode", "sarkp_n", "sarkp_inc", "sarkp_kind", "sarkp_nan"] + ins
             + ["sarkp_out", "sarkp_status", "sarkp_bad"])
    w = [f"  subroutine {p.name}_n({wrap_list(names)})"]
    if not p.commons:
        w.append("    !f2py threadsafe")
    w += ["    integer, intent(in) :: sarkp_mode, sarkp_n, sarkp_nan",
         f"    integer, intent(in) :: sarkp_inc({len(ins)}), sarkp_kind({len(ins)})"]
    for a in ins:
        arg = p.args[a]
        w.append("    " + arg.decl(dims=arg.dims + ("*",)))
    w += [f"    real(dp), intent(inout) :: sarkp_out(sarkp_n, {len(results)})",
          "    integer, intent(out) :: sarkp_status(sarkp_n), sarkp_bad(3)",
          "    integer :: sarkp_i, sarkp_state, sarkp_once"
          + (", sarkp_t, sarkp_j" if any(p.args[a].type == "real(dp)" for a in ins) else "")
          + (", sarkp_l" if any(p.args[a].dims for a in ins) else "")]
    if ints:
        w.append(f"    integer :: {', '.join('sarkp_' + n for n in ints)}")
    w += ["    sarkp_bad = 0",
          "    call set_mode(sarkp_mode)",
          "    sarkp_once = 0",
          "    do sarkp_i = 1, sarkp_n",
          "      ! the inputs of position i: a NaN is a missing input (status 5) when allowed;",
          "      ! anything else out of its kind's range stops the loop and is reported.  An",
          "      ! input passed once (inc 0) is screened at position 1 only, in its turn;",
          "      ! sarkp_once keeps what it found (0, or 1 for a missing input).",
          "      sarkp_state = sarkp_once"]
    for k, a in enumerate(ins, 1):
        arg = p.args[a]
        if arg.type != "real(dp)":
            continue
        w.append(f"      if (sarkp_inc({k}) /= 0 .or. sarkp_i == 1) then")
        w.append(f"        sarkp_j = 1 + (sarkp_i - 1)*sarkp_inc({k})")
        if arg.dims:
            w += ["        sarkp_t = 0",
                  f"        do sarkp_l = 1, {arg.dims[0]}",
                  f"          sarkp_t = max(sarkp_t, screen({a}(sarkp_l, sarkp_j), "
                  f"sarkp_kind({k}), sarkp_nan, {k}, sarkp_j, sarkp_bad))",
                  "        end do"]
        else:
            w.append(f"        sarkp_t = screen({a}(sarkp_j), "
                     f"sarkp_kind({k}), sarkp_nan, {k}, sarkp_j, sarkp_bad)")
        w.append("        sarkp_state = max(sarkp_state, sarkp_t)")
        w.append(f"        if (sarkp_inc({k}) == 0) sarkp_once = max(sarkp_once, sarkp_t)")
        w.append("      end if")
    w += ["      if (sarkp_state == 2) return",
          "      if (sarkp_state == 1) then",
          "        sarkp_status(sarkp_i) = st_missing",
          "        cycle",
          "      end if"]

    def ref(a):
        if a in ins:
            arg = p.args[a]
            return f"{a}({':, ' * len(arg.dims)}1 + (sarkp_i - 1)*sarkp_inc({ins.index(a) + 1}))"
        if a in ints:
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
    for n in ints:                                  # an integer result is stored as a real
        w.append(f"      sarkp_out(sarkp_i, {column[n]}) = real(sarkp_{n}, dp)")
    real_out = [(f"sarkp_out(sarkp_i, {column[r.name]})", False) for r in results
                if r.type == "real(dp)"]
    if real_out:
        w.append("      if (succeeded(sarkp_status(sarkp_i))) then")
        w.append(f"        if (.not. ({finite_test(real_out)})) sarkp_status(sarkp_i) = st_range")
        w.append("      end if")
    w.append("    end do")
    w.append("    sarkp_bad(3) = count(sarkp_status /= st_ok)   ! 0: nothing to look at")
    w.append(f"  end subroutine {p.name}_n")
    return w


SCREEN = """
  ! The state of input number k, element j, of a sweep: 0 valid; 1 NaN, a missing input
  ! (allowed when nan /= 0); 2 out of range for its kind -- 0 a finite number, 1 a length
  ! (> 0), 2 >= 0, 3 not 0, 4 an assembly branch (-1 or +1).  The first input in state 2
  ! (a NaN too, when not allowed) is recorded in bad = (k, j).
  integer function screen(x, kind, nan, k, j, bad)
    real(dp), intent(in) :: x
    integer, intent(in) :: kind, nan, k, j
    integer, intent(inout) :: bad(3)
    screen = 0
    if (x /= x) then
      screen = 1
      if (nan /= 0) return
      screen = 2
    else if (abs(x) > huge(x)) then
      screen = 2
    else
      select case (kind)
      case (1)
        if (.not. x > 0.0_dp) screen = 2
      case (2)
        if (x < 0.0_dp) screen = 2
      case (3)
        if (x == 0.0_dp) screen = 2
      case (4)
        if (x /= 1.0_dp .and. x /= -1.0_dp) screen = 2
      end select
    end if
    if (screen == 2 .and. bad(1) == 0) then
      bad(1) = k
      bad(2) = j
    end if
  end function screen
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
         "! the caller passes.",
         f"module drv_{module}",
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
    if any(p.sweepable for p in procs):
        w.append(SCREEN)
    w.append(f"end module drv_{module}")
    return "\n".join(w) + "\n"


def main(argv):
    source, out, *only = argv
    Path(out).write_text(generate(Path(source), only), encoding="utf-8")


if __name__ == "__main__":
    main(sys.argv[1:])
