"""The book's own code and its errata, as shipped with the package.

``listing(NAME)`` gives the book's listing of a routine or program as printed (OCR misreadings
corrected, each marked ``C OCR:``), by name (``"DPRM1"``) or by listing number (``"IV.1"``);
``listing(NAME, modern=True)`` gives sarkp's Fortran 90 routine; ``listing(NAME, diff=...)``
sets the two side by side or as a unified diff, each deviation annotated with the ERRATA ids
that explain it.  ``errata(ID_OR_NAME)`` gives one row of docs/ERRATA.md, or every row of a
routine.  The files are package data, read through ``importlib.resources``.
"""

from __future__ import annotations

import csv
import difflib
import io
import re
import textwrap
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

__all__ = ["listing", "errata", "listings", "Listing", "ErrataRow", "errata_ids_of"]

_ID = re.compile(r"E-[A-Z0-9]+(?:-[A-Z0-9]+)+")


def _data(*parts: str):
    return resources.files("sarkp").joinpath(*parts)


@dataclass(frozen=True)
class Listing:
    """One row of listings/index.csv."""
    name: str        # the book's name (DPRM1), or the listing number of a program (II.13)
    listing: str     # listing number in the chapter text (IV.1)
    kind: str        # subroutine, function or program
    file: str        # file name in sarkp/listings/
    lines: str       # book lines (L1479-1504)
    table33: str     # item, listing number and line of Table 33 ('' for programs)
    note: str

    def text(self) -> str:
        return _data("listings", self.file).read_text(encoding="utf-8")


@lru_cache(maxsize=None)
def listings() -> tuple[Listing, ...]:
    """Every listing of the book, in the book's order."""
    text = _data("listings", "index.csv").read_text(encoding="utf-8")
    return tuple(Listing(**row) for row in csv.DictReader(io.StringIO(text)))


def _find(name: str) -> Listing:
    key = str(name).strip().upper()
    for item in listings():            # a name first: VII.10 is the program, DNMA5 by name
        if item.name.upper() == key:
            return item
    for item in listings():
        if item.listing.upper() == key:
            return item
    raise ValueError(f"no listing named {name!r}: `sarkp listing` lists them "
                     "(a routine name such as DPRM1, or a listing number such as IV.1)")


# --- ERRATA.md ---------------------------------------------------------------------------

@dataclass(frozen=True)
class ErrataRow:
    id: str
    routine: str
    line: str
    as_printed: str
    correction: str
    kind: str
    as_printed_keeps: str
    test: str
    section: str

    def __str__(self) -> str:
        return "\n".join([
            f"{self.id}  {self.routine}  ({self.line})  [{self.section}]",
            f"  as printed:       {self.as_printed}",
            f"  correction:       {self.correction}",
            f"  kind:             {self.kind}",
            f"  as-printed keeps: {self.as_printed_keeps}",
            f"  test:             {self.test}",
        ])


def _cells(line: str) -> list[str]:
    """A table row's cells; a bar written "\\|" or inside a `code span` is part of a cell."""
    cells, cell, code, i = [], "", False, 0
    text = line.strip()
    while i < len(text):
        ch = text[i]
        if ch == "\\" and text[i + 1:i + 2] == "|":
            cell, i = cell + "|", i + 2
            continue
        if ch == "`":
            code = not code
        if ch == "|" and not code:
            cells.append(cell.strip())
            cell = ""
        else:
            cell += ch
        i += 1
    cells.append(cell.strip())
    return cells[1:-1]


@lru_cache(maxsize=None)
def _errata_rows() -> tuple[ErrataRow, ...]:
    rows, section = [], ""
    for line in _data("ERRATA.md").read_text(encoding="utf-8").splitlines():
        if line.startswith("## "):
            section = line[3:].strip()
        elif line.startswith("| E-"):
            cells = _cells(line)
            cells += [""] * (8 - len(cells))
            rows.append(ErrataRow(*cells[:8], section=section))
    return tuple(rows)


