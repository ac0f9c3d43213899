"""The book's listings and ERRATA.md as package data: `sarkp listing`, `sarkp errata`."""

import csv
import io
import os
import re
import shutil
import subprocess
import sys
from importlib import resources
from pathlib import Path

import pytest

import sarkp
from sarkp import listings as L

# Table 33 (book L6267-6330), in its order.  It spells DPRFLP "DPRFLD" and DCHRVC "DCHRCV";
# the listings' own headings (L3153, L4739) and every call use DPRFLP and DCHRVC.
TABLE33 = """DINTGR DFRNCL DUGL1 DUGL2 DUGL3 DUGL4 DUGL5 DUGOL DVKT DSMVKT DOMEGA DMOMNT
DSNTZR DSNTZ1 DSNTZ2 DSNTZ3 DSNTZK DPRM1 DPRM2 DPRM3 DPRM4 DSKOR1 DSKOR2 DSKOR3 DSKOR4
DSKOR5 DUSKR1 DUSKR2 DUSKR3 DUSKR4 DUSKR5 DKNMA1 DKNMA2 DKNMA3 DKNMA4 DKNMA5 DKLCHK DPRFLP
DPRFPL DPRFLK DZBPL DKRKT DUGINV DGMTZK DGMZPC DGMZVN DCHRVC DNMAF1 DNMAF2 DNMAF3 DNMAF4
DNMAF5 DNMA1 DNMA2 DNMA3 DNMA4 DNMA5 DZKNDV DMHVK""".split()
PROGRAMS = ["II.13", "III.5", "IV.15", "V.5", "VI.2", "VII.10", "X"]
BOOK = Path(os.environ.get("SARKP_BOOK",
                           "/work/shared/seeds/000_eb1ab766384ea773.txt"))
OCR_MARK = re.compile(r'"([^"]*)"\s*->\s*"([^"]*)"')


def package_file(*parts):
    return resources.files("sarkp").joinpath(*parts)


def index():
    text = package_file("listings", "index.csv").read_text(encoding="utf-8")
    return list(csv.DictReader(io.StringIO(text)))


def code_lines(text):
    return [l for l in text.splitlines() if l.strip() and l[:1] not in "Cc"]


def test_table33_has_59_routines():
    assert len(TABLE33) == len(set(TABLE33)) == 59


def test_every_table33_routine_and_program_has_a_listing_file():
    rows = {r["name"]: r for r in index()}
    assert set(rows) == set(TABLE33) | set(PROGRAMS)
    # the index's Table 33 column numbers the 59 routines 1..59 in the book's order
    numbered = sorted((int(r["table33"].split()[0]), n) for n, r in rows.items() if r["table33"])
    assert [n for _, n in numbered] == TABLE33


@pytest.mark.parametrize("row", index(), ids=lambda r: r["name"])
def test_listing_opens_from_the_installed_package(row):
    f = package_file("listings", row["file"])
    assert f.is_file()
    text = f.read_text(encoding="utf-8")
    header = text.splitlines()[0]
    assert header.startswith(f"C LISTING {row['listing']} ")
    assert ", ".join(row["lines"].split()) in header
    code = code_lines(text)
    assert code[-1].strip() == "END"
    if row["kind"] != "program":
        first = code[0].upper()
        assert re.match(rf"^\s+(SUBROUTINE|FUNCTION)\s+{row['name']}\s*\(", first), first
    # fixed form: a label in columns 1-5, a continuation mark in column 6, then the code
    for line in code:
        assert re.match(r"^(\d{1,5}\s*| {5})[ *]", line), line


def test_errata_and_fortran_sources_are_package_data():
    errata_md = package_file("ERRATA.md").read_text(encoding="utf-8")
    assert "| E-DUSKR1-1 |" in errata_md
    sources = [p.name for p in package_file("fortran").iterdir()]
    assert "kinematics.f90" in sources and "prmtr.f90" in sources


