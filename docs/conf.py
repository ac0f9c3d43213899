"""Sphinx configuration of sarkp's documentation (``bash scripts/build-docs.sh``).

The pages a student learns from (docs/concepts.md, tutorial.md, from-the-book.md, ...)
are Markdown whose ```` ```python ```` blocks run when the page is read, each block
followed by what it prints and draws (docs/_ext/sarkp_run.py); the pictures of the
concepts page are drawn by docs/_ext/concept_figures.py from sarkp's own solution.  The
API reference is generated at build time from the installed package: one page per book
chapter, every routine of the chapter module's ``__all__``, with numpydoc, then a page
per further public module.  The gallery runs ``docs/examples/*.py`` (sphinx-gallery)
and shows the figures and animations they draw.  docs/ERRATA.md is rendered by
myst-parser.  Generated sources go to ``docs/_generated`` (not in git).
"""

from __future__ import annotations

import contextlib
import importlib
import io
import re
import sys
from pathlib import Path

import sarkp

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
GENERATED = HERE / "_generated"
sys.path.insert(0, str(HERE / "_ext"))

project = "sarkp"
author = "the sarkp authors"
copyright = "sarkp authors; the FORTRAN library: I. M. Belokonev, 1990"
release = version = getattr(sarkp, "__version__", "")

extensions = [
    "sphinx.ext.autodoc",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "sarkp_run",                       # docs/_ext: run the pages' code blocks
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "_ext", "examples/GALLERY_HEADER.rst", "**.ipynb_checkpoints"]
root_doc = "index"
html_theme = "alabaster"
html_title = "sarkp"
html_static_path: list = []

autodoc_member_order = "bysource"
autodoc_typehints = "none"            # the numpydoc sections give the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# ERRATA.md is a table of the book's errors written for GitHub: its headings start at
# level 2 under a level-1 title.  (A link that points nowhere is a warning, so an error.)
myst_heading_anchors = 3
suppress_warnings = ["myst.header"]


# ---- the gallery ------------------------------------------------------------------------------

sphinx_gallery_conf = {
    "examples_dirs": str(HERE / "examples"),
    "gallery_dirs": str(GENERATED / "gallery"),
    "filename_pattern": r"/plot_",
    "image_scrapers": ("sarkp_scraper.scrape",),   # docs/_ext/sarkp_scraper.py
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "within_subsection_order": "FileNameSortKey",
    "show_memory": False,
    "write_computation_times": False,
    "plot_gallery": "True",
}


# ---- the API reference ---------------------------------------------------------------------

#: page name -> (title, module)
CHAPTERS = {
    "operators": ("Chapter 2: operator functions", "sarkp.operators"),
    "solver": ("GELG: the linear solver the book calls", "sarkp.solver"),
    "synthesis": ("Chapter 3: synthesis of linkages", "sarkp.synthesis"),
    "kinematics": ("Chapter 4: kinematics of Assur groups", "sarkp.kinematics"),
    "cams": ("Chapter 5: cam mechanisms", "sarkp.cams"),
    "gears": ("Chapter 6: gears", "sarkp.gears"),
    "forces": ("Chapter 7: force analysis", "sarkp.forces"),
    "dynamics": ("Chapter 8: dynamics", "sarkp.dynamics"),
}
#: the page of sarkp.Mechanism (written when the package has it)
MECHANISM = ("mechanism", "A whole mechanism: sarkp.Mechanism", "sarkp.mechanism")
#: modules documented whole (their __all__, or their public functions and classes)
SUPPORT = {
    "modes": ("Modes: corrected and as printed", "sarkp.modes"),
    "errors": ("Errors, warnings and status codes", "sarkp.errors"),
    "results": ("Result objects", "sarkp.results"),
    "plot": ("Pictures (sarkp.plot)", "sarkp.plot"),
    "book": ("The book's programs (sarkp.book)", "sarkp.book"),
    "listings": ("The book's listings and ERRATA (sarkp.listings)", "sarkp.listings"),
    "printed": ("The printed code compiled (sarkp.printed)", "sarkp.printed"),
}
#: modules that are not public API (the rest of sarkp's public modules get a page each)
PRIVATE = {"library", "report", "cli"}


def further_modules() -> dict:
    """sarkp's public modules without a page above (e.g. one added later): page name ->
    (title: the first line of the module's docstring, module)."""
    import pkgutil
    listed = {m for _, m in CHAPTERS.values()} | {m for _, m in SUPPORT.values()} | \
        {MECHANISM[2]}
    out = {}
    for info in pkgutil.iter_modules(sarkp.__path__):
        name = f"sarkp.{info.name}"
        if info.name.startswith("_") or info.name in PRIVATE or name in listed:
            continue
        module = importlib.import_module(name)
        first = (module.__doc__ or name).strip().splitlines()[0].rstrip(".")
        out[info.name] = (f"{first} ({name})" if name not in first else first, name)
    return out


def _public(module) -> list[str]:
    names = getattr(module, "__all__", None)
    if names is None:
        names = [n for n, v in vars(module).items()
                 if not n.startswith("_") and callable(v)
                 and getattr(v, "__module__", None) == module.__name__]
    return list(names)