def _mentions(row: ErrataRow, name: str) -> bool:
    """Whether an ERRATA row is about the routine or program NAME."""
    middle = row.id.split("-")[1]
    if name in (middle, middle.replace("II13", "II.13")):
        return True
    if re.fullmatch(r"[IVX]+\.\d+|X", name):        # a program: E-IV15-3, "IV.15 DATA"
        return middle == name.replace(".", "") or re.search(
            rf"(?<![\w.]){re.escape(name)}(?![\w.])", row.routine) is not None
    return re.search(rf"(?<!\w){re.escape(name)}(?!\w)", row.routine) is not None


def errata(key: str) -> str:
    """One ERRATA row by id (``"E-DUSKR1-1"``), or every row of a routine or program
    (``"DUSKR1"``, ``"IV.15"``), as text.  Raises ValueError for an unknown key."""
    rows = errata_rows(key)
    return "\n\n".join(str(r) for r in rows)


def errata_rows(key: str) -> list[ErrataRow]:
    """The ERRATA rows of ``errata(key)``, as records."""
    k = str(key).strip().upper()
    if _ID.fullmatch(k):
        found = [r for r in _errata_rows() if r.id == k]
        if not found:
            raise ValueError(f"no ERRATA row {key!r}")
        return found
    name = _find(k).name.upper() if any(
        k in (i.name.upper(), i.listing.upper()) for i in listings()) else k
    found = [r for r in _errata_rows() if _mentions(r, name)]
    if not found:
        if any(i.name.upper() == name for i in listings()):
            raise ValueError(f"docs/ERRATA.md has no row for {name}")
        raise ValueError(f"no ERRATA row or routine named {key!r}")
    return found


def errata_ids_of(text: str) -> list[str]:
    """The ERRATA ids cited in a text (a docstring, a Fortran header comment)."""
    return list(dict.fromkeys(_ID.findall(text)))


# --- the modern routine -------------------------------------------------------------------

def _modern(item: Listing) -> str:
    if item.kind == "program":
        raise ValueError(f"{item.name} is a program: sarkp runs it in Python "
                         f"(`sarkp book run {item.name}`), it has no Fortran 90 routine")
    start = re.compile(rf"^\s*((pure|elemental|recursive|real\(dp\)|integer)\s+)*"
                       rf"(subroutine|function)\s+{item.name}\s*\(", re.I)
    end = re.compile(rf"^\s*end\s+(subroutine|function)\s+{item.name}\b", re.I)
    for source in sorted(_data("fortran").iterdir(), key=lambda p: p.name):
        if not source.name.endswith(".f90"):
            continue
        lines = source.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines):
            if start.match(line):
                j = i
                while j > 0 and lines[j - 1].lstrip().startswith("!"):
                    j -= 1                          # the routine's header comment
                for k in range(i, len(lines)):
                    if end.match(lines[k]):
                        return "\n".join([f"! fortran/{source.name}, lines {j + 1}-{k + 1}"]
                                         + lines[j:k + 1]) + "\n"
    raise ValueError(f"{item.name} has no Fortran 90 routine in this build of sarkp")


# --- the corrected routine: the as-printed branches left out -----------------------------

def _split_if(code: str):
    """(indent, condition, rest) of a statement ``if (condition) rest``, else None."""
    m = re.match(r"^(\s*)if\s*\(", code, re.I)
    if not m:
        return None
    depth, start = 0, m.end() - 1
    for k in range(start, len(code)):
        depth += {"(": 1, ")": -1}.get(code[k], 0)
        if depth == 0:
            return m.group(1), code[start + 1:k].strip(), code[k + 1:].strip()
    return None


