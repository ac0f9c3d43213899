"""Sphinx configuration of sarkp's documentation (``bash scripts/build-docs.sh``).

The API reference is generated at build time from the installed package: one page per
book chapter, every routine of the chapter module's ``__all__``, with numpydoc; a page
for :class:`sarkp.Mechanism` when the package has it.  The tutorial runs the README's
Python examples and shows what they print.  The gallery runs ``docs/examples/*.py``
(sphinx-gallery) and shows the figures they draw.  docs/ERRATA.md is rendered by
myst-parser.  Generated sources go to ``docs/_generated`` (not in git).
"""

from __future__ import annotations

import contextlib
import importlib
import io
import os
import re
import sys
import tempfile
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
# level 2 under a level-1 title and some of its links point into the source tree.
myst_heading_anchors = 3
suppress_warnings = ["myst.header", "myst.xref_missing"]


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
    for number, (page, (title, module)) in enumerate(SUPPORT.items(), start=20):
        text = _api_page(page, title, module)
        if text:
            pages.append((f"{number:02d}_{page}", text))
    for name, text in pages:
        (out / f"{name}.rst").write_text(text, encoding="utf-8")


# ---- the tutorial: the README's examples, run ------------------------------------------------

@contextlib.contextmanager
def _inside(folder):
    """Work in ``folder`` for a while (contextlib.chdir, which Python 3.10 lacks)."""
    here = os.getcwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(here)


def _run_like_a_session(code, namespace):
    """Run ``code``; a top-level expression that is not a call of print shows its value,
    as the interpreter's prompt would (``>>> expression`` then the value)."""
    import ast
    tree = ast.parse(code)
    for node in tree.body:
        segment = ast.get_source_segment(code, node)
        if isinstance(node, ast.Expr) and not (
                isinstance(node.value, ast.Call) and getattr(node.value.func, "id", "") == "print"):
            value = eval(compile(ast.Expression(node.value), "README.md", "eval"), namespace)
            print(f">>> {segment}")
            print(repr(value))
        else:
            exec(compile(ast.Module([node], []), "README.md", "exec"), namespace)


def generate_tutorial():
    """Every ```python block of README.md under its section heading, with what it
    prints when run (all blocks in one namespace, in order, in a scratch folder).  A
    block that needs an optional package not installed is shown and marked not run; any
    other failure fails the build."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    parts = ["# Tutorial: the README's examples, run", "",
             "Every Python example of the README, in its order, under the README's "
             "section headings, run when these pages were built (one namespace for all "
             "of them); what each prints follows it.  The prose around them is in the "
             "README; each routine's reference is in the API pages.", ""]
    namespace: dict = {"__name__": "__readme__"}
    scratch = tempfile.mkdtemp(prefix="sarkp-readme-")     # files the examples write
    heading = None
    for match in re.finditer(r"^(#{2,3}) ([^\n]+)$|^( *)```python\n(.*?)^\3```", readme,
                             flags=re.M | re.S):
        if match.group(1):
            heading = match.group(2).strip()
            continue
        indent = match.group(3)
        code = "\n".join(line[len(indent):] for line in match.group(4).splitlines())
        if heading is not None:
            parts += [f"## {heading}", ""]
            heading = None
        output = io.StringIO()
        missing = None
        with contextlib.redirect_stdout(output), _inside(scratch):
            try:
                _run_like_a_session(code, namespace)
            except ImportError as exc:            # an optional package (dask, pandas)
                missing = exc.name or str(exc)
        parts += ["```python", code.rstrip("\n"), "```", ""]
        if missing:
            parts += [f"(Not run when these pages were built: it needs an optional "
                      f"package that is not installed there: {missing}.)", ""]
        elif output.getvalue().strip():
            parts += ["prints", "", "```text", output.getvalue().rstrip("\n"), "```", ""]
    GENERATED.mkdir(parents=True, exist_ok=True)
    (GENERATED / "tutorial.md").write_text("\n".join(parts), encoding="utf-8")


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


def generate_cli():
    """The command line's page: sarkp.cli's docstring and the help of each command."""
    from sarkp import cli
    parts = ["# The command line", "", "```text", cli.__doc__.strip("\n"), "```", ""]
    for command in (["book", "run"], ["book", "diff"], ["book", "list"], ["listing"],
                    ["errata"]):
        text = io.StringIO()
        with contextlib.redirect_stdout(text), contextlib.suppress(SystemExit):
            cli.main(command + ["--help"])
        parts += [f"## sarkp {' '.join(command)}", "", "```text",
                  text.getvalue().rstrip("\n"), "```", ""]
    GENERATED.mkdir(parents=True, exist_ok=True)
    (GENERATED / "cli.md").write_text("\n".join(parts), encoding="utf-8")


def setup(app):
    app.connect("autodoc-process-docstring", _absolute_values, priority=400)
    # stay off the source tree's python/ folder: the installed package is documented
    sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != ROOT / "python"]
    generate_api()
    generate_tutorial()
    generate_cli()
