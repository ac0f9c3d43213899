"""Build the printed code (run by meson at build time).

    python gen_printed.py OUT.f OUT.pyf LISTINGS_DIR CHAPTER.f90 [CHAPTER.f90 ...]

Writes OUT.f, the book's listings as printed (python/sarkp/listings/, OCR misreadings
corrected) of the routines that listings/printed.csv says run as printed, and OUT.pyf,
their f2py signatures for the extension ``sarkp._printed``.

* printed.csv lists every routine: ``runs = yes``, or ``no`` with the reason.  A routine is
  added only after it was checked against sarkp (tests/test_printed.py); a new chapter's
  routines stay out until then.  A listed routine's printed argument list must be sarkp's
  (the chapter module's, without the trailing IER), or the build stops.
* Types are the listing's: REAL (single precision) by FORTRAN's implicit rule unless the
  listing declares otherwise; INTEGER for I-N.  Which arguments are inputs and which are
  outputs comes from sarkp's routine (its ``intent``), since the book's FORTRAN does not say.
* COMMON results (the chapter module's ``!sarkp common:`` lines) are read from the
  listing's one COMMON block, word by word, which f2py exposes (``_printed.zpc.a``).
* FORMAT statements only lay out the printer's output, which sarkp.printed discards; their
  texts (Cyrillic Hollerith constants whose counts were set for the ES EVM's one-byte
  characters) become ``FORMAT(1X, (8G15.7))`` for the compiler.  Nothing else is changed.
"""

from __future__ import annotations

import csv
import re
import sys
from pathlib import Path

HEAD = re.compile(r"^\s*(?:(REAL|INTEGER)\s+)?(SUBROUTINE|FUNCTION)\s+(\w+)\s*\((.*)\)\s*$", re.I)


def statements(text: str) -> list[tuple[str, list[str]]]:
    """(statement with continuations joined, its source lines), comments dropped."""
    out: list[tuple[str, list[str]]] = []
    for line in text.splitlines():
        if not line.strip() or line[:1] in "Cc*":
            continue
        if len(line) > 5 and line[5] not in " 0" and out:
            out[-1] = (out[-1][0] + line[6:].rstrip(), out[-1][1] + [line])
        else:
            out.append((line[:5].strip() + " " + line[6:].rstrip(), [line]))
    return [(s.strip(), lines) for s, lines in out]


def printed_types(stmts) -> dict[str, str]:
    types = {}
    for s, _ in stmts:
        m = re.match(r"^(?:\d+\s+)?(REAL|INTEGER|DOUBLE\s*PRECISION)\s+(?!FUNCTION)(.*)$", s, re.I)
        if m:
            kind = "double precision" if m.group(1).upper().startswith("D") else m.group(1).lower()
            for name in re.sub(r"\([^)]*\)", "", m.group(2)).split(","):
                types[name.strip().upper()] = kind
    return types


def implicit(name: str, types: dict[str, str]) -> str:
    return types.get(name.upper(), "integer" if name[0].upper() in "IJKLMN" else "real")


def modern_interfaces(paths) -> dict[str, dict]:
    """name -> {'args': [...], 'intent': {arg: in/out}, 'dims': {arg: [...]}, 'function': bool}."""
    found = {}
    for path in paths:
        text = Path(path).read_text(encoding="utf-8")
        text = re.sub(r"&\s*\n\s*&?", " ", text)                 # free-form continuations
        for m in re.finditer(r"^\s*((?:pure|elemental|recursive|real\(dp\)|integer)\s+)*"
                             r"(subroutine|function)\s+(\w+)\s*\(([^)]*)\)(.*?)"
                             r"^\s*end\s+(subroutine|function)\s+\3\b", text, re.M | re.S | re.I):
            name, args, body = m.group(3).upper(), m.group(4), m.group(5)
            info = {"args": [a.strip().upper() for a in args.split(",") if a.strip()],
                    "intent": {}, "dims": {}, "function": m.group(2).lower() == "function"}
            for d in re.finditer(r"^\s*(real\(dp\)|integer)\s*,\s*intent\((in|out|inout)\)\s*::"
                                 r"(.*)$", body, re.M | re.I):
                for item in re.findall(r"(\w+)(\([^)]*\))?", re.sub(r"!.*", "", d.group(3))):
                    info["intent"][item[0].upper()] = d.group(2).lower()
                    if item[1]:
                        info["dims"][item[0].upper()] = [x.strip() for x in item[1][1:-1].split(",")]
            # COMMON results: the names before "=>" of the "!sarkp common:" lines, in order
            info["common"] = [c.split("=>")[0].strip().upper()
                              for line in re.findall(r"^\s*!sarkp common:(.*)$", body, re.M)
                              for c in line.split(",") if c.strip()]
            found[name] = info
    return found