def test_listing_by_name_and_number_from_python():
    text = sarkp.listing("DPRM1")
    assert text == sarkp.listing("IV.1") == sarkp.listing("dprm1")
    assert "SUBROUTINE DPRM1(XA, YA, XC, YC, RZ2, RZ3, P, AAA, FI2, FI3, XB, YB)" in text
    # VII.10 is the program of section 7.5; DNMA5 (Table 33's VII.10) by its name
    assert "SUBROUTINE" not in "".join(code_lines(sarkp.listing("VII.10")))
    assert "SUBROUTINE DNMA5(" in sarkp.listing("DNMA5")
    with pytest.raises(ValueError, match="no listing named"):
        sarkp.listing("DPRM9")


def test_modern_routine_is_the_fortran90_one_with_its_errata_ids():
    text = sarkp.listing("DUSKR1", modern=True)
    assert re.search(r"^\s*subroutine duskr1\(", text, re.M | re.I)
    assert re.search(r"^\s*end subroutine duskr1", text, re.M | re.I)
    assert "E-DUSKR1-1" in text
    with pytest.raises(ValueError, match="program"):
        sarkp.listing("II.13", modern=True)


def test_diff_marks_the_authors_error_with_its_errata_id():
    text = sarkp.listing("DUSKR1", diff=True)
    hunks = text.split("@@")[1:]
    hunk = next(h for h in hunks if "- ABCT = ABS(Y(1))" in h)
    assert "E-DUSKR1-1" in hunk.splitlines()[0]
    side = sarkp.listing("DUSKR1", diff="side")
    assert "E-DUSKR1-1" in side
    with pytest.raises(ValueError):
        sarkp.listing("DUSKR1", diff="sideways")


def test_errata_by_id_and_by_routine():
    row = sarkp.errata("E-DUSKR1-1")
    assert row.startswith("E-DUSKR1-1") and "ABS(Y(2))" in row
    rows = sarkp.errata("DUSKR1")
    for i in ("E-DUSKR1-1", "E-DUSKR1-2", "E-DUSKR1-3"):
        assert i in rows
    assert "E-DPRM1" not in rows
    assert "E-IV15-3" in sarkp.errata("IV.15")
    for bad in ("E-DUSKR1-99", "NOSUCH"):
        with pytest.raises(ValueError):
            sarkp.errata(bad)


def _cited_ids():
    found = {}
    for name in sarkp.__all__:
        doc = getattr(getattr(sarkp, name), "__doc__", None) or ""
        for i in L.errata_ids_of(doc):
            found.setdefault(i, f"docstring of {name}")
    stack = [package_file()]
    while stack:                                  # every Python file of the package
        for p in stack.pop().iterdir():
            if p.is_dir():
                stack.append(p)
            elif p.name.endswith(".py"):
                for i in L.errata_ids_of(p.read_text(encoding="utf-8")):
                    found.setdefault(i, p.name)
    for folder in ("fortran", "listings"):        # Fortran headers; the listings' marks
        for f in package_file(folder).iterdir():
            for i in L.errata_ids_of(f.read_text(encoding="utf-8")):
                found.setdefault(i, f"{folder}/{f.name}")
    return found


def test_every_cited_errata_id_is_a_row():
    cited = _cited_ids()
    assert cited, "no ERRATA id cited anywhere"
    for i, where in cited.items():
        assert sarkp.errata(i).startswith(i), where


def _ocr_marks():
    for row in index():
        lines = package_file("listings", row["file"]).read_text(encoding="utf-8").splitlines()
        for n, line in enumerate(lines):
            if line.startswith("C OCR:"):
                yield row, line, lines[n + 1:]