def _simplify(condition: str) -> str:
    """The condition in corrected mode: printed_mode = 0."""
    c = re.sub(r"printed_mode\s*/=\s*0", ".false.", condition, flags=re.I)
    c = re.sub(r"printed_mode\s*==\s*0", ".true.", c, flags=re.I)
    before = None
    while before != c:
        before = c
        c = re.sub(r"\.true\.\s*\.and\.\s*|\s*\.and\.\s*\.true\.", "", c, flags=re.I)
        c = re.sub(r"\.false\.\s*\.or\.\s*|\s*\.or\.\s*\.false\.", "", c, flags=re.I)
        c = re.sub(r"\(\s*(\.true\.|\.false\.)\s*\)", r"\1", c, flags=re.I)
        c = c.replace(".not. .true.", ".false.").replace(".not. .false.", ".true.")
    return c.strip()


def _dedent(lines: list[str], by: int) -> list[str]:
    return [x[min(by, len(x) - len(x.lstrip(" "))):] for x in lines]


def _comment(line: str) -> str:
    at = line.find("!")
    return line[at:] if at >= 0 else ""


def _strip_printed(lines: list[str]) -> tuple[list[str], int]:
    """The lines with every IF on printed_mode settled for corrected mode (its kept
    branch dedented, its dropped branches gone) and the number of IFs settled."""
    out, count, i = [], 0, 0
    while i < len(lines):
        line = lines[i]
        code = re.sub(r"!.*$", "", line).rstrip()
        parts = _split_if(code) if "printed_mode" in code.lower() else None
        if parts is None:
            out.append(line)
            i += 1
            continue
        count += 1
        indent, condition, rest = parts
        c = _simplify(condition)
        note = _comment(line)
        if rest.lower() != "then":                       # a one-line IF
            if c == ".true.":
                out.append(f"{indent}{rest}")
            elif c != ".false.":
                out.append(f"{indent}if ({c}) {rest}")
            i += 1
            continue
        clauses, depth, end = [], 0, None               # (line index, kind, condition)
        for j in range(i + 1, len(lines)):
            s = re.sub(r"!.*$", "", lines[j]).strip().lower()
            if re.match(r"if\s*\(.*\)\s*then$", s):
                depth += 1
            elif re.match(r"end\s*if\b", s):
                if depth == 0:
                    end = j
                    break
                depth -= 1
            elif depth == 0 and re.match(r"else\s*if\b", s):
                clauses.append((j, "elseif"))
            elif depth == 0 and s == "else":
                clauses.append((j, "else"))
        if end is None:
            raise ValueError("an IF block on printed_mode without its END IF")
        first = clauses[0][0] if clauses else end
        body = lines[i + 1:first]

        def inner(chunk):                     # how much deeper than the IF a branch sits
            lead = [len(x) - len(x.lstrip(" ")) for x in chunk if x.strip()]
            return max(0, min(lead, default=len(indent)) - len(indent))
        if c == ".true.":
            kept, n = _strip_printed(_dedent(body, inner(body)))
            out += kept
        elif c == ".false.":
            if clauses and clauses[0][1] == "elseif":
                k = clauses[0][0]
                tail = re.sub(r"^\s*else\s*", "", lines[k], flags=re.I)
                kept, n = _strip_printed([indent + tail] + lines[k + 1:end + 1])
                out += kept
            elif clauses:
                k = clauses[0][0]
                if _comment(lines[k]):
                    out.append(indent + _comment(lines[k]))
                chunk = lines[k + 1:end]
                kept, n = _strip_printed(_dedent(chunk, inner(chunk)))
                out += kept
            else:
                n = 0
        else:
            kept, n = _strip_printed([f"{indent}if ({c}) then" + (f"  {note}" if note else "")]
                                     + lines[i + 1:end + 1])
            out += kept
        count += n
        i = end + 1
    return out, count


def _corrected(item: Listing) -> str:
    """sarkp's routine as corrected mode runs it: the as-printed branches left out."""
    lines = _modern(item).rstrip("\n").split("\n")
    body, count = _strip_printed(lines[1:])
    head = (f"{lines[0]}; as corrected mode runs it, the as-printed branches left out "
            f"({count} IF on printed_mode settled; `sarkp listing {item.name} --modern` "
            "shows them)" if count else f"{lines[0]}; it has no as-printed branches")
    return "\n".join([head] + body) + "\n"


