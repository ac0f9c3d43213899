"""The documentation's sources: docs/conf.py documents every public routine, the
docstrings parse as numpydoc, and the gallery's scripts draw drawing-sheet figures.
The build itself (sphinx-build -W) is scripts/build-docs.sh, run by .ci/run."""

from __future__ import annotations

import importlib
import importlib.util
import runpy
import sys
import warnings
from pathlib import Path

import pytest

import sarkp

sys.path.insert(0, str(Path(__file__).resolve().parent))   # --import-mode=importlib
DOCS = Path(__file__).resolve().parents[1] / "docs"


def _conf():
    spec = importlib.util.spec_from_file_location("sarkp_docs_conf", DOCS / "conf.py")
    conf = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conf)
    return conf


def _documented(conf):
    pages = {**conf.CHAPTERS, **conf.SUPPORT, "mechanism": conf.MECHANISM[1:]}
    out = {}
    for title, module_name in pages.values():
        try:
            module = importlib.import_module(module_name)
        except ImportError:
            continue
        for name in conf._public(module):
            out[name] = getattr(module, name)
    return out


def test_every_public_name_of_sarkp_has_a_page():
    documented = _documented(_conf())
    missing = [n for n in sarkp.__all__ if callable(getattr(sarkp, n)) and n not in documented]
    assert missing == []
    # every routine of Table 33 (and the extensions) among them
    assert {"GELG", "DPRM1", "DKNMA5", "DZKNDV", "DMHVK", "DGMZVN", "DUGL6"} <= set(documented)


def test_docstrings_parse_as_numpydoc():
    docscrape = pytest.importorskip("numpydoc.docscrape")
    import inspect
    for name, value in _documented(_conf()).items():
        if not callable(value) or not (value.__doc__ or "").strip():
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            if inspect.isclass(value):
                docscrape.ClassDoc(value)
            else:
                doc = docscrape.FunctionDoc(value)
                if "Parameters" in value.__doc__:
                    assert doc["Parameters"], name


@pytest.mark.parametrize("script", sorted(p.name for p in (DOCS / "examples").glob("plot_*.py")))
def test_gallery_scripts_draw_drawing_sheets(script, capsys):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure
    from test_plots import sheet_problems
    names = runpy.run_path(str(DOCS / "examples" / script), run_name="__main__")
    figures = {id(v): v for v in names.values() if isinstance(v, Figure)}
    assert figures, "the script draws nothing"
    for figure in figures.values():
        assert sheet_problems(figure) == []


# ---- the pages a student learns from: their code runs, their pictures are right ----------

def _ext(name):
    """A module of docs/_ext (the build's own extensions), imported from its file."""
    sys.path.insert(0, str(DOCS / "_ext"))
    try:
        return importlib.import_module(name)
    finally:
        sys.path.remove(str(DOCS / "_ext"))


PAGES = sorted(p.stem for p in DOCS.glob("*.md")
               if "```python" in p.read_text(encoding="utf-8"))


def test_the_learning_pages_have_code():
    assert {"concepts", "tutorial", "from-the-book", "index"} <= set(PAGES)


@pytest.mark.parametrize("page", PAGES)
def test_every_code_block_of_the_docs_runs(page):
    """Every ```python block of the page runs, in order, in one namespace (as the build
    runs it), without an unexpected warning; the figures it draws are drawing sheets."""
    pytest.importorskip("matplotlib")
    from test_plots import sheet_problems
    run = _ext("sarkp_run")
    text = (DOCS / f"{page}.md").read_text(encoding="utf-8")
    shown, figures = run.run_page(text, page)
    blocks = len(run.BLOCK.findall(text))
    assert blocks > 0
    # what a block printed follows it: every block of these pages prints or draws
    assert shown.count("*Output:*") + len(figures) >= blocks
    for figure in figures:
        assert sheet_problems(figure) == [], page


def test_a_failing_code_block_fails_the_page_and_names_it():
    run = _ext("sarkp_run")
    text = "# t\n\n```python\nx = 2\nprint(x * 21)\n```\n\n```python\nimport sarkp\n" \
           "sarkp.DPRM1(0.0, 0.0, 10.0, 0.0, 1.0, 1.0, 1)\n```\n"
    with pytest.raises(run.PageError, match=r"t\.md, code block 2 \('import sarkp'\)"):
        run.run_page(text, "t")
    shown, _ = run.run_page(text.split("```python\nimport")[0], "t")
    assert "*Output:*\n\n```text\n42\n```" in shown
    # a warning the page does not expect fails it too
    with pytest.raises(run.PageError, match="UserWarning: unexpected"):
        run.run_page("```python\nimport warnings\nwarnings.warn('unexpected')\n```\n", "w")


def test_concept_pictures_are_drawing_sheets():
    pytest.importorskip("matplotlib")
    from test_plots import sheet_problems
    figures = _ext("concept_figures")
    for name, draw in figures.PICTURES.items():
        assert sheet_problems(draw()) == [], name


def test_concept_pictures_show_what_their_captions_say():
    """The branch picture's captions (B left of A->C for +1, ahead of the foot of A along
    the guide for +1; the mirror for -1) hold for the mechanisms it draws, over a turn."""
    figures = _ext("concept_figures")
    import numpy as np
    phi = np.linspace(0.0, 2 * np.pi, 73)
    for branch in (1, -1):
        for make in (figures.rrr, figures.rpr):
            r = make(branch).solve(phi, need="positions")
            A, B, C = r.position("A"), r.position("B"), r.position("C")
            cross = (C - A)[:, 0] * (B - A)[:, 1] - (C - A)[:, 1] * (B - A)[:, 0]
            assert np.all(branch * cross > 0), make.__name__
        r = figures.rrp(branch).solve(phi, need="positions")
        assert np.all(branch * (r.position("B")[:, 0] - r.position("A")[:, 0]) > 0)
    # kinds 4 and 5: B on both guides, K under the crank pin (x_K = x_A)
    r = figures.prp().solve(phi[:10], need="positions")
    np.testing.assert_allclose(r.position("B")[:, 1], 0.15, atol=1e-15)
    r = figures.rpp().solve(phi, need="positions")
    np.testing.assert_allclose(r.position("K")[:, 0], r.position("A")[:, 0], atol=1e-15)


def test_every_public_module_has_an_api_page():
    import pkgutil
    conf = _conf()
    pages = {m for _, m in conf.CHAPTERS.values()} | {m for _, m in conf.SUPPORT.values()} \
        | {conf.MECHANISM[2]} | {m for _, m in conf.further_modules().values()}
    public = {f"sarkp.{i.name}" for i in pkgutil.iter_modules(sarkp.__path__)
              if not i.name.startswith("_") and i.name not in conf.PRIVATE}
    assert public <= pages


def test_mechanism_result_members_are_on_its_page():
    """MechanismResult's methods live on its base class and its fields on the named
    tuple: its directive must take inherited and undocumented members."""
    conf = _conf()
    import sarkp.mechanism
    directive = conf._directive(sarkp.mechanism, "MechanismResult")
    assert ":inherited-members: tuple" in directive and ":undoc-members:" in directive


def test_the_command_line_page_has_no_rest_literals():
    conf = _conf()
    conf.generate_cli()
    text = (DOCS / "_generated" / "cli.md").read_text(encoding="utf-8")
    assert "``" not in text.replace("```", "")
    assert "`sarkp`" in text and "## `sarkp book run`" in text