def test_each_ocr_mark_names_what_the_ocr_read_and_its_correction():
    marks = list(_ocr_marks())
    assert len(marks) > 100
    for row, line, after in marks:
        pairs = OCR_MARK.findall(line)
        assert pairs, f"{row['file']}: {line}"
        # the statement(s) the mark precedes, continuation lines joined
        code = [l for l in after if not l.startswith("C OCR:")][:6]
        following = "".join(l[6:] if l[5:6] == "*" else l for l in code)
        squeeze = lambda s: re.sub(r"\s+", "", s)
        for read, fixed in pairs:
            assert read != fixed, line
            assert squeeze(read), line
            # the correction is what the file now says
            assert squeeze(fixed).lstrip("*") in squeeze(following), f"{row['file']}: {line}"


@pytest.mark.skipif(not BOOK.is_file(), reason="the book's OCR text is not on this machine")
def test_what_the_ocr_read_is_in_the_book_at_the_listings_lines():
    book = BOOK.read_text(encoding="utf-8").splitlines()

    def norm(s):
        s = re.sub(r"\$\\theta\$", "θ", s)
        s = re.sub(r"\\text\{([^}]*)\}", r"\1", s)
        return re.sub(r"[\s$\\]", "", s)

    for row, line, _ in _ocr_marks():
        spans = [tuple(int(x) for x in part[1:].split("-")) for part in row["lines"].split()]
        raw = norm("".join(book[a - 1] for a, b in spans for a in range(a, b + 1)))
        for read, _fixed in OCR_MARK.findall(line):
            assert norm(read) in raw, f"{row['file']}: {read!r} is not in the book"


def _authors_errors(kind="author"):
    """ERRATA rows of the kind whose printed text is code of one listing."""
    names = {r["name"]: r for r in index()}
    for r in L._errata_rows():
        if r.kind.strip() != kind:
            continue
        routine = r.routine.split(",")[0].split()[0]
        if routine not in names or re.search(r"\b(missing|no|never|not|lacks?)\b", r.as_printed):
            continue                 # the row quotes what is absent
        spans = [tuple(int(x) for x in p[1:].split("-")) for p in names[routine]["lines"].split()]
        cited = [int(x) for x in re.findall(r"L(\d+)", r.line)]
        if not any(a <= n <= b for n in cited for a, b in spans):
            continue                 # the row quotes the text or a table, not the listing
        # "`line` / `*continuation`": consecutive lines of one statement, quoted separately
        printed = re.sub(r"`\s*/\s*`\*?", "", r.as_printed)
        for snippet in re.findall(r"`([^`]+)`", printed):
            statement = re.match(r"(CALL|IF|DO|SUBROUTINE|FUNCTION|REAL|DIMENSION|WRITE|"
                                 r"PRINT|DATA|[A-Z][A-Z0-9]*(\(.*\))?\s*=)", snippet)
            printed_values = re.search(r"=\s*-?[\d.]+\s+[A-Z]", snippet)
            if statement and not printed_values:
                yield r.id, names[routine], snippet


def test_the_authors_errors_stay_as_printed():
    checked = 0
    for rid, row, snippet in _authors_errors():
        text = package_file("listings", row["file"]).read_text(encoding="utf-8")
        squeeze = lambda s: re.sub(r"\s+", "", s)
        code = squeeze("".join(l[6:] if l[5:6] == "*" else l for l in code_lines(text)))
        # the ERRATA quotes the OCR's text: undo the file's OCR corrections to compare
        as_read = code
        for mark in (l for l in text.splitlines() if l.startswith("C OCR:")):
            for read, fixed in OCR_MARK.findall(mark):
                as_read = as_read.replace(squeeze(fixed).lstrip("*"), squeeze(read).lstrip("*"))
        # " / " in an ERRATA quote is a line break (" / *" before a continuation line)
        want = squeeze(re.sub(r"\s/\s\*?", "", snippet.replace("\\*", "*")))
        if "..." in want:
            continue
        assert want in code or want in as_read, f"{rid}: {snippet!r} no longer in {row['file']}"
        checked += 1
    assert checked >= 10