# --- the diff -----------------------------------------------------------------------------

def _book_statements(text: str) -> list[str]:
    """The listing's statements, continuations joined, comments dropped."""
    out: list[str] = []
    for line in text.splitlines():
        if not line.strip() or line[:1] in "Cc*!":
            continue
        if len(line) > 5 and line[5] not in " 0" and not line[:5].strip():
            out[-1] += " " + line[6:].strip()        # continuation line
        else:
            label, body = line[:5].strip(), line[6:].strip()
            out.append(f"{label} {body}" if label else body)
    return out


def _modern_statements(text: str) -> list[str]:
    out, pending = [], ""
    for line in text.splitlines():
        code = re.sub(r"!.*$", "", line).rstrip()  # no "!" occurs inside a string here
        if not code.strip():
            continue
        code = pending + code.strip().lstrip("&").strip()
        if code.endswith("&"):
            pending = code[:-1].rstrip() + " "
            continue
        pending = ""
        out.extend(s.strip() for s in code.split(";") if s.strip())
    return out


_DECLARATION = re.compile(r"^(\d+\s+)?(REAL|INTEGER|DIMENSION|COMMON|IMPLICIT|USE|LOGICAL|"
                          r"DOUBLE\s*PRECISION)\b|^REAL\s*\(DP\)", re.I)


def _statements(statements: list[str]) -> list[str]:
    """Executable statements only (declarations differ by design), one END.  sarkp's
    statements are all shown as written, its status handling too (IER set and tested,
    outputs of a failed call zeroed): statements joined by ``;`` one by one, one-line IFs
    as they are."""
    out = [s for s in statements if not _DECLARATION.match(s)]
    out = [("END" if re.match(r"END\s+(SUBROUTINE|FUNCTION)\b", s, re.I) else s) for s in out]
    if len(out) > 1 and out[-1].upper() == "END" and out[-2].upper() == "RETURN":
        del out[-2]
    return out


def _key(statement: str) -> str:
    """What a statement says, without style: case, blanks, kinds and literal forms."""
    s = statement.upper()
    s = re.sub(r"^((PURE|ELEMENTAL|RECURSIVE|REAL\(DP\))\s+)+", "", s)
    s = re.sub(r"_DP\b", "", s)
    s = re.sub(r"(\d)D0\b", r"\1", s)
    s = re.sub(r"\s+", "", s)
    s = s.replace("ARCOS(", "ACOS(").replace("ARSIN(", "ASIN(")
    return s


def _normal(s: str) -> str:
    s = s.upper().replace("\\*", "*").replace("—", "-").replace("–", "-")
    return re.sub(r"\s+", "", s)


def _snippets(cell: str) -> list[str]:
    # " / " in an ERRATA quote is a line break (" / *" before a continuation line), also
    # between two quotes: "`line` / `*continuation`" is one statement
    cell = re.sub(r"`\s*/\s*`\*?", " ", cell)
    quotes = (re.sub(r"\s/\s\*?", " ", q) for q in re.findall(r"`([^`]+)`", cell))
    return [_normal(q) for q in quotes if len(_normal(q)) >= 3]


def _found(snippet: str, texts: tuple[str, ...]) -> bool:
    """Whether a quote (its "..." elisions allowed) occurs in one of the texts."""
    parts = [p for p in snippet.split("...") if p]
    for text in texts:
        at = 0
        for part in parts:
            at = text.find(part, at)
            if at < 0:
                break
            at += len(part)
        else:
            if parts:
                return True
    return False


def _as_read(text: str, pairs: list[tuple[str, str]]) -> str:
    """The text with the listing's OCR corrections undone: the ERRATA quotes the OCR."""
    for read, fixed in pairs:
        if _normal(fixed).lstrip("*"):
            text = text.replace(_normal(fixed).lstrip("*"), _normal(read).lstrip("*"))
    return text