def common_block(name: str, stmts, results: list[str], types: dict[str, str]) -> list[str]:
    """f2py's view of the listing's COMMON block that holds sarkp's COMMON results (by
    position, as COMMON associates storage; the listing's names and types)."""
    blocks = [m for m in (re.match(r"^(?:\d+\s+)?COMMON\s*/\s*(\w+)\s*/\s*(.*)$", s, re.I)
                          for s, _ in stmts) if m]
    if len(blocks) != 1:
        sys.exit(f"gen_printed: {name} returns COMMON results but its listing has "
                 f"{len(blocks)} COMMON statements (one expected)")
    block, members = blocks[0].group(1).lower(), [
        a.strip().upper() for a in blocks[0].group(2).split(",") if a.strip()]
    # sarkp's extension results follow the COMMON's words (DGMZPC's DA1, ...)
    if len(members) > len(results):
        sys.exit(f"gen_printed: the printed COMMON /{block.upper()}/ of {name} has "
                 f"{len(members)} words; sarkp returns {len(results)} COMMON results")
    return [f"      {implicit(a, types)} :: {a.lower()}" for a in members] + [
        f"      common /{block}/ {', '.join(a.lower() for a in members)}"]


def prepare(text: str) -> str:
    """The listing for the compiler: FORMAT texts replaced (see the module docstring)."""
    out = []
    for s, lines in statements(text):
        m = re.match(r"^(\d+)\s+FORMAT\s*\(", s, re.I)
        if m:
            out.append(f"{m.group(1):<5} FORMAT(1X, (8G15.7))")
        else:
            out.extend(lines)
    return "\n".join(out) + "\n"


def main(out_f: str, out_pyf: str, listings: str, *chapters: str) -> None:
    listings_dir = Path(listings)
    index = list(csv.DictReader((listings_dir / "index.csv").open(encoding="utf-8")))
    runs = {r["name"] for r in csv.DictReader(
        (listings_dir / "printed.csv").open(encoding="utf-8")) if r["runs"] == "yes"}
    modern = modern_interfaces(chapters)
    code, sigs = [], []
    for row in index:
        name = row["name"]
        if row["kind"] == "program" or name not in runs:
            continue
        if name not in modern:
            sys.exit(f"gen_printed: {name} runs as printed (printed.csv) but sarkp has no "
                     f"routine {name} to take its signature from")
        text = (listings_dir / row["file"]).read_text(encoding="utf-8")
        stmts = statements(text)
        head = HEAD.match(stmts[0][0])
        if not head or head.group(3).upper() != name:
            sys.exit(f"gen_printed: {row['file']} does not start with {name}'s header")
        args = [a.strip().upper() for a in head.group(4).split(",") if a.strip()]
        info = modern[name]
        want = [a for a in info["args"] if a != "IER"]
        # sarkp extension outputs after the book's arguments (DGMTZK's XUR) are not the
        # printed code's: sarkp.printed gives NaN for them
        extra = want[len(args):]
        if want[:len(args)] == args and all(info["intent"].get(a) == "out" for a in extra):
            want = args
        if args != want:
            sys.exit(f"gen_printed: the printed {name}({', '.join(args)}) is not sarkp's "
                     f"({', '.join(want)}): set runs = no in printed.csv, with the reason")
        types = printed_types(stmts)
        code.append(prepare(text))
        kind = "function" if head.group(2).upper() == "FUNCTION" else "subroutine"
        lines = [f"    {kind} {name.lower()}({', '.join(a.lower() for a in args)})"]
        if kind == "function":
            lines.append(f"      {(head.group(1) or implicit(name, types)).lower()} :: {name.lower()}")
        for a in args:
            dims = info["dims"].get(a)
            shape = f", dimension({', '.join(d.lower() for d in dims)})" if dims else ""
            lines.append(f"      {implicit(a, types)}{shape}, intent({info['intent'].get(a, 'in')})"
                         f" :: {a.lower()}")
        if info["common"]:
            lines.extend(common_block(name, stmts, info["common"], types))
        lines.append(f"    end {kind} {name.lower()}")
        sigs.append("\n".join(lines))
    sigs.append("    subroutine prinit(devnull)\n      character*(*), intent(in) :: devnull\n"
                "    end subroutine prinit")
    Path(out_f).write_text("".join(code), encoding="utf-8")
    Path(out_pyf).write_text("python module _printed\n  interface\n" + "\n".join(sigs)
                             + "\n  end interface\nend python module _printed\n", encoding="utf-8")


if __name__ == "__main__":
    main(*sys.argv[1:])