def test_ocr_rows_are_corrected_in_the_listings():
    checked = 0
    for rid, row, snippet in _authors_errors(kind="OCR"):
        text = package_file("listings", row["file"]).read_text(encoding="utf-8")
        squeeze = lambda s: re.sub(r"\s+", "", s)
        code = squeeze("".join(l[6:] if l[5:6] == "*" else l for l in code_lines(text)))
        want = squeeze(re.sub(r"\s/\s\*?", "", snippet.replace("\\*", "*")))
        if "..." in want:
            continue
        assert want not in code, f"{rid}: the OCR's {snippet!r} is still in {row['file']}"
        checked += 1
    assert checked >= 10


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "sarkp", *args], capture_output=True,
                          text=True, encoding="utf-8", env={**os.environ, "PYTHONUTF8": "1"})


def test_cli_listing_errata_and_exit_codes():
    r = run_cli("listing", "DPRM1")
    assert r.returncode == 0 and r.stdout.rstrip("\n") == sarkp.listing("DPRM1").rstrip("\n")
    assert run_cli("listing", "IV.1").stdout == r.stdout
    r = run_cli("listing")
    assert r.returncode == 0 and len(r.stdout.splitlines()) == 1 + len(TABLE33) + len(PROGRAMS)
    r = run_cli("listing", "DPRM1", "--modern")
    assert r.returncode == 0 and "subroutine dprm1" in r.stdout.lower()
    r = run_cli("listing", "DUSKR1", "--diff")
    assert r.returncode == 0 and "E-DUSKR1-1" in r.stdout
    r = run_cli("listing", "DUSKR1", "--diff", "side")
    assert r.returncode == 0 and " | " in r.stdout
    r = run_cli("errata", "E-DUSKR1-1")
    assert r.returncode == 0 and r.stdout.startswith("E-DUSKR1-1")
    r = run_cli("errata", "DUSKR1")
    assert r.returncode == 0 and "E-DUSKR1-3" in r.stdout
    for args in (("listing", "NOSUCH"), ("errata", "E-NOPE-1"), ("listing", "II.13", "--modern")):
        r = run_cli(*args)
        assert r.returncode == 2, args
        assert r.stdout == "" and len(r.stderr.strip().splitlines()) == 1, r.stderr


#: Listings gfortran rejects as printed (the ES EVM's compiler evidently did not).
DOES_NOT_COMPILE = {
    "III.4_DSNTZ3.f": "E-DSNTZ3-4: PI = 3.14159 before DIMENSION",
    "III.6_DSNTZK.f": "E-DSNTZK-1: PI = 3.14159 before REAL",
    "X_program.f": "L7605: WRITE(3, 15) names the executable statement 15 as its FORMAT",
}