def _annotate(book_side: list[str], modern_side: list[str], rows: list[ErrataRow],
              ocr: list[tuple[str, str]] = ()) -> list[str]:
    old, new = _normal(" ".join(book_side)), _normal(" ".join(modern_side))
    olds = (old, _as_read(old, list(ocr)))
    hits = []
    for r in rows:
        if r.kind.strip() == "OCR":
            continue                      # corrected in the listing itself, not a deviation
        printed = _snippets(r.as_printed)
        if any(_found(p, olds) or old and old in p for p in printed) or (
                not printed and any(c in new for c in _snippets(r.correction))):
            hits.append(r.id)
    return hits


def _loose(statement: str) -> str:
    """A looser key, to set equivalent statements side by side: Y(1) is y1."""
    return re.sub(r"\b([A-Z]+)\((\d)\)", r"\1\2", _key(statement))


def _pair(left: list[str], right: list[str]) -> list[tuple[str, str, str]]:
    """The statements of a differing hunk in rows, equivalent ones in the same row
    (marked "~"; "!" where they differ)."""
    rows: list[tuple[str, str, str]] = []
    m = difflib.SequenceMatcher(None, [_loose(s) for s in left], [_loose(t) for t in right],
                                autojunk=False)
    for tag, i1, i2, j1, j2 in m.get_opcodes():
        l, r = left[i1:i2], right[j1:j2]
        for k in range(max(len(l), len(r))):
            rows.append(("~" if tag == "equal" else "!", l[k] if k < len(l) else "",
                         r[k] if k < len(r) else ""))
    return rows


def _wrap(text: str, width: int) -> list[str]:
    """A statement in lines of at most ``width`` characters (never cut: wrapped)."""
    return textwrap.wrap(text, width, subsequent_indent="    ", break_on_hyphens=False,
                         break_long_words=True) or [""]


def _side(mark: str, left: str, right: str, width: int) -> list[str]:
    a, b = _wrap(left, width), _wrap(right, width)
    a += [""] * (len(b) - len(a))
    b += [""] * (len(a) - len(b))
    return [f"{mark} {x:<{width}} | {y}".rstrip() for x, y in zip(a, b)]