def _directive(module, name) -> str:
    import inspect
    value = getattr(module, name)
    if inspect.isclass(value):
        from sarkp.results import Result
        if issubclass(value, Result) and value.__mro__[1] is not Result and \
                value is not Result:
            # a result class on a base of its own (MechanismResult): its fields and the
            # base's methods are its members, the tuple's own (count, index) are not
            return (f".. autoclass:: {module.__name__}.{name}\n   :members:\n"
                    f"   :inherited-members: tuple\n   :undoc-members:\n")
        return f".. autoclass:: {module.__name__}.{name}\n   :members:\n"
    if callable(value):
        return f".. autofunction:: {module.__name__}.{name}\n"
    return f".. autodata:: {module.__name__}.{name}\n   :annotation:\n"


def _api_page(page, title, module_name) -> str | None:
    try:
        module = importlib.import_module(module_name)
    except ImportError:
        return None                      # not in this build (e.g. sarkp.results)
    lines = [title, "=" * len(title), "",
             f".. automodule:: {module_name}", "   :no-members:", "   :no-index:", ""]
    names = _public(module)
    if names:
        lines += [".. list-table::", "   :widths: 20 80", ""]
        for name in names:
            doc = (getattr(getattr(module, name), "__doc__", None) or "").strip()
            first = doc.split("\n\n")[0].replace("\n", " ") if callable(
                getattr(module, name)) else ""
            lines += [f"   * - :obj:`{module_name}.{name}`" if callable(getattr(module, name))
                      else f"   * - ``{name}``", f"     - {first or ' '}"]
        lines.append("")
        for name in names:
            if callable(getattr(module, name)):
                lines.append(_directive(module, name))
    return "\n".join(lines) + "\n"


def generate_api():
    out = GENERATED / "api"
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("*.rst"):
        old.unlink()
    pages = []
    for number, (page, (title, module)) in enumerate(CHAPTERS.items()):
        text = _api_page(page, title, module)
        if text:
            pages.append((f"{number:02d}_{page}", text))
    if hasattr(sarkp, "Mechanism"):         # the designer's interface, once it is built
        text = _api_page(*MECHANISM)
        if text:
            pages.append(("10_mechanism", text))
    for number, (page, (title, module)) in enumerate(
            {**SUPPORT, **further_modules()}.items(), start=20):
        text = _api_page(page, title, module)
        if text:
            pages.append((f"{number:02d}_{page}", text))
    for name, text in pages:
        (out / f"{name}.rst").write_text(text, encoding="utf-8")


# ---- the pictures of the concepts page -------------------------------------------------

def generate_concept_figures():
    import matplotlib
    matplotlib.use("Agg")
    import concept_figures                  # docs/_ext
    concept_figures.write(GENERATED / "img")


def _absolute_values(app, what, name, obj, options, lines):
    """The docstrings write absolute values as ``|x|``, which reST reads as a
    substitution: escape every ``|`` outside inline literals and outside table rows."""
    for i, line in enumerate(lines):
        row = line.strip()
        if "|" not in line or row.startswith("+") or (row[:1] == row[-1:] == "|"):
            continue
        parts = line.split("``")
        lines[i] = "``".join(p if k % 2 else p.replace("|", "\\|")
                             for k, p in enumerate(parts))


def _docstring_as_markdown(doc: str) -> list[str]:
    """A module docstring as Markdown: its indented paragraphs (a usage table) as text
    blocks, the others as prose, with reST's ``literal`` as Markdown's `literal`."""
    import textwrap
    out = []
    for block in re.split(r"\n\s*\n", doc.strip("\n")):
        lines = block.splitlines()
        if all(line.startswith("    ") or not line.strip() for line in lines):
            out += ["```text", textwrap.dedent(block), "```", ""]
        else:
            out += [re.sub(r"``([^`]+)``", r"`\1`", " ".join(l.strip() for l in lines)), ""]
    return out


def generate_cli():
    """The command line's page: sarkp.cli's docstring and the help of each command."""
    from sarkp import cli
    parts = ["# The command line", ""] + _docstring_as_markdown(cli.__doc__)
    for command in (["book", "list"], ["book", "run"], ["book", "diff"], ["listing"],
                    ["errata"]):
        text = io.StringIO()
        with contextlib.redirect_stdout(text), contextlib.suppress(SystemExit):
            cli.main(command + ["--help"])
        parts += [f"## `sarkp {' '.join(command)}`", "", "```text",
                  text.getvalue().rstrip("\n"), "```", ""]
    GENERATED.mkdir(parents=True, exist_ok=True)
    (GENERATED / "cli.md").write_text("\n".join(parts), encoding="utf-8")


def setup(app):
    app.connect("autodoc-process-docstring", _absolute_values, priority=400)
    # stay off the source tree's python/ folder: the installed package is documented
    sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != ROOT / "python"]
    generate_api()
    generate_cli()
    generate_concept_figures()