@pytest.mark.skipif(shutil.which("gfortran") is None, reason="no gfortran")
def test_every_listing_compiles_as_printed(tmp_path):
    """A transcription check: the listings are FORTRAN (FORMAT texts aside, which
    sarkp.printed's build replaces), except where the book's own code is at fault."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "fortran" / "printed"))
    try:
        from gen_printed import prepare
    finally:
        sys.path.pop(0)
    for row in index():
        source = tmp_path / row["file"]
        source.write_text(prepare(package_file("listings", row["file"]).read_text(
            encoding="utf-8")), encoding="utf-8")
        r = subprocess.run(["gfortran", "-fsyntax-only", "-std=legacy",
                            "-ffixed-line-length-none", "-w", str(source)],
                           capture_output=True, text=True, cwd=tmp_path)
        if row["file"] in DOES_NOT_COMPILE:
            assert r.returncode != 0, f"{row['file']} compiles: drop it from the list"
            assert sarkp.errata(DOES_NOT_COMPILE[row["file"]].split(":")[0]) \
                if DOES_NOT_COMPILE[row["file"]].startswith("E-") else True
        else:
            assert r.returncode == 0, f"{row['file']}:\n{r.stderr}"


def _errata_table_rows():
    text = package_file("ERRATA.md").read_text(encoding="utf-8") \
        if package_file("ERRATA.md").is_file() else \
        (Path(__file__).resolve().parents[1] / "docs" / "ERRATA.md").read_text("utf-8")
    return [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in text.splitlines() if line.startswith("| E-")]


def test_every_errata_id_is_unique():
    ids = [row[0] for row in _errata_table_rows()]
    assert len(ids) > 250
    assert sorted({i for i in ids if ids.count(i) > 1}) == []


def test_every_test_an_errata_row_cites_exists():
    """The last column of every row names the tests that pin it (``file.py::test_name``
    or a bare ``test_name``): each must be a test function of tests/."""
    here = Path(__file__).resolve().parent
    sources = {p.name: p.read_text(encoding="utf-8") for p in here.glob("*.py")}
    missing = []
    for row in _errata_table_rows():
        for m in re.finditer(r"(?:([\w/]+\.py)::)?(test_\w+)", row[-1]):
            name = m.group(2)
            files = [Path(m.group(1)).name] if m.group(1) else list(sources)
            if not any(re.search(rf"^def {name}\(", sources.get(f, ""), re.M) for f in files):
                missing.append((row[0], m.group(0)))
    assert missing == []


@pytest.mark.parametrize("name", ["DPRM1", "DSKOR1"])
def test_diff_shows_every_statement_of_sarkps_routine(name):
    """``sarkp listing NAME --diff`` is faithful to sarkp's routine as corrected mode runs
    it: every executable statement of that view appears on its side, statements joined by
    ``;`` one by one and one-line IFs as written (no empty IF blocks)."""
    source = L.listing(name, corrected=True)
    statements, pending = [], ""
    for line in source.splitlines()[1:]:
        code = re.sub(r"!.*$", "", line).strip()
        if not code:
            continue
        code = pending + code.lstrip("&").strip()
        if code.endswith("&"):                       # a continued statement
            pending = code[:-1].rstrip() + " "
            continue
        pending = ""
        for s in (x.strip() for x in code.split(";")):
            if s and not re.match(r"(real|integer|logical)\b", s, re.I):
                statements.append(s)
    diff = L.listing(name, diff="unified")
    added = [line[2:].strip() for line in diff.splitlines() if line.startswith("+ ")]
    # a statement not shown as added is one the book has too (shown as unchanged)
    book = {L._key(b) for b in L._book_statements(L.listing(name))}
    assert "if (failed(ier)) return" in added or name == "DPRM1"
    for s in statements:
        assert (s in added or L._key(s) in book
                or s.lower().startswith(("subroutine", "end subroutine"))), s
    for a, b in zip(added, added[1:]):
        assert not (a.lower().endswith("then") and b.lower() == "end if"), (a, b)


def _modern_names():
    return [i.name for i in L.listings() if i.kind != "program"
            and re.search(rf"subroutine\s+{i.name}\b|function\s+{i.name}\b",
                          "".join(p.read_text() for p in FORTRAN), re.I)]


FORTRAN = sorted((Path(__file__).resolve().parents[1] / "fortran").glob("*.f90"))


def _side_columns(text):
    """The left and right cells of ``--diff side``'s rows (hunk and note lines aside)."""
    left, right = [], []
    for line in text.splitlines():
        if len(line) > 2 and line[0] in " !~" and line[1] == " " and line[66:68] == " |":
            left.append(line[2:66].rstrip())          # two columns of 64 characters
            right.append(line[69:].rstrip())
    return left, right


@pytest.mark.parametrize("name", _modern_names())
def test_diff_errata_lines_agree_with_the_hunks(name):
    """The ids the first lines list are every id a hunk is labelled with (DPRM1 said
    "ERRATA ids the routine cites: none" and then labelled a hunk E-DPRM1-1)."""
    for style in ("side", "unified"):
        text = L.listing(name, diff=style)
        head = next(line for line in text.splitlines() if line.startswith("ERRATA"))
        listed = set(L.errata_ids_of(head))
        labels = {i for line in text.splitlines() if line.startswith("@@")
                  for i in L.errata_ids_of(line)}
        assert labels <= listed, (name, head, labels - listed)
        if not listed:
            assert "none" in head