def _diff(item: Listing, style: str) -> str:
    book_text, modern_text = item.text(), _corrected(item)
    ocr = [pair for line in book_text.splitlines() if line.startswith("C OCR:")
           for pair in re.findall(r'"([^"]*)"\s*->\s*"([^"]*)"', line)]
    cited = errata_ids_of(modern_text)
    try:
        rows = errata_rows(item.name)
    except ValueError:
        rows = []
    rows += [r for r in _errata_rows() if r.id in cited and r not in rows]
    a = _statements(_book_statements(book_text))
    b = _statements(_modern_statements(modern_text))
    head = re.compile(r"(\w+\s+)?(SUBROUTINE|FUNCTION)\s", re.I)
    headers = None
    if a and b and head.match(a[0]) and head.match(b[0]):
        headers, a, b = (a[0], b[0]), a[1:], b[1:]
    matcher = difflib.SequenceMatcher(None, [_key(s) for s in a], [_key(s) for s in b],
                                      autojunk=False)
    listed = list(dict.fromkeys([r.id for r in rows] + cited))
    out = [f"{item.name}: the book's listing {item.listing} ({item.lines}) against sarkp's "
           "Fortran 90 routine as corrected mode runs it (its as-printed branches left out: "
           f"`sarkp listing {item.name} --modern` shows them): executable statements, "
           "compared without case, blanks and kind suffixes (declarations differ by design: "
           "double precision, IER).",
           f"ERRATA rows of {item.name} (docs/ERRATA.md, and the ids its Fortran 90 cites): "
           f"{', '.join(listed) if listed else 'none'}", ""]
    used: set[str] = set()
    width = 64
    if headers and _key(headers[0]) != _key(headers[1]):
        ids = _annotate([headers[0]], [headers[1]], rows, ocr)
        used.update(ids)
        plain = re.sub(r",IER\)$", ")", _key(headers[1]))
        note = ", ".join(ids) if ids else (
            "the interface: IER appended (sarkp's design, not an erratum)"
            if plain == _key(headers[0]) else "no ERRATA row matches")
        out.append(f"@@ the header: {note}")
        if style == "side":
            out += _side("!", headers[0], headers[1], width)
        else:
            out += [f"- {headers[0]}", f"+ {headers[1]}"]
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            if style == "side":
                for s, t in zip(a[i1:i2], b[j1:j2]):
                    out += _side(" ", s, t, width)
            continue
        ids = _annotate(a[i1:i2], b[j1:j2], rows, ocr)
        used.update(ids)
        note = ", ".join(ids) if ids else "no ERRATA row matches (a rewrite of the same step)"
        where = lambda n1, n2: f"{n1 + 2}-{n2 + 1}" if n2 > n1 else f"none (after {n1 + 1})"
        out.append(f"@@ book statements {where(i1, i2)}, sarkp statements {where(j1, j2)}: "
                   f"{note}")
        if style == "side":
            for mark, s, t in _pair(a[i1:i2], b[j1:j2]):
                out += _side(mark, s, t, width)
        else:
            out += [f"- {s}" for s in a[i1:i2]] + [f"+ {t}" for t in b[j1:j2]]
    kinds = {r.id: r.kind for r in rows}
    reads = [_normal(r) for r, _ in ocr]
    by_id = {r.id: r for r in rows}

    def in_marks(i):                  # an "OCR/author" row the listing corrects as OCR
        r = by_id.get(i)
        return r is not None and any(any(p in m or m in p for m in reads if m)
                                     for p in _snippets(r.as_printed))
    ocr_ids = [i for i in cited if i not in used and (kinds.get(i, "").strip() == "OCR"
                                                      or in_marks(i))]
    other = [i for i in cited if i not in used and i not in ocr_ids]
    if ocr_ids:
        out += ["", "OCR misreadings, already corrected in the listing (its C OCR: lines): "
                + ", ".join(ocr_ids)]
    if other:
        out += ["", "Cited but not located in one hunk (declarations are not compared; "
                "see `sarkp errata ID`): " + ", ".join(other)]
    return "\n".join(out) + "\n"


def listing(name: str, modern: bool = False, diff: str | bool | None = None,
            corrected: bool = False) -> str:
    """The book's listing of a routine or program, as printed (OCR misreadings corrected,
    each marked ``C OCR:``).

    Parameters
    ----------
    name : str
        A routine's name (``"DPRM1"``) or a listing number (``"IV.1"``, ``"II.13"``).
    modern : bool
        Give sarkp's Fortran 90 routine instead (with its header comment and ERRATA ids).
    diff : {None, False, True, "unified", "side"}
        Compare the book's listing with sarkp's routine as corrected mode runs it (``corrected``)
        statement by statement: ``True`` or ``"unified"`` for a unified diff, ``"side"`` for
        side by side (long statements wrapped, never cut).  Each differing hunk names the
        ERRATA ids it matches; the second line lists every id of the routine.
    corrected : bool
        Give sarkp's Fortran 90 routine as corrected mode runs it: every IF on
        ``printed_mode`` settled, the as-printed branches left out (clean code to read).

    Raises
    ------
    ValueError
        For an unknown name, or ``modern``/``diff`` for a program or a routine sarkp lacks.
    """
    item = _find(name)
    if diff:
        style = "side" if diff == "side" else "unified"
        if diff not in (True, "unified", "side"):
            raise ValueError(f"diff must be 'unified' or 'side', not {diff!r}")
        return _diff(item, style)
    if corrected:
        return _corrected(item)
    if modern:
        return _modern(item)
    return item.text()


def table() -> str:
    """One line per listing: number, name, kind, book lines and file."""
    lines = [f"{'listing':8s} {'name':8s} {'kind':10s} {'book lines':24s} file"]
    for i in listings():
        lines.append(f"{i.listing:8s} {i.name:8s} {i.kind:10s} {i.lines:24s} {i.file}")
    return "\n".join(lines)