@pytest.mark.parametrize("name", ["DPRM1", "DUSKR1", "DKNMA1", "DGMZPC", "DSNTZ3"])
def test_diff_side_cuts_no_statement(name):
    """Every statement of both sides is shown whole (wrapped, never cut at 64
    characters), and no line of the output is wider than the two columns."""
    text = L.listing(name, diff="side")
    left, right = _side_columns(text)
    shown = (L._normal("".join(left)), L._normal("".join(right)))
    book = L._statements(L._book_statements(L.listing(name)))
    modern = L._statements(L._modern_statements(L.listing(name, corrected=True)))
    for side, statements in zip(shown, (book, modern)):
        for s in statements:
            assert L._normal(s) in side, s
    assert max(len(line) for line in text.splitlines()
               if not line.startswith(("@@", "ERRATA", name))) <= 2 + 2 * 64 + 3


def _if_depth_ok(text):
    depth = 0
    for line in text.splitlines():
        code = re.sub(r"!.*$", "", line).strip().lower()
        if re.match(r"(\w+\s*:\s*)?if\s*\(.*\)\s*then$", code):
            depth += 1
        elif re.match(r"end\s*if\b", code):
            depth -= 1
            if depth < 0:
                return False
    return depth == 0


@pytest.mark.parametrize("name", _modern_names())
def test_corrected_view_leaves_out_the_as_printed_branches(name):
    """``listing(NAME, corrected=True)``: the routine as corrected mode runs it, without
    its as-printed branches; every line of it is a line of the whole routine, its IF
    blocks balanced."""
    whole = L.listing(name, modern=True)
    clean = L.listing(name, corrected=True)
    assert "printed_mode" not in re.sub(r"!.*", "", clean)
    assert _if_depth_ok(clean), clean
    body = {line.strip() for line in whole.splitlines()}
    for line in clean.splitlines()[1:]:
        s = line.strip()
        # a line not in the routine is an IF whose condition lost its printed_mode term
        assert s in body or s.lower().startswith(("if (", "else if (")), s


def test_corrected_view_of_dprm1():
    clean = L.listing("DPRM1", corrected=True)
    code = [re.sub(r"!.*", "", x).strip() for x in clean.splitlines()]
    # corrected mode: the kind-1 kernel (issue 25), the apex of the triangle inside it
    assert any(c.startswith("call rrr_kernel(1, [xa, ya]") for c in code)
    # the as-printed branch (the book's DVKT and angles) is gone
    assert not any(c.startswith(("call dvkt", "ugbac =")) for c in code)
    assert code.count("else") == 0
    assert "as-printed branches left out" in clean.splitlines()[0]
    # the diff is against this view: the book's cosine law against the kernel
    left, right = _side_columns(L.listing("DPRM1", diff="side"))
    assert any(x.startswith("call rrr_kernel") for x in right)
    assert not any("dvkt" in x for x in right) and any("DVKT" in x for x in left)
    r = run_cli("listing", "DPRM1", "--corrected")
    assert r.returncode == 0 and r.stdout.rstrip("\n") == clean.rstrip("\n")


def test_dprm1_header_cites_its_erratum_and_names_tri_apex():
    """The Fortran header of DPRM1 cites E-DPRM1-1 and the routine it calls (tri_apex,
    as the ERRATA row says), not tri_angles."""
    whole = L.listing("DPRM1", modern=True)
    header = whole.split("subroutine dprm1")[0]
    assert "E-DPRM1-1" in L.errata_ids_of(header)
    assert "tri_apex" in header and "tri_angles" not in header
    assert "tri_apex" in L.errata("E-DPRM1-1")
